// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_TOOLS_IO_OFF_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_TOOLS_IO_OFF_H

// The OFF reader of the tool: ASCII OFF with CGAL's variants, and Geomview's binary OFF.

#include "common.h"
#include "polygon_soup.h"

#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include <CGAL/disable_warnings.h>

/// \file off.h

namespace hot_tools {
namespace io_impl {

/// Binary OFF as specified by Geomview ("OFF BINARY"): big-endian int32 counts,
/// float32 coordinates, faces as int32 n, n int32 indices, int32 number of color
/// components (0 to 4) and that many float32. Only plain OFF (no C/N/ST/4 prefix).
inline HOT::Status parse_off_binary(const char* b, const char* e, Polygon_soup& soup)
{
  const unsigned char* p = reinterpret_cast<const unsigned char*>(b);
  const unsigned char* end = reinterpret_cast<const unsigned char*>(e);
  auto remaining = [&]() { return static_cast<std::size_t>(end - p); };
  auto read_i32 = [&](std::int32_t& v) -> bool {
    if(remaining() < 4) return false;
    v = static_cast<std::int32_t>(load_u32_be(p));
    p += 4;
    return true;
  };
  auto read_f32 = [&](double& v) -> bool {
    if(remaining() < 4) return false;
    v = static_cast<double>(u32_to_float(load_u32_be(p)));
    p += 4;
    return true;
  };

  std::int32_t nv = 0, nf = 0, ne = 0;
  if(!read_i32(nv) || !read_i32(nf) || !read_i32(ne))
    return read_fail("binary OFF: the header is truncated (missing counts)");
  if(nv < 0 || nf < 0)
    return read_fail("binary OFF: negative vertex or face count in the header");
  if(std::size_t(nv) > remaining() / 12 || std::size_t(nf) > remaining() / 8)
    return read_fail("binary OFF: the header announces " + std::to_string(nv) + " vertices and "
                     + std::to_string(nf) + " faces, but only " + std::to_string(remaining())
                     + " bytes follow (truncated file or wrong header)");
  soup.points.reserve(std::size_t(nv));
  for(std::int32_t i = 0; i < nv; ++i) {
    std::array<double, 3> q;
    if(!read_f32(q[0]) || !read_f32(q[1]) || !read_f32(q[2]))
      return read_fail("binary OFF: the file ends after " + std::to_string(i) + " of the "
                       + std::to_string(nv) + " vertices announced by the header (truncated file?)");
    soup.points.push_back(q);
  }
  for(std::int32_t j = 0; j < nf; ++j) {
    std::int32_t n = 0;
    if(!read_i32(n))
      return read_fail("binary OFF: the file ends after " + std::to_string(j) + " of the "
                       + std::to_string(nf) + " faces announced by the header (truncated file?)");
    if(n < 0 || std::size_t(n) > remaining() / 4)
      return read_fail("binary OFF: face " + std::to_string(j) + " announces " + std::to_string(n)
                       + " vertices (negative, or more than the rest of the file holds)");
    for(std::int32_t k = 0; k < n; ++k) {
      std::int32_t id = 0;
      read_i32(id);
      if(id < 0 || id >= nv)
        return read_fail("binary OFF: face " + std::to_string(j) + ": vertex index " + std::to_string(id)
                         + " is out of range (the file has " + std::to_string(nv) + " vertices)");
      soup.face_vertices.push_back(std::size_t(id));
    }
    std::int32_t colors = 0;
    if(!read_i32(colors))
      return read_fail("binary OFF: the file ends inside face " + std::to_string(j) + " (truncated file?)");
    if(colors < 0 || colors > 4 || remaining() < std::size_t(colors) * 4)
      return read_fail("binary OFF: face " + std::to_string(j) + " has a bad number of color components ("
                       + std::to_string(colors) + ")");
    p += std::size_t(colors) * 4;
    soup.end_face();
  }
  return HOT::Status();
}

/// reads the OFF keyword ([ST][C][N][4][n]OFF, and the dimension 3 of nOFF): `prefixed`
/// if it has a prefix, `homogeneous` for 4OFF
inline HOT::Status read_off_keyword(Cursor& cur, bool& prefixed, bool& homogeneous)
{
  std::string_view tok;
  if(!cur.token(tok, true))
    return read_fail("the file holds no OFF header (it is blank or only comments)");
  const std::size_t header_line = cur.line();

  std::size_t j = 0;
  bool ndim = false;
  if(tok.substr(j, 2) == "ST") { j += 2; prefixed = true; }
  if(tok.substr(j, 1) == "C") { j += 1; prefixed = true; }
  if(tok.substr(j, 1) == "N") { j += 1; prefixed = true; }
  if(tok.substr(j, 1) == "4") { j += 1; prefixed = true; homogeneous = true; }
  if(tok.substr(j, 1) == "n") { j += 1; prefixed = true; ndim = true; }
  if(tok.substr(j) != "OFF")
    return read_fail(at_line(header_line) + quote(tok)
                     + " is not an OFF header keyword (OFF, COFF, NOFF, STOFF, 4OFF, ...)");
  if(ndim) {
    std::string_view d;
    if(!cur.token(d, true) || d != "3")
      return read_fail(at_line(cur.line()) + "nOFF files are supported only with dimension 3");
  }
  return HOT::Status();
}

/// reads the vertex, face and edge counts of the OFF header, and checks that the rest of
/// the file can hold that many vertex and face records
inline HOT::Status read_off_counts(Cursor& cur, std::uint64_t counts[3])
{
  std::string_view tok;
  const char* names[3] = { "vertex", "face", "edge" };
  for(int k = 0; k < 3; ++k) {
    if(!cur.token(tok, true))
      return read_fail(std::string("the OFF header is truncated: no ") + names[k] + " count");
    switch(parse_unsigned(tok, counts[k])) {
    case NUMBER_OK: break;
    case NEGATIVE_NUMBER:
      return read_fail(at_line(cur.line()) + "negative " + names[k] + " count " + quote(tok) + " in the OFF header");
    case NUMBER_TOO_LARGE:
      return read_fail(at_line(cur.line()) + names[k] + " count " + quote(tok) + " in the OFF header is too large");
    default:
      return read_fail(at_line(cur.line()) + "the OFF header's " + names[k] + " count " + quote(tok)
                       + " is not a non-negative integer");
    }
  }
  const std::uint64_t nv = counts[0], nf = counts[1];

  // A vertex record takes at least 6 bytes ("0 0 0\n"), a face record at least 2.
  const std::uint64_t rest = cur.remaining();
  if(nv > rest / 6 + 1 || nf > rest / 2 + 1 || nv * 6 + nf * 2 > rest + 8)
    return read_fail("the OFF header announces " + std::to_string(nv) + " vertices and " + std::to_string(nf)
                     + " faces, but only " + std::to_string(rest) + " bytes follow (truncated file or wrong header)");
  return HOT::Status();
}

/// reads the `nv` vertex records of an ASCII OFF file (4 coordinates if `homogeneous`)
inline HOT::Status read_off_vertices(Cursor& cur, std::uint64_t nv, bool homogeneous, Polygon_soup& soup,
                                      std::vector<std::string_view>& fields)
{
  const std::size_t needed = homogeneous ? 4 : 3;
  auto add_vertex = [&](double (&c)[4], std::size_t line) { // (c[3]: the homogeneous weight, else 1)
    if(homogeneous) {
      c[0] /= c[3];
      c[1] /= c[3];
      c[2] /= c[3];
    }
    soup.points.push_back({ { c[0], c[1], c[2] } });
    soup.point_lines.push_back(line);
  };
  for(std::uint64_t i = 0; i < nv; ++i) {
    cur.skip_space(true);
    if(cur.at_end())
      return read_fail("the file ends after " + std::to_string(i) + " of the " + std::to_string(nv)
                       + " vertices announced by the OFF header (truncated file?)");
    const std::size_t line = cur.line();
    { // the fast path: the coordinates are plain numbers
      const char* q = cur.position();
      double c[4] = { 0, 0, 0, 1 };
      std::size_t k = 0;
      while(k < needed && fast_real(q, cur.end(), c[k]))
        ++k;
      if(k == needed) {
        add_vertex(c, line);
        cur.skip_line_from(q);
        continue;
      }
    }
    split(cur.rest_of_line(true), fields);
    if(fields.size() < needed)
      return read_fail(at_line(line) + "vertex " + std::to_string(i) + " has " + std::to_string(fields.size())
                       + " coordinates, " + std::to_string(needed) + " expected (truncated or malformed record)");
    double c[4] = { 0, 0, 0, 1 };
    for(std::size_t k = 0; k < needed; ++k)
      if(!parse_real(fields[k], c[k]))
        return read_fail(at_line(line) + "vertex " + std::to_string(i) + ": coordinate " + quote(fields[k])
                         + " is not a number");
    add_vertex(c, line);
  }
  return HOT::Status();
}

/// reads the `nf` face records of an ASCII OFF file with `nv` vertices
inline HOT::Status read_off_faces(Cursor& cur, std::uint64_t nv, std::uint64_t nf, Polygon_soup& soup,
                                   std::vector<std::string_view>& fields)
{
  for(std::uint64_t f = 0; f < nf; ++f) {
    cur.skip_space(true);
    if(cur.at_end())
      return read_fail("the file ends after " + std::to_string(f) + " of the " + std::to_string(nf)
                       + " faces announced by the OFF header (truncated file?)");
    const std::size_t line = cur.line();
    { // the fast path: the count and the indices are digits, the indices in range
      const char* q = cur.position();
      const std::size_t before = soup.face_vertices.size();
      std::uint64_t n = 0, k = 0, id = 0;
      if(fast_unsigned(q, cur.end(), n) && n <= cur.remaining()) {
        while(k < n && fast_unsigned(q, cur.end(), id) && id < nv) {
          soup.face_vertices.push_back(static_cast<std::size_t>(id));
          ++k;
        }
        if(k == n) {
          soup.end_face(line);
          cur.skip_line_from(q);
          continue;
        }
      }
      soup.face_vertices.resize(before);
    }
    split(cur.rest_of_line(true), fields);
    std::uint64_t n = 0;
    if(parse_unsigned(fields[0], n) != NUMBER_OK)
      return read_fail(at_line(line) + "face " + std::to_string(f) + ": the vertex count " + quote(fields[0])
                       + " is not a non-negative integer");
    if(n > fields.size() - 1)
      return read_fail(at_line(line) + "face " + std::to_string(f) + " announces " + std::to_string(n)
                       + " vertices but lists only " + std::to_string(fields.size() - 1)
                       + " (truncated or malformed record)");
    for(std::uint64_t k = 1; k <= n; ++k) {
      std::uint64_t id = 0;
      switch(parse_unsigned(fields[k], id)) {
      case NUMBER_OK:
        if(id < nv) break;
        // fall through
      case NUMBER_TOO_LARGE:
        return read_fail(at_line(line) + "face " + std::to_string(f) + ": vertex index " + quote(fields[k])
                         + " is out of range (the file has " + std::to_string(nv) + " vertices)");
      case NEGATIVE_NUMBER:
        return read_fail(at_line(line) + "face " + std::to_string(f) + ": negative vertex index " + quote(fields[k]));
      default:
        return read_fail(at_line(line) + "face " + std::to_string(f) + ": " + quote(fields[k])
                         + " is not a vertex index");
      }
      soup.face_vertices.push_back(static_cast<std::size_t>(id));
    }
    soup.end_face(line);
  }
  return HOT::Status(); // whatever follows the last face is ignored, as CGAL does
}

/// ASCII OFF with the variants CGAL reads: [ST][C][N][4][n]OFF keyword, '#' comments,
/// counts anywhere after the keyword, one vertex / face record per line, trailing
/// normal / color / texture fields ignored; a zero homogeneous coordinate gives a
/// non-finite point. "OFF BINARY" goes to `parse_off_binary()`.
inline HOT::Status parse_off(const std::string& data, Polygon_soup& soup)
{
  Cursor cur(data.data(), data.data() + data.size());
  bool prefixed = false, homogeneous = false;
  HOT::Status r = read_off_keyword(cur, prefixed, homogeneous);
  if(!r)
    return r;
  {
    Cursor probe = cur;
    std::string_view b;
    if(probe.token(b, true) && b == "BINARY") {
      if(prefixed)
        return read_fail("binary OFF is supported only without C/N/ST/4/n prefix; convert the file to ASCII OFF");
      probe.rest_of_line(false);
      return parse_off_binary(probe.position(), data.data() + data.size(), soup);
    }
  }

  std::uint64_t counts[3] = { 0, 0, 0 };
  if(!(r = read_off_counts(cur, counts)))
    return r;
  const std::uint64_t nv = counts[0], nf = counts[1];
  soup.points.reserve(nv);
  soup.point_lines.reserve(nv);
  soup.face_begin.reserve(nf + 1);
  soup.face_lines.reserve(nf);
  soup.face_vertices.reserve(3 * nf);

  std::vector<std::string_view> fields;
  if(!(r = read_off_vertices(cur, nv, homogeneous, soup, fields)))
    return r;
  return read_off_faces(cur, nv, nf, soup, fields);
}

} // namespace io_impl
} // namespace hot_tools

#include <CGAL/enable_warnings.h>

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_TOOLS_IO_OFF_H
