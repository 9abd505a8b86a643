// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_TOOLS_IO_EMBEDDING_OBJ_READER_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_TOOLS_IO_EMBEDDING_OBJ_READER_H

// The reader of an embedding as an OBJ file (the `certify` command's input): `v` lines,
// `vt` lines (Poincare-disk coordinates) and triangles `f v/vt v/vt v/vt`, written by `embed`
// or by any other program.

#include "common.h"
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

/*!
Reads the embedding in the OBJ file `path`: `v x y z` lines (counted in `number_of_vertices`;
they are the mesh's vertices, in its order), `vt x y` lines (the points; "nan" and "inf" are
read as such, for the certificate to refuse them), and `f a/ta b/tb c/tc` triangles (`a/ta/na`
too; 1-based indices, negative ones relative, as the format specifies). Comments, normals,
groups, materials and the other statements of the format are skipped. Errors
(ERROR_READ_FAILED, the message starting with the file name and the line): a missing or
unreadable file, a malformed number or index, a face that is not a triangle or a corner
without its `vt` index, an index beyond the file's `v` or `vt` lines, an unknown statement.
`chart_points` (if not null) receives the number of `# hot vtc` comment lines: points that
`embed` wrote in charts around cone images (tools/io/embedding_obj.h), which are not read.
*/
inline HOT::Status read_embedding_obj(const std::string& path, HOT::Corner_embedding& embedding,
                                      std::size_t& number_of_vertices, std::size_t* chart_points = nullptr)
{
  using namespace io_impl;
  embedding.clear();
  number_of_vertices = 0;
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
    const std::string_view kw = fields[0];
    if(kw == "v") {
      double q;
      if(fields.size() < 4)
        return fail(line, "vertex " + std::to_string(number_of_vertices) + " has " + std::to_string(fields.size() - 1) +
                            " coordinates, 3 expected");
      for(int k = 1; k <= 3; ++k)
        if(!parse_real(fields[k], q))
          return fail(line, "vertex " + std::to_string(number_of_vertices) + ": coordinate " + quote(fields[k]) + " is not a number");
      ++number_of_vertices;
    } else if(kw == "vt") {
      std::array<double, 2> p;
      if(fields.size() < 3)
        return fail(line, "point (vt) " + std::to_string(embedding.points.size()) + " has " + std::to_string(fields.size() - 1) +
                            " coordinate" + (fields.size() == 2 ? "" : "s") + ", 2 expected");
      for(int k = 0; k < 2; ++k)
        if(!parse_real(fields[k + 1], p[k]))
          return fail(line, "point (vt) " + std::to_string(embedding.points.size()) + ": coordinate " + quote(fields[k + 1]) +
                              " is not a number");
      embedding.points.push_back(p);
    } else if(kw == "f") {
      const std::size_t f = embedding.face_vertices.size();
      if(fields.size() != 4)
        return fail(line, "face " + std::to_string(f) + " has " + std::to_string(fields.size() - 1) +
                            " corners: an embedding's faces are triangles");
      std::array<std::size_t, 3> fv, fp;
      for(int k = 0; k < 3; ++k) {
        const std::string_view field = fields[k + 1];
        const std::size_t s1 = field.find('/');
        if(s1 == std::string_view::npos || s1 + 1 >= field.size() || field[s1 + 1] == '/')
          return fail(line, "face " + std::to_string(f) + ": corner " + quote(field) + " has no point (vt) index: 'v/vt' expected");
        const std::size_t s2 = field.find('/', s1 + 1);
        const std::string_view vpart = field.substr(0, s1);
        const std::string_view tpart = field.substr(s1 + 1, s2 == std::string_view::npos ? std::string_view::npos : s2 - s1 - 1);
        if(!obj_index(vpart, number_of_vertices, fv[k]))
          return fail(line, "face " + std::to_string(f) + ": " + quote(vpart) + " is not a vertex index");
        if(!obj_index(tpart, embedding.points.size(), fp[k]))
          return fail(line, "face " + std::to_string(f) + ": " + quote(tpart) + " is not a point (vt) index");
      }
      embedding.face_vertices.push_back(fv);
      embedding.face_points.push_back(fp);
      face_lines.push_back(line);
    } else if(kw[0] == '#' || is_ignored_obj_statement(kw)) {
      continue;
    } else {
      return fail(line, "unknown OBJ statement " + quote(kw));
    }
  }
  if(embedding.face_vertices.empty()) {
    embedding.clear();
    return read_fail(path + ": the file has no face (f lines)");
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
