// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_INPUT_MESH_CHECKS_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_INPUT_MESH_CHECKS_H

// The steps of `check_mesh()` (check_input.h), in the order it runs them (the last, the
// topology, is in topology_check.h). Each returns an
// OK `Status` when the mesh passes it, or the failure with its one-line message. Vertex and
// face numbers in the messages are positions in `vertices(tm)` / `faces(tm)` (`Dense_index`).
// Every pointer is checked before it is followed, and every walk is bounded.

#include <CGAL/Hyperbolic_orbifold_Tutte/error_code.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/Orbifold_type.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/genus.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/core/dense_index.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/core/mesh_graph.h> // border_loops
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/input/topology_check.h>

#include <CGAL/boost/graph/helpers.h>     // is_border, is_valid_polygon_mesh
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/properties.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/number_utils.h>

#include <boost/graph/graph_traits.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <functional>
#include <iterator>
#include <limits>
#include <optional>
#include <sstream>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {

namespace internal {

inline const char* orbifold_type_name(Orbifold_type type)
{
  return type == Sphere_type ? "sphere" : "disk";
}

namespace check_mesh_impl {

// The message of the structure checks below when they find no specific reason.
inline std::string invalid_structure_message()
{
  return "invalid halfedge structure (CGAL::is_valid_polygon_mesh() fails): the mesh is not a valid 2-manifold";
}

// 1. pointer integrity: next, opposite, target of every halfedge exist
template <class TriangleMesh, class VertexIndex, class FaceIndex, class HalfedgeIndex>
Status check_halfedge_links(const TriangleMesh& tm, const VertexIndex& vindex,
                            const FaceIndex& findex, const HalfedgeIndex& hindex)
{
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  typedef typename GT::face_descriptor face_descriptor;
  const std::size_t npos = hindex.npos;
  for(halfedge_descriptor h : halfedges(tm)) {
    const halfedge_descriptor n = next(h, tm), o = opposite(h, tm);
    if(n == GT::null_halfedge() || o == GT::null_halfedge()
       || hindex(n) == npos || hindex(o) == npos
       || opposite(o, tm) != h
       || target(h, tm) == GT::null_vertex() || vindex(target(h, tm)) == npos)
      return Status::failure(ERROR_NON_MANIFOLD, invalid_structure_message() + " (broken halfedge links)");
    const face_descriptor f = face(h, tm);
    if(f != GT::null_face() && findex(f) == npos)
      return Status::failure(ERROR_NON_MANIFOLD, invalid_structure_message() + " (broken face links)");
  }
  return Status();
}

// 2. faces: bounded walk, a face using a vertex twice
template <class TriangleMesh, class VertexIndex, class FaceIndex, class HalfedgeIndex>
Status check_face_cycles(const TriangleMesh& tm, const VertexIndex& vindex,
                         const FaceIndex& findex, const HalfedgeIndex& hindex)
{
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  typedef typename GT::face_descriptor face_descriptor;
  const std::string generic = invalid_structure_message();
  const std::size_t nh = hindex.size();
  std::vector<std::size_t> fv;
  for(face_descriptor f : faces(tm)) {
    const halfedge_descriptor h0 = halfedge(f, tm);
    if(h0 == GT::null_halfedge() || hindex(h0) == hindex.npos)
      return Status::failure(ERROR_NON_MANIFOLD, generic + " (broken face links)");
    fv.clear();
    halfedge_descriptor h = h0;
    std::size_t steps = 0;
    do {
      if(face(h, tm) != f)
        return Status::failure(ERROR_NON_MANIFOLD, generic + " (broken face links)");
      fv.push_back(vindex(target(h, tm)));
      h = next(h, tm);
    } while(h != h0 && ++steps <= nh);
    if(h != h0)
      return Status::failure(ERROR_NON_MANIFOLD, generic + " (a face cycle does not close)");
    std::sort(fv.begin(), fv.end());
    auto dup = std::adjacent_find(fv.begin(), fv.end());
    if(dup != fv.end()) {
      std::ostringstream os;
      os << "face " << findex(f) << " uses vertex " << *dup << " more than once";
      return Status::failure(ERROR_DEGENERATE_FACE, os.str());
    }
  }
  return Status();
}

// 3. an edge with the same face on both sides
template <class TriangleMesh, class VertexIndex, class FaceIndex>
Status check_two_faces_per_edge(const TriangleMesh& tm, const VertexIndex& vindex, const FaceIndex& findex)
{
  typedef boost::graph_traits<TriangleMesh> GT;
  for(typename GT::halfedge_descriptor h : halfedges(tm)) {
    const typename GT::face_descriptor f = face(h, tm);
    if(f != GT::null_face() && f == face(opposite(h, tm), tm)) {
      std::ostringstream os;
      os << "edge (" << vindex(source(h, tm)) << ", " << vindex(target(h, tm))
         << ") has face " << findex(f) << " on both sides: the mesh is not a valid 2-manifold";
      return Status::failure(ERROR_NON_MANIFOLD, os.str());
    }
  }
  return Status();
}

// 4. non-manifold vertex: the halfedges around halfedge(v) do not reach all the
//    halfedges that point to v (its incident faces form several fans)
template <class TriangleMesh, class VertexIndex, class HalfedgeIndex>
Status check_vertex_fans(const TriangleMesh& tm, const VertexIndex& vindex, const HalfedgeIndex& hindex)
{
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  const std::string generic = invalid_structure_message();
  std::vector<std::size_t> incoming(vindex.size(), 0);
  for(halfedge_descriptor h : halfedges(tm))
    ++incoming[vindex(target(h, tm))];
  for(typename GT::vertex_descriptor v : vertices(tm)) {
    const std::size_t vi = vindex(v);
    const halfedge_descriptor h0 = halfedge(v, tm);
    if(h0 == GT::null_halfedge() || hindex(h0) == hindex.npos || target(h0, tm) != v)
      return Status::failure(ERROR_NON_MANIFOLD, generic + " (broken vertex links)");
    std::size_t k = 0;
    halfedge_descriptor h = h0;
    do {
      if(target(h, tm) != v)
        return Status::failure(ERROR_NON_MANIFOLD, generic + " (broken vertex links)");
      ++k;
      h = opposite(next(h, tm), tm);
    } while(h != h0 && k <= incoming[vi]);
    if(h != h0)
      return Status::failure(ERROR_NON_MANIFOLD, generic + " (broken vertex links)");
    if(k != incoming[vi]) {
      std::ostringstream os;
      os << "vertex " << vi << " is non-manifold: its incident faces form more than one fan"
         << " (" << k << " of its " << incoming[vi] << " incident edges are reachable around it)";
      return Status::failure(ERROR_NON_MANIFOLD, os.str());
    }
  }
  return Status();
}

// Called when CGAL::is_valid_polygon_mesh() fails: finds a more specific reason with the
// four checks above, in that order.
template <class TriangleMesh, class VertexIndex, class FaceIndex>
Status diagnose_invalid_structure(const TriangleMesh& tm,
                                  const VertexIndex& vindex,
                                  const FaceIndex& findex)
{
  typedef typename boost::graph_traits<TriangleMesh>::halfedge_descriptor halfedge_descriptor;
  const Dense_index<halfedge_descriptor> hindex(halfedges(tm));
  Status r = check_halfedge_links(tm, vindex, findex, hindex);
  if(r)
    r = check_face_cycles(tm, vindex, findex, hindex);
  if(r)
    r = check_two_faces_per_edge(tm, vindex, findex);
  if(r)
    r = check_vertex_fans(tm, vindex, hindex);
  if(r)
    r = Status::failure(ERROR_NON_MANIFOLD, invalid_structure_message());
  return r;
}

template <class FT>
bool is_finite_number(const FT& x)
{
  return std::isfinite(CGAL::to_double(x));
}

// The face's size is in the range of double-precision geometry: its squared edge lengths
// and the squared norm of its cross product (computed in double, as the edge weights
// are) are finite, and the squared area of a well-shaped face of its size (the squared
// longest edge, squared) does not underflow. On failure, `why` says which.
template <class Point>
bool face_in_double_range(const Point& p0, const Point& p1, const Point& p2, std::string& why)
{
  const Point* p[3] = { &p0, &p1, &p2 };
  double d[3][3]; // d[i]: p[i+1] - p[i]
  double longest2 = 0;
  for(int i = 0; i < 3; ++i) {
    const Point& a = *p[i];
    const Point& b = *p[(i + 1) % 3];
    d[i][0] = CGAL::to_double(b.x()) - CGAL::to_double(a.x());
    d[i][1] = CGAL::to_double(b.y()) - CGAL::to_double(a.y());
    d[i][2] = CGAL::to_double(b.z()) - CGAL::to_double(a.z());
    const double e2 = d[i][0] * d[i][0] + d[i][1] * d[i][1] + d[i][2] * d[i][2];
    if(!std::isfinite(e2)) {
      why = "its squared edge lengths overflow (coordinates too large: rescale the mesh)";
      return false;
    }
    longest2 = (std::max)(longest2, e2);
  }
  const double cx = d[0][1] * d[2][2] - d[0][2] * d[2][1];
  const double cy = d[0][2] * d[2][0] - d[0][0] * d[2][2];
  const double cz = d[0][0] * d[2][1] - d[0][1] * d[2][0];
  const double c2 = cx * cx + cy * cy + cz * cz;
  const bool too_large = !std::isfinite(c2) || !std::isfinite(longest2 * longest2);
  const bool too_small = longest2 * longest2 < (std::numeric_limits<double>::min)();
  if(!too_large && !too_small)
    return true;
  // for the message: the longest edge's length, computed without overflow or underflow
  double longest = 0;
  for(int i = 0; i < 3; ++i) {
    const double m = (std::max)((std::max)(std::abs(d[i][0]), std::abs(d[i][1])), std::abs(d[i][2]));
    if(m > 0)
      longest = (std::max)(longest, m * std::sqrt((d[i][0] / m) * (d[i][0] / m) + (d[i][1] / m) * (d[i][1] / m)
                                                  + (d[i][2] / m) * (d[i][2] / m)));
  }
  std::ostringstream os;
  os.precision(3);
  if(too_large) {
    os << "its longest edge has length " << longest
       << ", so its squared area overflows (coordinates too large: rescale the mesh)";
    why = os.str();
    return false;
  }
  os << "its longest edge has length " << longest
     << ", so its squared area underflows (coordinates too small: rescale the mesh)";
  why = os.str();
  return false;
}


// ---------------------------------------------------------------------------
// The steps of check_mesh()
// ---------------------------------------------------------------------------

// 1. empty
inline Status check_not_empty(std::size_t number_of_vertices, std::size_t number_of_faces)
{
  if(number_of_faces != 0)
    return Status();
  std::ostringstream os;
  os << "the mesh has no face";
  if(number_of_vertices > 0)
    os << " (it has " << plural(number_of_vertices, "vertex", "vertices") << " but no face)";
  return Status::failure(ERROR_EMPTY_MESH, os.str());
}

// 2. isolated vertices (CGAL::is_valid_polygon_mesh() rejects them without saying why)
template <class TriangleMesh, class VertexIndex>
Status check_no_isolated_vertex(const TriangleMesh& tm, const VertexIndex& vindex)
{
  typedef boost::graph_traits<TriangleMesh> GT;
  for(typename GT::vertex_descriptor v : vertices(tm)) {
    if(halfedge(v, tm) == GT::null_halfedge()) {
      std::ostringstream os;
      os << "vertex " << vindex(v) << " is isolated (it has no incident face); "
         << "remove unreferenced vertices from the input";
      return Status::failure(ERROR_NON_MANIFOLD, os.str());
    }
  }
  return Status();
}

// 3. halfedge structure, and the non-manifold vertices that is_valid_polygon_mesh()
//    accepts: several open fans around a vertex, chained by their border halfedges
//    (Euler::add_face() builds such "bowties"); such a vertex is the target of more than
//    one border halfedge
template <class TriangleMesh, class VertexIndex, class FaceIndex>
Status check_manifold(const TriangleMesh& tm, const VertexIndex& vindex, const FaceIndex& findex)
{
  if(!CGAL::is_valid_polygon_mesh(tm))
    return diagnose_invalid_structure(tm, vindex, findex);
  std::vector<unsigned char> border_in(vindex.size(), 0);
  for(auto h : halfedges(tm)) {
    if(!is_border(h, tm))
      continue;
    const std::size_t vi = vindex(target(h, tm));
    if(++border_in[vi] == 2) {
      std::ostringstream os;
      os << "vertex " << vi << " is non-manifold: its incident faces form more than one fan"
         << " (it lies on several boundary gaps)";
      return Status::failure(ERROR_NON_MANIFOLD, os.str());
    }
  }
  return Status();
}

// 4. triangles
template <class TriangleMesh, class FaceIndex>
Status check_triangles(const TriangleMesh& tm, const FaceIndex& findex)
{
  for(auto f : faces(tm)) {
    std::size_t d = 0;
    for(auto h : halfedges_around_face(halfedge(f, tm), tm)) {
      (void)h;
      ++d;
    }
    if(d != 3) {
      std::ostringstream os;
      os << "face " << findex(f) << " has " << d << " vertices; only triangle meshes are supported";
      return Status::failure(ERROR_NON_TRIANGULAR_MESH, os.str());
    }
  }
  return Status();
}

// 5. finite coordinates
template <class TriangleMesh, class VertexPointMap, class VertexIndex>
Status check_finite_coordinates(const TriangleMesh& tm, VertexPointMap vpm, const VertexIndex& vindex)
{
  typedef typename boost::property_traits<VertexPointMap>::value_type Point;
  for(auto v : vertices(tm)) {
    const Point& p = get(vpm, v);
    if(!is_finite_number(p.x()) || !is_finite_number(p.y()) || !is_finite_number(p.z())) {
      std::ostringstream os;
      os.precision(17);
      os << "vertex " << vindex(v) << " has a non-finite coordinate ("
         << CGAL::to_double(p.x()) << " " << CGAL::to_double(p.y()) << " " << CGAL::to_double(p.z()) << ")";
      return Status::failure(ERROR_NON_FINITE_COORDINATES, os.str());
    }
  }
  return Status();
}

// 6. degenerate faces (exact predicates of the kernel): say whether two vertices coincide
//    or the three are collinear
template <class TriangleMesh, class VertexPointMap, class VertexIndex, class FaceIndex>
Status check_nondegenerate_faces(const TriangleMesh& tm, VertexPointMap vpm,
                                 const VertexIndex& vindex, const FaceIndex& findex)
{
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  typedef typename boost::property_traits<VertexPointMap>::value_type Point;
  typedef typename CGAL::Kernel_traits<Point>::Kernel Kernel;
  const Kernel kernel;
  typename Kernel::Collinear_3 collinear = kernel.collinear_3_object();
  for(auto f : faces(tm)) {
    const auto h = halfedge(f, tm);
    const vertex_descriptor a = source(h, tm), b = target(h, tm), c = target(next(h, tm), tm);
    if(!collinear(get(vpm, a), get(vpm, b), get(vpm, c)))
      continue;
    const vertex_descriptor vs[3] = { a, b, c };
    for(int i = 0; i < 3; ++i) {
      const vertex_descriptor u = vs[i], w = vs[(i + 1) % 3];
      if(u == w) { // excluded by is_valid_polygon_mesh(), kept for safety
        std::ostringstream os;
        os << "face " << findex(f) << " uses vertex " << vindex(u) << " twice";
        return Status::failure(ERROR_DEGENERATE_FACE, os.str());
      }
      if(get(vpm, u) == get(vpm, w)) {
        std::ostringstream os;
        os << "face " << findex(f) << " is degenerate: its vertices " << vindex(u) << " and "
           << vindex(w) << " have the same coordinates";
        return Status::failure(ERROR_DEGENERATE_FACE, os.str());
      }
    }
    std::ostringstream os;
    os << "face " << findex(f) << " has zero area: its vertices " << vindex(a) << ", "
       << vindex(b) << ", " << vindex(c) << " are collinear";
    return Status::failure(ERROR_DEGENERATE_FACE, os.str());
  }
  return Status();
}

// 6b. faces out of the range of double-precision geometry (too large or too small)
template <class TriangleMesh, class VertexPointMap, class FaceIndex>
Status check_faces_in_double_range(const TriangleMesh& tm, VertexPointMap vpm, const FaceIndex& findex)
{
  std::string why;
  for(auto f : faces(tm)) {
    const auto h = halfedge(f, tm);
    if(face_in_double_range(get(vpm, source(h, tm)), get(vpm, target(h, tm)),
                            get(vpm, target(next(h, tm), tm)), why))
      continue;
    std::ostringstream os;
    os << "face " << findex(f) << " is out of the range of double-precision geometry: " << why;
    return Status::failure(ERROR_NON_FINITE_COORDINATES, os.str());
  }
  return Status();
}

// 7. connected components (faces connected through edges; a vertex-only contact
//    would be a non-manifold vertex, rejected above): union-find over the edges
template <class TriangleMesh, class FaceIndex>
Status check_one_component(const TriangleMesh& tm, const FaceIndex& findex)
{
  typedef boost::graph_traits<TriangleMesh> GT;
  const std::size_t nf = findex.size();
  std::vector<std::size_t> parent(nf);
  for(std::size_t i = 0; i < nf; ++i)
    parent[i] = i;
  auto find = [&parent](std::size_t x) {
    while(parent[x] != x) {
      parent[x] = parent[parent[x]];
      x = parent[x];
    }
    return x;
  };
  for(auto h : halfedges(tm)) {
    const typename GT::face_descriptor f = face(h, tm), g = face(opposite(h, tm), tm);
    if(f == GT::null_face() || g == GT::null_face())
      continue;
    const std::size_t x = find(findex(f)), y = find(findex(g));
    if(x != y)
      parent[(std::max)(x, y)] = (std::min)(x, y);
  }
  std::vector<std::size_t> sizes; // faces per component, in order of smallest face
  std::vector<std::size_t> component_of_root(nf, static_cast<std::size_t>(-1));
  std::size_t other = 0; // smallest face not in the component of face 0
  for(std::size_t i = 0; i < nf; ++i) {
    const std::size_t r = find(i);
    if(component_of_root[r] == static_cast<std::size_t>(-1)) {
      component_of_root[r] = sizes.size();
      sizes.push_back(0);
      if(sizes.size() == 2)
        other = i;
    }
    ++sizes[component_of_root[r]];
  }
  if(sizes.size() <= 1)
    return Status();
  std::ostringstream os;
  os << "the mesh has " << sizes.size() << " connected components (faces 0 and " << other
     << " are not connected; component sizes in faces:";
  for(std::size_t i = 0; i < sizes.size() && i < 5; ++i)
    os << " " << sizes[i];
  if(sizes.size() > 5)
    os << " ...";
  os << ")";
  return Status::failure(ERROR_SEVERAL_COMPONENTS, os.str());
}

// check_mesh() (check_input.h): every check in its order, the first failure returned; `mi`
// (a `Mesh_info`) is reset, then filled as far as the checks got
template <class TriangleMesh, class VertexPointMap>
Status run_all(const TriangleMesh& tm, VertexPointMap vpm, std::optional<Orbifold_type> required_type, Mesh_info& mi)
{
  typedef boost::graph_traits<TriangleMesh> GT;
  mi = Mesh_info();

  const Dense_index<typename GT::vertex_descriptor> vindex(vertices(tm));
  const Dense_index<typename GT::face_descriptor> findex(faces(tm));
  mi.number_of_vertices = vindex.size();
  mi.number_of_faces = findex.size();
  mi.number_of_edges = static_cast<std::size_t>(std::distance(edges(tm).begin(), edges(tm).end()));

  Status r = check_not_empty(mi.number_of_vertices, mi.number_of_faces);
  if(r) r = check_no_isolated_vertex(tm, vindex);
  if(r) r = check_manifold(tm, vindex, findex);
  if(r) r = check_triangles(tm, findex);
  if(r) r = check_finite_coordinates(tm, vpm, vindex);
  if(r) r = check_nondegenerate_faces(tm, vpm, vindex, findex);
  if(r) r = check_faces_in_double_range(tm, vpm, findex);
  if(r) r = check_one_component(tm, findex);
  if(r) r = check_topology(tm, vpm, vindex, required_type, mi);
  return r;
}

} // namespace check_mesh_impl

// detect_orbifold_type() (check_input.h): closed gives Sphere_type, one boundary loop
// Disk_type; false (type unchanged) without a face or with several boundary loops
template <class TriangleMesh>
bool orbifold_type_of_boundary(const TriangleMesh& tm, Orbifold_type& type)
{
  if(faces(tm).begin() == faces(tm).end())
    return false;
  const std::size_t loops = border_loops(tm).size();
  if(loops == 0) { type = Sphere_type; return true; }
  if(loops == 1) { type = Disk_type; return true; }
  return false;
}

} // namespace internal
} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_INPUT_MESH_CHECKS_H
