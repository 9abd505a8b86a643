// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_TOOLS_IO_STL_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_TOOLS_IO_STL_H

// The STL reader of the tool (ASCII and binary); equal points are merged in order of
// first appearance, as CGAL does.

#include "common.h"
#include "polygon_soup.h"

#include <array>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>
#include <unordered_map>

#include <CGAL/disable_warnings.h>

/// \file stl.h

namespace hot_tools {
namespace io_impl {

struct Point_key_hash
{
  std::size_t operator()(const std::array<std::uint64_t, 3>& k) const
  {
    std::uint64_t h = 1469598103934665603ull;
    for(std::uint64_t x : k) {
      h ^= x + 0x9e3779b97f4a7c15ull + (h << 6) + (h >> 2);
      h *= 1099511628211ull;
    }
    return static_cast<std::size_t>(h ^ (h >> 29));
  }
};

/// merges equal points (bitwise after mapping -0 to +0) in order of first appearance
class Point_merger
{
public:
  explicit Point_merger(Polygon_soup& soup) : soup_(soup) {}

  std::size_t index(const std::array<double, 3>& p, std::size_t line)
  {
    std::array<std::uint64_t, 3> key;
    for(int k = 0; k < 3; ++k) {
      const double x = p[std::size_t(k)] + 0.0; // -0 -> +0
      std::memcpy(&key[std::size_t(k)], &x, 8);
    }
    auto ins = map_.emplace(key, soup_.points.size());
    if(ins.second) {
      soup_.points.push_back(p);
      if(line != 0)
        soup_.point_lines.push_back(line);
    }
    return ins.first->second;
  }

private:
  Polygon_soup& soup_;
  std::unordered_map<std::array<std::uint64_t, 3>, std::size_t, Point_key_hash> map_;
};

inline HOT::Status parse_stl_binary(const std::string& data, Polygon_soup& soup)
{
  const unsigned char* p = reinterpret_cast<const unsigned char*>(data.data()) + 84;
  const std::size_t n = load_u32_le(reinterpret_cast<const unsigned char*>(data.data()) + 80);
  Point_merger merger(soup);
  soup.face_vertices.reserve(3 * n);
  soup.face_begin.reserve(n + 1);
  for(std::size_t t = 0; t < n; ++t, p += 50) {
    for(int v = 0; v < 3; ++v) {
      std::array<double, 3> q;
      for(int k = 0; k < 3; ++k)
        q[std::size_t(k)] = u32_to_float(load_u32_le(p + 12 + 12 * v + 4 * k));
      soup.face_vertices.push_back(merger.index(q, 0));
    }
    soup.end_face();
  }
  return HOT::Status();
}

inline HOT::Status parse_stl_ascii(const std::string& data, Polygon_soup& soup)
{
  Cursor cur(data.data(), data.data() + data.size());
  Point_merger merger(soup);
  std::string_view tok;
  bool in_solid = false;
  auto expect = [&](const char* word) -> std::string {
    if(!cur.token(tok, false))
      return std::string("the file ends early, '") + word + "' expected (truncated file?)";
    if(tok != word)
      return at_line(cur.line()) + "'" + word + "' expected, " + quote(tok) + " found";
    return std::string();
  };
  while(cur.token(tok, false)) {
    if(tok == "solid") {
      if(in_solid)
        return read_fail(at_line(cur.line()) + "'solid' inside a solid");
      in_solid = true;
      cur.rest_of_line(false); // name
    } else if(tok == "endsolid") {
      if(!in_solid)
        return read_fail(at_line(cur.line()) + "'endsolid' without 'solid'");
      in_solid = false;
      cur.rest_of_line(false);
    } else if(tok == "facet" && in_solid) {
      const std::size_t f = soup.number_of_faces();
      const std::size_t line = cur.line();
      std::string err = expect("normal");
      if(!err.empty()) return read_fail(err);
      for(int k = 0; k < 3; ++k) {
        double d;
        if(!cur.token(tok, false) || !parse_real(tok, d))
          return read_fail(at_line(cur.line()) + "facet " + std::to_string(f) + ": bad normal");
      }
      if(!(err = expect("outer")).empty() || !(err = expect("loop")).empty())
        return read_fail(err);
      for(int v = 0; v < 3; ++v) {
        if(!(err = expect("vertex")).empty())
          return read_fail(err + " (facet " + std::to_string(f) + " has fewer than 3 vertices?)");
        const std::size_t vline = cur.line();
        std::array<double, 3> q;
        for(int k = 0; k < 3; ++k) {
          if(!cur.token(tok, false))
            return read_fail("the file ends inside facet " + std::to_string(f) + " (truncated file?)");
          if(!parse_real(tok, q[std::size_t(k)]))
            return read_fail(at_line(cur.line()) + "facet " + std::to_string(f) + ": coordinate " + quote(tok)
                             + " is not a number");
        }
        soup.face_vertices.push_back(merger.index(q, vline));
      }
      if(!(err = expect("endloop")).empty())
        return read_fail(err + " (STL facets must be triangles)");
      if(!(err = expect("endfacet")).empty())
        return read_fail(err);
      soup.end_face(line);
    } else {
      return read_fail(at_line(cur.line()) + "unexpected " + quote(tok) + " in ASCII STL");
    }
  }
  if(in_solid)
    return read_fail("the file ends inside a solid (no 'endsolid': truncated file?)");
  return HOT::Status();
}

/// Binary STL if the size is exactly 84 + 50 N (N read at offset 80), else ASCII if
/// the file starts with "solid", else binary with a size mismatch (an error).
inline HOT::Status parse_stl(const std::string& data, Polygon_soup& soup)
{
  const std::size_t size = data.size();
  std::uint64_t n = 0;
  if(size >= 84) {
    n = load_u32_le(reinterpret_cast<const unsigned char*>(data.data()) + 80);
    if(84 + 50 * n == size)
      return parse_stl_binary(data, soup);
  }
  std::size_t i = 0;
  while(i < size && is_space(data[i]))
    ++i;
  if(data.compare(i, 5, "solid") == 0 && (i + 5 == size || is_space(data[i + 5])))
    return parse_stl_ascii(data, soup);
  if(size >= 84)
    return read_fail("binary STL: the header announces " + std::to_string(n) + " triangles, i.e. "
                     + std::to_string(84 + 50 * n) + " bytes, but the file has " + std::to_string(size)
                     + " bytes (truncated or not an STL file)");
  return read_fail("not an STL file (too short for binary STL and not starting with 'solid')");
}

} // namespace io_impl
} // namespace hot_tools

#include <CGAL/enable_warnings.h>

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_TOOLS_IO_STL_H
