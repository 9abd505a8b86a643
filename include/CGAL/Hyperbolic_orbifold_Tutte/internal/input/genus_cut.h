// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_INPUT_GENUS_CUT_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_INPUT_GENUS_CUT_H

// The cut of a closed mesh of genus g >= 1 into a disk through its landmarks: a tree-cotree
// construction (Eppstein 2003; with the loop lengths of Erickson and Whittlesey 2005 it gives
// the shortest system of loops through the root). T: the shortest-path tree from the root (the
// first landmark, else the first vertex); C: among the edges not in T, a spanning tree of the
// dual graph that keeps the longest loops out (maximum spanning tree by the length of the loop
// root -> u -> v -> root of each edge uv); the 2g edges in neither close the 2g handle loops.
// The cut graph is T with those edges, pruned of its leaves that are not landmarks: the handle
// loops through the root and the tree paths from the landmarks to it.

#include <CGAL/Hyperbolic_orbifold_Tutte/error_code.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/genus.h> // closed_mesh_genus
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/core/dense_index.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/core/mesh_graph.h>

#include <CGAL/boost/graph/helpers.h>

#include <algorithm>
#include <numeric>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {
namespace internal {

// The cut graph's edges as pairs of dense vertex indices (positions in vertices(tm)), for a
// closed connected manifold mesh of genus `genus` >= 1 and its landmarks.
template <class TriangleMesh, class VertexPointMap>
Status compute_genus_cut_graph(const TriangleMesh& tm, VertexPointMap vpm,
                               const std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>& landmarks,
                               long long genus, std::vector<std::pair<int, int> >& cut)
{
  typedef typename boost::graph_traits<TriangleMesh>::face_descriptor face_descriptor;
  cut.clear();
  const Mesh_graph<TriangleMesh> g(tm, vpm);
  const int n = static_cast<int>(g.size());
  if(n == 0 || genus < 1)
    return Status::failure(ERROR_WRONG_TOPOLOGY, "the cut graph of a surface of genus g >= 1 needs such a mesh");
  std::vector<int> lm;
  const std::string bad = landmark_indices(g, landmarks, lm);
  if(!bad.empty())
    return Status::failure(ERROR_LANDMARK_OUT_OF_RANGE, bad);
  const int root = lm.empty() ? 0 : lm[0];

  // T: the shortest-path tree
  Dijkstra_workspace ws;
  ws.init(static_cast<std::size_t>(n));
  ws.begin_run();
  dijkstra(g, ws, root, [](int) {}, [] { return false; });
  for(int v = 0; v < n; ++v)
    if(!ws.reached(v))
      return Status::failure(ERROR_SEVERAL_COMPONENTS, "the mesh is not connected");

  // C: a maximum spanning tree of the dual graph among the edges not in T (Kruskal)
  const Dense_index<face_descriptor> findex(faces(tm));
  struct Dual_edge
  {
    double loop;
    int a, b;   // vertices
    int fa, fb; // faces
  };
  std::vector<Dual_edge> dual;
  dual.reserve(num_edges(tm));
  for(auto e : edges(tm)) {
    const auto h = halfedge(e, tm);
    const int a = static_cast<int>(g.index(source(h, tm))), b = static_cast<int>(g.index(target(h, tm)));
    if(ws.pred[a] == b || ws.pred[b] == a)
      continue; // (a tree edge; of parallel edges between a and b, all are taken as tree edges)
    if(is_border(h, tm) || is_border(opposite(h, tm), tm))
      return Status::failure(ERROR_WRONG_TOPOLOGY, "the mesh has a border: a surface of genus g >= 1 must be closed");
    dual.push_back({ws.dist[a] + ws.dist[b] + g.euclidean_distance(a, b), a, b,
                    static_cast<int>(findex(face(h, tm))), static_cast<int>(findex(face(opposite(h, tm), tm)))});
  }
  std::stable_sort(dual.begin(), dual.end(), [](const Dual_edge& x, const Dual_edge& y) { return x.loop > y.loop; });
  std::vector<int> parent(findex.size());
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](int x) {
    while(parent[x] != x) {
      parent[x] = parent[parent[x]];
      x = parent[x];
    }
    return x;
  };
  std::vector<std::pair<int, int> > loops; // the edges in neither tree
  for(const Dual_edge& d : dual) {
    const int ra = find(d.fa), rb = find(d.fb);
    if(ra != rb)
      parent[ra] = rb;
    else
      loops.emplace_back(d.a, d.b);
  }
  if(static_cast<long long>(loops.size()) != 2 * genus)
    return Status::failure(ERROR_CUT_FAILED, "the tree-cotree cut left " + std::to_string(loops.size()) +
                                               " edges for the handle loops of a mesh of genus " + std::to_string(genus) +
                                               " (2g are needed): the mesh is not a closed connected manifold");

