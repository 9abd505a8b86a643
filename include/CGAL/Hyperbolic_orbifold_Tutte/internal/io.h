// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_IO_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_IO_H

// Readers for the command-line program: meshes and landmark files, with a specific
// `Error_code` and a one-line message (starting with the file name) for every bad
// input, and no assertion, exception, huge allocation or hang on hostile files.
//
// Meshes (`read_mesh()`): the file is read as a polygon soup, the soup is validated,
// then converted to the mesh by a linear-time builder of our own.
//
// * Why our own parsers for OFF, OBJ, PLY and STL rather than `CGAL::IO::read_polygon_soup()`
//   (CGAL 5.5)? Measured on hostile files, CGAL's readers
//   - resize their containers to the counts of the file before reading them: an OFF
//     header announcing 2e9 vertices, an OFF face announcing 1e18 vertices, a binary PLY
//     list size of 2^31-1 all throw std::bad_alloc out of the reader (or exhaust memory);
//   - reject "nan", "inf" and "1e400" in text files as a parse failure (istream >>
//     double), so a NaN coordinate would be a read failure, not
//     ERROR_NON_FINITE_COORDINATES (only binary files could carry NaN into CGAL);
//   - throw CGAL's assertion exception on a zero homogeneous coordinate (4OFF, w = 0);
//   - read OFF face entries through `double`: "3.7 0 1.9 2" is silently read as the
//     triangle 0 1 2;
//   - accept an OBJ face index equal to the number of vertices (an out-of-range index in
//     the returned soup), resolve negative OBJ indices against the final vertex count,
//     and reject a whole OBJ file for an "l" (polyline) statement;
//   - merge STL points through a std::map, whose ordering breaks with NaN;
//   - never say which line is wrong.
//   `CGAL::IO::read_polygon_mesh()` (BGL) additionally fails on non-manifold soups without
//   saying why, and the PMP variant silently repairs them (merges points, removes faces,
//   reorients and duplicates vertices), which changes the vertex and face numbering that
//   the landmark files refer to.
//   GOCAD TSurf (.ts) files have their own parser too: `CGAL::IO::read_GOCAD()` (CGAL 5.5)
//   computes vertex indices as `int` offsets from the file's ids (signed overflow, i.e.
//   undefined behaviour, on an id such as -2147483648: found by UndefinedBehaviorSanitizer),
//   ignores the VRTX ids after the first one (non-consecutive ids silently give wrong
//   triangles), ignores ATOM vertices, and says nothing but "cannot read" on any error.
// * Why our own soup-to-mesh builder rather than
//   `CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh()`? The latter is given
//   a valid soup only (precondition), builds the mesh face by face with `Euler::add_face()`,
//   which is quadratic around a vertex of high degree (measured: a fan of 40K triangles
//   around one vertex takes 2.6 s, so 200K take about a minute; 0.1 s here), and its
//   precondition check `is_polygon_soup_a_polygon_mesh()` uses a std::set of all edges.
//   Our builder links the halfedges directly from the edge table computed by the
//   validation, in linear time (1M vertices: about 0.5 s to parse a 60 MB OFF file,
//   0.2 s to validate, 0.2 s to build a Surface_mesh).
//
// Order guarantee (tested): vertex i of the mesh (the i-th of `vertices(mesh)`) is the
// file's vertex i, face j is the file's face j with the same cyclic vertex order and the
// same first vertex (`source(halfedge(f))` is its first vertex), unreferenced vertices
// included (check_mesh() then rejects them). For STL, which has no shared vertices,
// vertex i is the i-th distinct point in the order of first appearance (as in CGAL).
//
// Soup validation (`validate_polygon_soup()`), first failure wins:
//   ERROR_READ_FAILED            a vertex index is out of range
//   ERROR_DEGENERATE_FACE        a face has fewer than 3 vertices or uses a vertex twice
//   ERROR_NON_MANIFOLD           a face is repeated (same vertices, same cyclic order;
//                                reported instead of the edge errors below it causes)
//   ERROR_NON_MANIFOLD           an edge is shared by more than two faces
//   ERROR_NON_MANIFOLD           two faces traverse an edge in the same direction
//                                ("inconsistent face orientation"; also duplicated faces)
//   ERROR_NON_MANIFOLD           the faces around a vertex form several fans
//   ERROR_NON_FINITE_COORDINATES a coordinate is NaN or infinite (also a text coordinate
//                                that overflows a double, e.g. 1e999)
// A soup without face is not an error here (`check_mesh()` reports ERROR_EMPTY_MESH);
// an empty file is (ERROR_READ_FAILED).
//
// Landmark files (`read_landmarks()`): see the rule documented at that function.

#include <CGAL/Hyperbolic_orbifold_Tutte/error_code.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/input_checks.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/properties.h>

#include <boost/graph/graph_traits.hpp>

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <string_view>
#include <system_error>
#include <type_traits>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {
namespace internal {

// ---------------------------------------------------------------------------
// Polygon soup
// ---------------------------------------------------------------------------

/// Points and polygons as read from a file, in the file's order. Face `j` has the
/// vertices `face_vertices[face_begin[j]]` ... `face_vertices[face_begin[j+1]-1]`.
/// `point_lines` / `face_lines` give the 1-based line of each record in text files
/// (empty for binary files), for error messages.
struct Polygon_soup
{
  std::vector<std::array<double, 3> > points;
  std::vector<std::size_t> face_begin = std::vector<std::size_t>(1, 0);
  std::vector<std::size_t> face_vertices;
  std::vector<std::size_t> point_lines;
  std::vector<std::size_t> face_lines;

  std::size_t number_of_points() const { return points.size(); }
  std::size_t number_of_faces() const { return face_begin.size() - 1; }
  std::size_t face_size(std::size_t j) const { return face_begin[j + 1] - face_begin[j]; }

  void clear()
  {
    points.clear();
    face_begin.assign(1, 0);
    face_vertices.clear();
    point_lines.clear();
    face_lines.clear();
  }

  /// closes the face made of the vertices pushed to `face_vertices` since the last call
  void end_face(std::size_t line = 0)
  {
    face_begin.push_back(face_vertices.size());
    if(line != 0)
      face_lines.push_back(line);
  }

  std::string point_name(std::size_t i) const
  {
    std::ostringstream os;
    os << "vertex " << i;
    if(i < point_lines.size())
      os << " (line " << point_lines[i] << ")";
    return os.str();
  }

