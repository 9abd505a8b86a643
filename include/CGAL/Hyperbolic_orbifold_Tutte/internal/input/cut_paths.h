// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_INPUT_CUT_PATHS_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_INPUT_CUT_PATHS_H

// The steps of `compute_cut_through_landmarks()` (cut_through_landmarks.h): the input
// checks, the A* search of one piece of the cut, and the search of all pieces, reordered
// when a piece is walled in. They work on the dense vertex graph of mesh_graph.h.

#include <CGAL/Hyperbolic_orbifold_Tutte/internal/core/mesh_graph.h>

#include <CGAL/boost/graph/helpers.h>          // is_border
#include <CGAL/boost/graph/iterator.h>         // halfedges_around_target

#include <boost/graph/graph_traits.hpp>

#include <algorithm>
#include <cstddef>
#include <numeric>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {
namespace internal {

// the default of `Cut_options::chord_penalty` (cut_through_landmarks.h)
constexpr double default_chord_penalty = 2.0;

// Shortest path from s to t with A* (Euclidean straight-line lower bound,
// admissible and consistent because edge costs are >= Euclidean lengths).
// It returns the same kind of path as Dijkstra but explores far fewer
// vertices.  `passable(v)` filters vertices (s and t are always allowed);
// the cost of entering v through an edge of length w is `w * factor(v)`
// with factor(v) >= 1.  On success `out` gets the vertex indices s..t.
template <class Graph, class Passable, class Factor>
bool shortest_path_a_star(const Graph& g, Dijkstra_workspace& ws, int s, int t,
                          const Passable& passable, const Factor& factor,
                          std::vector<int>& out)
{
  out.clear();
  ws.begin_run();
  ws.set(s, 0., -1);
  ws.heap.push(g.euclidean_distance(s, t), s);
  bool found = false;
  while(!ws.heap.empty()) {
    const std::pair<double, int> top = ws.heap.pop();
    const int u = top.second;
    const double du = ws.dist[u];
    // lazy deletion: skip stale heap entries
    if(top.first > du + g.euclidean_distance(u, t)) continue;
    if(u == t) { found = true; break; }
    for(std::size_t e = g.offsets[u]; e < g.offsets[u + 1]; ++e) {
      const int v = g.nbrs[e];
      if(v != t && !passable(v)) continue;
      const double dv = du + g.lengths[e] * (v == t ? 1. : factor(v));
      if(dv < ws.distance(v)) {
        ws.set(v, dv, u);
        ws.heap.push(dv + g.euclidean_distance(v, t), v);
      }
    }
  }
  if(!found) return false;
  for(int v = t; v != -1; v = ws.pred[v]) out.push_back(v);
  std::reverse(out.begin(), out.end());
  return true;
}

// Returns the halfedge with source u and target v.  (We do not use
// `halfedge(u, v, tm)`: which of the two halfedges of the edge it returns is
// not the same for every graph type.)
template <class TriangleMesh>
typename boost::graph_traits<TriangleMesh>::halfedge_descriptor
halfedge_from_to(typename boost::graph_traits<TriangleMesh>::vertex_descriptor u,
                 typename boost::graph_traits<TriangleMesh>::vertex_descriptor v,
                 const TriangleMesh& tm)
{
  for(auto h : halfedges_around_target(v, tm))
    if(source(h, tm) == u) return h;
  return boost::graph_traits<TriangleMesh>::null_halfedge();
}

inline std::string describe_landmark(std::size_t pos, int vertex_index)
{
  std::ostringstream os;
  os << "landmark #" << pos << " (vertex " << vertex_index << ")";
  return os.str();
}

// The checks done before the graph is built: enough landmarks, and no border (a cut
// that is a simple path gives a disk only on a closed surface). Empty string if passed.
template <class TriangleMesh>
std::string check_cut_input(const TriangleMesh& tm, std::size_t k)
{
  if(k < 3)
    return "at least 3 landmarks are required, got " + std::to_string(k);
  for(auto h : halfedges(tm)) {
    if(is_border(h, tm))
      return "the mesh is not closed (it has border halfedges)";
  }
  return std::string();
}

// Genus 0 and connected: V - E + F = 2 and every vertex reachable from the first
// landmark `s`. Empty string if passed.
template <class TriangleMesh, class Graph>
std::string check_cut_sphere(const TriangleMesh& tm, const Graph& g, int s)
{
  const std::size_t n = g.size();
  const long long chi = static_cast<long long>(n)
                      - static_cast<long long>(num_edges(tm))
                      + static_cast<long long>(num_faces(tm));
  if(chi != 2)
    return "the mesh is not a topological sphere (Euler characteristic "
           + std::to_string(chi) + " instead of 2)";
  std::vector<char> seen(n, 0);
  std::vector<int> stack(1, s);
  seen[s] = 1;
  std::size_t reached = 1;
  while(!stack.empty()) {
    const int u = stack.back();
    stack.pop_back();
    for(std::size_t e = g.offsets[u]; e < g.offsets[u + 1]; ++e) {
      const int v = g.nbrs[e];
      if(!seen[v]) { seen[v] = 1; ++reached; stack.push_back(v); }
    }
  }
  if(reached != n)
    return "the mesh is not connected";
  return std::string();
}

// The search of the pieces lm[i] -> lm[i+1] of the cut, in a given computation order.
// Per-vertex state, reset at each attempt:
//  is_landmark[v]: landmark vertices are blocked except as path endpoints.
//  on_cut[v]:      interior vertex of an already computed piece.
//  near[v]:        number of (current or future) cut vertices adjacent to v,
//                  counted per adjacency slot; drives the chord penalty.
template <class Graph>
struct Cut_search
{
  const Graph& g;
  const std::vector<int>& lm;
  const double penalty;
  std::vector<char> is_landmark, on_cut;
  std::vector<int> near;
  Dijkstra_workspace ws;
  std::vector<int> buffer;