  // T with the loop edges, pruned of the leaves that are no landmarks
  std::vector<char> is_landmark(n, 0);
  for(int v : lm)
    is_landmark[v] = 1;
  std::vector<int> degree(n, 0);
  for(int v = 0; v < n; ++v)
    if(ws.pred[v] >= 0) {
      ++degree[v];
      ++degree[ws.pred[v]];
    }
  for(const auto& e : loops) {
    ++degree[e.first];
    ++degree[e.second];
  }
  std::vector<char> removed(n, 0); // (the tree edge from v to its parent)
  std::vector<int> stack;
  for(int v = 0; v < n; ++v)
    if(degree[v] == 1 && !is_landmark[v])
      stack.push_back(v);
  while(!stack.empty()) {
    const int v = stack.back();
    stack.pop_back();
    if(degree[v] != 1 || is_landmark[v])
      continue;
    // its one edge: to its parent, or the tree edge of a child (v is then the root)
    int other = -1;
    if(ws.pred[v] >= 0 && !removed[v]) {
      other = ws.pred[v];
      removed[v] = 1;
    } else {
      for(std::size_t e = g.offsets[v]; e < g.offsets[v + 1] && other < 0; ++e) {
        const int u = g.nbrs[e];
        if(ws.pred[u] == v && !removed[u]) {
          other = u;
          removed[u] = 1;
        }
      }
    }
    if(other < 0)
      continue; // (a loop edge never ends at a leaf: its two ends have degree >= 2)
    --degree[v];
    if(--degree[other] == 1 && !is_landmark[other])
      stack.push_back(other);
  }
  for(int v = 0; v < n; ++v)
    if(ws.pred[v] >= 0 && !removed[v])
      cut.emplace_back(ws.pred[v], v);
  cut.insert(cut.end(), loops.begin(), loops.end());
  return Status();
}

// The cut graph's edges (dense index pairs) as paths between its nodes (vertices of degree
// other than 2, and landmarks), each edge on one path; the first path starts at `first` when it
// is a node (the first landmark, the root), and every path goes from its smaller-index end
// unless it starts there. A cycle without node (impossible for a cut graph of genus >= 1) is
// given from its smallest vertex.
inline std::vector<std::vector<int> > cut_graph_paths(int n, const std::vector<std::pair<int, int> >& cut,
                                                      const std::vector<char>& is_landmark, int first)
{
  std::vector<std::vector<std::pair<int, int> > > adj(n); // (neighbour, edge)
  for(std::size_t e = 0; e < cut.size(); ++e) {
    adj[cut[e].first].emplace_back(cut[e].second, static_cast<int>(e));
    adj[cut[e].second].emplace_back(cut[e].first, static_cast<int>(e));
  }
  for(auto& a : adj)
    std::sort(a.begin(), a.end());
  auto is_node = [&](int v) { return !adj[v].empty() && (adj[v].size() != 2 || is_landmark[v]); };
  std::vector<char> used(cut.size(), 0);
  std::vector<std::vector<int> > paths;
  auto walk = [&](int v, std::size_t i) {
    std::vector<int> path(1, v);
    int e = adj[v][i].second, u = adj[v][i].first;
    used[e] = 1;
    path.push_back(u);
    while(!is_node(u) && path.front() != u) {
      int next = -1;
      for(const auto& ne : adj[u])
        if(!used[ne.second]) {
          next = ne.first;
          used[ne.second] = 1;
          break;
        }
      if(next < 0)
        break;
      u = next;
      path.push_back(u);
    }
    paths.push_back(path);
  };
  std::vector<int> order;
  if(first >= 0 && first < n && is_node(first))
    order.push_back(first);
  for(int v = 0; v < n; ++v)
    if(is_node(v))
      order.push_back(v);
  for(int v : order)
    for(std::size_t i = 0; i < adj[v].size(); ++i)
      if(!used[adj[v][i].second])
        walk(v, i);
  for(int v = 0; v < n; ++v) // (cycles without node)
    for(std::size_t i = 0; i < adj[v].size(); ++i)
      if(!used[adj[v][i].second])
        walk(v, i);
  return paths;
}

