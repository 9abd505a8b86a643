// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_TOOLS_IO_GOCAD_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_TOOLS_IO_GOCAD_H

// The GOCAD TSurf (.ts) reader of the tool.

#include "common.h"
#include "polygon_soup.h"

#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include <CGAL/disable_warnings.h>

/// \file gocad.h

namespace hot_tools {
namespace io_impl {

/// GOCAD TSurf (ASCII): everything before the first "TFACE" line is header (name, colour,
/// coordinate system, ...; the "GOCAD TSurf" line itself is optional, as in CGAL); then
/// "VRTX id x y z" / "PVRTX id x y z [properties]" define vertex `id` (file order = vertex
/// order), "ATOM id v" / "PATOM id v [...]" give vertex `v` a second id (the same vertex),
/// "TRGL a b c" is a triangle of ids (defined before or after it), "TFACE" starts another
/// patch, "BSTONE" / "BORDER" / "SEG" are ignored, and the first "END" ends the object
/// (what follows is ignored). Any other keyword after TFACE is an error.
inline HOT::Status parse_gocad(const std::string& data, Polygon_soup& soup)
{
  Cursor cur(data.data(), data.data() + data.size());
  std::vector<std::string_view> fields;
  bool tface = false, end = false;
  while(!cur.at_end() && !tface) {
    split(cur.rest_of_line(false), fields);
    tface = !fields.empty() && fields[0] == "TFACE";
  }
  if(!tface)
    return read_fail("no TFACE line: not a GOCAD TSurf file (or it holds no triangle surface)");

  std::unordered_map<std::int64_t, std::size_t> vertex_of_id;
  std::vector<std::int64_t> triangle_ids; // 3 per triangle, resolved at the end
  auto parse_id = [&](std::string_view t, std::size_t line, std::int64_t& id) -> HOT::Status {
    switch(parse_signed(t, id)) {
    case NUMBER_OK: return HOT::Status();
    case NUMBER_TOO_LARGE: return read_fail(at_line(line) + "vertex id " + quote(t) + " is too large");
    default: return read_fail(at_line(line) + quote(t) + " is not a vertex id (an integer)");
    }
  };
  for(std::size_t line = 0; next_fields(cur, false, fields, line);) {
    const std::string_view kw = fields[0];
    HOT::Status r;
    if(kw == "VRTX" || kw == "PVRTX") {
      const std::size_t i = soup.points.size();
      if(fields.size() < 5)
        return read_fail(at_line(line) + "vertex " + std::to_string(i) + ": '" + std::string(kw)
                         + " id x y z' expected, " + std::to_string(fields.size() - 1) + " fields found");
      std::int64_t id = 0;
      if(!(r = parse_id(fields[1], line, id)))
        return r;
      std::array<double, 3> q;
      for(int k = 0; k < 3; ++k)
        if(!parse_real(fields[std::size_t(k) + 2], q[std::size_t(k)]))
          return read_fail(at_line(line) + "vertex " + std::to_string(i) + ": coordinate "
                           + quote(fields[std::size_t(k) + 2]) + " is not a number");
      if(!vertex_of_id.emplace(id, i).second)
        return read_fail(at_line(line) + "vertex id " + std::to_string(id) + " is defined twice");
      soup.points.push_back(q);
      soup.point_lines.push_back(line);
    } else if(kw == "ATOM" || kw == "PATOM") {
      std::int64_t id = 0, target = 0;
      if(fields.size() < 3)
        return read_fail(at_line(line) + "'" + std::string(kw) + " id vertex_id' expected");
      if(!(r = parse_id(fields[1], line, id)) || !(r = parse_id(fields[2], line, target)))
        return r;
      const auto it = vertex_of_id.find(target);
      if(it == vertex_of_id.end())
        return read_fail(at_line(line) + std::string(kw) + " " + std::to_string(id) + " refers to vertex id "
                         + std::to_string(target) + ", which is not defined before it");
      if(!vertex_of_id.emplace(id, it->second).second)
        return read_fail(at_line(line) + "vertex id " + std::to_string(id) + " is defined twice");
    } else if(kw == "TRGL") {
      if(fields.size() < 4)
        return read_fail(at_line(line) + "triangle " + std::to_string(soup.number_of_faces())
                         + ": 'TRGL a b c' expected, " + std::to_string(fields.size() - 1) + " vertex ids found");
      for(int k = 1; k <= 3; ++k) {
        std::int64_t id = 0;
        if(!(r = parse_id(fields[std::size_t(k)], line, id)))
          return r;
        triangle_ids.push_back(id);
      }
      soup.end_face(line); // its vertices are filled in below
    } else if(kw == "END") {
      end = true;
      break;
    } else if(kw == "TFACE" || kw == "BSTONE" || kw == "BORDER" || kw == "SEG") {
      continue;
    } else {
      return read_fail(at_line(line) + "unknown GOCAD TSurf keyword " + quote(kw));
    }
  }
  if(!end)
    return read_fail("the file ends without END (truncated file?)");
  // resolve the ids of the triangles
  soup.face_begin.assign(1, 0);
  soup.face_vertices.reserve(triangle_ids.size());
  for(std::size_t t = 0; t < triangle_ids.size(); ++t) {
    const auto it = vertex_of_id.find(triangle_ids[t]);
    if(it == vertex_of_id.end())
      return read_fail(at_line(soup.face_lines[t / 3]) + "triangle " + std::to_string(t / 3) + ": vertex id "
                       + std::to_string(triangle_ids[t]) + " is not defined (no VRTX, PVRTX or ATOM with that id)");
    soup.face_vertices.push_back(it->second);
    if(t % 3 == 2)
      soup.face_begin.push_back(soup.face_vertices.size());
  }
  return HOT::Status();
}

} // namespace io_impl
} // namespace hot_tools

#include <CGAL/enable_warnings.h>

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_TOOLS_IO_GOCAD_H
