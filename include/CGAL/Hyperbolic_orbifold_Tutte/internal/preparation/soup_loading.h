// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_PREPARATION_SOUP_LOADING_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_PREPARATION_SOUP_LOADING_H

#include <CGAL/Hyperbolic_orbifold_Tutte/Mesh_preparation.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/error_code.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <sstream>
#include <vector>

// The mesh preparation's first step: the input's points and polygons read into the soup that
// the preparation works on (double points, each keeping the input index it comes from), the
// polygons that are not polygons dropped. (The rest: soup_preparation.h and
// mesh_preparation_steps.h, behind the door of preparation_door.h.)

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {
namespace internal {
namespace preparation {

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef Kernel::Point_3 Point;

struct Soup
{
  std::vector<Point> points;
  std::vector<std::vector<std::size_t> > polygons;
  std::vector<std::size_t> input; // per point: the input vertex it is (first of equal ones), or npos (added)
  std::vector<std::size_t> copy_of; // per point: for a copy of a non-manifold vertex, the input vertex it copies, else npos
};

// the coordinates of a point of any kernel, or of a std::array<double, 3>
template <class P>
std::array<double, 3> coordinates(const P& p)
{
  return {{CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())}};
}
template <class T>
std::array<double, 3> coordinates(const std::array<T, 3>& p)
{
  return {{static_cast<double>(p[0]), static_cast<double>(p[1]), static_cast<double>(p[2])}};
}

// Reads the points and checks they are finite; `prep.prepared_vertex[i]` temporarily holds the
// soup point of input vertex i (itself until merge_border_duplicates()).
template <class PointRange>
Status load_points(const PointRange& points, Soup& soup, Mesh_preparation& prep)
{
  std::size_t i = 0;
  for(const auto& p : points) {
    const std::array<double, 3> c = coordinates(p);
    if(!std::isfinite(c[0]) || !std::isfinite(c[1]) || !std::isfinite(c[2])) {
      std::ostringstream os;
      os << "vertex " << i << " has a coordinate that is not a finite number; no repair can place it";
      return Status::failure(ERROR_NON_FINITE_COORDINATES, os.str());
    }
    soup.points.push_back(Point(c[0], c[1], c[2]));
    soup.input.push_back(i);
    prep.prepared_vertex.push_back(i);
    ++i;
  }
  prep.number_of_input_vertices = i;
  return Status();
}

// true if `poly` (consecutive repeats dropped in place) is a polygon: 3 or more corners, none repeated
inline bool simplify_polygon(std::vector<std::size_t>& poly, std::vector<std::size_t>& scratch)
{
  poly.erase(std::unique(poly.begin(), poly.end()), poly.end());
  while(poly.size() > 1 && poly.front() == poly.back())
    poly.pop_back();
  scratch = poly;
  std::sort(scratch.begin(), scratch.end());
  return poly.size() >= 3 && std::adjacent_find(scratch.begin(), scratch.end()) == scratch.end();
}

// Reads the polygons; polygons with fewer than 3 corners or with a repeated corner are removed.
template <class PolygonRange>
Status load_polygons(const PolygonRange& polygons, Soup& soup, Mesh_preparation& prep)
{
  const std::size_t n = prep.number_of_input_vertices;
  std::size_t j = 0;
  std::vector<std::size_t> poly, scratch;
  for(const auto& polygon : polygons) {
    poly.clear();
    for(const auto id : polygon) {
      const std::size_t v = static_cast<std::size_t>(id);
      if(v >= n) {
        std::ostringstream os;
        os << "face " << j << " uses vertex " << v << ", but there are only " << n << " vertices";
        return Status::failure(ERROR_WRONG_PARAMETER, os.str());
      }
      poly.push_back(v);
    }
    if(simplify_polygon(poly, scratch)) soup.polygons.push_back(poly);
    else ++prep.invalid_faces_removed;
    ++j;
  }
  prep.number_of_input_faces = j;
  if(soup.polygons.empty())
    return Status::failure(ERROR_EMPTY_MESH, j == 0 ? "the mesh has no face" : "the mesh has no valid face");
  return Status();
}

} // namespace preparation
} // namespace internal
} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_PREPARATION_SOUP_LOADING_H
