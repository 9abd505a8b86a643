// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_TOOLS_IO_LANDMARKS_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_TOOLS_IO_LANDMARKS_H

// The tool's reader of landmark (cone) files: 0-based vertex indices.

#include "common.h"
#include "files.h"

#include <cstdint>
#include <limits>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <CGAL/disable_warnings.h>

/// \file landmarks.h

namespace hot_tools {

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
and a file without index (unless `allow_empty`, for a closed mesh of genus 2 or more, which needs
no cone; a selection file's line 1 must still hold indices). The range and duplicates are checked by `check_landmarks()`.
*/
inline HOT::Status read_landmarks(const std::string& path, std::vector<std::size_t>& indices, bool allow_empty = false)
{
  using namespace io_impl;
  indices.clear();
  std::string data;
  HOT::Status r = read_file_contents(path, data);
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
  if(tokens.empty() && allow_empty && !selection)
    return HOT::Status(); // (no cone: a closed mesh of genus 2 or more)
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
  return HOT::Status();
}

} // namespace hot_tools

#include <CGAL/enable_warnings.h>

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_TOOLS_IO_LANDMARKS_H
