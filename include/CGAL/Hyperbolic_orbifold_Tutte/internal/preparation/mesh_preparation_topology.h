// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

// A part of mesh_preparation_steps.h, which includes it (and which preparation_door.h
// includes, without extern instances): that header first, whichever is included first.
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/preparation/mesh_preparation_steps.h>

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_PREPARATION_MESH_PREPARATION_TOPOLOGY_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_PREPARATION_MESH_PREPARATION_TOPOLOGY_H

#include <CGAL/Hyperbolic_orbifold_Tutte/internal/preparation/work_mesh.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/genus.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/preparation/handle_loops.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/preparation/preparation_door.h>
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

// The topology steps of the mesh preparation (mesh_preparation_steps.h) on the work mesh:
// the boundary loops, holes filled (PMP's triangulate_refine_and_fair_hole()) and the type
// decided from the loops that remain; handles cut along their shortest loops down to a
// target genus.

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {
namespace internal {
namespace preparation {

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
  return genus_of_surface(euler_characteristic(m), cycles.size());
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

} // namespace preparation
} // namespace internal
} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_PREPARATION_MESH_PREPARATION_TOPOLOGY_H
