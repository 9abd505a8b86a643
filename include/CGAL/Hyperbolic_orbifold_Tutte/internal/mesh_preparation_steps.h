// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_MESH_PREPARATION_STEPS_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_MESH_PREPARATION_STEPS_H

#include <CGAL/Hyperbolic_orbifold_Tutte/internal/handle_loops.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/preparation_door.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/soup_preparation.h>

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

struct Boundary_loop
{
  Work_halfedge h;
  std::size_t vertices = 0;
  double length = 0;
};

inline std::vector<Boundary_loop> boundary_loops(const Work_mesh& m)
{
  std::vector<Work_halfedge> cycles;
  CGAL::Polygon_mesh_processing::extract_boundary_cycles(m, std::back_inserter(cycles));
  std::vector<Boundary_loop> loops;
  for(Work_halfedge h : cycles) {
    Boundary_loop l;
    l.h = h;
    for(Work_halfedge c : halfedges_around_face(h, m)) {
      ++l.vertices;
      l.length += std::sqrt(CGAL::squared_distance(m.point(source(c, m)), m.point(target(c, m))));
    }
    loops.push_back(l);
  }
  std::stable_sort(loops.begin(), loops.end(), [](const Boundary_loop& a, const Boundary_loop& b) { return a.length > b.length; });
  return loops;
}

// "2 loops of 120 and 96 vertices, lengths 3.1 and 0.84 (1.2 and 0.33 diagonals)"
inline std::string describe_loops(const std::vector<Boundary_loop>& loops, double diagonal)
{
  std::ostringstream os;
  os.precision(3);
  os << loops.size() << (loops.size() == 1 ? " loop of " : " loops of ");
  for(std::size_t i = 0; i < loops.size() && i < 6; ++i) os << (i ? ", " : "") << loops[i].vertices;
  os << (loops.size() > 6 ? ", ..." : "") << " vertices, lengths";
  for(std::size_t i = 0; i < loops.size() && i < 6; ++i) os << (i ? ", " : " ") << loops[i].length / diagonal;
  os << (loops.size() > 6 ? ", ..." : "") << " times the bounding box diagonal";
  return os.str();
}

// Fills one hole with PMP's triangulate_refine_and_fair_hole().
inline Status fill_hole(Work& w, const Boundary_loop& loop, Mesh_preparation& prep)
{
  std::vector<Work_face> new_faces;
  std::vector<Work_vertex> new_vertices;
  const Work_vertex where = target(loop.h, w.mesh);
  const auto r = CGAL::Polygon_mesh_processing::triangulate_refine_and_fair_hole(
    w.mesh, loop.h, std::back_inserter(new_faces), std::back_inserter(new_vertices));
  if(new_faces.empty()) {
    std::ostringstream os;
    os << "a hole with " << loop.vertices << " boundary vertices could not be filled";
    return Status::failure(ERROR_WRONG_TOPOLOGY, os.str());
  }
  for(Work_vertex v : new_vertices)
    w.input[v] = Mesh_preparation::npos; // a recycled slot keeps its old value otherwise
  for(Work_face f : new_faces)
    w.filled[f] = true;
  Filled_hole hole;
  hole.boundary_vertices = loop.vertices;
  hole.boundary_length = loop.length;
  hole.faces_added = new_faces.size();
  hole.vertices_added = new_vertices.size();
  hole.faired = std::get<0>(r);
  prep.filled_holes.push_back(hole);
  w.hole_vertex.push_back(where);
  return Status();
}

