// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_TOOLS_IO_EMBEDDING_OBJ_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_TOOLS_IO_EMBEDDING_OBJ_H

// The OBJ file of an embedding (the `embed` and `collection` commands' output).

#include <CGAL/Surface_mesh.h>

#include <boost/property_map/property_map.hpp>

#include <cstddef>
#include <ostream>
#include <utility>
#include <vector>

#include <CGAL/disable_warnings.h>

/// \file embedding_obj.h

namespace hot_tools {

// Writes an embedding as OBJ: v = input vertices, vt = one Poincare point per cut-mesh
// vertex (corners of a vertex with equal points share their vt), f = input faces in input
// order with their corners' vt. `uv` maps each halfedge to the point of its target corner.
template <class Point_3, class HalfedgeUVMap>
void write_embedding_obj(std::ostream& os, const CGAL::Surface_mesh<Point_3>& m, const HalfedgeUVMap& uv)
{
  typedef CGAL::Surface_mesh<Point_3> Mesh;
  typedef typename boost::property_traits<HalfedgeUVMap>::value_type Point_2;
  std::vector<std::vector<std::pair<Point_2, std::size_t> > > vts(num_vertices(m));
  std::vector<Point_2> vt_points;
  std::vector<std::size_t> corner_vt(num_halfedges(m), 0);
  for(typename Mesh::Face_index f : faces(m))
    for(typename Mesh::Halfedge_index h : halfedges_around_face(halfedge(f, m), m)) {
      const Point_2 p = get(uv, h);
      auto& list = vts[target(h, m).idx()];
      std::size_t id = std::size_t(-1);
      for(const auto& e : list)
        if(e.first == p) { id = e.second; break; }
      if(id == std::size_t(-1)) {
        id = vt_points.size();
        vt_points.push_back(p);
        list.push_back(std::make_pair(p, id));
      }
      corner_vt[h.idx()] = id;
    }
  os.precision(17);
  os << "# hyperbolic orbifold Tutte embedding: vt = Poincare-disk coordinates\n";
  for(typename Mesh::Vertex_index v : vertices(m))
    os << "v " << m.point(v) << "\n";
  for(const auto& p : vt_points)
    os << "vt " << p.x() << " " << p.y() << "\n";
  for(typename Mesh::Face_index f : faces(m)) {
    os << "f";
    // read_mesh() builds face f with source(halfedge(f)) = the file's first vertex of the face
    for(typename Mesh::Halfedge_index h : halfedges_around_face(prev(halfedge(f, m), m), m))
      os << " " << target(h, m).idx() + 1 << "/" << corner_vt[h.idx()] + 1;
    os << "\n";
  }
}

} // namespace hot_tools

#include <CGAL/enable_warnings.h>

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_TOOLS_IO_EMBEDDING_OBJ_H
