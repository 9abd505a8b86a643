// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_LOCATOR_LOCATOR_BUILD_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_LOCATOR_LOCATOR_BUILD_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Hyperbolic_orbifold_Tutte/internal/core/dense_index.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/locator/lifted_triangulation.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <array>
#include <cmath>
#include <utility>
#include <vector>

// The mesh-dependent part of building the point locator (Embedding_locator.h): the faces
// of a triangle mesh with their corner points, then their neighbours and the group element
// across every edge.

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {
namespace internal {

// the halfedges of the faces, in face order, and for each halfedge of a face the face's
// index and the edge's index in it (edge j is the halfedge h_{j+1})
template <class TriangleMesh>
struct Face_halfedges
{
  typedef typename boost::graph_traits<TriangleMesh>::halfedge_descriptor halfedge_descriptor;

  Dense_index<halfedge_descriptor> hindex;
  std::vector<std::array<halfedge_descriptor, 3> > fh;
  std::vector<std::pair<int, int> > edge_of;

  explicit Face_halfedges(const TriangleMesh& tm)
    : hindex(halfedges(tm)), edge_of(hindex.size(), std::make_pair(-1, -1))
  {
    fh.reserve(num_faces(tm));
  }
};

// reads the faces of `tm` (listed in `face_list`, its vertices in `vertex_list`) and their
// corner points from `uv` into `lt.faces`; false (lt.fail) for a face that is not a triangle
// or a corner point outside the unit disk
template <class TriangleMesh, class HalfedgeUVMap, class Traits>
bool read_lifted_faces(const TriangleMesh& tm, HalfedgeUVMap uv, Lifted_triangulation<Traits>& lt, Face_halfedges<TriangleMesh>& fhs,
                       std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor>& face_list,
                       std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>& vertex_list)
{
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename GT::vertex_descriptor vertex_descriptor;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  typedef typename GT::face_descriptor face_descriptor;
  const Dense_index<vertex_descriptor> vindex(vertices(tm));
  vertex_list.assign(vertices(tm).begin(), vertices(tm).end());
  face_list.reserve(num_faces(tm));
  lt.faces.reserve(num_faces(tm));
  for(face_descriptor f : faces(tm)) {
    const halfedge_descriptor h0 = halfedge(f, tm), h1 = next(h0, tm), h2 = next(h1, tm);
    if(next(h2, tm) != h0)
      return lt.fail("the mesh has a face that is not a triangle");
    const int fi = static_cast<int>(face_list.size());
    face_list.push_back(f);
    fhs.fh.push_back({{h0, h1, h2}});
    Lifted_face F;
    for(int j = 0; j < 3; ++j) {
      F.z[j] = Lifted_triangulation<Traits>::to_c(get(uv, fhs.fh.back()[j]));
      if(!std::isfinite(F.z[j].real()) || !std::isfinite(F.z[j].imag()) || !(squared_modulus(F.z[j]) < 1.0))
        return lt.fail("a corner point is not inside the unit disk");
      F.v[j] = static_cast<int>(vindex(target(fhs.fh.back()[j], tm)));
      F.nf[j] = -1;
      F.ne[j] = -1;
      F.tr[j] = -1;
      F.mirror[j] = false;
      fhs.edge_of[fhs.hindex(fhs.fh.back()[(j + 1) % 3])] = std::make_pair(fi, j); // edge j is halfedge h_{j+1}
    }
    lt.faces.push_back(F);
  }
  return true;
}

// the neighbour across every edge of the faces read by read_lifted_faces() and the group
// element that maps the neighbour's copy next to the face; false (lt.fail) if an edge's two
// sides are not related by the orbifold group
template <class TriangleMesh, class Traits>
bool link_lifted_faces(const TriangleMesh& tm, const Face_halfedges<TriangleMesh>& fhs, Lifted_triangulation<Traits>& lt)
{
  typedef typename boost::graph_traits<TriangleMesh>::halfedge_descriptor halfedge_descriptor;
  typedef std::complex<double> C;
  for(std::size_t fi = 0; fi < lt.faces.size(); ++fi) {
    Lifted_face& F = lt.faces[fi];
    for(int j = 0; j < 3; ++j) {
      const halfedge_descriptor h = fhs.fh[fi][(j + 1) % 3];
      const halfedge_descriptor o = opposite(h, tm);
      const C& a = F.z[j];            // source(h)
      const C& b = F.z[(j + 1) % 3];  // target(h)
      if(is_border(o, tm)) {
        const int t = lt.find_mirror(a, b);
        if(t < 0)
          return lt.fail("a border edge of the mesh does not lie on a mirror side of the tile");
        F.nf[j] = static_cast<int>(fi);
        F.ne[j] = j;
        F.tr[j] = t;
        F.mirror[j] = true;
        ++lt.n_border_edges;
        continue;
      }
      const std::pair<int, int> n = fhs.edge_of[fhs.hindex(o)];
      if(n.first < 0)
        return lt.fail("the mesh's halfedges are not consistent");
      F.nf[j] = n.first;
      F.ne[j] = n.second;
      const Lifted_face& G = lt.faces[n.first];
      // G's corner ne is target(h) = b, its corner ne+1 is source(h) = a
      const C& gb = G.z[n.second];
      const C& ga = G.z[(n.second + 1) % 3];
      if(ga == a && gb == b) {
        F.tr[j] = 0;
        continue;
      }
      // a cut edge: the neighbour's copy across it is g(G) with g(ga) = a, g(gb) = b
      const int t = lt.find_transition(ga, a, gb, b);
      if(t < 0)
        return lt.fail("the corner points on the two sides of a cut edge are not related by a side pairing of the tile");
      F.tr[j] = t;
      ++lt.n_cut_edges;
    }
  }
  lt.n_cut_edges /= 2;
  return true;
}

} // namespace internal
} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_LOCATOR_LOCATOR_BUILD_H