  std::string face_name(std::size_t j) const
  {
    std::ostringstream os;
    os << "face " << j;
    if(j < face_lines.size())
      os << " (line " << face_lines[j] << ")";
    return os.str();
  }
};

namespace io_impl {

inline Check_result fail(Error_code code, const std::string& message)
{
  return make_check_result(code, message);
}

inline Check_result read_fail(const std::string& message)
{
  return make_check_result(ERROR_READ_FAILED, message);
}

inline bool is_space(char c)
{
  return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f';
}

/// a token of the file, printable and at most 40 characters, in single quotes
inline std::string quote(std::string_view t)
{
  std::string s = "'";
  const std::size_t n = (std::min)(t.size(), std::size_t(40));
  for(std::size_t i = 0; i < n; ++i) {
    const unsigned char c = static_cast<unsigned char>(t[i]);
    if(c >= 32 && c < 127 && c != '\'') {
      s += static_cast<char>(c);
    } else {
      static const char hex[] = "0123456789abcdef";
      s += "\\x";
      s += hex[c >> 4];
      s += hex[c & 15];
    }
  }
  if(t.size() > n)
    s += "...";
  s += "'";
  return s;
}

inline std::string at_line(std::size_t line)
{
  std::ostringstream os;
  os << "line " << line << ": ";
  return os.str();
}

inline std::string lowercase(std::string s)
{
  for(char& c : s)
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

/// A read position in a text buffer that counts lines.
class Cursor
{
public:
  Cursor(const char* begin, const char* end, std::size_t first_line = 1)
    : p_(begin), end_(end), line_(first_line) {}

  bool at_end() const { return p_ == end_; }
  std::size_t line() const { return line_; }
  const char* position() const { return p_; }
  std::size_t remaining() const { return static_cast<std::size_t>(end_ - p_); }

  /// skips white space and, if `comments`, '#' comments up to the end of their line
  void skip_space(bool comments)
  {
    while(p_ != end_) {
      if(*p_ == '\n') {
        ++line_;
        ++p_;
      } else if(is_space(*p_)) {
        ++p_;
      } else if(comments && *p_ == '#') {
        while(p_ != end_ && *p_ != '\n')
          ++p_;
      } else {
        break;
      }
    }
  }

  /// the next white-space separated token (a '#' ends it if `comments`)
  bool token(std::string_view& t, bool comments)
  {
    skip_space(comments);
    if(p_ == end_)
      return false;
    const char* b = p_;
    while(p_ != end_ && !is_space(*p_) && !(comments && *p_ == '#'))
      ++p_;
    t = std::string_view(b, static_cast<std::size_t>(p_ - b));
    return true;
  }

  /// the rest of the current line without its end of line (nor a '#' comment if
  /// `comments`); moves to the beginning of the next line
  std::string_view rest_of_line(bool comments)
  {
    const char* b = p_;
    while(p_ != end_ && *p_ != '\n')
      ++p_;
    const char* e = p_;
    if(p_ != end_) {
      ++p_;
      ++line_;
    }
    if(comments) {
      const void* hash = std::memchr(b, '#', static_cast<std::size_t>(e - b));
      if(hash != nullptr)
        e = static_cast<const char*>(hash);
    }
    return std::string_view(b, static_cast<std::size_t>(e - b));
  }

private:
  const char* p_;
  const char* end_;
  std::size_t line_;
};

inline void split(std::string_view s, std::vector<std::string_view>& fields)
{
  fields.clear();
  std::size_t i = 0;
  while(true) {
    while(i < s.size() && is_space(s[i]))
      ++i;
    if(i == s.size())
      return;
    const std::size_t b = i;
    while(i < s.size() && !is_space(s[i]))
      ++i;
    fields.push_back(s.substr(b, i - b));
  }
}

/// moves `cur` past the next line that holds a field, `split()` into `fields` (without a
/// '#' comment if `comments`), and sets `line` to its number; false (`cur` at its end) if
/// no such line is left. The line reader of the keyword formats (OBJ, the PLY header, GOCAD).
inline bool next_fields(Cursor& cur, bool comments, std::vector<std::string_view>& fields, std::size_t& line)
{
  while(!cur.at_end()) {
    line = cur.line();
    split(cur.rest_of_line(comments), fields);
    if(!fields.empty())
      return true;
  }
  return false;
}

enum Number_status { NUMBER_OK, NOT_A_NUMBER, NEGATIVE_NUMBER, NUMBER_TOO_LARGE };

/// parses `[+]digits` completely; "-digits" gives NEGATIVE_NUMBER
inline Number_status parse_unsigned(std::string_view t, std::uint64_t& v)
{
  std::size_t i = 0;
  bool negative = false;
  if(!t.empty() && (t[0] == '+' || t[0] == '-')) {
    negative = (t[0] == '-');
    i = 1;
  }
  if(i == t.size())
    return NOT_A_NUMBER;
  for(std::size_t j = i; j < t.size(); ++j)
    if(t[j] < '0' || t[j] > '9')
      return NOT_A_NUMBER;
  if(negative)
    return NEGATIVE_NUMBER;
  const char* b = t.data() + i;
  const char* e = t.data() + t.size();
  auto res = std::from_chars(b, e, v);
  if(res.ec == std::errc::result_out_of_range)
    return NUMBER_TOO_LARGE;
  if(res.ec != std::errc() || res.ptr != e)
    return NOT_A_NUMBER;
  return NUMBER_OK;
}

/// parses `[+|-]digits` completely into a 64-bit signed integer
inline Number_status parse_signed(std::string_view t, std::int64_t& v)
{
  std::size_t i = 0;
  bool negative = false;
  if(!t.empty() && (t[0] == '+' || t[0] == '-')) {
    negative = (t[0] == '-');
    i = 1;
  }
  std::uint64_t u = 0;
  const Number_status s = parse_unsigned(t.substr(i), u);
  if(s != NUMBER_OK)
    return s == NEGATIVE_NUMBER ? NOT_A_NUMBER : s; // "--1", "-+1"
  if(i == 1 && t.size() > 1 && (t[1] == '+' || t[1] == '-'))
    return NOT_A_NUMBER;
  if(u > static_cast<std::uint64_t>((std::numeric_limits<std::int64_t>::max)()))
    return NUMBER_TOO_LARGE;
  v = negative ? -static_cast<std::int64_t>(u) : static_cast<std::int64_t>(u);
  return NUMBER_OK;
}

/// parses a real number completely (C locale; "nan", "inf", "infinity" are accepted;
/// a value beyond the range of double becomes +-inf, a tiny one 0 or a subnormal)
inline bool parse_real(std::string_view t, double& v)
{
  const char* b = t.data();
  const char* e = t.data() + t.size();
  if(b != e && *b == '+') {
    ++b;
    if(b != e && (*b == '-' || *b == '+'))
      return false;
  }
  if(b == e)
    return false;
  auto res = std::from_chars(b, e, v, std::chars_format::general);
  if(res.ptr != e)
    return false;
  if(res.ec == std::errc::result_out_of_range) {
    const std::string s(b, e);
    v = std::strtod(s.c_str(), nullptr); // +-HUGE_VAL (= inf) or 0 / subnormal
    return true;
  }
  return res.ec == std::errc();
}

// ---------------------------------------------------------------------------
// OFF
// ---------------------------------------------------------------------------

inline std::uint32_t load_u32_le(const unsigned char* p)
{
  return std::uint32_t(p[0]) | (std::uint32_t(p[1]) << 8) | (std::uint32_t(p[2]) << 16) | (std::uint32_t(p[3]) << 24);
}

inline std::uint32_t load_u32_be(const unsigned char* p)
{
  return std::uint32_t(p[3]) | (std::uint32_t(p[2]) << 8) | (std::uint32_t(p[1]) << 16) | (std::uint32_t(p[0]) << 24);
}

inline float u32_to_float(std::uint32_t u)
{
  float f;
  std::memcpy(&f, &u, 4);
  return f;
}

/// Binary OFF as specified by Geomview ("OFF BINARY"): big-endian int32 counts,
/// float32 coordinates, faces as int32 n, n int32 indices, int32 number of color
/// components (0 to 4) and that many float32. Only plain OFF (no C/N/ST/4 prefix).
inline Check_result parse_off_binary(const char* b, const char* e, Polygon_soup& soup)
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
  return Check_result();
}

/// ASCII OFF with the variants CGAL reads: [ST][C][N][4][n]OFF keyword, '#' comments,
/// counts anywhere after the keyword, one vertex / face record per line, trailing
/// normal / color / texture fields ignored; a zero homogeneous coordinate gives a
/// non-finite point. "OFF BINARY" goes to `parse_off_binary()`.
inline Check_result parse_off(const std::string& data, Polygon_soup& soup)
{
  Cursor cur(data.data(), data.data() + data.size());
  std::string_view tok;
  if(!cur.token(tok, true))
    return read_fail("the file holds no OFF header (it is blank or only comments)");
  const std::size_t header_line = cur.line();

  // keyword
  std::size_t j = 0;
  bool prefixed = false, homogeneous = false, ndim = false;
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

  // counts
  std::uint64_t counts[3] = { 0, 0, 0 };
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

  soup.points.reserve(nv);
  soup.point_lines.reserve(nv);
  soup.face_begin.reserve(nf + 1);
  soup.face_lines.reserve(nf);
  soup.face_vertices.reserve(3 * nf);

  std::vector<std::string_view> fields;
  const std::size_t needed = homogeneous ? 4 : 3;
  for(std::uint64_t i = 0; i < nv; ++i) {
    cur.skip_space(true);
    if(cur.at_end())
      return read_fail("the file ends after " + std::to_string(i) + " of the " + std::to_string(nv)
                       + " vertices announced by the OFF header (truncated file?)");
    const std::size_t line = cur.line();
    split(cur.rest_of_line(true), fields);
    if(fields.size() < needed)
      return read_fail(at_line(line) + "vertex " + std::to_string(i) + " has " + std::to_string(fields.size())
                       + " coordinates, " + std::to_string(needed) + " expected (truncated or malformed record)");
    double c[4] = { 0, 0, 0, 1 };
    for(std::size_t k = 0; k < needed; ++k)
      if(!parse_real(fields[k], c[k]))
        return read_fail(at_line(line) + "vertex " + std::to_string(i) + ": coordinate " + quote(fields[k])
                         + " is not a number");
    if(homogeneous) {
      c[0] /= c[3];
      c[1] /= c[3];
      c[2] /= c[3];
    }
    soup.points.push_back({ { c[0], c[1], c[2] } });
    soup.point_lines.push_back(line);
  }

  for(std::uint64_t f = 0; f < nf; ++f) {
    cur.skip_space(true);
    if(cur.at_end())
      return read_fail("the file ends after " + std::to_string(f) + " of the " + std::to_string(nf)
                       + " faces announced by the OFF header (truncated file?)");
    const std::size_t line = cur.line();
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
  return Check_result(); // whatever follows the last face is ignored, as CGAL does
}

// ---------------------------------------------------------------------------
// OBJ
// ---------------------------------------------------------------------------

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

/// Wavefront OBJ: "v x y z [...]" and "f i[/t[/n]] ..." (1-based; negative indices are
/// relative to the vertices read so far, as the format specifies); the statements listed
/// in `is_ignored_obj_statement()` and '#' comments are skipped; any other is an error.
inline Check_result parse_obj(const std::string& data, Polygon_soup& soup)
{
  Cursor cur(data.data(), data.data() + data.size());
  std::vector<std::string_view> fields;
  for(std::size_t line = 0; next_fields(cur, true, fields, line);) {
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
  return Check_result();
}

// ---------------------------------------------------------------------------
// PLY
// ---------------------------------------------------------------------------

enum Ply_type { PLY_NONE, PLY_INT8, PLY_UINT8, PLY_INT16, PLY_UINT16, PLY_INT32, PLY_UINT32, PLY_FLOAT32, PLY_FLOAT64 };

inline Ply_type ply_type(std::string_view s)
{
  if(s == "char" || s == "int8") return PLY_INT8;
  if(s == "uchar" || s == "uint8") return PLY_UINT8;
  if(s == "short" || s == "int16") return PLY_INT16;
  if(s == "ushort" || s == "uint16") return PLY_UINT16;
  if(s == "int" || s == "int32") return PLY_INT32;
  if(s == "uint" || s == "uint32") return PLY_UINT32;
  if(s == "float" || s == "float32") return PLY_FLOAT32;
  if(s == "double" || s == "float64") return PLY_FLOAT64;
  return PLY_NONE;
}

inline std::size_t ply_size(Ply_type t)
{
  switch(t) {
  case PLY_INT8: case PLY_UINT8: return 1;
  case PLY_INT16: case PLY_UINT16: return 2;
  case PLY_INT32: case PLY_UINT32: case PLY_FLOAT32: return 4;
  case PLY_FLOAT64: return 8;
  default: return 0;
  }
}

inline bool ply_is_integer(Ply_type t) { return t != PLY_FLOAT32 && t != PLY_FLOAT64; }

struct Ply_property
{
  std::string name;
  bool is_list = false;
  Ply_type count_type = PLY_NONE;
  Ply_type value_type = PLY_NONE;
};

struct Ply_element
{
  std::string name;
  std::uint64_t count = 0;
  std::vector<Ply_property> properties;
};

/// reads PLY values, ASCII or binary; a value is returned as a double and, for
/// integer types, exactly as an int64
class Ply_value_reader
{
public:
  Ply_value_reader(const char* b, const char* e, int format /*0 ascii, 1 le, 2 be*/, std::size_t first_line)
    : cur_(b, e, first_line), p_(reinterpret_cast<const unsigned char*>(b)), end_(reinterpret_cast<const unsigned char*>(e)),
      format_(format)
  {}

  std::size_t remaining() const
  {
    return format_ == 0 ? cur_.remaining() : static_cast<std::size_t>(end_ - p_);
  }
  std::size_t line() const { return format_ == 0 ? cur_.line() : 0; }

  /// the line where the next value starts (ASCII; 0 for binary files)
  std::size_t next_value_line()
  {
    if(format_ != 0)
      return 0;
    cur_.skip_space(false);
    return cur_.line();
  }

  // returns an empty string on success, else the reason
  std::string read(Ply_type t, double& d, std::int64_t& i)
  {
    if(format_ == 0) {
      std::string_view tok;
      if(!cur_.token(tok, false))
        return "the file ends early (truncated file?)";
      if(ply_is_integer(t)) {
        if(parse_signed(tok, i) != NUMBER_OK)
          return quote(tok) + " is not an integer";
        d = static_cast<double>(i);
      } else {
        if(!parse_real(tok, d))
          return quote(tok) + " is not a number";
        if(t == PLY_FLOAT32)
          d = static_cast<double>(static_cast<float>(d)); // the declared precision, as CGAL does
        i = 0;
      }
      return std::string();
    }
    const std::size_t n = ply_size(t);
    if(static_cast<std::size_t>(end_ - p_) < n)
      return "the file ends early (truncated file?)";
    unsigned char b[8];
    for(std::size_t k = 0; k < n; ++k)
      b[k] = p_[format_ == 1 ? k : n - 1 - k]; // to little endian
    p_ += n;
    switch(t) {
    case PLY_INT8: i = static_cast<std::int8_t>(b[0]); break;
    case PLY_UINT8: i = b[0]; break;
    case PLY_INT16: i = static_cast<std::int16_t>(std::uint16_t(b[0] | (b[1] << 8))); break;
    case PLY_UINT16: i = std::uint16_t(b[0] | (b[1] << 8)); break;
    case PLY_INT32: i = static_cast<std::int32_t>(load_u32_le(b)); break;
    case PLY_UINT32: i = load_u32_le(b); break;
    case PLY_FLOAT32: d = u32_to_float(load_u32_le(b)); return std::string();
    case PLY_FLOAT64: {
      std::uint64_t u = std::uint64_t(load_u32_le(b)) | (std::uint64_t(load_u32_le(b + 4)) << 32);
      std::memcpy(&d, &u, 8);
      return std::string();
    }
    default: return "bad type";
    }
    d = static_cast<double>(i);
    return std::string();
  }

private:
  Cursor cur_;
  const unsigned char* p_;
  const unsigned char* end_;
  int format_;
};

/// PLY (ascii, binary_little_endian, binary_big_endian): the "vertex" element's x, y, z
/// and the "face" element's "vertex_indices" (or "vertex_index") list; other properties
/// and elements are read and ignored.
inline Check_result parse_ply(const std::string& data, Polygon_soup& soup)
{
  Cursor cur(data.data(), data.data() + data.size());
  std::vector<std::string_view> fields;
  auto trim_cr = [](std::string_view s) {
    while(!s.empty() && (s.back() == '\r' || s.back() == ' ' || s.back() == '\t'))
      s.remove_suffix(1);
    return s;
  };
  if(trim_cr(cur.rest_of_line(false)) != "ply")
    return read_fail("line 1: not a PLY file (the first line is not 'ply')");

  int format = -1;
  std::vector<Ply_element> elements;
  bool end_header = false;
  for(std::size_t line = 0; next_fields(cur, false, fields, line);) {
    const std::string_view kw = fields[0];
    if(kw == "end_header") {
      end_header = true;
      break;
    } else if(kw == "comment" || kw == "obj_info") {
      continue;
    } else if(kw == "format") {
      if(fields.size() < 2)
        return read_fail(at_line(line) + "incomplete PLY format line");
      if(fields[1] == "ascii") format = 0;
      else if(fields[1] == "binary_little_endian") format = 1;
      else if(fields[1] == "binary_big_endian") format = 2;
      else return read_fail(at_line(line) + "unknown PLY format " + quote(fields[1]));
    } else if(kw == "element") {
      Ply_element el;
      if(fields.size() < 3 || parse_unsigned(fields[2], el.count) != NUMBER_OK)
        return read_fail(at_line(line) + "bad PLY element line (expected 'element <name> <non-negative count>')");
      el.name = std::string(fields[1]);
      elements.push_back(el);
    } else if(kw == "property") {
      if(elements.empty())
        return read_fail(at_line(line) + "PLY property before any element");
      Ply_property prop;
      if(fields.size() >= 5 && fields[1] == "list") {
        prop.is_list = true;
        prop.count_type = ply_type(fields[2]);
        prop.value_type = ply_type(fields[3]);
        prop.name = std::string(fields[4]);
        if(prop.count_type == PLY_NONE || prop.value_type == PLY_NONE || !ply_is_integer(prop.count_type))
          return read_fail(at_line(line) + "bad PLY list property types");
      } else if(fields.size() >= 3 && fields[1] != "list") {
        prop.value_type = ply_type(fields[1]);
        prop.name = std::string(fields[2]);
        if(prop.value_type == PLY_NONE)
          return read_fail(at_line(line) + "unknown PLY property type " + quote(fields[1]));
      } else {
        return read_fail(at_line(line) + "bad PLY property line");
      }
      elements.back().properties.push_back(prop);
    } else {
      return read_fail(at_line(line) + "unknown PLY header keyword " + quote(kw));
    }
  }
  if(!end_header)
    return read_fail("the PLY header has no end_header line (truncated file?)");
  if(format < 0)
    return read_fail("the PLY header has no format line");

  Ply_value_reader in(cur.position(), data.data() + data.size(), format, cur.line());
  bool vertex_element_seen = false;
  for(const Ply_element& el : elements) {
    if(el.properties.empty())
      continue; // such items hold no data, whatever their count
    std::size_t min_bytes = 0;
    for(const Ply_property& prop : el.properties)
      min_bytes += format == 0 ? 2 : ply_size(prop.is_list ? prop.count_type : prop.value_type);
    if(el.count > in.remaining() / min_bytes + 1)
      return read_fail("the PLY header announces " + std::to_string(el.count) + " '" + el.name + "' elements, but only "
                       + std::to_string(in.remaining()) + " bytes follow (truncated file or wrong header)");

    const bool is_vertex = (el.name == "vertex") && !vertex_element_seen;
    const bool is_face = (el.name == "face");
    int xyz[3] = { -1, -1, -1 };
    int indices = -1;
    for(std::size_t k = 0; k < el.properties.size(); ++k) {
      const Ply_property& prop = el.properties[k];
      if(is_vertex && !prop.is_list) {
        if(prop.name == "x") xyz[0] = int(k);
        if(prop.name == "y") xyz[1] = int(k);
        if(prop.name == "z") xyz[2] = int(k);
      }
      if(is_face && prop.is_list && (prop.name == "vertex_indices" || prop.name == "vertex_index") && indices < 0)
        indices = int(k);
    }
    if(is_vertex && (xyz[0] < 0 || xyz[1] < 0 || xyz[2] < 0))
      return read_fail("the PLY vertex element has no x, y and z properties");
    if(is_face && indices < 0)
      return read_fail("the PLY face element has no vertex_indices list");
    if(is_face && !ply_is_integer(el.properties[std::size_t(indices)].value_type))
      return read_fail("the PLY vertex_indices list does not hold integers");
    if(is_vertex) {
      vertex_element_seen = true;
      soup.points.reserve(el.count);
    }

    for(std::uint64_t item = 0; item < el.count; ++item) {
      const std::size_t line = in.next_value_line();
      std::array<double, 3> q = { { 0, 0, 0 } };
      auto where = [&]() {
        std::string s = format == 0 ? at_line(in.line()) : std::string();
        return s + el.name + " " + std::to_string(item) + ": ";
      };
      for(std::size_t k = 0; k < el.properties.size(); ++k) {
        const Ply_property& prop = el.properties[k];
        double d = 0;
        std::int64_t i = 0;
        std::string err;
        if(!prop.is_list) {
          err = in.read(prop.value_type, d, i);
          if(!err.empty())
            return read_fail(where() + err);
          for(int c = 0; c < 3; ++c)
            if(is_vertex && xyz[c] == int(k))
              q[std::size_t(c)] = d;
          continue;
        }
        err = in.read(prop.count_type, d, i);
        if(!err.empty())
          return read_fail(where() + err);
        const std::size_t value_bytes = format == 0 ? 2 : ply_size(prop.value_type);
        if(i < 0)
          return read_fail(where() + "negative list size " + std::to_string(i));
        if(std::uint64_t(i) > in.remaining() / value_bytes + 1)
          return read_fail(where() + "the list size " + std::to_string(i) + " is larger than the rest of the file holds"
                           + " (only " + std::to_string(in.remaining()) + (in.remaining() == 1 ? " byte" : " bytes")
                           + " left: truncated file?)");
        const bool keep = is_face && int(k) == indices;
        for(std::int64_t m = 0; m < i; ++m) {
          std::int64_t id = 0;
          err = in.read(prop.value_type, d, id);
          if(!err.empty())
            return read_fail(where() + err);
          if(keep) {
            if(id < 0)
              return read_fail(where() + "negative vertex index " + std::to_string(id));
            soup.face_vertices.push_back(static_cast<std::size_t>(id));
          }
        }
      }
      if(is_vertex) {
        soup.points.push_back(q);
        if(format == 0)
          soup.point_lines.push_back(line);
      }
      if(is_face)
        soup.end_face(format == 0 ? line : 0);
    }
  }
  return Check_result();
}

// ---------------------------------------------------------------------------
// STL
// ---------------------------------------------------------------------------

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

inline Check_result parse_stl_binary(const std::string& data, Polygon_soup& soup)
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
  return Check_result();
}

inline Check_result parse_stl_ascii(const std::string& data, Polygon_soup& soup)
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
  return Check_result();
}

/// Binary STL if the size is exactly 84 + 50 N (N read at offset 80), else ASCII if
/// the file starts with "solid", else binary with a size mismatch (an error).
inline Check_result parse_stl(const std::string& data, Polygon_soup& soup)
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

// ---------------------------------------------------------------------------
// GOCAD TSurf
// ---------------------------------------------------------------------------

/// GOCAD TSurf (ASCII): everything before the first "TFACE" line is header (name, colour,
/// coordinate system, ...; the "GOCAD TSurf" line itself is optional, as in CGAL); then
/// "VRTX id x y z" / "PVRTX id x y z [properties]" define vertex `id` (file order = vertex
/// order), "ATOM id v" / "PATOM id v [...]" give vertex `v` a second id (the same vertex),
/// "TRGL a b c" is a triangle of ids (defined before or after it), "TFACE" starts another
/// patch, "BSTONE" / "BORDER" / "SEG" are ignored, and the first "END" ends the object
/// (what follows is ignored). Any other keyword after TFACE is an error.
inline Check_result parse_gocad(const std::string& data, Polygon_soup& soup)
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
  auto parse_id = [&](std::string_view t, std::size_t line, std::int64_t& id) -> Check_result {
    switch(parse_signed(t, id)) {
    case NUMBER_OK: return Check_result();
    case NUMBER_TOO_LARGE: return read_fail(at_line(line) + "vertex id " + quote(t) + " is too large");
    default: return read_fail(at_line(line) + quote(t) + " is not a vertex id (an integer)");
    }
  };
  for(std::size_t line = 0; next_fields(cur, false, fields, line);) {
    const std::string_view kw = fields[0];
    Check_result r;
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
  return Check_result();
}

// ---------------------------------------------------------------------------
// Files
// ---------------------------------------------------------------------------

/// the file exists, is a regular file and can be opened
inline Check_result check_readable_file(const std::string& path)
{
  if(path.empty())
    return read_fail("no file name given");
  std::error_code ec;
  const std::filesystem::file_status st = std::filesystem::status(path, ec);
  if(ec || !std::filesystem::exists(st))
    return read_fail("'" + path + "': no such file");
  if(std::filesystem::is_directory(st))
    return read_fail("'" + path + "' is a directory, not a file");
  if(!std::filesystem::is_regular_file(st))
    return read_fail("'" + path + "' is not a regular file");
  std::ifstream in(path, std::ios::binary);
  if(!in)
    return read_fail("'" + path + "': cannot open the file for reading (permission denied?)");
  return Check_result();
}

inline Check_result read_file_contents(const std::string& path, std::string& data)
{
  data.clear();
  Check_result r = check_readable_file(path);
  if(!r)
    return r;
  std::error_code ec;
  const std::uintmax_t size = std::filesystem::file_size(path, ec);
  if(ec)
    return read_fail("'" + path + "': cannot get the file size (" + ec.message() + ")");
  std::ifstream in(path, std::ios::binary);
  if(!in)
    return read_fail("'" + path + "': cannot open the file for reading (permission denied?)");
  try {
    data.resize(static_cast<std::size_t>(size));
  } catch(const std::exception&) {
    return read_fail("'" + path + "': the file is too large to be read into memory");
  }
  if(size > 0 && !in.read(&data[0], static_cast<std::streamsize>(size)))
    return read_fail("'" + path + "': read error");
  return Check_result();
}

inline std::string file_extension(const std::string& path)
{
  const std::string name = std::filesystem::path(path).filename().string();
  const std::size_t dot = name.rfind('.');
  if(dot == std::string::npos || dot == 0)
    return std::string();
  return lowercase(name.substr(dot + 1));
}

} // namespace io_impl

/*!
Reads the polygon soup of a mesh file, in the file's order. The format is chosen by the
file extension (any case): .off (ASCII and Geomview binary), .obj, .ply (ASCII and
binary), .stl (ASCII and binary), and .ts (GOCAD TSurf).
Messages start with the file name. Only parse errors are reported here
(ERROR_READ_FAILED); see `validate_polygon_soup()` for the rest.
*/
inline Check_result read_polygon_soup_file(const std::string& path, Polygon_soup& soup)
{
  using namespace io_impl;
  soup.clear();
  if(path.empty())
    return read_fail("no file name given");
  const std::string ext = file_extension(path);
  if(ext != "off" && ext != "obj" && ext != "ply" && ext != "stl" && ext != "ts")
    return read_fail("'" + path + "': unsupported file extension '" + ext + "' (supported: off, obj, ply, stl, ts)");

  Check_result r;
  std::string data;
  if(!(r = read_file_contents(path, data)))
    return r;
  if(data.empty())
    return read_fail("'" + path + "': the file is empty");

  try {
    if(ext == "off")
      r = parse_off(data, soup);
    else if(ext == "obj")
      r = parse_obj(data, soup);
    else if(ext == "ply")
      r = parse_ply(data, soup);
    else if(ext == "stl")
      r = parse_stl(data, soup);
    else
      r = parse_gocad(data, soup);
  } catch(const std::exception&) { // bad_alloc, length_error: not expected, counts are bounded
    r = read_fail("out of memory");
  }
  if(!r) {
    soup.clear();
    r.message = path + ": " + r.message;
  }
  return r;
}

/// The edge table of a valid soup, used to build the halfedge structure.
struct Soup_topology
{
  typedef std::uint32_t Id;
  static constexpr Id none = static_cast<Id>(-1);

