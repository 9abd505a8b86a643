// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_CORE_SEAM_MESH_STORAGE_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_CORE_SEAM_MESH_STORAGE_H

#include <CGAL/Hyperbolic_orbifold_Tutte/internal/core/dense_index.h>

#include <CGAL/boost/graph/Seam_mesh.h>

#include <boost/property_map/property_map.hpp>

#include <vector>

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {
namespace internal {

// A read-write property map of flags: one char per descriptor of a range, found through
// its dense index (a vector for Surface_mesh, a flat hash table for handles), not a
// std::unordered_map per lookup: Seam_mesh asks for these flags in every target().
template <class Descriptor>
class Dense_flag_map
{
public:
  typedef Descriptor key_type;
  typedef bool value_type;
  typedef bool reference;
  typedef boost::read_write_property_map_tag category;

  Dense_flag_map(const Dense_index<Descriptor>* index, std::vector<char>* flags) : index_(index), flags_(flags) {}

  friend bool get(const Dense_flag_map& m, const Descriptor& d)
  {
    const std::size_t i = (*m.index_)(d);
    return i != Dense_index<Descriptor>::npos && (*m.flags_)[i] != 0;
  }
  friend void put(const Dense_flag_map& m, const Descriptor& d, bool b)
  {
    const std::size_t i = (*m.index_)(d);
    if(i != Dense_index<Descriptor>::npos)
      (*m.flags_)[i] = b ? 1 : 0;
  }

private:
  const Dense_index<Descriptor>* index_;
  std::vector<char>* flags_;
};

// A CGAL::Seam_mesh over a const mesh, its seam flags held apart (so that the input mesh
// is not modified), all flags false at construction. Not copyable: the mesh's property
// maps point into this object.
template <class TriangleMesh>
struct Seam_mesh_storage
{
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  typedef typename boost::graph_traits<TriangleMesh>::edge_descriptor edge_descriptor;
  typedef Dense_flag_map<edge_descriptor> SEM;
  typedef Dense_flag_map<vertex_descriptor> SVM;
  typedef CGAL::Seam_mesh<TriangleMesh, SEM, SVM> Mesh;
  typedef typename boost::graph_traits<Mesh>::halfedge_descriptor halfedge_descriptor;

  Dense_index<edge_descriptor> edge_index;
  Dense_index<vertex_descriptor> vertex_index;
  std::vector<char> edge_flags, vertex_flags;
  Mesh mesh;

  explicit Seam_mesh_storage(const TriangleMesh& tm)
    : edge_index(edges(tm)), vertex_index(vertices(tm)), edge_flags(edge_index.size(), 0),
      vertex_flags(vertex_index.size(), 0), mesh(tm, SEM(&edge_index, &edge_flags), SVM(&vertex_index, &vertex_flags))
  {}
  Seam_mesh_storage(const Seam_mesh_storage&) = delete;
  Seam_mesh_storage& operator=(const Seam_mesh_storage&) = delete;

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
};

// Points of the vertices of a Seam_mesh over `TriangleMesh` (a Seam_mesh vertex descriptor
// is a halfedge of the mesh): a vector through the dense index of the mesh's halfedges.
// `map()` is the writable property map (key: the seam mesh's vertex descriptor).
template <class SeamMesh, class Point>
class Seam_vertex_points
{
  typedef typename SeamMesh::TriangleMesh TM;
  typedef typename boost::graph_traits<TM>::halfedge_descriptor TM_halfedge;

public:
  typedef typename boost::graph_traits<SeamMesh>::vertex_descriptor vertex_descriptor;

  class Map
  {
  public:
    typedef vertex_descriptor key_type;
    typedef Point value_type;
    typedef const Point& reference;
    typedef boost::read_write_property_map_tag category;
    explicit Map(Seam_vertex_points* s) : s_(s) {}
    friend const Point& get(const Map& m, const key_type& v) { return m.s_->at(v); }
    friend void put(const Map& m, const key_type& v, const Point& p) { m.s_->set(v, p); }

  private:
    Seam_vertex_points* s_;
  };

  explicit Seam_vertex_points(const TM& tm) : index_(halfedges(tm)), points_(index_.size()) {}
  Seam_vertex_points(const Seam_vertex_points&) = delete;
  Seam_vertex_points& operator=(const Seam_vertex_points&) = delete;

  Map map() { return Map(this); }
  const Point& at(const vertex_descriptor& v) const { return points_[slot(v)]; }
  void set(const vertex_descriptor& v, const Point& p) { points_[slot(v)] = p; }

private:
  std::size_t slot(const vertex_descriptor& v) const
  {
    const std::size_t i = index_(v.hd.tmhd);
    CGAL_assertion(i != Dense_index<TM_halfedge>::npos);
    return i;
  }

  Dense_index<TM_halfedge> index_;
  std::vector<Point> points_;
};

} // namespace internal
} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_CORE_SEAM_MESH_STORAGE_H