// Fills the holes and decides the type from the loops that remain. Without landmarks: the
// loops no longer than `max_hole` diagonals (with a disk required, all but the longest). With
// landmarks (the orbifold they ask for): a loop holding every landmark is the boundary of a
// disk (unless a sphere is required) and the other loops are holes; landmarks not all on one
// loop ask for a sphere: every loop is a hole, whatever its length (unless a maximum length
// is given, `max_hole_given`); a disk required keeps the longest loop as without landmarks.
inline Status fill_holes(Work& w, const Preparation_options& o, Mesh_preparation& prep)
{
  const double max_hole_length = o.max_hole;
  const std::optional<Orbifold_type> required = o.required;
  const std::vector<Boundary_loop> loops = boundary_loops(w.mesh);
  const CGAL::Bbox_3 b = CGAL::Polygon_mesh_processing::bbox(w.mesh);
  const double diagonal = std::sqrt(CGAL::square(b.xmax() - b.xmin()) + CGAL::square(b.ymax() - b.ymin()) +
                                    CGAL::square(b.zmax() - b.zmin()));
  // with landmarks: the loop that holds them all (npos: none)
  std::vector<Work_vertex> lv = landmark_vertices(w);
  lv.erase(std::remove(lv.begin(), lv.end(), Work_vertex()), lv.end());
  const bool by_landmarks = !lv.empty();
  std::size_t landmark_loop = Mesh_preparation::npos;
  if(by_landmarks && !(required && *required == Sphere_type)) {
    for(std::size_t i = 0; i < loops.size() && landmark_loop == Mesh_preparation::npos; ++i) {
      std::vector<Work_vertex> on;
      for(Work_halfedge c : halfedges_around_face(loops[i].h, w.mesh)) on.push_back(target(c, w.mesh));
      std::sort(on.begin(), on.end());
      bool all = true;
      for(Work_vertex v : lv) all = all && std::binary_search(on.begin(), on.end(), v);
      if(all) landmark_loop = i;
    }
  }
  prep.landmarks_decided = by_landmarks;
  const bool any_length = by_landmarks && !o.max_hole_given;
  const double limit = any_length ? HUGE_VAL : max_hole_length * diagonal;
  std::vector<Boundary_loop> kept;
  std::vector<Boundary_loop> holes;
  for(std::size_t i = 0; i < loops.size(); ++i) {
    const bool keep_as_disk_border = landmark_loop != Mesh_preparation::npos
                                       ? i == landmark_loop
                                       : required && *required == Disk_type && i == 0;
    if(!keep_as_disk_border && loops[i].length <= limit) holes.push_back(loops[i]);
    else kept.push_back(loops[i]);
  }
  // a sphere is asked for: required, or (nothing required) by landmarks not all on one loop
  const bool sphere = required ? *required == Sphere_type : by_landmarks && landmark_loop == Mesh_preparation::npos;
  if(kept.size() > 1 || (sphere && !kept.empty())) {
    std::ostringstream os;
    os.precision(3);
    os << "after filling the holes no longer than " << max_hole_length << " times the bounding box diagonal, the mesh would keep "
       << describe_loops(kept, diagonal) << "; "
       << (sphere ? (required ? "a sphere-type orbifold needs none"
                              : "landmarks inside the surface ask for a sphere-type orbifold, which needs none")
                  : "an orbifold needs at most one")
       << " (raise maximum_hole_length, --max-hole, to fill longer ones)";
    return Status::failure(ERROR_WRONG_TOPOLOGY, os.str());
  }
  if(required && *required == Disk_type && kept.empty())
    return Status::failure(ERROR_WRONG_TOPOLOGY, "the disk-type orbifold needs a boundary loop, but the mesh is closed");
  for(const Boundary_loop& h : holes) {
    const Status r = fill_hole(w, h, prep);
    if(!r) return r;
  }
  prep.type = kept.empty() ? Sphere_type : Disk_type;
  return Status();
}

// the genus of the work mesh (its boundary loops counted)
inline long long work_genus(const Work_mesh& m)
{
  std::vector<Work_halfedge> cycles;
  CGAL::Polygon_mesh_processing::extract_boundary_cycles(m, std::back_inserter(cycles));
  const long long chi = static_cast<long long>(num_vertices(m)) - static_cast<long long>(num_edges(m)) + static_cast<long long>(num_faces(m));
  return (2 - chi - static_cast<long long>(cycles.size())) / 2;
}

