// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_TOOLS_IO_OBJ_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_TOOLS_IO_OBJ_H

// The Wavefront OBJ reader of the tool.

#include "common.h"
#include "polygon_soup.h"

#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include <CGAL/disable_warnings.h>

/// \file obj.h

namespace hot_tools {
namespace io_impl {

inline bool is_ignored_obj_statement(std::string_view s)
{
  static const char* const ignored[] = {
    "vt", "vn", "vp", "l", "p", "o", "g", "s", "mg", "usemtl", "mtllib", "usemap", "maplib",
    "cstype", "deg", "bmat", "step", "curv", "curv2", "surf", "parm", "trim", "hole", "scrv", "sp",
    "end", "con", "bevel", "c_interp", "d_interp", "lod", "shadow_obj", "trace_obj", "ctech", "stech",
    "bsp", "bzp", "cdc", "cdp", "res"
  };
  for(const char* k : ignored)
    if(s == k)
      return true;
  return false;
}

/// the fast path of a "v x y z ..." line (plain numbers) or an "f i[/t[/n]] ..." line (plain
/// positive or negative indices, the relative ones in range): read and true, else false
/// with nothing read (the general code then reads the line)
inline bool fast_obj_record(Cursor& cur, Polygon_soup& soup)
{
  const char* p = cur.position();
  const char* end = cur.end();
  if(end - p < 2 || (p[0] != 'v' && p[0] != 'f') || !is_blank(p[1]))
    return false;
  const char* q = p + 1;
  if(p[0] == 'v') {
    std::array<double, 3> c;
    if(!fast_real(q, end, c[0]) || !fast_real(q, end, c[1]) || !fast_real(q, end, c[2]))
      return false;
    soup.points.push_back(c);
    soup.point_lines.push_back(cur.line());
    cur.skip_line_from(q);
    return true;
  }
  const std::size_t before = soup.face_vertices.size();
  const std::size_t np = soup.points.size();
  while(true) {
    while(q != end && is_blank(*q))
      ++q;
    if(q == end || *q == '\n' || *q == '#' || (*q == '\r' && (q + 1 == end || q[1] == '\n')))
      break; // the end of the line's fields
    const bool negative = *q == '-';
    if(negative)
      ++q;
    const char* digits = q;
    std::uint64_t id = 0;
    while(q != end && static_cast<unsigned char>(*q - '0') < 10 && q - digits < 18) // (18 digits: below 2^63)
      id = 10 * id + static_cast<unsigned char>(*q++ - '0');
    if(q == digits || (q != end && static_cast<unsigned char>(*q - '0') < 10) || id == 0 || (negative && id > np)) {
      soup.face_vertices.resize(before);
      return false;
    }
    if(q != end && *q == '/')
      while(q != end && (*q == '/' || *q == '-' || (*q >= '0' && *q <= '9')))
        ++q;
    if(!ends_token(q, end)) {
      soup.face_vertices.resize(before);
      return false;
    }
    // forward references are allowed; the range is checked at the end
    soup.face_vertices.push_back(negative ? static_cast<std::size_t>(np - id) : static_cast<std::size_t>(id - 1));
  }
  soup.end_face(cur.line());
  cur.skip_line_from(q);
  return true;
}

/// Wavefront OBJ: "v x y z [...]" and "f i[/t[/n]] ..." (1-based; negative indices are
/// relative to the vertices read so far, as the format specifies); the statements listed
/// in `is_ignored_obj_statement()` and '#' comments are skipped; any other is an error.
inline HOT::Status parse_obj(const std::string& data, Polygon_soup& soup)
{
  Cursor cur(data.data(), data.data() + data.size());
  std::vector<std::string_view> fields;
  for(std::size_t line = 0; !cur.at_end();) {
    line = cur.line();
    if(fast_obj_record(cur, soup))
      continue;
    split(cur.rest_of_line(true), fields);
    if(fields.empty())
      continue;
    const std::string_view kw = fields[0];
    if(kw == "v") {
      if(fields.size() < 4)
        return read_fail(at_line(line) + "vertex " + std::to_string(soup.points.size()) + " has "
                         + std::to_string(fields.size() - 1) + " coordinates, 3 expected");
      std::array<double, 3> q;
      for(int k = 0; k < 3; ++k)
        if(!parse_real(fields[k + 1], q[k]))
          return read_fail(at_line(line) + "vertex " + std::to_string(soup.points.size()) + ": coordinate "
                           + quote(fields[k + 1]) + " is not a number");
      soup.points.push_back(q);
      soup.point_lines.push_back(line);
    } else if(kw == "f") {
      const std::size_t f = soup.number_of_faces();
      for(std::size_t k = 1; k < fields.size(); ++k) {
        const std::string_view field = fields[k];
        const std::size_t slash = field.find('/');
        const std::string_view id_part = field.substr(0, slash);
        if(slash != std::string_view::npos) {
          for(char c : field.substr(slash))
            if(c != '/' && c != '-' && (c < '0' || c > '9'))
              return read_fail(at_line(line) + "face " + std::to_string(f) + ": " + quote(field)
                               + " is not a vertex reference");
        }
        std::int64_t id = 0;
        const Number_status s = parse_signed(id_part, id);
        if(s == NUMBER_TOO_LARGE)
          return read_fail(at_line(line) + "face " + std::to_string(f) + ": vertex index " + quote(id_part)
                           + " is out of range");
        if(s != NUMBER_OK)
          return read_fail(at_line(line) + "face " + std::to_string(f) + ": " + quote(field)
                           + " is not a vertex reference");
        if(id == 0)
          return read_fail(at_line(line) + "face " + std::to_string(f)
                           + ": vertex index 0 is invalid (OBJ indices start at 1)");
        if(id < 0) {
          const std::uint64_t back = static_cast<std::uint64_t>(-(id + 1)) + 1;
          if(back > soup.points.size())
            return read_fail(at_line(line) + "face " + std::to_string(f) + ": relative vertex index "
                             + quote(id_part) + " refers to a vertex before the first one");
          soup.face_vertices.push_back(static_cast<std::size_t>(soup.points.size() - back));
        } else {
          // forward references are allowed; the range is checked at the end
          soup.face_vertices.push_back(static_cast<std::size_t>(id - 1));
        }
      }
      soup.end_face(line);
    } else if(kw[0] == '#' || is_ignored_obj_statement(kw)) {
      continue;
    } else {
      return read_fail(at_line(line) + "unknown OBJ statement " + quote(kw));
    }
  }
  // indices past the last vertex, reported as written in the file (1-based)
  const std::size_t np = soup.points.size();
  for(std::size_t f = 0; f < soup.number_of_faces(); ++f)
    for(std::size_t c = soup.face_begin[f]; c < soup.face_begin[f + 1]; ++c)
      if(soup.face_vertices[c] >= np)
        return read_fail(at_line(soup.face_lines[f]) + "face " + std::to_string(f) + ": vertex index "
                         + std::to_string(soup.face_vertices[c] + 1) + " is out of range (the file has "
                         + std::to_string(np) + " vertices)");
  return HOT::Status();
}

} // namespace io_impl
} // namespace hot_tools

#include <CGAL/enable_warnings.h>

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_TOOLS_IO_OBJ_H
