// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_TOOLS_IO_POLYGON_SOUP_TO_MESH_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_TOOLS_IO_POLYGON_SOUP_TO_MESH_H

// A validated polygon soup turned into a mesh in linear time, keeping the soup's order.
//
// * Why our own soup-to-mesh builder rather than
//   `CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh()`? The latter is given
//   a valid soup only (precondition), builds the mesh face by face with `Euler::add_face()`,
//   which is quadratic around a vertex of high degree (measured: a fan of 40K triangles
//   around one vertex takes 2.6 s, so 200K take about a minute; 0.1 s here), and its
//   precondition check `is_polygon_soup_a_polygon_mesh()` uses a std::set of all edges.
//   Our builder links the halfedges directly from the edge table computed by the
//   validation, in linear time (1M vertices, a 108 MB OFF file with 17 digits, measured
//   in a fresh process: 0.11 s to read the file, 0.2 s to parse it, 0.23 s to validate,
//   0.15 s to build a Surface_mesh).
//
// Order guarantee (tested): vertex i of the mesh (the i-th of `vertices(mesh)`) is the
// file's vertex i, face j is the file's face j with the same cyclic vertex order and the
// same first vertex (`source(halfedge(f))` is its first vertex), unreferenced vertices
// included (check_mesh() then rejects them). For STL, which has no shared vertices,
// vertex i is the i-th distinct point in the order of first appearance (as in CGAL).

#include "common.h"
#include "polygon_soup.h"
#include "timings.h"
#include "validate_polygon_soup.h"

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/properties.h>
#include <CGAL/Surface_mesh/Surface_mesh_fwd.h>

#include <boost/graph/graph_traits.hpp>

#include <cstddef>
#include <new>
#include <type_traits>
#include <utility>
#include <vector>

#include <CGAL/disable_warnings.h>

/// \file polygon_soup_to_mesh.h