  std::vector<Id> corner_face;              ///< face of each corner (position in face_vertices)
  std::vector<Id> corner_edge;              ///< edge of the halfedge that leaves each corner
  std::vector<unsigned char> corner_side;   ///< 0: first halfedge of that edge, 1: its opposite
  std::vector<std::array<Id, 2> > edge_corners; ///< corners of the two sides (`none`: border side)
};

/*!
Validates `soup` (see the list at the top of this file) in linear expected time and,
if `topology` is not null and the soup is valid, fills the edge table used by
`polygon_soup_to_mesh()`.
*/
inline Check_result validate_polygon_soup(const Polygon_soup& soup, Soup_topology* topology = nullptr)
{
  typedef Soup_topology::Id Id;
  const Id none = Soup_topology::none;
  const std::size_t np = soup.number_of_points();
  const std::size_t nf = soup.number_of_faces();
  const std::vector<std::size_t>& fv = soup.face_vertices;
  const std::size_t m = fv.size();

  if(np >= none || m >= none || nf >= none)
    return io_impl::read_fail("the mesh is too large (more than 4 billion vertices or face corners)");

  // 1. faces: indices in range, at least 3 distinct vertices
  std::vector<Id> corner_face(m);
  {
    std::vector<Id> seen(np, none);
    for(std::size_t f = 0; f < nf; ++f) {
      const std::size_t b = soup.face_begin[f], e = soup.face_begin[f + 1];
      for(std::size_t c = b; c < e; ++c) {
        if(fv[c] >= np) {
          std::ostringstream os;
          os << soup.face_name(f) << ": vertex index " << fv[c] << " is out of range (the file has "
             << np << " vertices)";
          return io_impl::read_fail(os.str());
        }
      }
      if(e - b < 3) {
        std::ostringstream os;
        os << soup.face_name(f) << " is degenerate: it has only " << (e - b) << " vertices";
        return io_impl::fail(ERROR_DEGENERATE_FACE, os.str());
      }
      for(std::size_t c = b; c < e; ++c) {
        corner_face[c] = static_cast<Id>(f);
        if(seen[fv[c]] == static_cast<Id>(f)) {
          std::ostringstream os;
          os << soup.face_name(f) << " is degenerate: it uses vertex " << fv[c] << " more than once";
          return io_impl::fail(ERROR_DEGENERATE_FACE, os.str());
        }
        seen[fv[c]] = static_cast<Id>(f);
      }
    }
  }
  auto next_corner = [&](std::size_t c) -> std::size_t {
    const std::size_t f = corner_face[c];
    return c + 1 < soup.face_begin[f + 1] ? c + 1 : soup.face_begin[f];
  };

  // 1b. a face repeated (the same vertices in the same cyclic order): hash of each face
  //     read from its smallest vertex, faces with equal hashes compared. A repeated face
  //     makes two faces traverse an edge in the same direction, so this runs only when
  //     step 2 finds such an edge (no cost for valid soups), to give the specific reason.
  auto find_duplicated_face = [&]() -> Check_result {
    auto smallest_corner = [&](std::size_t f) {
      std::size_t best = soup.face_begin[f];
      for(std::size_t c = best + 1; c < soup.face_begin[f + 1]; ++c)
        if(fv[c] < fv[best])
          best = c;
      return best;
    };
    std::vector<std::size_t> first_corner(nf);
    std::unordered_map<std::uint64_t, Id> first_with_hash;
    std::vector<Id> next_with_hash(nf, none);
    first_with_hash.reserve(nf);
    for(std::size_t f = 0; f < nf; ++f) {
      const std::size_t c0 = first_corner[f] = smallest_corner(f);
      std::uint64_t h = soup.face_size(f);
      std::size_t c = c0;
      do {
        h = (h ^ fv[c]) * 0x100000001b3ull + 0x9e3779b97f4a7c15ull;
        h ^= h >> 29;
        c = next_corner(c);
      } while(c != c0);
      auto ins = first_with_hash.emplace(h, static_cast<Id>(f));
      if(ins.second)
        continue;
      for(Id g = ins.first->second; g != none; g = next_with_hash[g]) {
        if(soup.face_size(g) != soup.face_size(f))
          continue;
        std::size_t a = first_corner[g], b = c0;
        std::size_t k = 0;
        while(k < soup.face_size(f) && fv[a] == fv[b]) {
          a = next_corner(a);
          b = next_corner(b);
          ++k;
        }
        if(k == soup.face_size(f)) {
          std::ostringstream os;
          os << "duplicated face: " << soup.face_name(f) << " repeats " << soup.face_name(g)
             << " (the same vertices in the same order)";
          return io_impl::fail(ERROR_NON_MANIFOLD, os.str());
        }
      }
      next_with_hash[f] = next_with_hash[ins.first->second]; // chain f after the first face with this hash
      next_with_hash[ins.first->second] = static_cast<Id>(f);
    }
    return Check_result();
  };

  // 2. edges: halfedges grouped by their smaller vertex (counting sort), then by the other
  struct Entry { Id other; Id corner; };
  std::vector<Id> start(np + 1, 0);
  for(std::size_t c = 0; c < m; ++c)
    ++start[(std::min)(fv[c], fv[next_corner(c)]) + 1];
  for(std::size_t v = 0; v < np; ++v)
    start[v + 1] += start[v];
  std::vector<Entry> entries(m);
  {
    std::vector<Id> fill(start.begin(), start.end() - 1);
    for(std::size_t c = 0; c < m; ++c) {
      const std::size_t a = fv[c], b = fv[next_corner(c)];
      entries[fill[(std::min)(a, b)]++] = Entry{ static_cast<Id>((std::max)(a, b)), static_cast<Id>(c) };
    }
  }

  std::vector<Id> corner_edge(m, none);
  std::vector<unsigned char> corner_side(m, 0);
  std::vector<std::array<Id, 2> > edge_corners;
  edge_corners.reserve(m / 2 + 1);
  std::string non_manifold_edge, bad_orientation;
  for(std::size_t a = 0; a < np; ++a) {
    const auto first = entries.begin() + start[a], last = entries.begin() + start[a + 1];
    std::sort(first, last, [](const Entry& x, const Entry& y) {
      return x.other < y.other || (x.other == y.other && x.corner < y.corner);
    });
    for(auto g = first; g != last;) {
      auto h = g;
      while(h != last && h->other == g->other)
        ++h;
      const std::size_t s = static_cast<std::size_t>(h - g);
      if(s > 2) {
        if(non_manifold_edge.empty()) {
          std::ostringstream os;
          os << "non-manifold edge: the edge (" << a << ", " << g->other << ") is shared by " << s << " faces (";
          for(auto k = g; k != h && k - g < 4; ++k)
            os << (k == g ? "" : ", ") << soup.face_name(corner_face[k->corner]);
          os << (s > 4 ? ", ...)" : ")");
          non_manifold_edge = os.str();
        }
      } else if(s == 2 && (fv[g->corner] == a) == (fv[(g + 1)->corner] == a)) {
        if(bad_orientation.empty()) {
          const std::size_t from = fv[g->corner], to = fv[next_corner(g->corner)];
          std::ostringstream os;
          os << "inconsistent face orientation: " << soup.face_name(corner_face[g->corner]) << " and "
             << soup.face_name(corner_face[(g + 1)->corner]) << " both traverse the edge " << from << " -> " << to
             << " (faces must be oriented consistently; or a face is duplicated)";
          bad_orientation = os.str();
        }
      } else {
        const Id e = static_cast<Id>(edge_corners.size());
        edge_corners.push_back({ { g->corner, s == 2 ? (g + 1)->corner : none } });
        corner_edge[g->corner] = e;
        corner_side[g->corner] = 0;
        if(s == 2) {
          corner_edge[(g + 1)->corner] = e;
          corner_side[(g + 1)->corner] = 1;
        }
      }
      g = h;
    }
  }
  if(!non_manifold_edge.empty() || !bad_orientation.empty()) {
    Check_result dup = find_duplicated_face();
    if(!dup)
      return dup;
    return io_impl::fail(ERROR_NON_MANIFOLD, !non_manifold_edge.empty() ? non_manifold_edge : bad_orientation);
  }
  { std::vector<Entry>().swap(entries); std::vector<Id>().swap(start); }

  // 3. vertices: the corners around a vertex must form a single fan (union-find of
  //    the corners at a vertex that share an edge)
  {
    std::vector<Id> parent(m);
    for(std::size_t c = 0; c < m; ++c)
      parent[c] = static_cast<Id>(c);
    auto find = [&](Id x) {
      while(parent[x] != x) {
        parent[x] = parent[parent[x]];
        x = parent[x];
      }
      return x;
    };
    auto unite = [&](Id x, Id y) {
      x = find(x);
      y = find(y);
      if(x != y)
        parent[(std::max)(x, y)] = (std::min)(x, y);
    };
    for(const auto& ec : edge_corners) {
      if(ec[1] == none)
        continue;
      // ec[0]: u -> w in one face; ec[1]: w -> u in the other
      unite(ec[0], static_cast<Id>(next_corner(ec[1]))); // corners at u
      unite(static_cast<Id>(next_corner(ec[0])), ec[1]); // corners at w
    }
    std::vector<Id> fan(np, none);
    for(std::size_t c = 0; c < m; ++c) {
      const Id r = find(static_cast<Id>(c));
      Id& f = fan[fv[c]];
      if(f == none) {
        f = r;
      } else if(f != r) {
        std::ostringstream os;
        os << "non-manifold vertex: the faces around " << soup.point_name(fv[c]) << " form more than one fan ("
           << soup.face_name(corner_face[f]) << " and " << soup.face_name(corner_face[c])
           << " are in different fans)";
        return io_impl::fail(ERROR_NON_MANIFOLD, os.str());
      }
    }
  }

  // 4. coordinates
  for(std::size_t i = 0; i < np; ++i) {
    const auto& p = soup.points[i];
    if(!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2])) {
      std::ostringstream os;
      os << soup.point_name(i) << " has a non-finite coordinate (" << p[0] << " " << p[1] << " " << p[2] << ")";
      return io_impl::fail(ERROR_NON_FINITE_COORDINATES, os.str());
    }
  }

  if(topology) {
    topology->corner_face.swap(corner_face);
    topology->corner_edge.swap(corner_edge);
    topology->corner_side.swap(corner_side);
    topology->edge_corners.swap(edge_corners);
  }
  return Check_result();
}

