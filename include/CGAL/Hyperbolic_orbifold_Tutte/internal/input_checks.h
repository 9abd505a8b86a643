// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_INPUT_CHECKS_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_INPUT_CHECKS_H

// Checks run on a triangle mesh and its landmarks before embedding the mesh into a
// hyperbolic orbifold. Bad input always gets a specific `Error_code` and a one-line
// message naming the offending element (vertex and face numbers are 0-based positions
// in the iteration order of `vertices(tm)` / `faces(tm)`; for a mesh read with
// `internal::read_mesh()` they are the file's vertex and face numbers). No check
// asserts, throws, or loops forever, and each runs in (expected) linear time.
//
// Everything works on any model of `FaceListGraph` / `HalfedgeListGraph` through BGL
// free functions and property maps only; tested with `CGAL::Surface_mesh` and
// `CGAL::Polyhedron_3` (also a Surface_mesh with removed elements, i.e. garbage).
// Descriptors that have an `idx()` member (Surface_mesh) are indexed with vectors; the
// others (Polyhedron_3 handles) with an open-addressing hash table on `std::hash`,
// which is slower by a constant factor. Measured with g++ -O2 on a closed genus-0 mesh
// of 1M vertices: check_mesh() takes about 0.3 s on a Surface_mesh (half of it in
// CGAL::is_valid_polygon_mesh()) and about 1 s on a Polyhedron_3.
//
// `check_mesh()` runs, in this order, and stops at the first failure:
//   1. ERROR_EMPTY_MESH            the mesh has no face
//   2. ERROR_NON_MANIFOLD          a vertex has no incident face (isolated vertex)
//   3. ERROR_NON_MANIFOLD          the halfedge structure is invalid
//                                  (`CGAL::is_valid_polygon_mesh()` fails), including a
//                                  non-manifold vertex (incident faces forming several
//                                  fans) and an edge with the same face on both sides;
//      ERROR_DEGENERATE_FACE       ... unless the reason is a face using a vertex twice;
//      ERROR_NON_MANIFOLD          a vertex whose incident faces form several open fans
//                                  (a "bowtie", which is_valid_polygon_mesh() accepts)
//   4. ERROR_NON_TRIANGULAR_MESH   a face is not a triangle
//   5. ERROR_NON_FINITE_COORDINATES a coordinate is NaN or infinite
//   6. ERROR_DEGENERATE_FACE       a face has two vertices at the same position or
//                                  three collinear vertices (exact `collinear` test of
//                                  the point type's kernel: exact with Epick)
//      ERROR_NON_FINITE_COORDINATES a face is out of the range of double-precision
//                                  geometry: its squared edge lengths or squared area
//                                  (the 4th power of its size, as the edge weights
//                                  compute it) overflow, or its size is so small that
//                                  the squared area of a well-shaped face of that size
//                                  underflows (edges longer than about 1e77 or all
//                                  shorter than about 1e-77: rescale the mesh); the
//                                  solver would otherwise fail with a misleading reason
//   7. ERROR_SEVERAL_COMPONENTS    the faces form more than one connected component
//   8. ERROR_WRONG_TOPOLOGY        sphere type: not closed, or V-E+F != 2 (genus > 0);
//                                  disk type: not exactly one boundary loop, or
//                                  V-E+F != 1; automatic type: neither closed nor one
//                                  boundary loop, or wrong genus for the detected type;
//                                  when there are boundary loops too many, the message
//                                  names two border vertices with equal coordinates if
//                                  there are some (unwelded duplicates, e.g. from STL).
//
// Distinct vertices with equal coordinates are accepted as long as the mesh is a valid
// manifold and no face gets degenerate (e.g. a surface cut open along a seam).