namespace hot_tools {

namespace io_impl {

template <class PM, class = void>
struct Has_bgl_reserve : std::false_type {};

template <class PM>
struct Has_bgl_reserve<PM, std::void_t<decltype(reserve(std::declval<PM&>(),
                                                        typename boost::graph_traits<PM>::vertices_size_type(0),
                                                        typename boost::graph_traits<PM>::edges_size_type(0),
                                                        typename boost::graph_traits<PM>::faces_size_type(0)))> >
  : std::true_type {};

/// a CGAL::Surface_mesh: its elements are made all at once (`resize()`), with the indices
/// add_vertex(), add_edge() and add_face() would give them one by one on a cleared mesh
template <class PM>
struct Is_surface_mesh : std::false_type {};

template <class Point>
struct Is_surface_mesh<CGAL::Surface_mesh<Point> > : std::true_type {};

} // namespace io_impl

/*!
Builds `mesh` (cleared first) from a soup; the soup is validated first and nothing is
built if it is invalid. Vertex i of the mesh is point i of the soup (unreferenced points
included), face j is polygon j with its vertex order, `source(halfedge(face j))` being
its first vertex. Linear time. `PolygonMesh` is a model of `MutableFaceGraph` with an
internal vertex point map (Surface_mesh, Polyhedron_3).
*/
template <class PolygonMesh>
HOT::Status polygon_soup_to_mesh(const Polygon_soup& soup, PolygonMesh& mesh)
{
  typedef boost::graph_traits<PolygonMesh> GT;
  typedef typename GT::vertex_descriptor vertex_descriptor;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  typedef typename GT::face_descriptor face_descriptor;
  typedef typename boost::property_map<PolygonMesh, CGAL::vertex_point_t>::type VPM;
  typedef typename boost::property_traits<VPM>::value_type Point;

  CGAL::clear(mesh);
  Soup_topology topo;
  HOT::Status r = validate_polygon_soup(soup, &topo);
  if(!r)
    return r;
  timings().phase("validate the soup");

  try {
    const std::size_t np = soup.number_of_points(), nf = soup.number_of_faces();
    const std::size_t ne = topo.edge_corners.size();
    if constexpr(io_impl::Has_bgl_reserve<PolygonMesh>::value && !io_impl::Is_surface_mesh<PolygonMesh>::value)
      reserve(mesh, typename GT::vertices_size_type(np), typename GT::edges_size_type(ne),
              typename GT::faces_size_type(nf));
    constexpr bool all_at_once = io_impl::Is_surface_mesh<PolygonMesh>::value;
    if constexpr(all_at_once)
      mesh.resize(typename PolygonMesh::size_type(np), typename PolygonMesh::size_type(ne), typename PolygonMesh::size_type(nf));
    VPM vpm = get(CGAL::vertex_point, mesh);

    std::vector<vertex_descriptor> V(np);
    for(std::size_t i = 0; i < np; ++i) {
      if constexpr(all_at_once)
        V[i] = vertex_descriptor(typename PolygonMesh::size_type(i));
      else
        V[i] = add_vertex(mesh);
      put(vpm, V[i], Point(soup.points[i][0], soup.points[i][1], soup.points[i][2]));
    }

    const std::vector<std::size_t>& fv = soup.face_vertices;
    auto next_corner = [&](std::size_t c) { return io_impl::next_corner(soup, topo.corner_face, c); };

    std::vector<halfedge_descriptor> H(2 * ne);
    for(std::size_t e = 0; e < ne; ++e) {
      halfedge_descriptor h;
      if constexpr(all_at_once)
        h = halfedge_descriptor(typename PolygonMesh::size_type(2 * e));
      else
        h = halfedge(add_edge(mesh), mesh);
      H[2 * e] = h;
      H[2 * e + 1] = opposite(h, mesh);
      const std::size_t c0 = topo.edge_corners[e][0]; // u -> w
      set_target(H[2 * e], V[fv[next_corner(c0)]], mesh);
      set_target(H[2 * e + 1], V[fv[c0]], mesh);
    }
    auto corner_halfedge = [&](std::size_t c) { return H[2 * topo.corner_edge[c] + topo.corner_side[c]]; };

    for(std::size_t f = 0; f < nf; ++f) {
      face_descriptor fd;
      if constexpr(all_at_once)
        fd = face_descriptor(typename PolygonMesh::size_type(f));
      else
        fd = add_face(mesh);
      const std::size_t b = soup.face_begin[f], e = soup.face_begin[f + 1];
      for(std::size_t c = b; c < e; ++c) {
        const halfedge_descriptor h = corner_halfedge(c);
        set_face(h, fd, mesh);
        set_next(h, corner_halfedge(next_corner(c)), mesh);
        set_halfedge(target(h, mesh), h, mesh);
      }
      // the halfedge of the face leaves its first vertex
      set_halfedge(fd, corner_halfedge(b), mesh);
    }

    // border halfedges: w -> u opposite to a lone u -> w; in a manifold soup every
    // border vertex has exactly one outgoing border halfedge
    std::vector<halfedge_descriptor> border_out(np, GT::null_halfedge());
    for(std::size_t e = 0; e < ne; ++e) {
      if(topo.edge_corners[e][1] != Soup_topology::none)
        continue;
      const halfedge_descriptor bh = H[2 * e + 1];
      set_face(bh, GT::null_face(), mesh);
      border_out[fv[next_corner(topo.edge_corners[e][0])]] = bh; // source w
    }
    for(std::size_t e = 0; e < ne; ++e) {
      if(topo.edge_corners[e][1] != Soup_topology::none)
        continue;
      const halfedge_descriptor bh = H[2 * e + 1];
      const std::size_t u = fv[topo.edge_corners[e][0]]; // target of bh
      set_next(bh, border_out[u], mesh);
      set_halfedge(V[u], bh, mesh); // a border vertex points to its incoming border halfedge
    }
  } catch(const std::bad_alloc&) {
    CGAL::clear(mesh);
    return io_impl::fail(HOT::ERROR_READ_FAILED, "out of memory while building the mesh");
  }
  // The result is a valid polygon mesh (CGAL::is_valid_polygon_mesh() holds when every
  // point is referenced; the test suite checks it). It is not re-checked here:
  // check_mesh() does it.
  timings().phase("build the mesh");
  return HOT::Status();
}

} // namespace hot_tools

#include <CGAL/enable_warnings.h>

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_TOOLS_IO_POLYGON_SOUP_TO_MESH_H
