// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_TOOLS_IO_COMMON_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_TOOLS_IO_COMMON_H

// The common ground of the command-line tool's readers (application/hot_app/io/): the result type
// and its messages, a line-counting cursor over a text buffer, white-space tokenising,
// strict integer and real number parsing, and little / big endian binary values.

#include <CGAL/Hyperbolic_orbifold_Tutte/error_code.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <sstream>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

#include <CGAL/disable_warnings.h>

/// \file common.h

namespace hot_tools {

namespace HOT = CGAL::Hyperbolic_orbifold_Tutte;

// The cone orders the programs accept (files, options, Python): integers p from 2 (cone angle
// 2 pi / p) to `max_cone_order`. The library takes any p >= 2 that makes a hyperbolic orbifold
// (check_cone_orders()); the programs' bound keeps p an int read from text.
constexpr long long max_cone_order = 1000000;
inline bool is_cone_order(long long p) { return p >= 2 && p <= max_cone_order; }

namespace io_impl {

inline HOT::Status fail(HOT::Error_code code, const std::string& message)
{
  return HOT::Status::failure(code, message);
}

inline HOT::Status read_fail(const std::string& message)
{
  return HOT::Status::failure(HOT::ERROR_READ_FAILED, message);
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

  const char* end() const { return end_; }

  /// moves to `p`, a position after the current one on the same line
  void advance_within_line(const char* p) { p_ = p; }

  /// moves to the beginning of the line after the one holding `p` (a position at or after
  /// the current one, on the current line), or to the end
  void skip_line_from(const char* p)
  {
    const void* nl = std::memchr(p, '\n', static_cast<std::size_t>(end_ - p));
    if(nl == nullptr) {
      p_ = end_;
    } else {
      p_ = static_cast<const char*>(nl) + 1;
      ++line_;
    }
  }

private:
  const char* p_;
  const char* end_;
  std::size_t line_;
};

// The fast paths of the line-based readers read the common simple form of a record directly
// from the buffer (no token list) and return false on anything else; the caller then reads
// the record with its general code, which gives the same result, or the error's message.

inline bool is_blank(char c) { return c == ' ' || c == '\t'; }

/// a token ends at white space, a '#' comment or the end of the buffer
inline bool ends_token(const char* p, const char* end) { return p == end || is_space(*p) || *p == '#'; }

/// the real number at `p` (after blanks) as `parse_real()` reads its token, if the token is
/// a plain number (no '+' sign, in the range of double); `p` moves past it
inline bool fast_real(const char*& p, const char* end, double& v)
{
  while(p != end && is_blank(*p))
    ++p;
  const auto r = std::from_chars(p, end, v, std::chars_format::general);
  if(r.ec != std::errc() || r.ptr == p || !ends_token(r.ptr, end))
    return false;
  p = r.ptr;
  return true;
}

/// the non-negative integer at `p` (after blanks) as `parse_unsigned()` reads its token, if
/// the token is digits only (no sign, below 2^64); `p` moves past it
inline bool fast_unsigned(const char*& p, const char* end, std::uint64_t& v)
{
  while(p != end && is_blank(*p))
    ++p;
  const char* q = p;
  std::uint64_t x = 0;
  while(q != end && static_cast<unsigned char>(*q - '0') < 10 && q - p < 19) // (19 digits: no overflow)
    x = 10 * x + static_cast<unsigned char>(*q++ - '0');
  if(q == p || !ends_token(q, end)) // (also 20 digits or more)
    return false;
  v = x;
  p = q;
  return true;
}

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

// little / big endian unsigned 32-bit integers, and their bits as a float

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

} // namespace io_impl

} // namespace hot_tools

#include <CGAL/enable_warnings.h>

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_TOOLS_IO_COMMON_H
