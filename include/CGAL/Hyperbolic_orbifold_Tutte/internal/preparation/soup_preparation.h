// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_PREPARATION_SOUP_PREPARATION_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_PREPARATION_SOUP_PREPARATION_H

#include <CGAL/Hyperbolic_orbifold_Tutte/Mesh_preparation.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/error_code.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/preparation/soup_loading.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/number_utils.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>

#include <boost/functional/hash.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <sstream>
#include <unordered_map>
#include <vector>

// The polygon-soup half of prepare_polygon_soup_for_embedding(): the soup is read into
// double points (soup_loading.h), duplicated border points are merged (exact equality), invalid polygons dropped,
// and, when the soup is not already an oriented manifold polygon mesh, CGAL PMP removes
// duplicated polygons and orients the soup (duplicating non-manifold vertices). Every point
// keeps the input index it comes from, so that the prepared mesh stays addressed by the input.

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {
namespace internal {
namespace preparation {

// records, per point added by orient_polygon_soup(), the point it duplicates (the visitor is
// copied by PMP, hence the pointer)
struct Copy_recorder : CGAL::Polygon_mesh_processing::Default_orientation_visitor
{
  std::vector<std::size_t>* copy_of;
  void duplicated_vertex(std::size_t original, std::size_t copy)
  {
    if(copy_of->size() <= copy) copy_of->resize(copy + 1, Mesh_preparation::npos);
    (*copy_of)[copy] = original;
  }
};

struct Coordinates_hash
{
  std::size_t operator()(const std::array<double, 3>& c) const
  {
    std::size_t h = 0;
    for(double x : c) {
      if(x == 0) x = 0; // -0.0 and 0.0 are one position
      std::uint64_t b;
      std::memcpy(&b, &x, sizeof b);
      h = (h ^ (b + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2)));
    }
    return h;
  }
};

// Merges the points on the border of the soup (on an edge of one polygon only) that have equal
// coordinates into the first of them: unwelded seams and triangle soups (STL) get glued.
// Distinct inner vertices at one position are kept apart: they are a valid mesh already.
inline Status merge_border_duplicates(Soup& soup, Mesh_preparation& prep)
{
  std::unordered_map<std::pair<std::size_t, std::size_t>, int, boost::hash<std::pair<std::size_t, std::size_t> > > uses;
  for(const auto& poly : soup.polygons)
    for(std::size_t i = 0; i < poly.size(); ++i) {
      const std::size_t a = poly[i], b = poly[(i + 1) % poly.size()];
      ++uses[std::make_pair((std::min)(a, b), (std::max)(a, b))];
    }
  std::vector<char> border(soup.points.size(), 0);
  for(const auto& e : uses)
    if(e.second == 1) border[e.first.first] = border[e.first.second] = 1;
  std::unordered_map<std::array<double, 3>, std::size_t, Coordinates_hash> first;
  std::vector<std::size_t>& rep = prep.prepared_vertex;
  for(std::size_t i = 0; i < soup.points.size(); ++i) {
    if(!border[i]) continue;
    const Point& p = soup.points[i];
    const std::size_t r = first.emplace(std::array<double, 3>{{p.x(), p.y(), p.z()}}, i).first->second;
    if(r != i) { rep[i] = r; ++prep.merged_duplicate_vertices; }
  }
  if(prep.merged_duplicate_vertices == 0)
    return Status();
  std::vector<std::vector<std::size_t> > kept;
  std::vector<std::size_t> scratch;
  for(auto& poly : soup.polygons) {
    for(std::size_t& v : poly) v = rep[v];
    if(simplify_polygon(poly, scratch)) kept.push_back(std::move(poly));
    else ++prep.invalid_faces_removed; // collapsed by the merge
  }
  soup.polygons.swap(kept);
  if(soup.polygons.empty())
    return Status::failure(ERROR_EMPTY_MESH, "the mesh has no valid face");
  return Status();
}

// Makes the soup an oriented manifold polygon mesh when it is not one: PMP removes
// duplicated polygons (either orientation) and orients the soup, duplicating the points
// where the surface is not a manifold (the copies are added vertices).
inline Status make_oriented_manifold(Soup& soup, Mesh_preparation& prep)
{
  namespace PMP = CGAL::Polygon_mesh_processing;
  if(PMP::is_polygon_soup_a_polygon_mesh(soup.polygons))
    return Status();
  // polygons with two corners at one position (distinct inner vertices, not merged) are
  // degenerate, and merge_duplicate_polygons_in_polygon_soup() requires there are none
  std::vector<std::vector<std::size_t> > kept;
  std::vector<Point> corners;
  for(auto& poly : soup.polygons) {
    corners.clear();
    for(std::size_t v : poly) corners.push_back(soup.points[v]);
    std::sort(corners.begin(), corners.end());
    if(std::adjacent_find(corners.begin(), corners.end()) == corners.end()) kept.push_back(std::move(poly));
    else ++prep.invalid_faces_removed;
  }
  soup.polygons.swap(kept);
  if(soup.polygons.empty())
    return Status::failure(ERROR_EMPTY_MESH, "the mesh has no valid face");
  prep.duplicate_faces_removed = PMP::merge_duplicate_polygons_in_polygon_soup(soup.points, soup.polygons);
  const std::vector<std::vector<std::size_t> > before = soup.polygons;
  const std::size_t points_before = soup.points.size();
  std::vector<std::size_t> duplicated(points_before, Mesh_preparation::npos);
  Copy_recorder recorder;
  recorder.copy_of = &duplicated;
  PMP::orient_polygon_soup(soup.points, soup.polygons, CGAL::parameters::visitor(recorder));
  prep.non_manifold_vertices_split = soup.points.size() - points_before;
  soup.input.resize(soup.points.size(), Mesh_preparation::npos);
  soup.copy_of.assign(soup.points.size(), Mesh_preparation::npos);
  for(std::size_t p = points_before; p < soup.points.size() && p < duplicated.size(); ++p)
    if(duplicated[p] < points_before) soup.copy_of[p] = soup.input[duplicated[p]];
  for(std::size_t f = 0; f < before.size() && f < soup.polygons.size(); ++f) {
    // a reversed polygon has the same vertices (up to the copies) in the other order
    const std::vector<std::size_t>& a = before[f];
    const std::vector<std::size_t>& b = soup.polygons[f];
    bool same = a.size() == b.size();
    for(std::size_t i = 0; same && i < a.size(); ++i)
      same = a[i] == b[i] || (b[i] >= points_before && soup.points[b[i]] == soup.points[a[i]]);
    if(!same)
      ++prep.reoriented_faces;
  }
  if(!PMP::is_polygon_soup_a_polygon_mesh(soup.polygons))
    return Status::failure(ERROR_NON_MANIFOLD, "the polygon soup could not be made an oriented manifold surface");
  return Status();
}

// Drops the points on no polygon; counts the input vertices among them.
inline void drop_unused_points(Soup& soup, Mesh_preparation& prep)
{
  std::vector<std::size_t> new_index(soup.points.size(), Mesh_preparation::npos);
  for(const auto& poly : soup.polygons)
    for(std::size_t v : poly)
      new_index[v] = 0;
  std::size_t k = 0;
  for(std::size_t v = 0; v < soup.points.size(); ++v) {
    if(new_index[v] == Mesh_preparation::npos)
      continue;
    new_index[v] = k;
    soup.points[k] = soup.points[v];
    soup.input[k] = soup.input[v];
    if(!soup.copy_of.empty()) soup.copy_of[k] = soup.copy_of[v];
    ++k;
  }
  soup.points.resize(k);
  soup.input.resize(k);
  if(!soup.copy_of.empty()) soup.copy_of.resize(k);
  for(auto& poly : soup.polygons)
    for(std::size_t& v : poly)
      v = new_index[v];
  for(std::size_t& p : prep.prepared_vertex) {
    p = new_index[p];
    if(p == Mesh_preparation::npos)
      ++prep.isolated_vertices;
  }
}

} // namespace preparation
} // namespace internal
} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_PREPARATION_SOUP_PREPARATION_H