// Marks the cut graph's edges as seams of `mesh` (a Seam_mesh on tm).
template <class SeamMesh, class TriangleMesh>
bool add_cut_graph_to_seam_mesh(SeamMesh& mesh, const TriangleMesh& tm, const std::vector<std::pair<int, int> >& cut)
{
  const std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor> verts(vertices(tm).begin(),
                                                                                       vertices(tm).end());
  bool all = true;
  for(const auto& e : cut)
    if(!mesh.add_seam(verts[e.first], verts[e.second]))
      all = false;
  return all;
}


// compute_cut_graph() (cut_graph.h): the cut graph through the landmarks as vertex paths between
// its nodes, the first from the first landmark (else the node of smallest index) towards its
// neighbour of smallest index
template <class TriangleMesh, class VertexPointMap>
Status cut_graph_through_landmarks(const TriangleMesh& tm,
                                   const std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>& landmarks,
                                   VertexPointMap vpm,
                                   std::vector<std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor> >& paths)
{
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  paths.clear();
  const long long genus = closed_mesh_genus(tm);
  if(genus < 1)
    return Status::failure(ERROR_WRONG_TOPOLOGY, "a cut graph is for a closed mesh of genus 1 or more; this one has V-E+F = " +
                                                   std::to_string(euler_characteristic(tm)));
  std::vector<std::pair<int, int> > cut;
  const Status r = compute_genus_cut_graph(tm, vpm, landmarks, genus, cut);
  if(!r)
    return r;
  const std::vector<vertex_descriptor> verts(vertices(tm).begin(), vertices(tm).end());
  const Dense_index<vertex_descriptor> index(vertices(tm));
  std::vector<char> is_landmark(verts.size(), 0);
  for(vertex_descriptor v : landmarks) { // each a vertex: compute_genus_cut_graph() checked it
    const std::size_t i = index(v);
    if(i < is_landmark.size())
      is_landmark[i] = 1;
  }
  // the first path: from the first landmark, else from the node of smallest index, towards its
  // neighbour of smallest index (the default corner 0 of the tile: see set_cut_graph_start())
  const int first = landmarks.empty() ? -1 : static_cast<int>(index(landmarks[0]));
  for(const std::vector<int>& p : cut_graph_paths(static_cast<int>(verts.size()), cut, is_landmark, first)) {
    paths.emplace_back();
    for(int v : p)
      paths.back().push_back(verts[v]);
  }
  return Status();
}

// check_cut_graph() (cut_graph.h): a given cut graph's paths checked against the mesh and the
// landmarks (every path of 2 vertices or more along edges, no edge twice, every landmark on it)
template <class TriangleMesh>
Status check_cut_graph_paths(const TriangleMesh& tm,
                             const std::vector<std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor> >& paths,
                             const std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>& landmarks)
{
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  const Dense_index<vertex_descriptor> index(vertices(tm));
  if(paths.empty())
    return Status::failure(ERROR_WRONG_PARAMETER, "the cut graph has no path");
  std::set<std::pair<std::size_t, std::size_t> > seen;
  std::vector<char> on_graph(index.size(), 0);
  for(std::size_t i = 0; i < paths.size(); ++i) {
    const std::string which = "path " + std::to_string(i) + " of the cut graph";
    if(paths[i].size() < 2)
      return Status::failure(ERROR_WRONG_PARAMETER, which + " has fewer than 2 vertices");
    for(std::size_t j = 0; j < paths[i].size(); ++j) {
      const std::size_t a = index(paths[i][j]);
      if(a == index.npos)
        return Status::failure(ERROR_LANDMARK_OUT_OF_RANGE, which + ": its vertex " + std::to_string(j) + " is not a vertex of the mesh");
      on_graph[a] = 1;
      if(j == 0)
        continue;
      const std::size_t b = index(paths[i][j - 1]);
      if(!edge(paths[i][j - 1], paths[i][j], tm).second)
        return Status::failure(ERROR_WRONG_PARAMETER, which + ": mesh vertices " + std::to_string(b) + " and " + std::to_string(a) +
                                                        " are not joined by an edge");
      if(!seen.insert(std::make_pair((std::min)(a, b), (std::max)(a, b))).second)
        return Status::failure(ERROR_WRONG_PARAMETER, which + ": the edge between mesh vertices " + std::to_string(b) + " and " +
                                                        std::to_string(a) + " is on the cut graph twice");
    }
  }
  for(std::size_t c = 0; c < landmarks.size(); ++c) {
    const std::size_t a = index(landmarks[c]);
    if(a == index.npos || !on_graph[a])
      return Status::failure(ERROR_WRONG_PARAMETER, "landmark " + std::to_string(c) + " is not on the cut graph");
  }
  return Status();
}

} // namespace internal
} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_INPUT_GENUS_CUT_H