// Cuts the (closed, garbage-free) work mesh along `cycle`: the corners on its left side move
// to copies of the loop's vertices (added vertices), the mesh is rebuilt with its properties,
// and the two sides of the cut are closed (fill_hole()).
// A disk's boundary capped (`cap`: the cap's vertex, the last one, joined to every boundary
// vertex by a fan of faces) is left out of the rebuilt mesh: the boundary is open again, and
// the two sides of the cut are the loops that do not hold an old boundary vertex.
inline Status cut_along_loop(Work& w, const std::vector<Work_vertex>& cycle, Mesh_preparation& prep,
                             Work_vertex cap = Work_vertex())
{
  bool ok = false;
  const std::vector<char> moved = handles::left_corners(w.mesh, cycle, ok);
  if(!ok || w.mesh.has_garbage() || (cap != Work_vertex() && std::size_t(cap.idx()) + 1 != num_vertices(w.mesh)))
    return Status::failure(ERROR_WRONG_TOPOLOGY, "a handle's loop could not be cut");
  std::vector<char> rim(num_vertices(w.mesh), 0); // the capped boundary's vertices
  if(cap != Work_vertex())
    for(Work_vertex v : vertices_around_target(halfedge(cap, w.mesh), w.mesh)) rim[v.idx()] = 1;
  const std::size_t n = num_vertices(w.mesh);
  std::vector<Point> points;
  std::vector<std::size_t> input, copy_of;
  for(Work_vertex v : vertices(w.mesh)) { // (idx order: no garbage)
    if(v == cap) continue;
    points.push_back(w.mesh.point(v));
    input.push_back(w.input[v]);
    copy_of.push_back(w.copy_of[v]);
  }
  std::vector<std::size_t> copy(n, Mesh_preparation::npos);
  for(Work_vertex v : cycle) {
    copy[v.idx()] = points.size();
    points.push_back(w.mesh.point(v));
    input.push_back(Mesh_preparation::npos);
    copy_of.push_back(Mesh_preparation::npos);
  }
  std::vector<std::array<std::size_t, 3> > triangles;
  std::vector<char> filled;
  std::size_t j = 0;
  for(Work_face f : faces(w.mesh)) {
    std::array<std::size_t, 3> t;
    std::size_t c = 0;
    bool capping = false;
    for(Work_halfedge h : halfedges_around_face(halfedge(f, w.mesh), w.mesh)) {
      const std::size_t v = target(h, w.mesh).idx();
      capping = capping || target(h, w.mesh) == cap;
      t[c] = moved[3 * j + c] ? copy[v] : v;
      ++c;
    }
    ++j;
    if(capping) continue;
    triangles.push_back(t);
    filled.push_back(w.filled[f] ? 1 : 0);
  }
  Work_mesh cut;
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, triangles, cut);
  if(num_vertices(cut) != points.size() || num_faces(cut) != triangles.size() || !CGAL::is_valid_polygon_mesh(cut))
    return Status::failure(ERROR_WRONG_TOPOLOGY, "the cut along a handle's loop is not a valid surface");
  w.mesh = std::move(cut);
  w.input = w.mesh.add_property_map<Work_vertex, std::size_t>("v:hot_input", Mesh_preparation::npos).first;
  w.copy_of = w.mesh.add_property_map<Work_vertex, std::size_t>("v:hot_copy_of", Mesh_preparation::npos).first;
  w.filled = w.mesh.add_property_map<Work_face, bool>("f:hot_filled", false).first;
  std::size_t i = 0;
  for(Work_vertex v : vertices(w.mesh)) { // (in the points' order; the loops' vertices keep their indices)
    w.input[v] = input[i];
    w.copy_of[v] = copy_of[i++];
  }
  j = 0;
  for(Work_face f : faces(w.mesh)) w.filled[f] = filled[j++] != 0;
  std::vector<Boundary_loop> sides;
  for(const Boundary_loop& l : boundary_loops(w.mesh)) {
    bool old_rim = false;
    for(Work_halfedge h : halfedges_around_face(l.h, w.mesh))
      old_rim = old_rim || (std::size_t(target(h, w.mesh).idx()) < rim.size() && rim[target(h, w.mesh).idx()]);
    if(!old_rim) sides.push_back(l);
  }
  if(sides.size() != 2)
    return Status::failure(ERROR_WRONG_TOPOLOGY, "the cut along a handle's loop did not give two sides");
  for(const Boundary_loop& l : sides) {
    const Status r = fill_hole(w, l, prep);
    if(!r) return r;
  }
  return Status();
}