namespace io_impl {

template <class PM, class = void>
struct Has_bgl_reserve : std::false_type {};

template <class PM>
struct Has_bgl_reserve<PM, std::void_t<decltype(reserve(std::declval<PM&>(),
                                                        typename boost::graph_traits<PM>::vertices_size_type(0),
                                                        typename boost::graph_traits<PM>::edges_size_type(0),
                                                        typename boost::graph_traits<PM>::faces_size_type(0)))> >
  : std::true_type {};

} // namespace io_impl

/*!
Builds `mesh` (cleared first) from a soup; the soup is validated first and nothing is
built if it is invalid. Vertex i of the mesh is point i of the soup (unreferenced points
included), face j is polygon j with its vertex order, `source(halfedge(face j))` being
its first vertex. Linear time. `PolygonMesh` is a model of `MutableFaceGraph` with an
internal vertex point map (Surface_mesh, Polyhedron_3).
*/
template <class PolygonMesh>
Check_result polygon_soup_to_mesh(const Polygon_soup& soup, PolygonMesh& mesh)
{
  typedef boost::graph_traits<PolygonMesh> GT;
  typedef typename GT::vertex_descriptor vertex_descriptor;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  typedef typename GT::face_descriptor face_descriptor;
  typedef typename boost::property_map<PolygonMesh, CGAL::vertex_point_t>::type VPM;
  typedef typename boost::property_traits<VPM>::value_type Point;

  CGAL::clear(mesh);
  Soup_topology topo;
  Check_result r = validate_polygon_soup(soup, &topo);
  if(!r)
    return r;

  try {
    const std::size_t np = soup.number_of_points(), nf = soup.number_of_faces();
    const std::size_t ne = topo.edge_corners.size();
    if constexpr(io_impl::Has_bgl_reserve<PolygonMesh>::value)
      reserve(mesh, typename GT::vertices_size_type(np), typename GT::edges_size_type(ne),
              typename GT::faces_size_type(nf));
    VPM vpm = get(CGAL::vertex_point, mesh);

    std::vector<vertex_descriptor> V(np);
    for(std::size_t i = 0; i < np; ++i) {
      V[i] = add_vertex(mesh);
      put(vpm, V[i], Point(soup.points[i][0], soup.points[i][1], soup.points[i][2]));
    }

    const std::vector<std::size_t>& fv = soup.face_vertices;
    auto next_corner = [&](std::size_t c) -> std::size_t {
      const std::size_t f = topo.corner_face[c];
      return c + 1 < soup.face_begin[f + 1] ? c + 1 : soup.face_begin[f];
    };

    std::vector<halfedge_descriptor> H(2 * ne);
    for(std::size_t e = 0; e < ne; ++e) {
      const halfedge_descriptor h = halfedge(add_edge(mesh), mesh);
      H[2 * e] = h;
      H[2 * e + 1] = opposite(h, mesh);
      const std::size_t c0 = topo.edge_corners[e][0]; // u -> w
      set_target(H[2 * e], V[fv[next_corner(c0)]], mesh);
      set_target(H[2 * e + 1], V[fv[c0]], mesh);
    }
    auto corner_halfedge = [&](std::size_t c) { return H[2 * topo.corner_edge[c] + topo.corner_side[c]]; };

    for(std::size_t f = 0; f < nf; ++f) {
      const face_descriptor fd = add_face(mesh);
      const std::size_t b = soup.face_begin[f], e = soup.face_begin[f + 1];
      for(std::size_t c = b; c < e; ++c) {
        const halfedge_descriptor h = corner_halfedge(c);
        set_face(h, fd, mesh);
        set_next(h, corner_halfedge(next_corner(c)), mesh);
        set_halfedge(target(h, mesh), h, mesh);
      }
      // the halfedge of the face leaves its first vertex
      set_halfedge(fd, corner_halfedge(b), mesh);
    }

    // border halfedges: w -> u opposite to a lone u -> w; in a manifold soup every
    // border vertex has exactly one outgoing border halfedge
    std::vector<halfedge_descriptor> border_out(np, GT::null_halfedge());
    for(std::size_t e = 0; e < ne; ++e) {
      if(topo.edge_corners[e][1] != Soup_topology::none)
        continue;
      const halfedge_descriptor bh = H[2 * e + 1];
      set_face(bh, GT::null_face(), mesh);
      border_out[fv[next_corner(topo.edge_corners[e][0])]] = bh; // source w
    }
    for(std::size_t e = 0; e < ne; ++e) {
      if(topo.edge_corners[e][1] != Soup_topology::none)
        continue;
      const halfedge_descriptor bh = H[2 * e + 1];
      const std::size_t u = fv[topo.edge_corners[e][0]]; // target of bh
      set_next(bh, border_out[u], mesh);
      set_halfedge(V[u], bh, mesh); // a border vertex points to its incoming border halfedge
    }
  } catch(const std::bad_alloc&) {
    CGAL::clear(mesh);
    return io_impl::fail(ERROR_READ_FAILED, "out of memory while building the mesh");
  }
  // The result is a valid polygon mesh (CGAL::is_valid_polygon_mesh() holds when every
  // point is referenced; the test suite checks it). It is not re-checked here:
  // check_mesh() does it.

  return Check_result();
}

