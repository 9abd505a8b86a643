// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_TOOLS_IO_PLY_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_TOOLS_IO_PLY_H

// The PLY reader of the tool (ascii, binary_little_endian, binary_big_endian).

#include "common.h"
#include "polygon_soup.h"

#include <array>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

#include <CGAL/disable_warnings.h>

/// \file ply.h

namespace hot_tools {
namespace io_impl {

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
      { // the fast path: a plain number (no sign; the token not ended by '#', which is no comment here)
        cur_.skip_space(false);
        const char* q = cur_.position();
        std::uint64_t u = 0;
        if(ply_is_integer(t) ? fast_unsigned(q, cur_.end(), u) && u <= std::uint64_t((std::numeric_limits<std::int64_t>::max)())
                             : fast_real(q, cur_.end(), d)) {
          if(q == cur_.end() || *q != '#') {
            cur_.advance_within_line(q);
            if(ply_is_integer(t)) {
              i = static_cast<std::int64_t>(u);
              d = static_cast<double>(i);
            } else {
              if(t == PLY_FLOAT32)
                d = static_cast<double>(static_cast<float>(d)); // the declared precision, as CGAL does
              i = 0;
            }
            return std::string();
          }
        }
      }
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

/// reads a "property" line of the PLY header into `prop`
inline HOT::Status parse_ply_property(const std::vector<std::string_view>& fields, std::size_t line,
                                       Ply_property& prop)
{
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
  return HOT::Status();
}

/// reads the PLY header up to its end_header line: the `format` (0 ascii, 1 little
/// endian, 2 big endian) and the elements with their properties
inline HOT::Status read_ply_header(Cursor& cur, int& format, std::vector<Ply_element>& elements)
{
  std::vector<std::string_view> fields;
  auto trim_cr = [](std::string_view s) {
    while(!s.empty() && (s.back() == '\r' || s.back() == ' ' || s.back() == '\t'))
      s.remove_suffix(1);
    return s;
  };
  if(trim_cr(cur.rest_of_line(false)) != "ply")
    return read_fail("line 1: not a PLY file (the first line is not 'ply')");

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
      const HOT::Status r = parse_ply_property(fields, line, prop);
      if(!r)
        return r;
      elements.back().properties.push_back(prop);
    } else {
      return read_fail(at_line(line) + "unknown PLY header keyword " + quote(kw));
    }
  }
  if(!end_header)
    return read_fail("the PLY header has no end_header line (truncated file?)");
  if(format < 0)
    return read_fail("the PLY header has no format line");
  return HOT::Status();
}

/// What the reader keeps of an element: the points of the (first) "vertex" element, the
/// vertex index list of the "face" elements.
struct Ply_roles
{
  bool is_vertex = false;
  bool is_face = false;
  int xyz[3] = { -1, -1, -1 }; ///< properties x, y, z of a vertex element
  int indices = -1;            ///< the vertex_indices list of a face element
};

/// finds the properties the reader keeps in `el`
inline HOT::Status find_ply_roles(const Ply_element& el, bool vertex_element_seen, Ply_roles& roles)
{
  roles.is_vertex = (el.name == "vertex") && !vertex_element_seen;
  roles.is_face = (el.name == "face");
  for(std::size_t k = 0; k < el.properties.size(); ++k) {
    const Ply_property& prop = el.properties[k];
    if(roles.is_vertex && !prop.is_list) {
      if(prop.name == "x") roles.xyz[0] = int(k);
      if(prop.name == "y") roles.xyz[1] = int(k);
      if(prop.name == "z") roles.xyz[2] = int(k);
    }
    if(roles.is_face && prop.is_list && (prop.name == "vertex_indices" || prop.name == "vertex_index")
       && roles.indices < 0)
      roles.indices = int(k);
  }
  if(roles.is_vertex && (roles.xyz[0] < 0 || roles.xyz[1] < 0 || roles.xyz[2] < 0))
    return read_fail("the PLY vertex element has no x, y and z properties");
  if(roles.is_face && roles.indices < 0)
    return read_fail("the PLY face element has no vertex_indices list");
  if(roles.is_face && !ply_is_integer(el.properties[std::size_t(roles.indices)].value_type))
    return read_fail("the PLY vertex_indices list does not hold integers");
  return HOT::Status();
}

/// reads item `item` of the element `el`, keeping what `roles` says in `soup`
inline HOT::Status read_ply_item(Ply_value_reader& in, int format, const Ply_element& el, const Ply_roles& roles,
                                  std::uint64_t item, Polygon_soup& soup)
{
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
        if(roles.is_vertex && roles.xyz[c] == int(k))
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
    const bool keep = roles.is_face && int(k) == roles.indices;
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
  if(roles.is_vertex) {
    soup.points.push_back(q);
    if(format == 0)
      soup.point_lines.push_back(line);
  }
  if(roles.is_face)
    soup.end_face(format == 0 ? line : 0);
  return HOT::Status();
}

/// PLY (ascii, binary_little_endian, binary_big_endian): the "vertex" element's x, y, z
/// and the "face" element's "vertex_indices" (or "vertex_index") list; other properties
/// and elements are read and ignored.
inline HOT::Status parse_ply(const std::string& data, Polygon_soup& soup)
{
  Cursor cur(data.data(), data.data() + data.size());
  int format = -1;
  std::vector<Ply_element> elements;
  HOT::Status r = read_ply_header(cur, format, elements);
  if(!r)
    return r;

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

    Ply_roles roles;
    if(!(r = find_ply_roles(el, vertex_element_seen, roles)))
      return r;
    if(roles.is_vertex) {
      vertex_element_seen = true;
      soup.points.reserve(el.count);
    }
    for(std::uint64_t item = 0; item < el.count; ++item)
      if(!(r = read_ply_item(in, format, el, roles, item, soup)))
        return r;
  }
  return HOT::Status();
}

} // namespace io_impl
} // namespace hot_tools

#include <CGAL/enable_warnings.h>

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_TOOLS_IO_PLY_H