// With a target genus (target_genus) below the mesh's: cuts the shortest non-separating loop
// found (handle_loops.h) and closes both sides, until the genus is the target's; a loop
// longer than `max_handle` diagonals is a refusal that says which handle. A disk's target is
// 0 unless one is given (a disk-type orbifold has genus 0: its handles are noise to cut).
inline Status cut_handles(Work& w, const Preparation_options& o, Mesh_preparation& prep)
{
  const long long target_g = o.target_genus >= 0 ? o.target_genus : prep.type == Disk_type ? 0 : -1;
  if(target_g < 0)
    return Status();
  long long g = work_genus(w.mesh);
  if(g <= target_g)
    return Status();
  // what asked for the target, as the messages say it
  const std::string asked = std::string(" and genus ") + std::to_string(target_g) +
                            (o.target_genus >= 0 ? " is asked for (target_genus, --target-genus)" : " is a disk-type orbifold's");
  const long long g0 = g;
  const CGAL::Bbox_3 b = CGAL::Polygon_mesh_processing::bbox(w.mesh);
  const double diagonal = std::sqrt(CGAL::square(b.xmax() - b.xmin()) + CGAL::square(b.ymax() - b.ymin()) +
                                    CGAL::square(b.zmax() - b.zmin()));
  for(long long k = 1; g > target_g; ++k) {
    // a disk's boundary is capped by a fan around a new last vertex while the loop is sought
    // and cut (same genus, closed), its vertices avoided: the loop stays inside the disk
    Work_vertex cap;
    std::vector<char> avoided;
    if(prep.type == Disk_type) {
      std::vector<Boundary_loop> loops = boundary_loops(w.mesh);
      if(loops.size() != 1 || w.mesh.has_garbage())
        return Status::failure(ERROR_WRONG_TOPOLOGY, "a handle of a mesh with a boundary could not be cut");
      std::vector<Work_halfedge> border;
      for(Work_halfedge h : halfedges_around_face(loops[0].h, w.mesh)) border.push_back(h);
      // a copy: add_vertex may reallocate the point array a reference would point into
      const Point at = w.mesh.point(target(border[0], w.mesh));
      cap = w.mesh.add_vertex(at);
      w.input[cap] = w.copy_of[cap] = Mesh_preparation::npos;
      for(Work_halfedge h : border)
        if(w.mesh.add_face(source(h, w.mesh), target(h, w.mesh), cap) == Work_face())
          return Status::failure(ERROR_WRONG_TOPOLOGY, "a handle of a mesh with a boundary could not be cut (capping its boundary failed)");
      avoided.assign(num_vertices(w.mesh), 0);
      for(Work_halfedge h : border) avoided[target(h, w.mesh).idx()] = 1;
      avoided[cap.idx()] = 1;
    }
    const handles::Loop_finder<Work_mesh> finder(w.mesh, avoided);
    handles::Loop<Work_mesh> loop = finder.shortest();
    bool touches = false;
    for(Work_vertex v : loop.cycle) touches = touches || (!avoided.empty() && avoided[v.idx()]);
    if(touches) {
      std::ostringstream os;
      os << "the mesh has genus " << g0 << " and a boundary loop" << asked << ", but the shortest loop found around handle " << k << " of " << g0
         << " touches the boundary: it is not cut";
      return Status::failure(ERROR_WRONG_TOPOLOGY, os.str());
    }
    if(loop.cycle.empty())
      return Status::failure(ERROR_WRONG_TOPOLOGY, "no non-separating loop was found on a mesh of genus " + std::to_string(g));
    if(!(loop.length <= o.max_handle * diagonal)) {
      std::ostringstream os;
      os.precision(3);
      os << "the mesh has genus " << g0 << asked << ", but handle " << k
         << " of " << g0 << " is long: its shortest loop found is " << loop.length / diagonal << " times the bounding box diagonal ("
         << loop.cycle.size() << " vertices";
      for(Work_vertex v : loop.cycle)
        if(w.input[v] != Mesh_preparation::npos) { os << ", through vertex " << w.input[v]; break; }
      os << "), over the bound " << o.max_handle << " (maximum_handle_length, --max-handle): a real handle rather than topological noise?";
      return Status::failure(ERROR_WRONG_TOPOLOGY, os.str());
    }
    const Status r = cut_along_loop(w, loop.cycle, prep, cap);
    if(!r) return r;
    const long long after = work_genus(w.mesh);
    if(after != g - 1)
      return Status::failure(ERROR_WRONG_TOPOLOGY, "cutting a handle's loop did not lower the genus");
    g = after;
    Cut_handle c;
    c.length = loop.length;
    prep.cut_handles.push_back(c);
    w.handle_loops.push_back(loop.cycle);
  }
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

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_MESH_PREPARATION_STEPS_H
