// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_PREPARATION_WORK_MESH_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_PREPARATION_WORK_MESH_H

#include <CGAL/Hyperbolic_orbifold_Tutte/genus.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/preparation/handle_loops.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/preparation/soup_preparation.h>

#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/Orthogonal_k_neighbor_search.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/repair_degeneracies.h>
#include <CGAL/Polygon_mesh_processing/shape_predicates.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Polygon_mesh_processing/triangulate_hole.h>
#include <CGAL/property_map.h>
#include <CGAL/Search_traits_3.h>
#include <CGAL/Search_traits_adapter.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <map>
#include <optional>
#include <sstream>
#include <utility>
#include <vector>

// The work mesh of the mesh half of prepare_polygon_soup_for_embedding() (mesh_preparation_steps.h):
// a CGAL::Surface_mesh built from the prepared soup, with the input index of every vertex
// (npos: added); its landmarks, and whether a polygon's corners project onto one point.

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {
namespace internal {
namespace preparation {

typedef CGAL::Surface_mesh<Point> Work_mesh;
typedef Work_mesh::Vertex_index Work_vertex;
typedef Work_mesh::Halfedge_index Work_halfedge;
typedef Work_mesh::Face_index Work_face;

struct Work
{
  Work_mesh mesh;
  Work_mesh::Property_map<Work_vertex, std::size_t> input; // input index, npos for added vertices
  Work_mesh::Property_map<Work_vertex, std::size_t> copy_of; // a non-manifold vertex's copy: the input vertex it copies
  std::vector<char> dropped;                               // per input vertex: on a removed component
  std::vector<std::pair<Work_vertex, Work_vertex> > chords; // split chords' endpoints
  std::vector<Work_vertex> hole_vertex;                     // a boundary vertex per filled hole
  Work_mesh::Property_map<Work_face, bool> filled;           // the faces that fill holes
  // the landmarks (Preparation_options::landmarks), each as the input vertex that represents
  // it in the soup (the first of merged ones), npos if on no face
  std::vector<std::size_t> landmark_input;
  std::vector<std::vector<Work_vertex> > handle_loops; // the loops cut (right side's vertices)
};

// the work mesh's vertex of each landmark (a null vertex where there is none: on no face, on
// a dropped component, or collapsed with a degenerate face)
inline std::vector<Work_vertex> landmark_vertices(const Work& w)
{
  std::vector<Work_vertex> r(w.landmark_input.size());
  if(w.landmark_input.empty())
    return r;
  std::map<std::size_t, std::vector<std::size_t> > which; // input vertex -> landmarks
  for(std::size_t k = 0; k < w.landmark_input.size(); ++k)
    if(w.landmark_input[k] != Mesh_preparation::npos) which[w.landmark_input[k]].push_back(k);
  for(Work_vertex v : vertices(w.mesh)) {
    const auto it = which.find(w.input[v]);
    if(it != which.end())
      for(std::size_t k : it->second) r[k] = v;
  }
  return r;
}

// "landmarks 0, 2 and 5"
inline std::string landmark_list(const std::vector<std::size_t>& ks)
{
  std::ostringstream os;
  os << (ks.size() == 1 ? "landmark " : "landmarks ");
  for(std::size_t i = 0; i < ks.size(); ++i)
    os << (i == 0 ? "" : i + 1 == ks.size() ? " and " : ", ") << ks[i];
  return os.str();
}

inline Status build_work_mesh(const Soup& soup, Work& w, std::size_t number_of_input_vertices)
{
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(soup.points, soup.polygons, w.mesh);
  if(num_vertices(w.mesh) != soup.points.size() || num_faces(w.mesh) != soup.polygons.size())
    return Status::failure(ERROR_NON_MANIFOLD, "the repaired polygon soup could not be built into a mesh");
  w.input = w.mesh.add_property_map<Work_vertex, std::size_t>("v:hot_input", Mesh_preparation::npos).first;
  w.copy_of = w.mesh.add_property_map<Work_vertex, std::size_t>("v:hot_copy_of", Mesh_preparation::npos).first;
  std::size_t i = 0;
  for(Work_vertex v : vertices(w.mesh)) { // polygon_soup_to_polygon_mesh adds the points in order
    if(!soup.copy_of.empty()) w.copy_of[v] = soup.copy_of[i];
    w.input[v] = soup.input[i++];
  }
  w.dropped.assign(number_of_input_vertices, 0);
  w.filled = w.mesh.add_property_map<Work_face, bool>("f:hot_filled", false).first;
  return Status();
}

// Whether two vertices of polygon f project onto one point of the plane of its Newell normal,
// to 1e-9 of the polygon's extent there (a conservative test of what CGAL's
// Projection_traits_3 compares, in double: equal there means within rounding here).
inline bool has_coincident_projections(const Work_mesh& m, Work_face f)
{
  typedef Kernel::Vector_3 Vector;
  const Vector n = CGAL::Polygon_mesh_processing::compute_face_normal(f, m);
  if(n == CGAL::NULL_VECTOR)
    return false; // (triangulate_face() refuses such a polygon itself)
  // an orthonormal basis (b1, b2) of the plane
  const Vector a = std::abs(n.x()) < std::abs(n.y()) ? (std::abs(n.x()) < std::abs(n.z()) ? Vector(1, 0, 0) : Vector(0, 0, 1))
                                                     : (std::abs(n.y()) < std::abs(n.z()) ? Vector(0, 1, 0) : Vector(0, 0, 1));
  Vector b1 = CGAL::cross_product(n, a);
  b1 = b1 / std::sqrt(b1.squared_length());
  Vector b2 = CGAL::cross_product(n, b1);
  b2 = b2 / std::sqrt(b2.squared_length());
  std::vector<std::pair<double, double> > q;
  double lo[2] = { HUGE_VAL, HUGE_VAL }, hi[2] = { -HUGE_VAL, -HUGE_VAL };
  for(Work_vertex v : vertices_around_face(halfedge(f, m), m)) {
    const Vector p = m.point(v) - CGAL::ORIGIN;
    q.emplace_back(p * b1, p * b2);
    lo[0] = (std::min)(lo[0], q.back().first);
    hi[0] = (std::max)(hi[0], q.back().first);
    lo[1] = (std::min)(lo[1], q.back().second);
    hi[1] = (std::max)(hi[1], q.back().second);
  }
  const double tol = 1e-9 * (std::max)(hi[0] - lo[0], hi[1] - lo[1]);
  if(!(tol > 0))
    return true; // every vertex projects onto one point (or a coordinate is not finite)
  // a grid of cells of size tol (at most 1e9 + 1 per side): a coincident pair is in one cell
  // or in neighbouring ones; each cell holds a point at most, or the test has answered
  std::map<std::pair<long long, long long>, std::size_t> cell;
  for(std::size_t i = 0; i < q.size(); ++i) {
    const long long cx = static_cast<long long>(std::floor((q[i].first - lo[0]) / tol));
    const long long cy = static_cast<long long>(std::floor((q[i].second - lo[1]) / tol));
    for(long long dx = -1; dx <= 1; ++dx)
      for(long long dy = -1; dy <= 1; ++dy) {
        const auto it = cell.find(std::make_pair(cx + dx, cy + dy));
        if(it != cell.end() && std::abs(q[it->second].first - q[i].first) <= tol &&
           std::abs(q[it->second].second - q[i].second) <= tol)
          return true;
      }
    cell.emplace(std::make_pair(cx, cy), i);
  }
  return false;
}

} // namespace preparation
} // namespace internal
} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_PREPARATION_WORK_MESH_H