#include <CGAL/Hyperbolic_orbifold_Tutte/error_code.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/Orbifold_tile.h> // Orbifold_type
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/dense_index.h>

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
#include <cstdint>
#include <functional>
#include <iterator>
#include <limits>
#include <optional>
#include <sstream>
#include <string>
#include <type_traits>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {
namespace internal {

/// The outcome of a check (the package's `Status`).
typedef Status Check_result;

inline Check_result make_check_result(Error_code code, const std::string& message)
{
  Check_result r;
  r.code = code;
  r.message = message;
  return r;
}

/// What `check_mesh()` learnt about the mesh; fields are filled as far as the checks got.
struct Mesh_info
{
  std::size_t number_of_vertices = 0;
  std::size_t number_of_edges = 0;
  std::size_t number_of_faces = 0;
  std::size_t number_of_border_loops = 0;
  long long euler_characteristic = 0; ///< V - E + F
  long long genus = -1;               ///< (2 - border loops - (V-E+F)) / 2, or -1 if not computed
  bool type_known = false;            ///< true once the topology check passed
  Orbifold_type type = Sphere_type;   ///< the required or detected orbifold type
};

// ---------------------------------------------------------------------------
// Border loops and orbifold type
// ---------------------------------------------------------------------------

/// The number of boundary loops (cycles of border halfedges) of `tm`.
/// Precondition: `tm` is a valid polygon mesh (each halfedge is visited once at most,
/// so an invalid mesh gives a wrong count but never a hang).
template <class TriangleMesh>
std::size_t count_border_loops(const TriangleMesh& tm)
{
  typedef typename boost::graph_traits<TriangleMesh>::halfedge_descriptor halfedge_descriptor;
  std::unordered_set<halfedge_descriptor> border;
  for(halfedge_descriptor h : halfedges(tm))
    if(is_border(h, tm))
      border.insert(h);
  std::size_t loops = 0;
  while(!border.empty()) {
    halfedge_descriptor h = *border.begin();
    ++loops;
    // erase the loop of h; stops at a halfedge already erased or not border
    while(border.erase(h) == 1)
      h = next(h, tm);
  }
  return loops;
}

/// Decides the orbifold type from the boundary: a closed mesh gives `Sphere_type`, a
/// mesh with exactly one boundary loop gives `Disk_type`; returns `false` (and leaves
/// `type` unchanged) for a mesh without face or with two or more boundary loops.
/// The genus is not looked at: `check_mesh()` does that.
template <class TriangleMesh>
bool detect_orbifold_type(const TriangleMesh& tm, Orbifold_type& type)
{
  if(faces(tm).begin() == faces(tm).end())
    return false;
  const std::size_t loops = count_border_loops(tm);
  if(loops == 0) { type = Sphere_type; return true; }
  if(loops == 1) { type = Disk_type; return true; }
  return false;
}

inline const char* orbifold_type_name(Orbifold_type type)
{
  return type == Sphere_type ? "sphere" : "disk";
}

// ---------------------------------------------------------------------------
// check_mesh
// ---------------------------------------------------------------------------

namespace check_mesh_impl {

inline std::string plural(std::size_t n, const char* singular, const char* plural_form)
{
  std::ostringstream os;
  os << n << " " << (n == 1 ? singular : plural_form);
  return os.str();
}

// Called when CGAL::is_valid_polygon_mesh() fails: finds a more specific reason.
// Every pointer is checked before it is followed, and every walk is bounded.
template <class TriangleMesh, class VertexIndex, class FaceIndex>
Check_result diagnose_invalid_structure(const TriangleMesh& tm,
                                        const VertexIndex& vindex,
                                        const FaceIndex& findex)
{
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  typedef typename GT::vertex_descriptor vertex_descriptor;
  typedef typename GT::face_descriptor face_descriptor;

  const std::string generic =
    "invalid halfedge structure (CGAL::is_valid_polygon_mesh() fails): the mesh is not a valid 2-manifold";

  Dense_index<halfedge_descriptor> hindex(halfedges(tm));
  const std::size_t nh = hindex.size();
  const std::size_t npos = hindex.npos;

  // 1. pointer integrity: next, opposite, target of every halfedge exist
  for(halfedge_descriptor h : halfedges(tm)) {
    const halfedge_descriptor n = next(h, tm), o = opposite(h, tm);
    if(n == GT::null_halfedge() || o == GT::null_halfedge()
       || hindex(n) == npos || hindex(o) == npos
       || opposite(o, tm) != h
       || target(h, tm) == GT::null_vertex() || vindex(target(h, tm)) == npos)
      return make_check_result(ERROR_NON_MANIFOLD, generic + " (broken halfedge links)");
    const face_descriptor f = face(h, tm);
    if(f != GT::null_face() && findex(f) == npos)
      return make_check_result(ERROR_NON_MANIFOLD, generic + " (broken face links)");
  }

  // 2. faces: bounded walk, a face using a vertex twice
  std::vector<std::size_t> fv;
  for(face_descriptor f : faces(tm)) {
    const halfedge_descriptor h0 = halfedge(f, tm);
    if(h0 == GT::null_halfedge() || hindex(h0) == npos)
      return make_check_result(ERROR_NON_MANIFOLD, generic + " (broken face links)");
    fv.clear();
    halfedge_descriptor h = h0;
    std::size_t steps = 0;
    do {
      if(face(h, tm) != f)
        return make_check_result(ERROR_NON_MANIFOLD, generic + " (broken face links)");
      fv.push_back(vindex(target(h, tm)));
      h = next(h, tm);
    } while(h != h0 && ++steps <= nh);
    if(h != h0)
      return make_check_result(ERROR_NON_MANIFOLD, generic + " (a face cycle does not close)");
    std::sort(fv.begin(), fv.end());
    auto dup = std::adjacent_find(fv.begin(), fv.end());
    if(dup != fv.end()) {
      std::ostringstream os;
      os << "face " << findex(f) << " uses vertex " << *dup << " more than once";
      return make_check_result(ERROR_DEGENERATE_FACE, os.str());
    }
  }

  // 3. an edge with the same face on both sides
  for(halfedge_descriptor h : halfedges(tm)) {
    const face_descriptor f = face(h, tm);
    if(f != GT::null_face() && f == face(opposite(h, tm), tm)) {
      std::ostringstream os;
      os << "edge (" << vindex(source(h, tm)) << ", " << vindex(target(h, tm))
         << ") has face " << findex(f) << " on both sides: the mesh is not a valid 2-manifold";
      return make_check_result(ERROR_NON_MANIFOLD, os.str());
    }
  }

  // 4. non-manifold vertex: the halfedges around halfedge(v) do not reach all the
  //    halfedges that point to v (its incident faces form several fans)
  std::vector<std::size_t> incoming(vindex.size(), 0);
  for(halfedge_descriptor h : halfedges(tm))
    ++incoming[vindex(target(h, tm))];
  for(vertex_descriptor v : vertices(tm)) {
    const std::size_t vi = vindex(v);
    const halfedge_descriptor h0 = halfedge(v, tm);
    if(h0 == GT::null_halfedge() || hindex(h0) == npos || target(h0, tm) != v)
      return make_check_result(ERROR_NON_MANIFOLD, generic + " (broken vertex links)");
    std::size_t k = 0;
    halfedge_descriptor h = h0;
    do {
      if(target(h, tm) != v)
        return make_check_result(ERROR_NON_MANIFOLD, generic + " (broken vertex links)");
      ++k;
      h = opposite(next(h, tm), tm);
    } while(h != h0 && k <= incoming[vi]);
    if(h != h0)
      return make_check_result(ERROR_NON_MANIFOLD, generic + " (broken vertex links)");
    if(k != incoming[vi]) {
      std::ostringstream os;
      os << "vertex " << vi << " is non-manifold: its incident faces form more than one fan"
         << " (" << k << " of its " << incoming[vi] << " incident edges are reachable around it)";
      return make_check_result(ERROR_NON_MANIFOLD, os.str());
    }
  }

  return make_check_result(ERROR_NON_MANIFOLD, generic);
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

// Two border vertices with the same coordinates (the first pair found), if any.
template <class TriangleMesh, class VertexPointMap, class VertexIndex>
bool coincident_border_vertices(const TriangleMesh& tm, VertexPointMap vpm, const VertexIndex& vindex,
                                std::size_t& a, std::size_t& b)
{
  typedef typename boost::graph_traits<TriangleMesh>::halfedge_descriptor halfedge_descriptor;
  struct Key_hash
  {
    std::size_t operator()(const std::array<double, 3>& k) const
    {
      std::size_t h = 0;
      for(double x : k)
        h = h * 1000003u ^ std::hash<double>()(x);
      return h;
    }
  };
  std::unordered_map<std::array<double, 3>, std::size_t, Key_hash> first;
  for(halfedge_descriptor h : halfedges(tm)) {
    if(!is_border(h, tm))
      continue;
    const auto& p = get(vpm, target(h, tm));
    const std::array<double, 3> key = { { CGAL::to_double(p.x()) + 0.0, CGAL::to_double(p.y()) + 0.0,
                                          CGAL::to_double(p.z()) + 0.0 } }; // -0 -> +0
    const std::size_t vi = vindex(target(h, tm));
    auto ins = first.emplace(key, vi);
    if(!ins.second && ins.first->second != vi) {
      a = (std::min)(ins.first->second, vi);
      b = (std::max)(ins.first->second, vi);
      return true;
    }
  }
  return false;
}

} // namespace check_mesh_impl

/*!
Checks that `tm` can be embedded into a hyperbolic orbifold of type `required_type`
(see the list of checks at the top of this file); `std::nullopt` means automatic:
sphere type for a closed mesh, disk type for a mesh with one boundary loop.
`vpm` maps vertices to points of a CGAL kernel (`Kernel_traits` must know the type).
If `info` is not null, it receives the sizes, boundary loops, V-E+F, genus and the
required or detected type (as far as the checks got). Linear time.
*/
template <class TriangleMesh, class VertexPointMap>
Check_result check_mesh(const TriangleMesh& tm,
                        VertexPointMap vpm,
                        std::optional<Orbifold_type> required_type,
                        Mesh_info* info = nullptr)
{
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename GT::vertex_descriptor vertex_descriptor;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  typedef typename GT::face_descriptor face_descriptor;
  typedef typename boost::property_traits<VertexPointMap>::value_type Point;
  typedef typename CGAL::Kernel_traits<Point>::Kernel Kernel;

  using check_mesh_impl::plural;

  Mesh_info local_info;
  Mesh_info& mi = info ? *info : local_info;
  mi = Mesh_info();

  Dense_index<vertex_descriptor> vindex(vertices(tm));
  Dense_index<face_descriptor> findex(faces(tm));
  mi.number_of_vertices = vindex.size();
  mi.number_of_faces = findex.size();
  mi.number_of_edges = static_cast<std::size_t>(std::distance(edges(tm).begin(), edges(tm).end()));

  // 1. empty
  if(mi.number_of_faces == 0) {
    std::ostringstream os;
    os << "the mesh has no face";
    if(mi.number_of_vertices > 0)
      os << " (it has " << plural(mi.number_of_vertices, "vertex", "vertices") << " but no face)";
    return make_check_result(ERROR_EMPTY_MESH, os.str());
  }

  // 2. isolated vertices (CGAL::is_valid_polygon_mesh() rejects them without saying why)
  for(vertex_descriptor v : vertices(tm)) {
    if(halfedge(v, tm) == GT::null_halfedge()) {
      std::ostringstream os;
      os << "vertex " << vindex(v) << " is isolated (it has no incident face); "
         << "remove unreferenced vertices from the input";
      return make_check_result(ERROR_NON_MANIFOLD, os.str());
    }
  }

  // 3. halfedge structure
  if(!CGAL::is_valid_polygon_mesh(tm))
    return check_mesh_impl::diagnose_invalid_structure(tm, vindex, findex);

  // 3b. non-manifold vertices that is_valid_polygon_mesh() accepts: several open fans
  //     around a vertex, chained by their border halfedges (Euler::add_face() builds
  //     such "bowties"); such a vertex is the target of more than one border halfedge
  {
    std::vector<unsigned char> border_in(mi.number_of_vertices, 0);
    for(halfedge_descriptor h : halfedges(tm)) {
      if(!is_border(h, tm))
        continue;
      const std::size_t vi = vindex(target(h, tm));
      if(++border_in[vi] == 2) {
        std::ostringstream os;
        os << "vertex " << vi << " is non-manifold: its incident faces form more than one fan"
           << " (it lies on several boundary gaps)";
        return make_check_result(ERROR_NON_MANIFOLD, os.str());
      }
    }
  }

  // 4. triangles
  for(face_descriptor f : faces(tm)) {
    std::size_t d = 0;
    for(halfedge_descriptor h : halfedges_around_face(halfedge(f, tm), tm)) {
      (void)h;
      ++d;
    }
    if(d != 3) {
      std::ostringstream os;
      os << "face " << findex(f) << " has " << d << " vertices; only triangle meshes are supported";
      return make_check_result(ERROR_NON_TRIANGULAR_MESH, os.str());
    }
  }

  // 5. finite coordinates
  for(vertex_descriptor v : vertices(tm)) {
    const Point& p = get(vpm, v);
    if(!check_mesh_impl::is_finite_number(p.x()) || !check_mesh_impl::is_finite_number(p.y())
       || !check_mesh_impl::is_finite_number(p.z())) {
      std::ostringstream os;
      os.precision(17);
      os << "vertex " << vindex(v) << " has a non-finite coordinate ("
         << CGAL::to_double(p.x()) << " " << CGAL::to_double(p.y()) << " " << CGAL::to_double(p.z()) << ")";
      return make_check_result(ERROR_NON_FINITE_COORDINATES, os.str());
    }
  }

  // 6. degenerate faces (exact predicates of the kernel)
  {
    const Kernel kernel;
    typename Kernel::Collinear_3 collinear = kernel.collinear_3_object();
    for(face_descriptor f : faces(tm)) {
      const halfedge_descriptor h = halfedge(f, tm);
      const vertex_descriptor a = source(h, tm), b = target(h, tm), c = target(next(h, tm), tm);
      if(!collinear(get(vpm, a), get(vpm, b), get(vpm, c)))
        continue;
      // degenerate: say whether two vertices coincide or the three are collinear
      const vertex_descriptor vs[3] = { a, b, c };
      for(int i = 0; i < 3; ++i) {
        const vertex_descriptor u = vs[i], w = vs[(i + 1) % 3];
        if(u == w) { // excluded by is_valid_polygon_mesh(), kept for safety
          std::ostringstream os;
          os << "face " << findex(f) << " uses vertex " << vindex(u) << " twice";
          return make_check_result(ERROR_DEGENERATE_FACE, os.str());
        }
        if(get(vpm, u) == get(vpm, w)) {
          std::ostringstream os;
          os << "face " << findex(f) << " is degenerate: its vertices " << vindex(u) << " and "
             << vindex(w) << " have the same coordinates";
          return make_check_result(ERROR_DEGENERATE_FACE, os.str());
        }
      }
      std::ostringstream os;
      os << "face " << findex(f) << " has zero area: its vertices " << vindex(a) << ", "
         << vindex(b) << ", " << vindex(c) << " are collinear";
      return make_check_result(ERROR_DEGENERATE_FACE, os.str());
    }
  }

  // 6b. faces out of the range of double-precision geometry (too large or too small)
  {
    std::string why;
    for(face_descriptor f : faces(tm)) {
      const halfedge_descriptor h = halfedge(f, tm);
      if(check_mesh_impl::face_in_double_range(get(vpm, source(h, tm)), get(vpm, target(h, tm)),
                                               get(vpm, target(next(h, tm), tm)), why))
        continue;
      std::ostringstream os;
      os << "face " << findex(f) << " is out of the range of double-precision geometry: " << why;
      return make_check_result(ERROR_NON_FINITE_COORDINATES, os.str());
    }
  }

  // 7. connected components (faces connected through edges; a vertex-only contact
  //    would be a non-manifold vertex, rejected above): union-find over the edges
  {
    const std::size_t nf = mi.number_of_faces;
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
    for(halfedge_descriptor h : halfedges(tm)) {
      const face_descriptor f = face(h, tm), g = face(opposite(h, tm), tm);
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
    if(sizes.size() > 1) {
      std::ostringstream os;
      os << "the mesh has " << sizes.size() << " connected components (faces 0 and " << other
         << " are not connected; component sizes in faces:";
      for(std::size_t i = 0; i < sizes.size() && i < 5; ++i)
        os << " " << sizes[i];
      if(sizes.size() > 5)
        os << " ...";
      os << ")";
      return make_check_result(ERROR_SEVERAL_COMPONENTS, os.str());
    }
  }

  // 8. topology
  mi.number_of_border_loops = count_border_loops(tm);
  mi.euler_characteristic = static_cast<long long>(mi.number_of_vertices)
                          - static_cast<long long>(mi.number_of_edges)
                          + static_cast<long long>(mi.number_of_faces);
  mi.genus = (2 - static_cast<long long>(mi.number_of_border_loops) - mi.euler_characteristic) / 2;

  const std::size_t b = mi.number_of_border_loops;
  Orbifold_type type;
  if(required_type) {
    type = *required_type;
  } else if(b == 0) {
    type = Sphere_type;
  } else if(b == 1) {
    type = Disk_type;
  } else {
    std::ostringstream os;
    os << "the mesh has " << b << " boundary loops: sphere-type orbifolds need a closed mesh"
       << " and disk-type orbifolds a mesh with one boundary loop";
    std::size_t da = 0, db = 0;
    if(check_mesh_impl::coincident_border_vertices(tm, vpm, vindex, da, db))
      os << " (border vertices " << da << " and " << db << " have the same coordinates:"
         << " duplicated vertices that should be one?)";
    return make_check_result(ERROR_WRONG_TOPOLOGY, os.str());
  }
  mi.type = type;

  std::ostringstream os;
  if(type == Sphere_type) {
    if(b != 0)
      os << "the sphere-type orbifold needs a closed genus-0 mesh, but the mesh has "
         << plural(b, "boundary loop", "boundary loops");
    else if(mi.euler_characteristic != 2)
      os << "the sphere-type orbifold needs a genus-0 mesh, but the mesh has genus " << mi.genus
         << " (V-E+F = " << mi.euler_characteristic << ")";
  } else {
    if(b == 0)
      os << "the disk-type orbifold needs a mesh with one boundary loop, but the mesh is closed";
    else if(b != 1)
      os << "the disk-type orbifold needs a mesh with one boundary loop, but the mesh has "
         << plural(b, "boundary loop", "boundary loops");
    else if(mi.euler_characteristic != 1)
      os << "the disk-type orbifold needs a topological disk, but the mesh has genus " << mi.genus
         << " (V-E+F = " << mi.euler_characteristic << ")";
  }
  if(!os.str().empty()) {
    std::size_t da = 0, db = 0;
    if(b > (type == Sphere_type ? 0u : 1u) && check_mesh_impl::coincident_border_vertices(tm, vpm, vindex, da, db))
      os << " (border vertices " << da << " and " << db << " have the same coordinates:"
         << " duplicated vertices that should be one?)";
    return make_check_result(ERROR_WRONG_TOPOLOGY, os.str());
  }

  mi.type_known = true;
  return Check_result();
}

/// Same as above with the mesh's internal vertex point map `get(CGAL::vertex_point, tm)`.
template <class TriangleMesh>
Check_result check_mesh(const TriangleMesh& tm,
                        std::optional<Orbifold_type> required_type = std::nullopt,
                        Mesh_info* info = nullptr)
{
  return check_mesh(tm, get(CGAL::vertex_point, tm), required_type, info);
}

// ---------------------------------------------------------------------------
// check_landmarks
// ---------------------------------------------------------------------------

/// The number of landmarks (cones or corners) the orbifolds need at least.
inline constexpr std::size_t minimum_number_of_landmarks = 5;

/*!
Checks the landmark (cone / corner) vertex indices of `tm` and converts them to
vertex descriptors: index `i` is the `i`-th vertex of `vertices(tm)` (for a mesh read
with `read_mesh()`, the file's vertex `i`). In this order:
fewer than 5 (ERROR_TOO_FEW_LANDMARKS), an index >= number of vertices
(ERROR_LANDMARK_OUT_OF_RANGE), an index given twice (ERROR_DUPLICATE_LANDMARK), and
for `Disk_type` a landmark that is not a border vertex (ERROR_LANDMARK_NOT_ON_BORDER).
The order of the landmarks is kept. `landmarks_out` is filled only on success (it is
cleared otherwise). Precondition: `check_mesh()` succeeded on `tm`. Linear time.
*/
template <class TriangleMesh>
Check_result check_landmarks(const TriangleMesh& tm,
                             const std::vector<std::size_t>& landmark_indices,
                             Orbifold_type type,
                             std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>& landmarks_out)
{
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  landmarks_out.clear();

  const std::size_t k = landmark_indices.size();
  if(k < minimum_number_of_landmarks) {
    std::ostringstream os;
    os << k << " landmark" << (k == 1 ? " is" : "s are") << " given, but the " << orbifold_type_name(type)
       << "-type orbifold needs at least " << minimum_number_of_landmarks;
    return make_check_result(ERROR_TOO_FEW_LANDMARKS, os.str());
  }

  std::vector<vertex_descriptor> verts;
  for(vertex_descriptor v : vertices(tm))
    verts.push_back(v);
  const std::size_t n = verts.size();

  for(std::size_t i = 0; i < k; ++i) {
    if(landmark_indices[i] >= n) {
      std::ostringstream os;
      os << "landmark " << i << " is vertex " << landmark_indices[i] << ", but the mesh has only "
         << n << " vertices (valid indices are 0 to " << (n == 0 ? 0 : n - 1) << ")";
      return make_check_result(ERROR_LANDMARK_OUT_OF_RANGE, os.str());
    }
  }

  std::unordered_map<std::size_t, std::size_t> first_position;
  for(std::size_t i = 0; i < k; ++i) {
    auto ins = first_position.emplace(landmark_indices[i], i);
    if(!ins.second) {
      std::ostringstream os;
      os << "vertex " << landmark_indices[i] << " is given twice, as landmarks " << ins.first->second
         << " and " << i;
      return make_check_result(ERROR_DUPLICATE_LANDMARK, os.str());
    }
  }

  if(type == Disk_type) {
    for(std::size_t i = 0; i < k; ++i) {
      if(!CGAL::is_border(verts[landmark_indices[i]], tm)) {
        std::ostringstream os;
        os << "landmark " << i << " (vertex " << landmark_indices[i]
           << ") is not on the boundary loop; disk-type orbifold corners must be boundary vertices";
        return make_check_result(ERROR_LANDMARK_NOT_ON_BORDER, os.str());
      }
    }
  }

  landmarks_out.reserve(k);
  for(std::size_t i = 0; i < k; ++i)
    landmarks_out.push_back(verts[landmark_indices[i]]);
  return Check_result();
}

} // namespace internal
} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_INPUT_CHECKS_H
