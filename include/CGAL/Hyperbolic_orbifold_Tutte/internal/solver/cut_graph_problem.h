// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_SOLVER_CUT_GRAPH_PROBLEM_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_SOLVER_CUT_GRAPH_PROBLEM_H

// A closed mesh of genus g >= 1 cut open along a graph (internal/input/genus_cut.h): the polygon
// that the border of the cut mesh becomes (its corners: the copies of the graph's nodes; its
// sides: the copies of the graph's edges, glued in pairs), its tile (make_cut_graph_tile())
// and the flat problem: cones fixed at their corners; every other vertex free, one copy of
// each cut vertex owning the variables and the other copies its images by group elements (a
// side pairing for a vertex inside a side; for a node, the product of side pairings that goes
// from the owner's corner to the copy's around the node's vertex cycle).

#include <CGAL/Hyperbolic_orbifold_Tutte/Orbifold_tile.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/error_code.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/solver/flat_problem.h>

#include <algorithm>
#include <string>
#include <unordered_map>
#include <vector>

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {
namespace internal {

// The border loop of a cut mesh as a polygon
struct Cut_polygon
{
  std::vector<int> loop;        // cut-mesh vertices, counterclockwise, starting at corner 0
  std::vector<int> corner_pos;  // position in `loop` of each corner
  std::vector<int> corner_node; // node of each corner
  std::vector<int> node_base;   // base vertex of each node
  std::vector<int> node_cone;   // cone of each node, or -1
  std::vector<int> paired_side; // side glued to each side
};

// The polygon of the border loop `loop` of P's cut mesh (P.n, P.base, P.n_base set), with
// `landmarks` the base indices of the cones. Corner 0 (so that two meshes cut along
// corresponding graphs get the same polygon): with a start edge (a, b) (base indices; the first
// edge of a cut graph given as paths), the corner where the border, running along the edge from
// a to b, last left a corner; otherwise the copy of the first landmark (else of the node with the
// smallest base index) whose side leaves it towards the smallest base index.
inline Status cut_polygon_of_loop(const Flat_problem& P, std::vector<int> loop, const std::vector<int>& landmarks,
                                  std::pair<int, int> start_edge, Cut_polygon& poly)
{
  poly = Cut_polygon();
  const int L = static_cast<int>(loop.size());
  std::vector<int> copies(P.n_base, 0), cone_of_base(P.n_base, -1);
  for(int v : loop)
    ++copies[P.base[v]];
  for(std::size_t c = 0; c < landmarks.size(); ++c) {
    cone_of_base[landmarks[c]] = static_cast<int>(c);
    if(copies[landmarks[c]] == 0)
      return Status::failure(ERROR_CUT_FAILED, "landmark " + std::to_string(c) + " (mesh vertex " +
                                                 std::to_string(landmarks[c]) + ") is not on the cut");
  }
  auto is_corner = [&](int v) { return cone_of_base[P.base[v]] >= 0 || copies[P.base[v]] != 2; };
  auto base_at = [&](int i) { return P.base[loop[((i % L) + L) % L]]; };
  int start = -1;
  if(start_edge.first >= 0) {
    for(int i = 0; i < L && start < 0; ++i)
      if(base_at(i) == start_edge.first && base_at(i + 1) == start_edge.second)
        start = i;
    if(start < 0)
      return Status::failure(ERROR_CUT_FAILED, "the first edge of the cut graph (mesh vertices " + std::to_string(start_edge.first) +
                                                 " to " + std::to_string(start_edge.second) + ") is not on the cut");
    for(int j = 0; j < L && !is_corner(loop[start]); ++j)
      start = (start + L - 1) % L;
  } else {
    int a = landmarks.empty() ? -1 : landmarks[0];
    if(a < 0)
      for(int i = 0; i < L; ++i)
        if(is_corner(loop[i]) && (a < 0 || base_at(i) < a))
          a = base_at(i);
    for(int i = 0; i < L; ++i)
      if(base_at(i) == a && (start < 0 || base_at(i + 1) < base_at(start + 1)))
        start = i;
  }
  if(start < 0 || !is_corner(loop[start]))
    return Status::failure(ERROR_CUT_FAILED, "the border of the cut mesh has no corner: the cut graph is a single loop");
  std::rotate(loop.begin(), loop.begin() + start, loop.end());
  std::unordered_map<int, int> node_of_base;
  for(int i = 0; i < L; ++i)
    if(is_corner(loop[i])) {
      const int b = P.base[loop[i]];
      auto it = node_of_base.find(b);
      if(it == node_of_base.end()) {
        it = node_of_base.emplace(b, static_cast<int>(poly.node_base.size())).first;
        poly.node_base.push_back(b);
        poly.node_cone.push_back(cone_of_base[b]);
      }
      poly.corner_pos.push_back(i);
      poly.corner_node.push_back(it->second);
    }
  const int n = static_cast<int>(poly.corner_pos.size());
  // sides: from corner s to corner s+1; each is glued to the side that runs along its edges backwards
  auto key = [](int a, int b) { return (static_cast<long long>(a) << 32) | static_cast<unsigned int>(b); };
  std::unordered_map<long long, int> side_of_first_edge;
  for(int s = 0; s < n; ++s) {
    const int a = poly.corner_pos[s];
    if(!side_of_first_edge.emplace(key(P.base[loop[a]], P.base[loop[(a + 1) % L]]), s).second)
      return Status::failure(ERROR_CUT_FAILED, "the cut graph runs twice along an edge in one direction");
  }
  poly.paired_side.assign(n, -1);
  for(int s = 0; s < n; ++s) {
    const int a = poly.corner_pos[s], b = (s + 1 < n) ? poly.corner_pos[s + 1] : L;
    const auto it = side_of_first_edge.find(key(P.base[loop[b % L]], P.base[loop[b - 1]]));
    bool ok = it != side_of_first_edge.end();
    if(ok) { // the same base vertices, backwards
      const int t = it->second;
      const int ta = poly.corner_pos[t], tb = (t + 1 < n) ? poly.corner_pos[t + 1] : L;
      ok = tb - ta == b - a;
      for(int j = 0; ok && j <= b - a; ++j)
        ok = P.base[loop[(a + j) % L]] == P.base[loop[(tb - j) % L]];
      if(ok)
        poly.paired_side[s] = t;
    }
    if(!ok)
      return Status::failure(ERROR_CUT_FAILED, "a side of the cut mesh's border has no twin side: the seams are not a cut graph");
  }
  poly.loop.swap(loop);
  return Status();
}

// The flat problem of the cut mesh whose polygon is `poly`, with its tile `tile`
// (make_cut_graph_tile() of the same polygon).
template <class Tile>
Status constrain_cut_polygon(const Cut_polygon& poly, const Tile& tile, Flat_problem& P)
{
  typedef std::complex<double> C;
  typedef Hyperbolic_isometry_2<double> Isometry;
  const std::vector<int>& loop = poly.loop;
  const int L = static_cast<int>(loop.size());
  const int n = static_cast<int>(poly.corner_pos.size());
  P.border_loop = loop;
  P.side.assign(P.n, -1);
  P.corner.assign(P.n, -1);
  P.border_param.assign(P.n, 0.0);
  P.kind.assign(P.n, Free);
  P.var.assign(P.n, -1);
  P.twin.assign(P.n, -1);
  P.transform.assign(P.n, Isometry());
  P.fixed.assign(P.n, C());
  P.line_k0.assign(P.n, C());
  P.line_D.assign(P.n, C());
  auto corner_point = [&](int c) { return C(CGAL::to_double(tile.corner(c).x()), CGAL::to_double(tile.corner(c).y())); };
  for(int s = 0; s < n; ++s) {
    const int a = poly.corner_pos[s], b = (s + 1 < n) ? poly.corner_pos[s + 1] : L;
    const int v = loop[a];
    P.corner[v] = s;
    P.fixed[v] = corner_point(s); // (cones stay there; the other corners start there)
    if(poly.node_cone[poly.corner_node[s]] >= 0)
      P.kind[v] = Fixed;
    for(int i = a + 1; i < b; ++i)
      P.side[loop[i]] = s;
    // inside a side: the copies on the side of larger index are images of the other's
    const int t = poly.paired_side[s];
    if(t < s) {
      const int ta = poly.corner_pos[t], tb = (t + 1 < n) ? poly.corner_pos[t + 1] : L;
      for(int j = 1; j < b - a; ++j) {
        const int w = loop[a + j], owner = loop[tb - j];
        P.kind[w] = Transformed;
        P.twin[w] = owner;
        P.transform[w] = tile.side_pairing(t); // maps side t onto side s
      }
      (void)ta;
    }
  }
  // nodes that are no cone: the first copy owns the variables; a copy at corner c at
  // T(owner) gives copies at the neighbouring corners of its vertex cycle: side c goes onto
  // side j = paired(c), corner c to corner j+1; side c-1 onto j' = paired(c-1), corner c to j'
  std::vector<char> done(n, 0);
  std::vector<Isometry> T(n);
  for(int c0 = 0; c0 < n; ++c0) {
    if(done[c0] || poly.node_cone[poly.corner_node[c0]] >= 0)
      continue;
    done[c0] = 1;
    T[c0] = Isometry();
    std::vector<int> stack(1, c0);
    while(!stack.empty()) {
      const int c = stack.back();
      stack.pop_back();
      const int j = poly.paired_side[c], jp = poly.paired_side[(c + n - 1) % n];
      const int next[2] = {(j + 1) % n, jp};
      const Isometry g[2] = {tile.side_pairing(c), tile.side_pairing((c + n - 1) % n)};
      for(int q = 0; q < 2; ++q)
        if(!done[next[q]]) {
          done[next[q]] = 1;
          T[next[q]] = g[q] * T[c];
          stack.push_back(next[q]);
        }
    }
    for(int c = 0; c < n; ++c)
      if(c != c0 && poly.corner_node[c] == poly.corner_node[c0]) {
        const int w = loop[poly.corner_pos[c]];
        if(!done[c])
          return Status::failure(ERROR_CUT_FAILED, "a node's copies do not form one vertex cycle");
        P.kind[w] = Transformed;
        P.twin[w] = loop[poly.corner_pos[c0]];
        P.transform[w] = T[c];
      }
  }
  number_variables(P);
  return Status();
}

// The base indices of `landmarks` (numbered as P.base is)
template <class TMVertex, class BaseIndex>
Status landmark_base_indices(const std::vector<TMVertex>& landmarks, const BaseIndex& base_of, std::vector<int>& idx)
{
  idx.clear();
  for(const TMVertex& v : landmarks) {
    const std::size_t b = base_of(v);
    if(b == BaseIndex::npos)
      return Status::failure(ERROR_LANDMARK_OUT_OF_RANGE, "a landmark is not a vertex of the mesh");
    idx.push_back(static_cast<int>(b));
  }
  return Status();
}

// Numbers the cut mesh, its faces, edges and border loop and finds its polygon
template <class SeamMesh>
Status analyse_cut_graph_mesh(const SeamMesh& mesh, typename boost::graph_traits<SeamMesh>::halfedge_descriptor bhd,
                              const std::vector<typename boost::graph_traits<typename SeamMesh::TriangleMesh>::vertex_descriptor>& landmarks,
                              std::pair<int, int> start_edge, Flat_problem& P, Cut_polygon& poly,
                              std::vector<typename boost::graph_traits<typename SeamMesh::TriangleMesh>::vertex_descriptor>& base_vertex,
                              std::vector<typename boost::graph_traits<SeamMesh>::vertex_descriptor>& cut_vertices)
{
  P = Flat_problem();
  P.type = Sphere_type;
  P.k = static_cast<int>(landmarks.size());
  Cut_mesh_numbering<SeamMesh> numbering(mesh.mesh());
  number_cut_mesh(mesh, numbering, P, base_vertex, cut_vertices);
  std::string message;
  Error_code ec = flat_faces_and_edges(mesh, numbering, P, message);
  std::vector<int> loop;
  if(ec == OK)
    ec = flat_border_loop(mesh, bhd, numbering, P, loop, message);
  if(ec != OK)
    return Status::failure(ec, message);
  const long long chi = static_cast<long long>(P.n) - static_cast<long long>(P.edges.size()) + static_cast<long long>(P.faces.size());
  if(chi != 1)
    return Status::failure(ERROR_CUT_FAILED, "the seams do not cut the mesh into a disk (V-E+F of the cut mesh is " +
                                               std::to_string(chi) + "): the cut graph must join 2g handle loops and the landmarks");
  std::vector<int> lm;
  const Status r = landmark_base_indices(landmarks, numbering.base_of, lm);
  return r ? cut_polygon_of_loop(P, loop, lm, start_edge, poly) : r;
}

// The tile of a closed mesh of genus `genus` >= 1 cut open along a graph (the seams of `mesh`)
// with cones of orders `orders` at `landmarks`
template <class SeamMesh, class Tile>
Status cut_graph_tile(const SeamMesh& mesh, typename boost::graph_traits<SeamMesh>::halfedge_descriptor bhd,
                      const std::vector<typename boost::graph_traits<typename SeamMesh::TriangleMesh>::vertex_descriptor>& landmarks,
                      int genus, const std::vector<int>& orders, std::pair<int, int> start_edge, Tile& tile,
                      const typename Tile::Traits& traits, Cut_polygon& poly)
{
  Flat_problem P;
  std::vector<typename boost::graph_traits<typename SeamMesh::TriangleMesh>::vertex_descriptor> base_vertex;
  std::vector<typename boost::graph_traits<SeamMesh>::vertex_descriptor> cut_vertices;
  const Status r = analyse_cut_graph_mesh(mesh, bhd, landmarks, start_edge, P, poly, base_vertex, cut_vertices);
  if(!r)
    return r;
  const Orbifold_signature sig(genus, orders);
  const Error_code ec = make_cut_graph_tile(sig, poly.corner_node, poly.node_cone, poly.paired_side, tile, traits);
  if(ec == ERROR_NOT_HYPERBOLIC)
    return Status::failure(ec, "the orbifold of genus " + std::to_string(genus) + " with " + std::to_string(orders.size()) +
                                 " cones is not hyperbolic (genus 1 needs at least one cone)");
  if(ec != OK)
    return Status::failure(ERROR_CUT_FAILED, "the seams do not cut the mesh of genus " + std::to_string(genus) +
                                               " into a disk whose border is the polygon of a cut graph through the landmarks");
  return Status();
}

// The flat problem of such a cut mesh, for the tile cut_graph_tile() gave
template <class SeamMesh, class Tile>
Error_code build_cut_graph_topology(const SeamMesh& mesh, typename boost::graph_traits<SeamMesh>::halfedge_descriptor bhd,
                                    const std::vector<typename boost::graph_traits<typename SeamMesh::TriangleMesh>::vertex_descriptor>& landmarks,
                                    std::pair<int, int> start_edge, const Tile& tile, Flat_problem& P,
                                    std::vector<typename boost::graph_traits<typename SeamMesh::TriangleMesh>::vertex_descriptor>& base_vertex,
                                    std::vector<typename boost::graph_traits<SeamMesh>::vertex_descriptor>& cut_vertices,
                                    std::string& message)
{
  Cut_polygon poly;
  Status r = analyse_cut_graph_mesh(mesh, bhd, landmarks, start_edge, P, poly, base_vertex, cut_vertices);
  if(r && static_cast<int>(poly.corner_pos.size()) != tile.number_of_corners())
    r = Status::failure(ERROR_CUT_FAILED, "the tile does not belong to this cut");
  if(r)
    r = constrain_cut_polygon(poly, tile, P);
  if(!r) {
    message = r.message;
    return r.code;
  }
  return OK;
}

} // namespace internal
} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_SOLVER_CUT_GRAPH_PROBLEM_H