  Cut_search(const Graph& graph, const std::vector<int>& landmarks, double chord_penalty)
    : g(graph), lm(landmarks), penalty(chord_penalty),
      is_landmark(graph.size(), 0), on_cut(graph.size(), 0), near(graph.size(), 0)
  {
    for(int v : lm) is_landmark[v] = 1;
    ws.init(g.size());
  }

  void add_near(int c, int delta)
  {
    for(std::size_t e = g.offsets[c]; e < g.offsets[c + 1]; ++e) near[g.nbrs[e]] += delta;
  }

  // Piece i, avoiding the landmarks and the cut so far; the result is in `buffer`.
  bool find_piece(std::size_t i)
  {
    const int s = lm[i], t = lm[i + 1];
    // Adjacency to the path's own endpoints is not a chord: discount it.
    add_near(s, -1);
    add_near(t, -1);
    auto passable = [&](int v) { return !is_landmark[v] && !on_cut[v]; };
    auto factor = [&](int v) { return near[v] > 0 ? 1. + penalty : 1.; };
    const bool found = shortest_path_a_star(g, ws, s, t, passable, factor, buffer);
    add_near(s, 1);
    add_near(t, 1);
    return found;
  }

  // Computes the pieces in the order `order` (indices of pieces) into `path_vertices`.
  // Returns the position in `order` of the first piece not found, or order.size().
  std::size_t attempt(const std::vector<std::size_t>& order,
                      std::vector<std::vector<int> >& path_vertices)
  {
    std::fill(on_cut.begin(), on_cut.end(), char(0));
    std::fill(near.begin(), near.end(), 0);
    for(int v : lm) add_near(v, 1); // landmarks always end up on the cut
    for(auto& p : path_vertices) p.clear();

    for(std::size_t pos = 0; pos < order.size(); ++pos) {
      const std::size_t i = order[pos];
      if(!find_piece(i))
        return pos;
      path_vertices[i] = buffer;
      for(std::size_t j = 1; j + 1 < buffer.size(); ++j) {
        on_cut[buffer[j]] = 1;
        add_near(buffer[j], 1);
      }
    }
    return order.size();
  }
};

// Computes the k-1 pieces of the cut through the landmarks `lm` (vertex indices of `g`):
// first in chain order; when piece i cannot be found, it is moved to the front of the
// computation order and everything is recomputed, at most `max_attempts` times.
// Returns the piece that failed last, or k-1 on success; `attempts` gets the number of
// computation orders tried.
template <class Graph>
std::size_t compute_cut_pieces(const Graph& g, const std::vector<int>& lm,
                               double penalty, std::size_t max_attempts,
                               std::vector<std::vector<int> >& path_vertices,
                               std::size_t& attempts)
{
  const std::size_t n_paths = lm.size() - 1;
  Cut_search<Graph> search(g, lm, penalty);
  std::vector<std::size_t> order(n_paths);
  std::iota(order.begin(), order.end(), std::size_t(0));
  path_vertices.assign(n_paths, std::vector<int>());

  std::size_t failed = n_paths;
  for(std::size_t attempt = 1; attempt <= max_attempts; ++attempt) {
    attempts = attempt;
    const std::size_t failed_pos = search.attempt(order, path_vertices);
    failed = failed_pos < n_paths ? order[failed_pos] : n_paths;
    if(failed == n_paths) break;  // success
    if(failed_pos == 0) break;    // only landmarks are in the way
    // Give the failing piece the first pick and recompute everything.
    order.erase(order.begin() + failed_pos);
    order.insert(order.begin(), failed);
  }
  return failed;
}

// compute_cut_through_landmarks() (cut_through_landmarks.h): the pieces of the cut as halfedge
// paths (filled only on success) and the number of computation orders tried; returns the
// reason of a failure, empty on success. A `chord_penalty` <= 0 means plain shortest paths, a
// `max_attempts` of 0 the number of landmarks.
template <class TriangleMesh, class VertexPointMap>
std::string cut_through_landmarks(
  const TriangleMesh& tm,
  const std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>& landmarks,
  VertexPointMap vpm, double chord_penalty, std::size_t max_attempts_option,
  std::vector<std::vector<typename boost::graph_traits<TriangleMesh>::halfedge_descriptor> >& paths,
  std::size_t& number_of_attempts)
{
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;

  const std::size_t k = landmarks.size();
  std::string message = check_cut_input(tm, k);
  if(!message.empty()) return message;

  const Mesh_graph<TriangleMesh> g(tm, vpm);
  std::vector<int> lm;
  message = landmark_indices(g, landmarks, lm);
  if(!message.empty()) return message;
  message = check_cut_sphere(tm, g, lm[0]);
  if(!message.empty()) return message;

  const double penalty = chord_penalty > 0. ? chord_penalty : 0.;
  const std::size_t max_attempts = max_attempts_option > 0 ? max_attempts_option : k;
  std::vector<std::vector<int> > path_vertices;
  const std::size_t failed =
    compute_cut_pieces(g, lm, penalty, max_attempts, path_vertices, number_of_attempts);
  if(failed != k - 1) {
    std::ostringstream os;
    os << "no path from " << describe_landmark(failed, lm[failed])
       << " to " << describe_landmark(failed + 1, lm[failed + 1])
       << " avoiding the other landmarks and the rest of the cut ("
       << number_of_attempts << " computation order(s) tried)";
    return os.str();
  }

  paths.resize(k - 1);
  for(std::size_t i = 0; i + 1 < k; ++i) {
    const std::vector<int>& pv = path_vertices[i];
    paths[i].reserve(pv.size() - 1);
    for(std::size_t j = 0; j + 1 < pv.size(); ++j) {
      const vertex_descriptor a = g.verts[pv[j]], b = g.verts[pv[j + 1]];
      paths[i].push_back(halfedge_from_to(a, b, tm));
    }
  }
  return std::string();
}

// add_cut_to_seam_mesh() (cut_through_landmarks.h): every edge of the halfedge paths marked
// as a seam of `mesh`; false when one was not newly marked
template <class SeamMesh, class TriangleMesh, class HalfedgePaths>
bool mark_seams(SeamMesh& mesh, const TriangleMesh& tm, const HalfedgePaths& paths)
{
  bool all_added = true;
  for(const auto& path : paths)
    for(const auto& h : path)
      if(!mesh.add_seam(source(h, tm), target(h, tm))) all_added = false;
  return all_added;
}

} // namespace internal
} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_INPUT_CUT_PATHS_H
