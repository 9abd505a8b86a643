// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_SOLVER_FLAT_PROBLEM_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_SOLVER_FLAT_PROBLEM_H

#include <CGAL/Hyperbolic_orbifold_Tutte/Orbifold_tile.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/error_code.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/core/dense_index.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/core/disk_models.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/solver/hyperbolic_energy.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/core/mesh_graph.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <array>
#include <string>
#include <vector>

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {
namespace internal {

// The cut mesh (a topological disk) as plain arrays, with what each vertex is in the
// orbifold: a cone copy fixed at a tile corner, a free interior vertex, a seam vertex
// tied to its twin by a side pairing, or a disk-boundary vertex sliding on a side.
struct Flat_problem
{
  typedef std::complex<double> C;
  typedef Hyperbolic_isometry_2<double> Isometry;

  Orbifold_type type = Sphere_type;
  int k = 0;
  int n = 0;                                 // cut-mesh (seam-mesh) vertices
  std::vector<std::array<int, 3> > faces;    // counterclockwise in the mesh's orientation
  std::vector<int> base;                     // base-mesh vertex index of each cut-mesh vertex
  int n_base = 0;
  std::vector<int> border_loop;              // counterclockwise, starting at the first landmark's copy
  std::vector<int> side;                     // tile side of a border vertex (-1: interior or corner)
  std::vector<int> corner;                   // tile corner of a cone copy (-1 otherwise)
  std::vector<double> border_param;          // position along its side in [0,1] (initialisation)
  std::vector<Position_kind> kind;
  std::vector<int> var;                      // first variable (Free, On_line)
  std::vector<int> twin;                     // Transformed: the vertex whose variables it uses
  std::vector<Isometry> transform;           // Transformed: z = transform(z_twin)
  std::vector<C> fixed;                      // Fixed: position
  std::vector<C> line_k0, line_D;            // On_line: Klein segment of the side
  std::vector<std::array<int, 2> > edges;    // each cut-mesh edge once
  std::vector<double> edge_weight;           // with seam copies halved (each base edge counts once)
  int n_vars = 0;
  bool landmark_order_reversed = false;      // disk type: given order was clockwise
  std::vector<int> problem_vertices;         // base-mesh indices named by an error (e.g. a boundary chord)
};

// Position of vertex v (and derivatives) for the variable vector x.
inline void position_jet(const Flat_problem& P, const std::vector<double>& x, int v, Position_jet& jet)
{
  typedef std::complex<double> C;
  switch(P.kind[v]) {
    case Fixed:
      jet.z = P.fixed[v];
      jet.dim = 0;
      break;
    case Free:
      jet.z = C(x[P.var[v]], x[P.var[v] + 1]);
      jet.dim = 2;
      jet.dz[0] = C(1, 0);
      jet.dz[1] = C(0, 1);
      jet.ddz[0][0] = jet.ddz[0][1] = jet.ddz[1][0] = jet.ddz[1][1] = C();
      break;
    case Transformed: {
      const int t = P.twin[v];
      transformed_jet(P.transform[v], C(x[P.var[t]], x[P.var[t] + 1]), jet);
      break;
    }
    case On_line:
      on_line_jet(P.line_k0[v], P.line_D[v], x[P.var[v]], jet);
      break;
  }
}

inline std::complex<double> position(const Flat_problem& P, const std::vector<double>& x, int v)
{
  typedef std::complex<double> C;
  switch(P.kind[v]) {
    case Fixed: return P.fixed[v];
    case Free: return C(x[P.var[v]], x[P.var[v] + 1]);
    case Transformed: return P.transform[v].apply(C(x[P.var[P.twin[v]]], x[P.var[P.twin[v]] + 1]));
    case On_line: {
      return klein_to_poincare(P.line_k0[v] + x[P.var[v]] * P.line_D[v]);
    }
  }
  return C();
}

// the vertex whose variables v uses: its twin for a seam copy, else v itself
inline int owner_vertex(const Flat_problem& P, int v)
{
  return P.kind[v] == Transformed ? P.twin[v] : v;
}

// the first variable index of the vertex that owns v's variables, or -1
inline int variable_owner(const Flat_problem& P, int v)
{
  switch(P.kind[v]) {
    case Free:
    case On_line: return P.var[v];
    case Transformed: return P.var[P.twin[v]];
    default: return -1;
  }
}

// The dense numbering of the vertices of a seam mesh (by their canonical halfedge of tm: a
// Seam_mesh vertex descriptor is a halfedge of tm, not on the seam) and of its base mesh
// (a vertex's base index is its position in vertices(tm)).
template <class SeamMesh>
struct Cut_mesh_numbering
{
  typedef typename SeamMesh::TriangleMesh TM;
  typedef typename boost::graph_traits<SeamMesh>::vertex_descriptor vertex_descriptor;
  typedef typename boost::graph_traits<TM>::vertex_descriptor tm_vertex_descriptor;
  typedef typename boost::graph_traits<TM>::halfedge_descriptor tm_halfedge_descriptor;

  const Dense_index<tm_vertex_descriptor> base_of;
  const Dense_index<tm_halfedge_descriptor> hindex;
  std::vector<int> vindex; // seam-mesh vertex index of each halfedge of tm (-1: none)

  explicit Cut_mesh_numbering(const TM& tm)
    : base_of(vertices(tm)), hindex(halfedges(tm)), vindex(hindex.size(), -1)
  {}

  // the cut-mesh index of a seam-mesh vertex, or -1
  int operator()(vertex_descriptor vd) const
  {
    const std::size_t i = hindex(vd.hd.tmhd);
    return i == Dense_index<tm_halfedge_descriptor>::npos ? -1 : vindex[i];
  }
};

// Numbers the vertices of `mesh` (`cut_vertices`, P.n, P.base) and of its base mesh
// (`base_vertex`, P.n_base).
template <class SeamMesh>
void number_cut_mesh(const SeamMesh& mesh, Cut_mesh_numbering<SeamMesh>& numbering, Flat_problem& P,
                     std::vector<typename boost::graph_traits<typename SeamMesh::TriangleMesh>::vertex_descriptor>& base_vertex,
                     std::vector<typename boost::graph_traits<SeamMesh>::vertex_descriptor>& cut_vertices)
{
  const typename SeamMesh::TriangleMesh& tm = mesh.mesh();
  base_vertex.assign(vertices(tm).begin(), vertices(tm).end());
  P.n_base = static_cast<int>(base_vertex.size());
  cut_vertices.clear();
  for(auto vd : vertices(mesh)) {
    numbering.vindex[numbering.hindex(vd.hd.tmhd)] = static_cast<int>(cut_vertices.size());
    cut_vertices.push_back(vd);
  }
  P.n = static_cast<int>(cut_vertices.size());
  P.base.resize(P.n);
  for(int i = 0; i < P.n; ++i)
    P.base[i] = static_cast<int>(numbering.base_of(target(cut_vertices[i].hd.tmhd, tm)));
}

// The triangles of `mesh` (P.faces) and its edges, each once (P.edges, from the halfedge
// with the smaller index pair).
template <class SeamMesh>
Error_code flat_faces_and_edges(const SeamMesh& mesh, const Cut_mesh_numbering<SeamMesh>& numbering,
                                Flat_problem& P, std::string& message)
{
  P.faces.reserve(num_faces(mesh.mesh()));
  for(auto f : faces(mesh)) {
    std::array<int, 3> t;
    int j = 0;
    for(auto h : halfedges_around_face(halfedge(f, mesh), mesh)) {
      if(j < 3)
        t[j] = numbering(target(h, mesh));
      ++j;
    }
    if(j != 3 || t[0] < 0 || t[1] < 0 || t[2] < 0) {
      message = "the mesh has a face that is not a triangle";
      return ERROR_NON_TRIANGULAR_MESH;
    }
    P.faces.push_back(t);
  }

  std::vector<std::vector<int> > adj(P.n);
  for(const auto& t : P.faces)
    for(int e = 0; e < 3; ++e) {
      const int a = t[e], b = t[(e + 1) % 3];
      adj[std::min(a, b)].push_back(std::max(a, b));
    }
  for(int a = 0; a < P.n; ++a) {
    std::sort(adj[a].begin(), adj[a].end());
    adj[a].erase(std::unique(adj[a].begin(), adj[a].end()), adj[a].end());
    for(int b : adj[a])
      P.edges.push_back({a, b});
  }
  return OK;
}

// The border loop of `mesh` through `bhd`, counterclockwise (next() walks border halfedges
// with the mesh on their right: the walk is reversed), as cut-mesh vertex indices.
template <class SeamMesh>
Error_code flat_border_loop(const SeamMesh& mesh, typename boost::graph_traits<SeamMesh>::halfedge_descriptor bhd,
                            const Cut_mesh_numbering<SeamMesh>& numbering, const Flat_problem& P,
                            std::vector<int>& loop, std::string& message)
{
  if(!is_border(bhd, mesh)) {
    message = "the given halfedge is not on the border of the cut mesh";
    return ERROR_WRONG_PARAMETER;
  }
  loop.clear();
  if(!walk_next_cycle(bhd, mesh, static_cast<std::size_t>(P.n) + 1,
                      [&](typename boost::graph_traits<SeamMesh>::halfedge_descriptor h) {
                        loop.push_back(numbering(target(h, mesh)));
                        return true;
                      })) {
    message = "the border of the cut mesh is not a simple loop";
    return ERROR_CUT_FAILED;
  }
  std::reverse(loop.begin(), loop.end());
  std::vector<char> seen(P.n, 0);
  for(int v : loop) {
    if(v < 0 || seen[v]) {
      message = "the border of the cut mesh is not a simple loop";
      return ERROR_CUT_FAILED;
    }
    seen[v] = 1;
  }
  return OK;
}

// Checks that the border loop holds one copy of each tile corner's cone, in the tile's
// order (disk type: or the reverse order, then P.landmark_order_reversed), and rotates it
// to start at a copy of cone 0 (P.border_loop); `loop_cone_pos` gets the sorted positions
// of the cone copies along it.
template <class TMVertex, class Tile, class BaseIndex>
Error_code start_border_loop_at_first_landmark(const std::vector<TMVertex>& landmarks, const Tile& tile,
                                               const BaseIndex& base_of, Flat_problem& P,
                                               std::vector<int>& loop, std::vector<int>& loop_cone_pos,
                                               std::string& message)
{
  const int k = static_cast<int>(landmarks.size());
  // cone index of each base vertex
  std::vector<int> cone_of_base(P.n_base, -1);
  for(int c = 0; c < k; ++c) {
    const std::size_t b = base_of(landmarks[c]);
    if(b == BaseIndex::npos) {
      message = "a landmark is not a vertex of the mesh";
      return ERROR_LANDMARK_OUT_OF_RANGE;
    }
    cone_of_base[b] = c;
  }

  // Positions of cone copies along the loop, in loop order.
  loop_cone_pos.clear(); // indices into loop
  for(std::size_t i = 0; i < loop.size(); ++i)
    if(cone_of_base[P.base[loop[i]]] >= 0)
      loop_cone_pos.push_back(static_cast<int>(i));

  // Expected cone sequence along the counterclockwise loop: the tile's corner cones.
  const int nc = tile.number_of_corners();
  std::vector<int> expected(nc);
  for(int i = 0; i < nc; ++i)
    expected[i] = tile.corner_cone(i);

  if(static_cast<int>(loop_cone_pos.size()) != nc) {
    message = "the border of the cut mesh holds " + std::to_string(loop_cone_pos.size()) +
              " landmark copies, the orbifold tile has " + std::to_string(nc) + " corners";
    return tile.type() == Disk_type ? ERROR_LANDMARK_NOT_ON_BORDER : ERROR_CUT_FAILED;
  }
  // rotate so that the loop starts at a copy of cone 0
  int start = -1;
  for(int i = 0; i < nc; ++i)
    if(cone_of_base[P.base[loop[loop_cone_pos[i]]]] == 0) {
      start = i;
      break;
    }
  std::vector<int> seq(nc);
  for(int i = 0; i < nc; ++i)
    seq[i] = cone_of_base[P.base[loop[loop_cone_pos[(start + i) % nc]]]];
  if(seq != expected) {
    bool ok = false;
    if(tile.type() == Disk_type) {
      // a clockwise order is accepted: landmark c then goes to corner (k - c) mod k
      std::vector<int> rev(nc);
      for(int i = 0; i < nc; ++i)
        rev[i] = (k - seq[i]) % k;
      if(rev == expected) {
        ok = true;
        P.landmark_order_reversed = true;
      }
    }
    if(!ok) {
      message = tile.type() == Disk_type
                  ? "the landmarks are not in boundary order (clockwise or counterclockwise)"
                  : "the cut does not visit the landmarks in order p1 -> ... -> pk and back";
      return ERROR_CUT_FAILED;
    }
  }
  const int shift = loop_cone_pos[start];
  std::rotate(loop.begin(), loop.begin() + shift, loop.end());
  P.border_loop = loop;
  for(int& p : loop_cone_pos)
    p = (p - shift + static_cast<int>(loop.size())) % static_cast<int>(loop.size());
  std::sort(loop_cone_pos.begin(), loop_cone_pos.end());
  return OK;
}

// Sizes the per-vertex arrays of P, fixes the cone copies at the tile corners and gives
// every other border vertex its tile side.
template <class Tile>
void place_corners_and_sides(const Tile& tile, const std::vector<int>& loop,
                             const std::vector<int>& loop_cone_pos, Flat_problem& P)
{
  typedef std::complex<double> C;
  P.side.assign(P.n, -1);
  P.corner.assign(P.n, -1);
  P.border_param.assign(P.n, 0.0);
  P.kind.assign(P.n, Free);
  P.var.assign(P.n, -1);
  P.twin.assign(P.n, -1);
  P.transform.assign(P.n, Hyperbolic_isometry_2<double>());
  P.fixed.assign(P.n, C());
  P.line_k0.assign(P.n, C());
  P.line_D.assign(P.n, C());

  const int nc = tile.number_of_corners();
  const int L = static_cast<int>(loop.size());
  for(int s = 0; s < nc; ++s) {
    const int a = loop_cone_pos[s], b = (s + 1 < nc) ? loop_cone_pos[s + 1] : L;
    P.corner[loop[a]] = s;
    P.kind[loop[a]] = Fixed;
    P.fixed[loop[a]] = C(CGAL::to_double(tile.corner(s).x()), CGAL::to_double(tile.corner(s).y()));
    for(int i = a + 1; i < b; ++i)
      P.side[loop[i]] = s;
  }
}

// The constraints of the border vertices: sphere type, seam twins (q-side vertices are
// images of their p-side copies); disk type, sliding on the Klein segment of their side.
template <class Tile>
Error_code constrain_border_vertices(const Tile& tile, const std::vector<int>& loop, Flat_problem& P,
                                     std::string& message)
{
  typedef std::complex<double> C;
  const int k = P.k;
  if(tile.type() == Sphere_type) {
    std::vector<int> p_copy(P.n_base, -1);
    for(int v : loop)
      if(P.side[v] >= 0 && P.side[v] <= k - 2)
        p_copy[P.base[v]] = v;
    for(int v : loop) {
      const int s = P.side[v];
      if(s >= k - 1) {
        const int t = p_copy[P.base[v]];
        const int ps = tile.paired_side(s);
        if(t < 0 || P.side[t] != ps) {
          message = "a seam vertex has no twin on the paired side of the cut";
          return ERROR_CUT_FAILED;
        }
        P.kind[v] = Transformed;
        P.twin[v] = t;
        P.transform[v] = tile.side_pairing(ps); // maps side ps onto side s
      }
    }
  } else {
    for(int v : loop)
      if(P.side[v] >= 0) {
        const int s = P.side[v];
        P.kind[v] = On_line;
        const auto K = tile.traits().construct_Klein_point_2_object(); // (the tile's traits)
        const auto k0 = K(tile.corner(tile.side_source(s)));
        const auto k1 = K(tile.corner(tile.side_target(s)));
        P.line_k0[v] = C(CGAL::to_double(k0.x()), CGAL::to_double(k0.y()));
        P.line_D[v] = C(CGAL::to_double(k1.x() - k0.x()), CGAL::to_double(k1.y() - k0.y()));
      }
  }
  return OK;
}

// Disk type: an inner edge (not on the border loop) whose two ends lie on one closed
// tile side bounds, with the border, a region that the embedding must flatten onto a
// straight Klein segment: its triangles would be degenerate. Refuse such input.
template <class Tile>
Error_code check_boundary_chords(const Tile& tile, const std::vector<int>& loop, Flat_problem& P,
                                 std::string& message)
{
  const int nc = tile.number_of_corners();
  const int L = static_cast<int>(loop.size());
  std::vector<int> loop_pos(P.n, -1);
  for(int i = 0; i < L; ++i)
    loop_pos[loop[i]] = i;
  auto on_closed_side = [&](int v, int s) {
    if(P.side[v] == s)
      return true;
    const int c = P.corner[v];
    return c >= 0 && (c == tile.side_source(s) || c == tile.side_target(s));
  };
  for(const auto& e : P.edges) {
    const int a = e[0], b = e[1];
    if(loop_pos[a] < 0 || loop_pos[b] < 0)
      continue;
    const int d = std::abs(loop_pos[a] - loop_pos[b]);
    if(d == 1 || d == L - 1)
      continue; // a border edge
    for(int s = 0; s < nc; ++s)
      if(on_closed_side(a, s) && on_closed_side(b, s)) {
        P.problem_vertices = {P.base[a], P.base[b]};
        message = "the inner edge between mesh vertices " + std::to_string(P.base[a]) + " and " +
                  std::to_string(P.base[b]) + " joins two boundary vertices of tile side " + std::to_string(s) +
                  " (between landmarks " + std::to_string(s) + " and " + std::to_string((s + 1) % nc) +
                  "): its triangles would be degenerate; put a landmark on the boundary between its ends, or split it";
        return ERROR_BOUNDARY_CHORD;
      }
  }
  return OK;
}

// The variables: two per free vertex, one per vertex sliding on a side.
inline void number_variables(Flat_problem& P)
{
  P.n_vars = 0;
  for(int v = 0; v < P.n; ++v) {
    if(P.kind[v] == Free) {
      P.var[v] = P.n_vars;
      P.n_vars += 2;
    } else if(P.kind[v] == On_line) {
      P.var[v] = P.n_vars;
      P.n_vars += 1;
    }
  }
}

// Builds the topology part of a Flat_problem from a seam mesh (a topological disk) whose
// border loop goes through copies of the landmarks. `landmarks` are base-mesh vertices in
// cone order. Fills faces, base, border_loop, side, corner, kind, var, twin, transform,
// fixed, line_k0/D, edges (weights are set by the caller); `base_vertex`: the mesh vertex of
// each base index (the order of vertices(tm)).
template <class SeamMesh, class Tile>
Error_code build_flat_topology(const SeamMesh& mesh,
                               typename boost::graph_traits<SeamMesh>::halfedge_descriptor bhd,
                               const std::vector<typename boost::graph_traits<typename SeamMesh::TriangleMesh>::vertex_descriptor>& landmarks,
                               const Tile& tile,
                               Flat_problem& P,
                               std::vector<typename boost::graph_traits<typename SeamMesh::TriangleMesh>::vertex_descriptor>& base_vertex,
                               std::vector<typename boost::graph_traits<SeamMesh>::vertex_descriptor>& cut_vertices,
                               std::string& message)
{
  P = Flat_problem();
  P.type = tile.type();
  P.k = static_cast<int>(landmarks.size());

  Cut_mesh_numbering<SeamMesh> numbering(mesh.mesh());
  number_cut_mesh(mesh, numbering, P, base_vertex, cut_vertices);
  Error_code ec = flat_faces_and_edges(mesh, numbering, P, message);
  std::vector<int> loop, loop_cone_pos;
  if(ec == OK)
    ec = flat_border_loop(mesh, bhd, numbering, P, loop, message);
  if(ec == OK)
    ec = start_border_loop_at_first_landmark(landmarks, tile, numbering.base_of, P, loop, loop_cone_pos, message);
  if(ec != OK)
    return ec;
  place_corners_and_sides(tile, loop, loop_cone_pos, P);
  ec = constrain_border_vertices(tile, loop, P, message);
  if(ec == OK && tile.type() == Disk_type)
    ec = check_boundary_chords(tile, loop, P, message);
  if(ec != OK)
    return ec;
  number_variables(P);
  return OK;
}

} // namespace internal
} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_SOLVER_FLAT_PROBLEM_H
