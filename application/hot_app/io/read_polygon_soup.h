// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_TOOLS_IO_READ_POLYGON_SOUP_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_TOOLS_IO_READ_POLYGON_SOUP_H

// A mesh file read as a polygon soup, in the file's order, the parser chosen by the
// file extension.
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

#include "common.h"
#include "files.h"
#include "gocad.h"
#include "obj.h"
#include "off.h"
#include "ply.h"
#include "polygon_soup.h"
#include "stl.h"
#include "timings.h"

#include <exception>
#include <string>

#include <CGAL/disable_warnings.h>

/// \file read_polygon_soup.h

namespace hot_tools {

/*!
Reads the polygon soup of a mesh file, in the file's order. The format is chosen by the
file extension (any case): .off (ASCII and Geomview binary), .obj, .ply (ASCII and
binary), .stl (ASCII and binary), and .ts (GOCAD TSurf).
Messages start with the file name. Only parse errors are reported here
(ERROR_READ_FAILED); see `validate_polygon_soup()` for the rest.
*/
inline HOT::Status read_polygon_soup_file(const std::string& path, Polygon_soup& soup)
{
  using namespace io_impl;
  soup.clear();
  if(path.empty())
    return read_fail("no file name given");
  const std::string ext = file_extension(path);
  if(ext != "off" && ext != "obj" && ext != "ply" && ext != "stl" && ext != "ts")
    return read_fail("'" + path + "': unsupported file extension '" + ext + "' (supported: off, obj, ply, stl, ts)");

  HOT::Status r;
  std::string data;
  if(!(r = read_file_contents(path, data)))
    return r;
  timings().phase("read the file");
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
  timings().phase("parse");
  return r;
}

} // namespace hot_tools

#include <CGAL/enable_warnings.h>

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_TOOLS_IO_READ_POLYGON_SOUP_H