/*!
Reads a mesh file into `mesh` (cleared first; left empty on failure), keeping the
file's vertex and face order. Errors: ERROR_READ_FAILED (missing / unreadable file,
unsupported extension, parse error, truncated file, implausible counts, out-of-range
index), then the soup errors of `validate_polygon_soup()`. Quads and other polygons,
isolated vertices, several components etc. are read without error; `check_mesh()`
reports them. Every message starts with the file name.
*/
template <class PolygonMesh>
Check_result read_mesh(const std::string& path, PolygonMesh& mesh)
{
  CGAL::clear(mesh);
  Polygon_soup soup;
  Check_result r = read_polygon_soup_file(path, soup);
  if(!r)
    return r;
  r = polygon_soup_to_mesh(soup, mesh);
  if(!r) {
    CGAL::clear(mesh);
    r.message = path + ": " + r.message;
  }
  return r;
}

/*!
Reads 0-based vertex indices (landmarks / cones) from a text file. The rule:

* '#' starts a comment up to the end of its line;
* if the file name ends with ".selection.txt" (a CGAL Polyhedron-demo selection file:
  line 1 = selected vertices, then lines of faces and edges), the indices are the tokens
  of line 1, the other lines are ignored;
* otherwise the file must hold either all its indices on one single non-empty line, or
  one index per non-empty line (like the `.cones.txt` files); any other layout (several
  lines with several tokens) is rejected as ambiguous.

Every index is a non-negative decimal integer (an optional '+' is allowed). A token that
is not one (garbage, a negative number, "12abc", "1.0", a number that overflows 64 bits)
gives ERROR_READ_FAILED with the token and its line; so do a missing / unreadable file
and a file without index. The range and duplicates are checked by `check_landmarks()`.
*/
inline Check_result read_landmarks(const std::string& path, std::vector<std::size_t>& indices)
{
  using namespace io_impl;
  indices.clear();
  std::string data;
  Check_result r = read_file_contents(path, data);
  if(!r)
    return r;

  const std::string suffix = ".selection.txt";
  const bool selection = path.size() >= suffix.size()
                      && lowercase(path.substr(path.size() - suffix.size())) == suffix;

  Cursor cur(data.data(), data.data() + data.size());
  std::vector<std::string_view> fields;
  std::vector<std::pair<std::string_view, std::size_t> > tokens; // token, line
  std::size_t lines_with_tokens = 0, lines_with_several = 0, first_several_line = 0;
  while(!cur.at_end()) {
    const std::size_t line = cur.line();
    split(cur.rest_of_line(true), fields);
    if(selection && line > 1)
      break;
    if(fields.empty())
      continue;
    ++lines_with_tokens;
    if(fields.size() > 1 && lines_with_several++ == 0)
      first_several_line = line;
    for(std::string_view f : fields)
      tokens.emplace_back(f, line);
  }
  if(tokens.empty())
    return read_fail(path + ": " + (selection ? "line 1 of the selection file holds no vertex index"
                                              : "the file holds no vertex index"));
  indices.reserve(tokens.size());
  for(const auto& t : tokens) {
    std::uint64_t v = 0;
    switch(parse_unsigned(t.first, v)) {
    case NUMBER_OK:
      if(v <= static_cast<std::uint64_t>((std::numeric_limits<std::size_t>::max)())) {
        indices.push_back(static_cast<std::size_t>(v));
        continue;
      }
      // fall through
    case NUMBER_TOO_LARGE:
      indices.clear();
      return read_fail(path + ": " + at_line(t.second) + "vertex index " + quote(t.first) + " is too large");
    case NEGATIVE_NUMBER:
      indices.clear();
      return read_fail(path + ": " + at_line(t.second) + "negative vertex index " + quote(t.first));
    default:
      indices.clear();
      return read_fail(path + ": " + at_line(t.second) + quote(t.first) + " is not a vertex index"
                       + " (a non-negative integer)");
    }
  }
  // the layout once every token is an index (a garbage file gets its first bad token)
  if(!selection && lines_with_tokens > 1 && lines_with_several > 0) {
    indices.clear();
    return read_fail(path + ": " + at_line(first_several_line)
                     + "ambiguous layout: give all indices on one line, or one index per line");
  }
  return Check_result();
}

