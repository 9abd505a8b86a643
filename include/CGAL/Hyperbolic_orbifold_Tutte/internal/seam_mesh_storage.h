// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_SEAM_MESH_STORAGE_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_SEAM_MESH_STORAGE_H

#include <CGAL/boost/graph/Seam_mesh.h>

#include <boost/functional/hash.hpp>
#include <boost/property_map/property_map.hpp>

#include <unordered_map>

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {
namespace internal {

// A CGAL::Seam_mesh over a const mesh, its seam flags held in hash maps (so the input
// mesh is not modified), all flags false at construction.
template <class TriangleMesh>
struct Seam_mesh_storage
{
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  typedef typename boost::graph_traits<TriangleMesh>::edge_descriptor edge_descriptor;
  typedef std::unordered_map<edge_descriptor, bool, boost::hash<edge_descriptor> > Edge_flags;
  typedef std::unordered_map<vertex_descriptor, bool, boost::hash<vertex_descriptor> > Vertex_flags;
  typedef boost::associative_property_map<Edge_flags> SEM;
  typedef boost::associative_property_map<Vertex_flags> SVM;
  typedef CGAL::Seam_mesh<TriangleMesh, SEM, SVM> Mesh;
  typedef typename boost::graph_traits<Mesh>::halfedge_descriptor halfedge_descriptor;

  Edge_flags edge_flags;
  Vertex_flags vertex_flags;
  Mesh mesh;

  explicit Seam_mesh_storage(const TriangleMesh& tm)
    : edge_flags(initial_edges(tm)), vertex_flags(initial_vertices(tm)), mesh(tm, SEM(edge_flags), SVM(vertex_flags))
  {}

  // a halfedge on the border of the cut mesh; false if there is none (nothing cut)
  bool border_halfedge(halfedge_descriptor& bhd) const
  {
    for(halfedge_descriptor h : halfedges(mesh))
      if(is_border(h, mesh)) {
        bhd = h;
        return true;
      }
    return false;
  }

private:
  static Edge_flags initial_edges(const TriangleMesh& tm)
  {
    Edge_flags f;
    for(edge_descriptor e : edges(tm))
      f.emplace(e, false);
    return f;
  }
  static Vertex_flags initial_vertices(const TriangleMesh& tm)
  {
    Vertex_flags f;
    for(vertex_descriptor v : vertices(tm))
      f.emplace(v, false);
    return f;
  }
};

} // namespace internal
} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_SEAM_MESH_STORAGE_H
