// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_TOOLS_IO_POLYGON_SOUP_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_TOOLS_IO_POLYGON_SOUP_H

// The polygon soup the tool's readers produce: points and polygons in the file's order,
// with the line of each record for the messages.

#include <array>
#include <cstddef>
#include <sstream>
#include <string>
#include <vector>

#include <CGAL/disable_warnings.h>

/// \file polygon_soup.h

namespace hot_tools {

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

} // namespace hot_tools

#include <CGAL/enable_warnings.h>

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_TOOLS_IO_POLYGON_SOUP_H