// ---------------------------------------------------------------------------
// Reading and checking, as the command-line program does (and the fuzz target)
// ---------------------------------------------------------------------------

/*!
Reads the mesh file `path` (`read_mesh()`) and checks it (`check_mesh()`) for
`required_type`, or, if `std::nullopt`, for the type of its topology; `info` (if not
null) receives the required or detected type. Every message starts with the file name.
A mesh that is neither closed nor a disk gets the first failing check of `check_mesh()`
as its reason (no face, isolated vertex, several components, ..., boundary loops).
*/
template <class TriangleMesh>
Check_result read_and_check_mesh(const std::string& path, std::optional<Orbifold_type> required_type,
                                 TriangleMesh& mesh, Mesh_info* info = nullptr)
{
  Check_result r = read_mesh(path, mesh); // its messages already start with the file name
  if(!r)
    return r;
  r = check_mesh(mesh, required_type, info);
  if(!r)
    r.message = path + ": " + r.message;
  return r;
}

/*!
Reads the landmark file `path` (`read_landmarks()`) and checks the indices against
`mesh` (`check_landmarks()`, which fills `landmarks` on success). Every message starts
with the file name. Precondition: `check_mesh()` succeeded on `mesh` for `type`.
*/
template <class TriangleMesh>
Check_result read_and_check_landmarks(const std::string& path, const TriangleMesh& mesh, Orbifold_type type,
                                      std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>& landmarks)
{
  landmarks.clear();
  std::vector<std::size_t> indices;
  Check_result r = read_landmarks(path, indices); // its messages already start with the file name
  if(!r)
    return r;
  r = check_landmarks(mesh, indices, type, landmarks);
  if(!r)
    r.message = path + ": " + r.message;
  return r;
}

} // namespace internal
} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_IO_H
