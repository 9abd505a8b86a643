// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_PREPARATION_MESH_PREPARATION_STEPS_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_PREPARATION_MESH_PREPARATION_STEPS_H

#include <CGAL/Hyperbolic_orbifold_Tutte/genus.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/preparation/handle_loops.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/preparation/mesh_preparation_topology.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/preparation/preparation_door.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/preparation/soup_preparation.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/preparation/work_mesh.h>

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

// The mesh half of prepare_polygon_soup_for_embedding(), on a CGAL::Surface_mesh built from
// the prepared soup: triangulate polygons, keep one component, remove degenerate faces, fill
// holes, split the boundary chords of a disk, then write the result in the addressing order
// (input vertices first, in input order, then the added ones). Each step is CGAL PMP or an
// Euler operation; a vertex property keeps the input index of every vertex (npos: added).

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {
namespace internal {
namespace preparation {

inline Status triangulate_polygons(Work& w, Mesh_preparation& prep)
{
  for(Work_face f : faces(w.mesh)) {
    const std::size_t d = degree(f, w.mesh);
    if(d > 3) {
      ++prep.polygons_triangulated;
      prep.triangles_from_polygons += d - 2;
    }
  }
  if(prep.polygons_triangulated == 0)
    return Status();
  // CGAL's triangulate_faces(), face by face in the same order; but a polygon two of whose
  // vertices project onto one point of its (Newell) plane breaks the precondition of the
  // constrained Delaunay triangulation it uses, which only assertions check (a crash in a
  // release build, found by replaying the fuzz corpus): such a polygon is filled as a hole
  // (PMP::triangulate_hole_polyline, in 3D) instead
  std::vector<Work_face> polygons;
  for(Work_face f : faces(w.mesh))
    if(degree(f, w.mesh) > 3)
      polygons.push_back(f);
  for(Work_face f : polygons) {
    const bool cdt = !has_coincident_projections(w.mesh, f);
    if(!CGAL::Polygon_mesh_processing::triangulate_face(f, w.mesh, CGAL::parameters::use_delaunay_triangulation(cdt)))
      return Status::failure(ERROR_NON_TRIANGULAR_MESH, "a polygon of the mesh could not be triangulated");
  }
  // a diagonal of a polygon may already be an edge of the mesh (a non-planar polygon folded
  // over its neighbours): the result is then not a valid surface, which later steps need
  if(!CGAL::is_valid_polygon_mesh(w.mesh) || !CGAL::is_triangle_mesh(w.mesh))
    return Status::failure(ERROR_NON_MANIFOLD, "the triangulation of a polygon of the mesh does not give a valid surface");
  return Status();
}

// Keeps one connected component: the one holding the landmarks (if any are given and on a
// face), else the largest (in faces; the first of equal ones). The other components are
// dropped when they hold no landmark and have fewer faces than `debris_fraction` of the mesh
// (debris), or all of them if `keep_largest` is asked for; otherwise it fails with the
// components' sizes. Landmarks on several components always fail.
inline Status keep_one_component(Work& w, const Preparation_options& o, Mesh_preparation& prep)
{
  namespace PMP = CGAL::Polygon_mesh_processing;
  auto fcc = w.mesh.add_property_map<Work_face, std::size_t>("f:hot_component", 0).first;
  const std::size_t n = PMP::connected_components(w.mesh, fcc);
  if(n <= 1) {
    w.mesh.remove_property_map(fcc);
    return Status();
  }
  auto component_of = [&](Work_vertex v) {
    const Work_halfedge h = halfedge(v, w.mesh);
    return fcc[is_border(h, w.mesh) ? face(opposite(h, w.mesh), w.mesh) : face(h, w.mesh)];
  };
  std::vector<std::size_t> size(n, 0);
  for(Work_face f : faces(w.mesh)) ++size[fcc[f]];
  const std::size_t total = num_faces(w.mesh);
  std::size_t kept_component = static_cast<std::size_t>(std::max_element(size.begin(), size.end()) - size.begin());
  // the components of the landmarks
  std::map<std::size_t, std::vector<std::size_t> > landmarks_on; // component -> landmarks
  const std::vector<Work_vertex> lv = landmark_vertices(w);
  for(std::size_t k = 0; k < lv.size(); ++k)
    if(lv[k] != Work_vertex()) landmarks_on[component_of(lv[k])].push_back(k);
  if(landmarks_on.size() > 1) {
    std::ostringstream os;
    os << "the landmarks lie on " << landmarks_on.size() << " different connected components of the mesh (";
    const char* sep = "";
    for(const auto& c : landmarks_on) {
      os << sep << landmark_list(c.second) << " on one of " << size[c.first] << " faces";
      sep = ", ";
    }
    os << "): a map needs them on one surface (mend the mesh, or the landmark file)";
    w.mesh.remove_property_map(fcc);
    return Status::failure(ERROR_SEVERAL_COMPONENTS, os.str());
  }
  if(!landmarks_on.empty())
    kept_component = landmarks_on.begin()->first;
  // the others: debris, or components that only keep_largest drops
  std::vector<std::size_t> large;
  std::size_t debris = 0;
  for(std::size_t c = 0; c < n; ++c) {
    if(c == kept_component) continue;
    if(static_cast<double>(size[c]) < o.debris_fraction * static_cast<double>(total)) ++debris;
    else large.push_back(size[c]);
  }
  if(!large.empty() && !o.keep_largest) {
    std::sort(large.rbegin(), large.rend());
    std::ostringstream os;
    os << "the mesh has " << n << " connected components: besides the one " << (landmarks_on.empty() ? "kept (the largest, " : "of the landmarks (")
       << size[kept_component] << " faces), " << large.size() << (large.size() == 1 ? " is" : " are") << " not small debris (sizes in faces:";
    for(std::size_t i = 0; i < large.size() && i < 5; ++i) os << " " << large[i];
    os << (large.size() > 5 ? " ..." : "") << "; debris has fewer than " << o.debris_fraction * 100
       << "% of the faces); keeping " << (landmarks_on.empty() ? "the largest" : "the landmarks'") << " one only must be asked for"
       << " (keep_largest_component, --largest-component)";
    w.mesh.remove_property_map(fcc);
    return Status::failure(ERROR_SEVERAL_COMPONENTS, os.str());
  }
  auto in_kept = [&](Work_vertex v) { return component_of(v) == kept_component; };
  std::vector<char> kept(w.dropped.size(), 0);
  for(Work_vertex v : vertices(w.mesh))
    if(w.input[v] != Mesh_preparation::npos)
      (in_kept(v) ? kept : w.dropped)[w.input[v]] = 1;
  // a split non-manifold vertex whose original is on a dropped component but a copy on the
  // kept one: the (first) copy becomes that input vertex, which stays addressed
  for(Work_vertex v : vertices(w.mesh)) {
    const std::size_t c = w.copy_of[v];
    if(c != Mesh_preparation::npos && !kept[c] && in_kept(v)) {
      w.input[v] = c;
      kept[c] = 1;
      w.dropped[c] = 0;
    }
  }
  prep.components_removed = n - 1;
  prep.debris_components_removed = debris;
  prep.component_faces_removed = total - size[kept_component];
  PMP::keep_connected_components(w.mesh, std::vector<std::size_t>(1, kept_component), fcc);
  w.mesh.remove_property_map(fcc);
  w.mesh.collect_garbage();
  return Status();
}

// Removes the faces that are degenerate (exactly collinear or coincident corners) with
// PMP's remove_degenerate_faces() (edge collapses and flips).
inline Status remove_degenerate_faces(Work& w, Mesh_preparation& prep)
{
  namespace PMP = CGAL::Polygon_mesh_processing;
  auto count_degenerate = [&w]() {
    std::size_t n = 0;
    for(Work_face f : faces(w.mesh)) n += PMP::is_degenerate_triangle_face(f, w.mesh) ? 1 : 0;
    return n;
  };
  const std::size_t before = count_degenerate();
  if(before == 0)
    return Status();
  const bool ok = PMP::remove_degenerate_faces(w.mesh);
  w.mesh.collect_garbage();
  // the degenerate faces gone (a flip replaces a cap without changing the number of faces)
  const std::size_t after = count_degenerate();
  prep.degenerate_faces_removed = before > after ? before - after : 0;
  if(num_faces(w.mesh) == 0)
    return Status::failure(ERROR_DEGENERATE_FACE, "every face of the mesh is degenerate (zero area)");
  if(!ok)
    return Status::failure(ERROR_DEGENERATE_FACE, "some degenerate faces (zero area) could not be removed");
  return Status();
}

// Splits every inner edge joining two boundary vertices at its midpoint, connecting the
// midpoint to the two opposite corners (Euler operations), so that no triangle of a disk
// has its three corners on the boundary through such an edge.
inline void split_boundary_chords(Work& w, Mesh_preparation&)
{
  std::vector<Work_halfedge> chords;
  for(auto e : edges(w.mesh)) {
    const Work_halfedge h = halfedge(e, w.mesh);
    if(is_border_edge(h, w.mesh)) continue;
    if(CGAL::is_border(source(h, w.mesh), w.mesh) && CGAL::is_border(target(h, w.mesh), w.mesh))
      chords.push_back(h);
  }
  for(Work_halfedge h : chords) {
    const Work_vertex a = source(h, w.mesh), b = target(h, w.mesh);
    const Point m = CGAL::midpoint(w.mesh.point(a), w.mesh.point(b));
    const Work_halfedge hn = CGAL::Euler::split_edge(h, w.mesh); // a -> m, then h: m -> b
    const Work_vertex mv = target(hn, w.mesh);
    w.mesh.point(mv) = m;
    w.input[mv] = Mesh_preparation::npos;
    const bool f1 = w.filled[face(h, w.mesh)], f2 = w.filled[face(opposite(h, w.mesh), w.mesh)];
    const Work_halfedge s1 = CGAL::Euler::split_face(hn, next(h, w.mesh), w.mesh); // (both sides: parts of one face)
    w.filled[face(s1, w.mesh)] = f1;
    w.filled[face(opposite(s1, w.mesh), w.mesh)] = f1;
    const Work_halfedge oh = opposite(h, w.mesh);   // b -> m
    const Work_halfedge s2 = CGAL::Euler::split_face(oh, next(opposite(hn, w.mesh), w.mesh), w.mesh);
    w.filled[face(s2, w.mesh)] = f2;
    w.filled[face(opposite(s2, w.mesh), w.mesh)] = f2;
    w.chords.emplace_back(a, b);
  }
}


// the index of the point of `points` nearest to each of `queries` (a k-d tree)
inline std::vector<std::size_t> nearest_points(const std::vector<Point>& points, const std::vector<Point>& queries)
{
  typedef CGAL::Search_traits_3<Kernel> Base_traits;
  typedef CGAL::Pointer_property_map<Point>::const_type Point_map;
  typedef CGAL::Search_traits_adapter<std::size_t, Point_map, Base_traits> Traits;
  typedef CGAL::Orthogonal_k_neighbor_search<Traits> Search;
  typedef typename Search::Tree Tree;
  typedef typename Search::Distance Distance;
  if(points.empty())
    return std::vector<std::size_t>(queries.size(), Mesh_preparation::npos);
  const Point_map pmap = CGAL::make_property_map(points);
  std::vector<std::size_t> ids(points.size());
  for(std::size_t i = 0; i < ids.size(); ++i) ids[i] = i;
  Tree tree(ids.begin(), ids.end(), typename Tree::Splitter(), Traits(pmap));
  std::vector<std::size_t> result;
  for(const Point& q : queries) {
    Search search(tree, q, 1, 0, true, Distance(pmap));
    result.push_back(search.begin()->first);
  }
  return result;
}

// The prepared mesh as a soup in the addressing order (input vertices in input order, then
// the added ones), and the addressing of `prep`, whose `prepared_vertex` holds on entry the
// soup point of each input vertex (npos: on no face).
inline void prepared_soup(const Work& w, const Soup& soup, Mesh_preparation& prep, std::vector<Point>& points,
                          std::vector<std::array<std::size_t, 3> >& triangles)
{
  const std::size_t n = prep.number_of_input_vertices;
  std::vector<std::pair<std::size_t, Work_vertex> > order;
  for(Work_vertex v : vertices(w.mesh))
    order.emplace_back(w.input[v] != Mesh_preparation::npos ? w.input[v] : n + std::size_t(v.idx()), v);
  std::sort(order.begin(), order.end());
  std::vector<std::size_t> prepared(num_vertices(w.mesh) + w.mesh.number_of_removed_vertices(), Mesh_preparation::npos);
  std::vector<std::size_t> prepared_of_input(n, Mesh_preparation::npos);
  points.clear();
  triangles.clear();
  prep.output_index.clear();
  std::size_t added = 0;
  for(const auto& o : order) {
    prepared[o.second.idx()] = points.size();
    if(w.input[o.second] != Mesh_preparation::npos) {
      prepared_of_input[w.input[o.second]] = points.size();
      prep.output_index.push_back(w.input[o.second]);
    } else {
      prep.output_index.push_back(n + added++);
    }
    points.push_back(w.mesh.point(o.second));
  }
  prep.filled_faces.clear();
  for(Work_face f : faces(w.mesh)) {
    if(w.filled[f]) prep.filled_faces.push_back(triangles.size());
    std::array<std::size_t, 3> t;
    std::size_t k = 0;
    for(Work_vertex v : vertices_around_face(halfedge(f, w.mesh), w.mesh)) t[k++] = prepared[v.idx()];
    triangles.push_back(t);
  }
  // the input's vertices: themselves, merged into the first at their position, or (collapsed
  // by the removal of degenerate faces) the nearest remaining vertex
  std::vector<std::size_t> collapsed;
  std::vector<Point> queries;
  for(std::size_t i = 0; i < n; ++i) {
    const std::size_t s = prep.prepared_vertex[i];
    prep.prepared_vertex[i] = Mesh_preparation::npos;
    const std::size_t r = s == Mesh_preparation::npos ? s : soup.input[s]; // the first input vertex there
    if(r == Mesh_preparation::npos || w.dropped[r]) continue;
    if(prepared_of_input[r] != Mesh_preparation::npos) {
      prep.prepared_vertex[i] = prepared_of_input[r];
    } else {
      collapsed.push_back(i);
      queries.push_back(soup.points[s]);
    }
  }
  if(!collapsed.empty()) {
    const std::vector<std::size_t> near = nearest_points(points, queries);
    for(std::size_t j = 0; j < collapsed.size(); ++j) prep.prepared_vertex[collapsed[j]] = near[j];
  }
  for(std::size_t i = 0; i < prep.filled_holes.size(); ++i)
    prep.filled_holes[i].vertex = prep.output_index[prepared[w.hole_vertex[i].idx()]];
  for(std::size_t i = 0; i < prep.cut_handles.size(); ++i)
    for(Work_vertex v : w.handle_loops[i])
      prep.cut_handles[i].vertices.push_back(prep.output_index[prepared[v.idx()]]);
  for(const auto& c : w.chords)
    prep.split_chords.emplace_back(prep.output_index[prepared[c.first.idx()]], prep.output_index[prepared[c.second.idx()]]);
}

// The steps after the soup is loaded, up to the prepared soup (prepared_soup()): merge,
// orient, build the work mesh, triangulate, keep one component, remove degenerate faces,
// fill holes, split the chords of a disk. (The door declared in preparation_door.h.)
template <int>
Status prepare_loaded_soup(Soup& soup, const Preparation_options& o, Mesh_preparation& prep, std::vector<Point>& points,
                           std::vector<std::array<std::size_t, 3> >& triangles)
{
  Status r = merge_border_duplicates(soup, prep);
  if(r) r = make_oriented_manifold(soup, prep);
  if(!r) return r;
  drop_unused_points(soup, prep);
  Work w;
  r = build_work_mesh(soup, w, prep.number_of_input_vertices);
  for(std::size_t i : o.landmarks) { // (checked in range by the caller)
    const std::size_t p = prep.prepared_vertex[i];
    w.landmark_input.push_back(p == Mesh_preparation::npos ? p : soup.input[p]);
  }
  if(r) r = triangulate_polygons(w, prep);
  if(r) r = keep_one_component(w, o, prep);
  if(r) r = remove_degenerate_faces(w, prep);
  if(r) r = fill_holes(w, o, prep);
  if(r) r = cut_handles(w, o, prep);
  if(!r) return r;
  if(prep.type == Disk_type && o.split_chords)
    split_boundary_chords(w, prep);
  prepared_soup(w, soup, prep, points, triangles);
  return r;
}

} // namespace preparation
} // namespace internal
} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_PREPARATION_MESH_PREPARATION_STEPS_H
