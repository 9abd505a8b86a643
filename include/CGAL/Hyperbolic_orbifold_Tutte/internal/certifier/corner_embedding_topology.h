// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_CERTIFIER_CORNER_EMBEDDING_TOPOLOGY_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_CERTIFIER_CORNER_EMBEDDING_TOPOLOGY_H

// The combinatorics of certify_corner_embedding(), written for it alone (it does not use the
// solver's input checks, cut or seam mesh): the mesh's own topology (a triangulated closed
// surface of any genus, or a disk, from its Euler characteristic, boundary loops, components
// and vertex fans), dense
// indices of its elements, its boundary loop in counterclockwise order, and the match of the
// embedding's faces with the mesh's.

#include <CGAL/Hyperbolic_orbifold_Tutte/Corner_embedding.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/Corner_embedding_certificate.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/error_code.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/genus.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/properties.h>

#include <boost/graph/graph_traits.hpp>

#include <array>
#include <cstddef>
#include <functional>
#include <numeric>
#include <optional>
#include <string>
#include <vector>

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {
namespace internal {
namespace corner_certificate {

// A failure of a check: counted, and the first one kept with its element and message.
inline void record(Corner_embedding_certificate& cert, Corner_embedding_check check,
                   Corner_embedding_certificate::Element_kind kind, std::size_t first, std::size_t second,
                   const std::string& message)
{
  Corner_embedding_certificate::Check_result& r = cert.checks[check];
  if(r.failures++ == 0) {
    r.element = kind;
    r.first = first;
    r.second = second;
    r.message = message;
  }
}

// The mesh with dense indices: vertices and faces in the order of vertices(tm) and faces(tm);
// per face, its halfedges h_0, h_1, h_2 (h_0 = halfedge(f)) and the vertices target(h_c).
template <class TriangleMesh>
struct Indexed_mesh
{
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename GT::vertex_descriptor vertex_descriptor;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  typedef typename GT::face_descriptor face_descriptor;
  typedef typename boost::property_map<TriangleMesh, CGAL::dynamic_vertex_property_t<std::size_t> >::const_type Vertex_index;
  typedef typename boost::property_map<TriangleMesh, CGAL::dynamic_face_property_t<std::size_t> >::const_type Face_index;

  const TriangleMesh& tm;
  Vertex_index vindex;
  Face_index findex;
  std::vector<vertex_descriptor> vertex;
  std::vector<std::array<halfedge_descriptor, 3> > face_halfedges;
  std::vector<std::array<std::size_t, 3> > face_vertices;
  std::vector<std::size_t> border_loop; // disk type: the boundary vertices, counterclockwise (interior on the left)

  explicit Indexed_mesh(const TriangleMesh& m)
    : tm(m), vindex(get(CGAL::dynamic_vertex_property_t<std::size_t>(), m)),
      findex(get(CGAL::dynamic_face_property_t<std::size_t>(), m))
  {}

  std::size_t index(vertex_descriptor v) const { return get(vindex, v); }
  std::size_t index(face_descriptor f) const { return get(findex, f); }
  std::size_t number_of_vertices() const { return vertex.size(); }
  std::size_t number_of_faces() const { return face_vertices.size(); }
};

// Indexes the mesh and checks that it is a triangulated closed surface (no boundary) or disk
// (one boundary loop), as `required` says or as found; `type` receives it, `genus` the closed
// surface's genus (0 for a sphere or a disk; a closed mesh of genus g >= 1 only when `genus` is
// not null, else it is refused as before). Own checks: every face a triangle, every vertex on a
// face with one fan of faces, one component, and the Euler characteristic
// V - E + F = 2 - 2g - (boundary loops), with g = 0 unless the mesh is closed.
template <class TriangleMesh>
Status index_and_check_mesh(Indexed_mesh<TriangleMesh>& M, std::optional<Orbifold_type> required, Orbifold_type& type,
                            int* genus = nullptr)
{
  typedef typename Indexed_mesh<TriangleMesh>::halfedge_descriptor halfedge_descriptor;
  typedef typename Indexed_mesh<TriangleMesh>::vertex_descriptor vertex_descriptor;
  typedef typename Indexed_mesh<TriangleMesh>::face_descriptor face_descriptor;
  const TriangleMesh& tm = M.tm;
  if(!CGAL::is_valid_polygon_mesh(tm))
    return Status::failure(ERROR_NON_MANIFOLD, "the mesh is not a valid halfedge structure");
  for(vertex_descriptor v : vertices(tm)) {
    put(M.vindex, v, M.vertex.size());
    M.vertex.push_back(v);
  }
  const std::size_t V = M.vertex.size();
  std::size_t F = 0;
  for(face_descriptor f : faces(tm)) {
    put(M.findex, f, F);
    const halfedge_descriptor h0 = halfedge(f, tm), h1 = next(h0, tm), h2 = next(h1, tm);
    if(next(h2, tm) != h0)
      return Status::failure(ERROR_NON_TRIANGULAR_MESH, "face " + std::to_string(F) + " of the mesh is not a triangle");
    M.face_halfedges.push_back({{h0, h1, h2}});
    M.face_vertices.push_back({{M.index(target(h0, tm)), M.index(target(h1, tm)), M.index(target(h2, tm))}});
    ++F;
  }
  if(F == 0)
    return Status::failure(ERROR_EMPTY_MESH, "the mesh has no face");

  // every vertex on a face, with one fan: the halfedges around it are all that end there
  std::vector<std::size_t> ending(V, 0);
  std::size_t H = 0;
  for(halfedge_descriptor h : halfedges(tm)) {
    ++ending[M.index(target(h, tm))];
    ++H;
  }
  for(std::size_t i = 0; i < V; ++i) {
    const halfedge_descriptor h = halfedge(M.vertex[i], tm);
    if(h == boost::graph_traits<TriangleMesh>::null_halfedge() || ending[i] == 0)
      return Status::failure(ERROR_NON_MANIFOLD, "vertex " + std::to_string(i) + " of the mesh is on no face");
    std::size_t around = 0;
    for(halfedge_descriptor g : halfedges_around_target(h, tm)) {
      (void)g;
      ++around;
    }
    if(around != ending[i])
      return Status::failure(ERROR_NON_MANIFOLD, "vertex " + std::to_string(i) + " of the mesh is not manifold (its faces form several fans)");
  }

  // one connected component (union-find over the edges)
  std::vector<std::size_t> parent(V);
  std::iota(parent.begin(), parent.end(), std::size_t(0));
  std::function<std::size_t(std::size_t)> find = [&](std::size_t x) {
    while(parent[x] != x) {
      parent[x] = parent[parent[x]];
      x = parent[x];
    }
    return x;
  };
  std::size_t components = V;
  for(halfedge_descriptor h : halfedges(tm)) {
    const std::size_t a = find(M.index(source(h, tm))), b = find(M.index(target(h, tm)));
    if(a != b) {
      parent[a] = b;
      --components;
    }
  }
  if(components != 1)
    return Status::failure(ERROR_SEVERAL_COMPONENTS, "the mesh has " + std::to_string(components) + " connected components");

  // boundary loops, and the disk's loop counterclockwise: a border halfedge b runs clockwise
  // (the face of opposite(b) is on the left of opposite(b)), so the loop goes target(b) -> source(b)
  std::size_t loops = 0;
  halfedge_descriptor first_border = boost::graph_traits<TriangleMesh>::null_halfedge();
  {
    auto visited = get(CGAL::dynamic_halfedge_property_t<bool>(), tm);
    for(halfedge_descriptor h : halfedges(tm))
      put(visited, h, false);
    for(halfedge_descriptor h : halfedges(tm)) {
      if(!is_border(h, tm) || get(visited, h))
        continue;
      ++loops;
      first_border = h;
      halfedge_descriptor g = h;
      do {
        put(visited, g, true);
        g = next(g, tm);
      } while(g != h);
    }
  }
  const long long chi = static_cast<long long>(V) - static_cast<long long>(H / 2) + static_cast<long long>(F);
  const long long twice_genus = 2 - static_cast<long long>(loops) - chi;
  const bool closed_genus = genus != nullptr && loops == 0 && twice_genus > 0 && twice_genus % 2 == 0;
  if(genus != nullptr)
    *genus = closed_genus ? static_cast<int>(genus_of_surface(chi, loops)) : 0;
  if(!closed_genus && (twice_genus != 0 || loops > 1))
    return Status::failure(ERROR_WRONG_TOPOLOGY, "the mesh is neither a closed surface nor a disk (Euler characteristic " +
                                                   std::to_string(chi) + ", " + std::to_string(loops) + " boundary loops)");
  type = loops == 0 ? Sphere_type : Disk_type;
  if(required && *required != type)
    return Status::failure(ERROR_WRONG_TOPOLOGY, *required == Sphere_type
                                                   ? "a sphere-type orbifold needs a closed mesh, but the mesh has a boundary loop"
                                                   : "a disk-type orbifold needs a mesh with one boundary loop, but the mesh is closed");
  if(type == Disk_type) {
    halfedge_descriptor g = first_border;
    do {
      M.border_loop.push_back(M.index(target(g, tm)));
      g = prev(g, tm);
    } while(g != first_border);
  }
  return Status();
}

// the key of an oriented triangle: its vertices rotated to start with the smallest
inline std::array<std::size_t, 3> oriented_key(const std::array<std::size_t, 3>& t)
{
  const int m = (t[0] < t[1]) ? (t[0] < t[2] ? 0 : 2) : (t[1] < t[2] ? 1 : 2);
  return {{t[m], t[(m + 1) % 3], t[(m + 2) % 3]}};
}

// The mesh's faces by their oriented keys, bucketed by the key's first (smallest) vertex: a
// lookup compares the few faces of one vertex (faster than a hash table on large meshes).
class Face_lookup
{
public:
  Face_lookup(const std::vector<std::array<std::size_t, 3> >& faces, std::size_t number_of_vertices)
    : begin_(number_of_vertices + 1, 0), keys_(faces.size()), face_(faces.size())
  {
    for(const auto& t : faces)
      ++begin_[oriented_key(t)[0] + 1];
    std::partial_sum(begin_.begin(), begin_.end(), begin_.begin());
    std::vector<std::size_t> fill(begin_.begin(), begin_.end() - 1);
    for(std::size_t f = 0; f < faces.size(); ++f) {
      const std::array<std::size_t, 3> k = oriented_key(faces[f]);
      keys_[fill[k[0]]] = k;
      face_[fill[k[0]]++] = f;
    }
  }
  // the face with this oriented triangle (vertices below the mesh's number), or none
  std::size_t find(const std::array<std::size_t, 3>& t) const
  {
    const std::array<std::size_t, 3> k = oriented_key(t);
    for(std::size_t i = begin_[k[0]]; i < begin_[k[0] + 1]; ++i)
      if(keys_[i] == k)
        return face_[i];
    return none;
  }
  static constexpr std::size_t none = std::size_t(-1);

private:
  std::vector<std::size_t> begin_;
  std::vector<std::array<std::size_t, 3> > keys_;
  std::vector<std::size_t> face_;
};

inline std::string triangle_string(const std::array<std::size_t, 3>& t)
{
  return "(" + std::to_string(t[0]) + ", " + std::to_string(t[1]) + ", " + std::to_string(t[2]) + ")";
}

// Matches the embedding's faces with the mesh's (checks repeated_face and mesh_faces): for each
// mesh face, the embedding face and the rotation r with embedding corner (c + r) mod 3 at mesh
// corner c. Returns false when a face is repeated, foreign, reversed or missing.
template <class TriangleMesh>
bool match_faces(const Indexed_mesh<TriangleMesh>& M, const Corner_embedding& E, Corner_embedding_certificate& cert,
                 std::vector<std::size_t>& embedding_face, std::vector<int>& rotation)
{
  typedef Corner_embedding_certificate Cert;
  const std::size_t F = M.number_of_faces(), V = M.number_of_vertices(), none = std::size_t(-1);
  const Face_lookup mesh_face(M.face_vertices, V);
  embedding_face.assign(F, none);
  rotation.assign(F, 0);
  cert.checks[Repeated_face_check].run = cert.checks[Mesh_face_check].run = true;
  for(std::size_t e = 0; e < E.number_of_faces(); ++e) {
    const std::array<std::size_t, 3>& t = E.face_vertices[e];
    ++cert.checks[Repeated_face_check].checked;
    ++cert.checks[Mesh_face_check].checked;
    if(t[0] >= V || t[1] >= V || t[2] >= V) {
      record(cert, Mesh_face_check, Cert::Face, e, 0, "face " + std::to_string(e) + " " + triangle_string(t) +
             " has a vertex index beyond the mesh's " + std::to_string(V) + " vertices");
      continue;
    }
    if(t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) {
      record(cert, Mesh_face_check, Cert::Face, e, 0, "face " + std::to_string(e) + " " + triangle_string(t) +
             " repeats a vertex: it is not a face of the mesh");
      continue;
    }
    const std::size_t f = mesh_face.find(t);
    if(f == none) {
      const std::size_t rev = mesh_face.find({{t[0], t[2], t[1]}});
      if(rev != none)
        record(cert, Mesh_face_check, Cert::Face, e, 0, "face " + std::to_string(e) + " " + triangle_string(t) +
               " has the opposite orientation of the mesh's face " + std::to_string(rev));
      else
        record(cert, Mesh_face_check, Cert::Face, e, 0, "face " + std::to_string(e) + " " + triangle_string(t) +
               " is not a face of the mesh");
      continue;
    }
    if(embedding_face[f] != none) {
      record(cert, Repeated_face_check, Cert::Face, e, 0, "face " + std::to_string(e) + " " + triangle_string(t) +
             " repeats face " + std::to_string(embedding_face[f]));
      continue;
    }
    embedding_face[f] = e;
    int r = 0;
    while(t[r] != M.face_vertices[f][0])
      ++r;
    rotation[f] = r;
  }
  for(std::size_t f = 0; f < F; ++f)
    if(embedding_face[f] == none)
      record(cert, Mesh_face_check, Cert::Mesh_face, f, 0, "the mesh's face " + std::to_string(f) + " " +
             triangle_string(M.face_vertices[f]) + " is not in the embedding");
  return cert.checks[Repeated_face_check].failures == 0 && cert.checks[Mesh_face_check].failures == 0;
}

} // namespace corner_certificate
} // namespace internal
} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_CERTIFIER_CORNER_EMBEDDING_TOPOLOGY_H
