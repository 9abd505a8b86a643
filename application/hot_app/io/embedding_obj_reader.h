// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_TOOLS_IO_EMBEDDING_OBJ_READER_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_TOOLS_IO_EMBEDDING_OBJ_READER_H

// The reader of an embedding as an OBJ file (the `certify` command's input): `v` lines,
// `vt` lines (Poincare-disk coordinates) and triangles `f v/vt v/vt v/vt`, written by `embed`
// or by any other program.

#include "common.h"
#include "embedding_cones.h"
#include "files.h"
#include "obj.h" // is_ignored_obj_statement()

#include <CGAL/Hyperbolic_orbifold_Tutte/Corner_embedding.h>

#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include <CGAL/disable_warnings.h>

/// \file embedding_obj_reader.h

namespace hot_tools {

namespace io_impl {

// a 1-based OBJ index (negative: relative to the `count` elements read so far) made 0-based;
// false if it is 0, not a number or before the first element (a forward reference is kept
// and checked at the end)
inline bool obj_index(std::string_view t, std::size_t count, std::size_t& index)
{
  std::int64_t id = 0;
  if(parse_signed(t, id) != NUMBER_OK || id == 0)
    return false;
  if(id < 0) {
    const std::uint64_t back = static_cast<std::uint64_t>(-(id + 1)) + 1;
    if(back > count)
      return false;
    index = static_cast<std::size_t>(count - back);
    return true;
  }
  index = static_cast<std::size_t>(id - 1);
  return true;
}

} // namespace io_impl

/// what an OBJ file written by `embed` holds besides the embedding (read_embedding_obj())
struct Embedding_obj_extras
{
  std::vector<std::array<double, 3> > vertex_points;           ///< the v lines
  Embedding_cones cones;                                       ///< the orbifold and cone lines
  bool has_cones = false;                                      ///< whether there are such lines
  std::vector<std::pair<std::size_t, std::size_t> > same;      ///< the `# hot same J K` lines (0-based)
};

namespace io_impl {

// one statement of an embedding's OBJ file (v, vt, f; comments and the format's other
// statements skipped): "" or what is wrong with it
inline std::string read_embedding_obj_statement(const std::vector<std::string_view>& fields, HOT::Corner_embedding& embedding,
                                                std::size_t& number_of_vertices, std::vector<std::array<double, 3> >* vertex_points,
                                                std::vector<std::size_t>& face_lines, std::size_t line)
{
  const std::string_view kw = fields[0];
  if(kw == "v") {
    std::array<double, 3> q;
    if(fields.size() < 4)
      return std::string("vertex " + std::to_string(number_of_vertices) + " has " + std::to_string(fields.size() - 1) +
                          " coordinates, 3 expected");
    for(int k = 1; k <= 3; ++k)
      if(!parse_real(fields[k], q[k - 1]))
        return std::string("vertex " + std::to_string(number_of_vertices) + ": coordinate " + quote(fields[k]) + " is not a number");
    if(vertex_points)
      vertex_points->push_back(q);
    ++number_of_vertices;
  } else if(kw == "vt") {
    std::array<double, 2> p;
    if(fields.size() < 3)
      return std::string("point (vt) " + std::to_string(embedding.points.size()) + " has " + std::to_string(fields.size() - 1) +
                          " coordinate" + (fields.size() == 2 ? "" : "s") + ", 2 expected");
    for(int k = 0; k < 2; ++k)
      if(!parse_real(fields[k + 1], p[k]))
        return std::string("point (vt) " + std::to_string(embedding.points.size()) + ": coordinate " + quote(fields[k + 1]) +
                            " is not a number");
    embedding.points.push_back(p);
  } else if(kw == "f") {
    const std::size_t f = embedding.face_vertices.size();
    if(fields.size() != 4)
      return std::string("face " + std::to_string(f) + " has " + std::to_string(fields.size() - 1) +
                          " corners: an embedding's faces are triangles");
    std::array<std::size_t, 3> fv, fp;
    for(int k = 0; k < 3; ++k) {
      const std::string_view field = fields[k + 1];
      const std::size_t s1 = field.find('/');
      if(s1 == std::string_view::npos || s1 + 1 >= field.size() || field[s1 + 1] == '/')
        return std::string("face " + std::to_string(f) + ": corner " + quote(field) + " has no point (vt) index: 'v/vt' expected");
      const std::size_t s2 = field.find('/', s1 + 1);
      const std::string_view vpart = field.substr(0, s1);
      const std::string_view tpart = field.substr(s1 + 1, s2 == std::string_view::npos ? std::string_view::npos : s2 - s1 - 1);
      if(!obj_index(vpart, number_of_vertices, fv[k]))
        return std::string("face " + std::to_string(f) + ": " + quote(vpart) + " is not a vertex index");
      if(!obj_index(tpart, embedding.points.size(), fp[k]))
        return std::string("face " + std::to_string(f) + ": " + quote(tpart) + " is not a point (vt) index");
    }
    embedding.face_vertices.push_back(fv);
    embedding.face_points.push_back(fp);
    face_lines.push_back(line);
  } else if(kw[0] == '#' || is_ignored_obj_statement(kw)) {
    return std::string();
  } else {
    return std::string("unknown OBJ statement " + quote(kw));
  }
  return std::string();
}

// a '# hot orbifold' or '# hot cone' line into `c`: "" or what is wrong with it
inline std::string read_cone_comment(bool is_orbifold, const std::vector<std::string_view>& f, Embedding_cones& c, bool* has_cones)
{
  if(is_orbifold) {
    // # hot orbifold TYPE genus G cones K reversed R
    std::uint64_t g = 0, k = 0, r = 0;
    if(f.size() != 10 || (f[3] != "sphere" && f[3] != "disk") || f[4] != "genus" || parse_unsigned(f[5], g) != NUMBER_OK ||
       f[6] != "cones" || parse_unsigned(f[7], k) != NUMBER_OK || k > 1000000 || f[8] != "reversed" ||
       parse_unsigned(f[9], r) != NUMBER_OK || r > 1)
      return std::string("orbifold line: '# hot orbifold sphere|disk genus G cones K reversed 0|1' expected");
    if(has_cones && *has_cones)
      return std::string("a second orbifold line");
    c.type = f[3] == "sphere" ? HOT::Sphere_type : HOT::Disk_type;
    c.genus = static_cast<long long>(g);
    c.reversed = r == 1;
    c.landmark.assign(k, std::size_t(-1));
    c.vertex.assign(k, std::size_t(-1));
    c.order.assign(k, 0);
    if(has_cones)
      *has_cones = true;
  } else {
    // # hot cone C LANDMARK VERTEX ORDER
    std::uint64_t i = 0, l = 0, v = 0, p = 0;
    if(f.size() != 7 || parse_unsigned(f[3], i) != NUMBER_OK || parse_unsigned(f[4], l) != NUMBER_OK ||
       parse_unsigned(f[5], v) != NUMBER_OK || parse_unsigned(f[6], p) != NUMBER_OK || !is_cone_order(static_cast<long long>((std::min)(p, std::uint64_t(max_cone_order) + 1))))
      return std::string("cone line: '# hot cone C LANDMARK VERTEX ORDER' expected (integers, ORDER >= 2)");
    if(i >= c.landmark.size() || c.order[i] != 0)
      return std::string("cone line: cone " + std::to_string(i) + " is not a cone of the orbifold line before it, or is given twice");
    c.landmark[i] = static_cast<std::size_t>(l);
    c.vertex[i] = static_cast<std::size_t>(v);
    c.order[i] = static_cast<int>(p);
  }
  return std::string();
}

// a '# hot chart I AR AI BR BI C' line: "" or what is wrong with it
inline std::string read_chart_comment(const std::vector<std::string_view>& f, HOT::Corner_embedding& embedding)
{
  const std::size_t i = embedding.charts.size();
  std::uint64_t id = 0, corner = 0;
  std::array<double, 4> c;
  if(f.size() != 9)
    return std::string("chart line: 6 fields expected (# hot chart I AR AI BR BI C), " + std::to_string(f.size() - 3) + " found");
  if(parse_unsigned(f[3], id) != NUMBER_OK || id != i)
    return std::string("chart line: chart " + quote(f[3]) + " where chart " + std::to_string(i) + " is next (charts are numbered from 0 in order)");
  for(int k = 0; k < 4; ++k)
    if(!parse_real(f[4 + k], c[k]))
      return std::string("chart " + std::to_string(i) + ": coefficient " + quote(f[4 + k]) + " is not a number");
  if(parse_unsigned(f[8], corner) != NUMBER_OK || corner > 1000000)
    return std::string("chart " + std::to_string(i) + ": tile corner " + quote(f[8]) + " is not an index");
  embedding.charts.push_back(c);
  embedding.chart_corners.push_back(static_cast<int>(corner));
  return std::string();
}

// a '# hot vtc K I X Y' line: "" or what is wrong with it
inline std::string read_vtc_comment(const std::vector<std::string_view>& f, HOT::Corner_embedding& embedding)
{
  std::uint64_t k = 0, ch = 0;
  std::array<double, 2> w;
  if(f.size() != 7)
    return std::string("vtc line: 4 fields expected (# hot vtc K I X Y), " + std::to_string(f.size() - 3) + " found");
  if(parse_unsigned(f[3], k) != NUMBER_OK || k == 0 || k > embedding.points.size())
    return std::string("vtc line: " + quote(f[3]) + " is not a point (vt) index of the file's " + std::to_string(embedding.points.size()) + " points");
  if(parse_unsigned(f[4], ch) != NUMBER_OK || ch >= embedding.charts.size())
    return std::string("vtc line of vt " + std::to_string(k) + ": " + quote(f[4]) + " is not a chart of the table before it (" +
                            std::to_string(embedding.charts.size()) + " charts)");
  for(int j = 0; j < 2; ++j)
    if(!parse_real(f[5 + j], w[j]))
      return std::string("vtc line of vt " + std::to_string(k) + ": coordinate " + quote(f[5 + j]) + " is not a number");
  if(embedding.point_charts.empty()) {
    embedding.point_charts.assign(embedding.points.size(), -1);
    embedding.chart_points.assign(embedding.points.size(), std::array<double, 2>{{0.0, 0.0}});
  }
  if(embedding.point_charts[k - 1] >= 0)
    return std::string("vtc line: vt " + std::to_string(k) + " is given a chart point twice");
  embedding.point_charts[k - 1] = static_cast<int>(ch);
  embedding.chart_points[k - 1] = w;
  return std::string();
}

// the '# hot' comment lines (charts around cone images, the orbifold and its cones, merged
// vertices): "" or what is wrong, at line `line`
inline std::string read_hot_comments(const std::string& data, std::size_t number_of_vertices, HOT::Corner_embedding& embedding,
                                     Embedding_obj_extras* extras, Embedding_cones* cones, bool* has_cones, std::size_t& line)
{
  line = 0;
  Embedding_cones ignored_cones; // (the cone lines when `cones` is null: checked all the same)
  for(std::size_t at = 0; at < data.size();) {
    std::size_t end = data.find('\n', at);
    if(end == std::string::npos)
      end = data.size();
    ++line;
    const std::string_view text(data.data() + at, end - at);
    at = end + 1;
    const bool is_chart = text.substr(0, 12) == "# hot chart ", is_vtc = text.substr(0, 10) == "# hot vtc ";
    const bool is_orbifold = text.substr(0, 15) == "# hot orbifold ", is_cone = text.substr(0, 11) == "# hot cone ";
    const bool is_same = text.substr(0, 11) == "# hot same ";
    if(!is_chart && !is_vtc && !is_orbifold && !is_cone && !is_same)
      continue;
    std::vector<std::string_view> f;
    split(text, f);
    std::string m;
    if(is_same) {
      std::uint64_t j = 0, k = 0;
      if(f.size() != 5 || parse_unsigned(f[3], j) != NUMBER_OK || parse_unsigned(f[4], k) != NUMBER_OK || j >= number_of_vertices ||
         k >= number_of_vertices)
        return std::string("same line: '# hot same J K' expected, J and K vertices of the file (0-based)");
      if(extras)
        extras->same.emplace_back(static_cast<std::size_t>(j), static_cast<std::size_t>(k));
      continue;
    }
    if(is_orbifold || is_cone)
      m = read_cone_comment(is_orbifold, f, cones ? *cones : ignored_cones, has_cones);
    else if(is_chart) // (f[0] = "#", f[1] = "hot", f[2] = "chart" or "vtc")
      m = read_chart_comment(f, embedding);
    else
      m = read_vtc_comment(f, embedding);
    if(!m.empty())
      return m;
  }
  if(!embedding.charts.empty() && embedding.point_charts.empty()) {
    // a chart table without chart points: no face is in a chart
    embedding.point_charts.assign(embedding.points.size(), -1);
    embedding.chart_points.assign(embedding.points.size(), std::array<double, 2>{{0.0, 0.0}});
  }
  return std::string();
}

} // namespace io_impl

/*!
Reads the embedding in the OBJ file `path`: `v x y z` lines (counted in `number_of_vertices`;
they are the mesh's vertices, in its order), `vt x y` lines (the points; "nan" and "inf" are
read as such, for the certificate to refuse them), and `f a/ta b/tb c/tc` triangles (`a/ta/na`
too; 1-based indices, negative ones relative, as the format specifies). Comments, normals,
groups, materials and the other statements of the format are skipped. Errors
(ERROR_READ_FAILED, the message starting with the file name and the line): a missing or
unreadable file, a malformed number or index, a face that is not a triangle or a corner
without its `vt` index, an index beyond the file's `v` or `vt` lines, an unknown statement.
The charts around cone images that `embed` writes as comments (hot_app/io/embedding_obj.h) are
read too: `# hot chart I AR AI BR BI C` lines (charts 0, 1, ... in order) into
`embedding.charts` and `chart_corners`, `# hot vtc K I X Y` lines (vt K, 1-based, is the point
(X, Y) of chart I; at most one per vt) into `point_charts` and `chart_points`; a malformed
one, a vtc line without the chart table or of a chart or vt the file does not have is an
error like the others. `chart_points` (if not null) receives the number of `# hot vtc` lines.
`extras` (if not null) receives the `v` lines' points, the orbifold and cone lines `embed`
writes at the head of the file (`# hot orbifold`, `# hot cone`; hot_app/io/embedding_cones.h) and
its `# hot same J K` lines (v line J, on no face, is the same vertex as v line K: a merged
duplicate of a repaired input); malformed ones are errors.
*/
inline HOT::Status read_embedding_obj(const std::string& path, HOT::Corner_embedding& embedding,
                                      std::size_t& number_of_vertices, std::size_t* chart_points = nullptr,
                                      Embedding_obj_extras* extras = nullptr)
{
  std::vector<std::array<double, 3> >* vertex_points = extras ? &extras->vertex_points : nullptr;
  Embedding_cones* cones = extras ? &extras->cones : nullptr;
  bool* has_cones = extras ? &extras->has_cones : nullptr;
  if(extras)
    extras->same.clear();
  using namespace io_impl;
  embedding.clear();
  number_of_vertices = 0;
  if(vertex_points)
    vertex_points->clear();
  if(has_cones)
    *has_cones = false;
  if(cones)
    *cones = Embedding_cones();
  std::string data;
  HOT::Status r = read_file_contents(path, data);
  if(!r)
    return r;
  auto fail = [&](std::size_t line, const std::string& m) {
    embedding.clear();
    return read_fail(path + ": " + at_line(line) + m);
  };
  if(chart_points) {
    *chart_points = 0;
    const std::string tag = "# hot vtc ";
    for(std::size_t at = data.find(tag); at != std::string::npos; at = data.find(tag, at + tag.size()))
      if(at == 0 || data[at - 1] == '\n')
        ++*chart_points;
  }
  std::vector<std::size_t> face_lines;
  Cursor cur(data.data(), data.data() + data.size());
  std::vector<std::string_view> fields;
  for(std::size_t line = 0; next_fields(cur, true, fields, line);) {
    const std::string m = read_embedding_obj_statement(fields, embedding, number_of_vertices, vertex_points, face_lines, line);
    if(!m.empty())
      return fail(line, m);
  }
  if(embedding.face_vertices.empty()) {
    embedding.clear();
    return read_fail(path + ": the file has no face (f lines)");
  }
  // the charts around cone images ('# hot chart' and '# hot vtc' comment lines), the cones
  {
    std::size_t line = 0;
    const std::string m = read_hot_comments(data, number_of_vertices, embedding, extras, cones, has_cones, line);
    if(!m.empty())
      return fail(line, m);
  }
  if(cones)
    for(std::size_t i = 0; i < cones->order.size(); ++i) {
      if(cones->order[i] == 0)
        return read_fail(path + ": cone " + std::to_string(i) + " of the orbifold line has no cone line");
      if(cones->vertex[i] >= number_of_vertices)
        return read_fail(path + ": cone " + std::to_string(i) + " is at vertex " + std::to_string(cones->vertex[i]) +
                         ", beyond the file's " + std::to_string(number_of_vertices) + " vertices");
    }
  for(std::size_t f = 0; f < embedding.face_vertices.size(); ++f)
    for(int k = 0; k < 3; ++k) {
      if(embedding.face_vertices[f][k] >= number_of_vertices)
        return fail(face_lines[f], "face " + std::to_string(f) + ": vertex index " + std::to_string(embedding.face_vertices[f][k] + 1) +
                                     " is beyond the file's " + std::to_string(number_of_vertices) + " vertices (v lines)");
      if(embedding.face_points[f][k] >= embedding.points.size())
        return fail(face_lines[f], "face " + std::to_string(f) + ": point index " + std::to_string(embedding.face_points[f][k] + 1) +
                                     " is beyond the file's " + std::to_string(embedding.points.size()) + " points (vt lines)");
    }
  return HOT::Status();
}

} // namespace hot_tools

#include <CGAL/enable_warnings.h>

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_TOOLS_IO_EMBEDDING_OBJ_READER_H
