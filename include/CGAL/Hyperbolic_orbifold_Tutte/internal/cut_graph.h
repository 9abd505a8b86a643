// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers
#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_CUT_GRAPH_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_CUT_GRAPH_H

// Cutting a closed genus-0 triangle mesh into a topological disk along a
// simple path p1 -> p2 -> ... -> pk through its landmark (cone) vertices, and
// ordering the landmarks as in Aigerman & Lipman 2016, section 7 (shortest
// closed tour through the landmarks, opened at its longest edge).
//
// Why not `Surface_mesh_parameterization::compute_shortest_paths_between_cones`:
// it computes each shortest path independently, so consecutive paths may share
// edges or vertices and the union is then not a tree, i.e. not a valid cut.
// Here the paths are computed one after the other, each one forbidden to touch
// the vertices used by the paths already computed and the other landmarks.
//
// Everything works on any `FaceListGraph` / `HalfedgeListGraph` model through
// BGL free functions only (tested with `Surface_mesh` and `Polyhedron_3`).

#include <CGAL/boost/graph/helpers.h>          // is_border
#include <CGAL/boost/graph/iterator.h>         // halfedges_around_target
#include <CGAL/boost/graph/properties.h>
#include <CGAL/squared_distance_3.h>           // squared_distance
#include <CGAL/number_utils.h>                 // to_double

#include <boost/graph/graph_traits.hpp>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#endif

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <functional>
#include <limits>
#include <numeric>
#include <sstream>
#include <string>
#include <type_traits>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {
namespace internal {

// ---------------------------------------------------------------------------
// Results and options
// ---------------------------------------------------------------------------

/// Result of `compute_cut_through_landmarks()`.
///
/// When `ok` is true, `paths[i]` (for i = 0..k-2) is the ordered list of
/// halfedges of the mesh going from `landmarks[i]` to `landmarks[i+1]`:
/// `source(paths[i].front()) == landmarks[i]`,
/// `target(paths[i].back()) == landmarks[i+1]` and
/// `target(paths[i][j]) == source(paths[i][j+1])`.
/// The union of the paths is a simple path through all landmarks in order.
/// When `ok` is false, `message` gives a one-line reason and `paths` is empty.
template <class TriangleMesh>
struct Cut_result
{
  typedef typename boost::graph_traits<TriangleMesh>::halfedge_descriptor halfedge_descriptor;

  bool ok = false;
  std::string message;
  std::vector<std::vector<halfedge_descriptor> > paths;
  /// Number of path orders tried (1 when the plain p1->p2->... order worked).
  std::size_t number_of_attempts = 0;

  std::size_t number_of_cut_edges() const
  {
    std::size_t n = 0;
    for(const auto& p : paths) n += p.size();
    return n;
  }

  /// A simple path with E edges has E+1 vertices.
  std::size_t number_of_cut_vertices() const
  {
    return ok ? number_of_cut_edges() + 1 : 0;
  }
};

/// Tuning of `compute_cut_through_landmarks()`.
struct Cut_options
{
  /// Soft penalty discouraging "chords" (non-cut edges whose two endpoints are
  /// on the cut): the length of an edge entering a vertex that is adjacent to
  /// the cut (or to a landmark) is multiplied by `1 + chord_penalty`.
  /// 0 gives plain shortest paths.  It never blocks anything; it only makes
  /// paths keep one ring away from the rest of the cut when that is cheap.
  /// Measured on TSP-ordered landmarks (k = 8..50, meshes of 1k-40k
  /// vertices): 2.0 removes 80-100% of the chords of plain shortest paths
  /// for a total cut length 1-6% longer.  Chords also matter for robustness:
  /// a chord closes a loop of cut vertices, which can separate the remaining
  /// free vertices and make a later path impossible.
  double chord_penalty = 2.0;

  /// Maximal number of path orders tried (0 means: number of landmarks).
  std::size_t max_attempts = 0;
};

namespace cut_graph_detail {

// ---------------------------------------------------------------------------
// Vertex -> dense index lookup.
// Meshes whose vertex descriptors expose `idx()` (Surface_mesh, OpenMesh...)
// use a vector, everything else (Polyhedron_3 handles...) a hash map.  We do
// not use dynamic_vertex_property_t: on a const Surface_mesh it is sized by
// num_vertices() and would be indexed out of range if the mesh has removed
// (garbage) vertices, and on Polyhedron_3 it is a hash map anyway.
// ---------------------------------------------------------------------------
template <class VD, class = void>
struct Vertex_index_lookup
{
  std::unordered_map<VD, int> map;

  void reserve(std::size_t n) { map.reserve(n); }
  void insert(const VD& v, int i) { map.emplace(v, i); }
  int find(const VD& v) const
  {
    typename std::unordered_map<VD, int>::const_iterator it = map.find(v);
    return it == map.end() ? -1 : it->second;
  }
};

template <class VD>
struct Vertex_index_lookup<VD, std::void_t<decltype(std::declval<const VD&>().idx())> >
{
  std::vector<int> table;

  void reserve(std::size_t n) { table.reserve(n); }
  void insert(const VD& v, int i)
  {
    const long long id = static_cast<long long>(v.idx());
    if(id < 0) return;
    const std::size_t s = static_cast<std::size_t>(id);
    if(s >= table.size()) table.resize(s + 1, -1);
    table[s] = i;
  }
  int find(const VD& v) const
  {
    const long long id = static_cast<long long>(v.idx());
    if(id < 0 || static_cast<unsigned long long>(id) >= table.size()) return -1;
    return table[static_cast<std::size_t>(id)];
  }
};

// ---------------------------------------------------------------------------
// Compressed adjacency of the mesh vertices, with Euclidean edge lengths.
// Built once per call so that the Dijkstra loops touch only flat arrays.
// ---------------------------------------------------------------------------
template <class TriangleMesh>
struct Mesh_graph
{
  typedef boost::graph_traits<TriangleMesh>          GT;
  typedef typename GT::vertex_descriptor             vertex_descriptor;
  typedef typename GT::halfedge_descriptor           halfedge_descriptor;

  std::vector<vertex_descriptor> verts;      // dense index -> descriptor
  Vertex_index_lookup<vertex_descriptor> index;
  std::vector<std::size_t> offsets;          // CSR offsets, size n+1
  std::vector<int> nbrs;                     // neighbour indices
  std::vector<double> lengths;               // matching edge lengths
  std::vector<double> xyz;                   // coordinates (A* lower bound)

  std::size_t size() const { return verts.size(); }

  template <class VertexPointMap>
  void build(const TriangleMesh& tm, VertexPointMap vpm)
  {
    verts.clear();
    for(vertex_descriptor v : vertices(tm)) verts.push_back(v);
    const std::size_t n = verts.size();
    index.reserve(n);
    for(std::size_t i = 0; i < n; ++i) index.insert(verts[i], static_cast<int>(i));

    xyz.resize(3 * n);
    for(std::size_t i = 0; i < n; ++i) {
      const auto& p = get(vpm, verts[i]);
      xyz[3 * i]     = CGAL::to_double(p.x());
      xyz[3 * i + 1] = CGAL::to_double(p.y());
      xyz[3 * i + 2] = CGAL::to_double(p.z());
    }

    offsets.assign(n + 1, 0);
    nbrs.clear();
    lengths.clear();
    nbrs.reserve(6 * n + 16);
    lengths.reserve(6 * n + 16);
    for(std::size_t i = 0; i < n; ++i) {
      const vertex_descriptor v = verts[i];
      // An isolated vertex has no halfedge; it then simply has no neighbour
      // (and the connectivity check rejects the mesh).
      if(halfedge(v, tm) != GT::null_halfedge()) {
        const auto& pv = get(vpm, v);
        for(halfedge_descriptor h : halfedges_around_target(v, tm)) {
          const vertex_descriptor u = source(h, tm);
          const int j = index.find(u);
          if(j < 0) continue; // cannot happen on a valid mesh
          nbrs.push_back(j);
          lengths.push_back(std::sqrt(CGAL::to_double(CGAL::squared_distance(pv, get(vpm, u)))));
        }
      }
      offsets[i + 1] = nbrs.size();
    }
  }

  double euclidean_distance(int a, int b) const
  {
    const double dx = xyz[3 * a] - xyz[3 * b];
    const double dy = xyz[3 * a + 1] - xyz[3 * b + 1];
    const double dz = xyz[3 * a + 2] - xyz[3 * b + 2];
    return std::sqrt(dx * dx + dy * dy + dz * dz);
  }
};

// Scratch arrays reused by every shortest-path run of one call: a stamp
// tells whether dist/pred are valid for the current run, so starting a run
// costs O(1) instead of O(n).
struct Dijkstra_workspace
{
  std::vector<double> dist;
  std::vector<int> pred;
  std::vector<unsigned int> stamp;
  unsigned int current = 0;
  std::vector<std::pair<double, int> > heap; // (key, vertex), min-heap

  void init(std::size_t n)
  {
    dist.assign(n, 0.);
    pred.assign(n, -1);
    stamp.assign(n, 0u);
    current = 0;
    heap.clear();
    heap.reserve(1024);
  }

  void begin_run()
  {
    heap.clear();
    if(++current == 0u) { // wrapped around: invalidate everything once
      std::fill(stamp.begin(), stamp.end(), 0u);
      current = 1u;
    }
  }

  bool reached(int v) const { return stamp[v] == current; }
  double distance(int v) const
  {
    return reached(v) ? dist[v] : std::numeric_limits<double>::infinity();
  }
  void set(int v, double d, int p)
  {
    stamp[v] = current;
    dist[v] = d;
    pred[v] = p;
  }
  // std::greater on (key, index): smallest key first, ties broken by the
  // smallest vertex index, which makes the runs independent of the order in
  // which neighbours are enumerated (Surface_mesh vs Polyhedron_3).
  void push(double key, int v)
  {
    heap.emplace_back(key, v);
    std::push_heap(heap.begin(), heap.end(), std::greater<std::pair<double, int> >());
  }
  std::pair<double, int> pop()
  {
    std::pop_heap(heap.begin(), heap.end(), std::greater<std::pair<double, int> >());
    std::pair<double, int> top = heap.back();
    heap.pop_back();
    return top;
  }
};

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
  ws.push(g.euclidean_distance(s, t), s);
  bool found = false;
  while(!ws.heap.empty()) {
    const std::pair<double, int> top = ws.pop();
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
        ws.push(dv + g.euclidean_distance(v, t), v);
      }
    }
  }
  if(!found) return false;
  for(int v = t; v != -1; v = ws.pred[v]) out.push_back(v);
  std::reverse(out.begin(), out.end());
  return true;
}

// Plain Dijkstra from s, stopping once every vertex flagged in `targets`
// (count `n_targets`) is settled.  Distances are read from `ws` afterwards.
template <class Graph>
void dijkstra_to_targets(const Graph& g, Dijkstra_workspace& ws, int s,
                         const std::vector<char>& targets, std::size_t n_targets)
{
  ws.begin_run();
  ws.set(s, 0., -1);
  ws.push(0., s);
  std::size_t settled = 0;
  while(!ws.heap.empty() && settled < n_targets) {
    const std::pair<double, int> top = ws.pop();
    const int u = top.second;
    if(top.first > ws.dist[u]) continue; // stale entry
    if(targets[u]) ++settled;
    for(std::size_t e = g.offsets[u]; e < g.offsets[u + 1]; ++e) {
      const int v = g.nbrs[e];
      const double dv = top.first + g.lengths[e];
      if(dv < ws.distance(v)) {
        ws.set(v, dv, u);
        ws.push(dv, v);
      }
    }
  }
}

// Maps landmarks to dense indices; returns an empty string on success or the
// reason of failure (unknown vertex, duplicate).
template <class Graph, class VD>
std::string landmark_indices(const Graph& g, const std::vector<VD>& landmarks,
                             std::vector<int>& idx)
{
  idx.assign(landmarks.size(), -1);
  std::unordered_map<int, std::size_t> seen;
  for(std::size_t i = 0; i < landmarks.size(); ++i) {
    const int id = g.index.find(landmarks[i]);
    if(id < 0) {
      std::ostringstream os;
      os << "landmark #" << i << " is not a vertex of the mesh";
      return os.str();
    }
    const auto ins = seen.emplace(id, i);
    if(!ins.second) {
      std::ostringstream os;
      os << "landmark #" << i << " is a duplicate of landmark #" << ins.first->second
         << " (vertex " << id << ")";
      return os.str();
    }
    idx[i] = id;
  }
  return std::string();
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

} // namespace cut_graph_detail

// ---------------------------------------------------------------------------
// Cut through the landmarks
// ---------------------------------------------------------------------------

/// Computes a cut of the closed genus-0 mesh `tm` that is a simple path
/// through `landmarks[0] -> landmarks[1] -> ... -> landmarks[k-1]`.
///
/// Each piece `landmarks[i] -> landmarks[i+1]` is a shortest path (on edge
/// lengths, slightly biased away from the rest of the cut by
/// `options.chord_penalty`) among the vertices that are neither on an
/// already computed piece nor another landmark.  The pieces are therefore
/// vertex-disjoint except for the shared landmarks, and their union is a tree
/// (a simple path), which cuts a sphere into a disk.
///
/// Order of computation: the pieces are first computed in chain order
/// (piece 0, then 1, ...).  Being greedy, an early piece can wall in the two
/// endpoints of a later one.  If piece i cannot be found, it is moved to the
/// front of the computation order and everything is recomputed (the chain
/// p1 -> ... -> pk itself is unchanged; only who gets the "free" shortest
/// path changes).  This is repeated at most `options.max_attempts` times
/// (default k).  If the failing piece is already computed first, only the
/// other landmarks are in its way and no reordering can help.
///
/// Never asserts: invalid input (fewer than 3 landmarks, a landmark that is
/// not a vertex of `tm`, duplicates, a mesh with a border, a mesh that is not
/// a connected genus-0 surface) gives `ok == false` and a message.
///
/// Landmark order matters: in an arbitrary (e.g. random) order, each new
/// piece has to wind around the previous ones, the cut length explodes and
/// for k >~ 15 the free vertices run out (measured on 1k-40k vertex meshes:
/// random orders fail for most k = 16 sets and all k = 25 sets, while
/// TSP-ordered sets up to k = 50 always succeeded).  Order the landmarks with
/// `compute_tsp_landmark_order()` first.
///
/// Cost: O(n) to build the adjacency plus k A* searches, each at most
/// O(n log n); typically a small fraction of the mesh is explored (0.9 s in
/// total on a 2.6M-vertex mesh, k = 50).  When no cut exists, up to
/// `max_attempts` full rounds are tried, i.e. O(k^2) searches.
template <class TriangleMesh, class VertexPointMap>
Cut_result<TriangleMesh>
compute_cut_through_landmarks(
  const TriangleMesh& tm,
  const std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>& landmarks,
  VertexPointMap vpm,
  const Cut_options& options)
{
  typedef boost::graph_traits<TriangleMesh>         GT;
  typedef typename GT::vertex_descriptor            vertex_descriptor;
  typedef typename GT::halfedge_descriptor          halfedge_descriptor;
  using namespace cut_graph_detail;

  Cut_result<TriangleMesh> res;
  const std::size_t k = landmarks.size();
  if(k < 3) {
    res.message = "at least 3 landmarks are required, got " + std::to_string(k);
    return res;
  }

  // A cut that is a simple path gives a disk only on a closed surface.
  for(halfedge_descriptor h : halfedges(tm)) {
    if(is_border(h, tm)) {
      res.message = "the mesh is not closed (it has border halfedges)";
      return res;
    }
  }

  Mesh_graph<TriangleMesh> g;
  g.build(tm, vpm);
  const std::size_t n = g.size();

  std::vector<int> lm;
  res.message = landmark_indices(g, landmarks, lm);
  if(!res.message.empty()) return res;

  // Genus 0 and connected: V - E + F = 2 on a connected closed surface.
  {
    const long long chi = static_cast<long long>(n)
                        - static_cast<long long>(num_edges(tm))
                        + static_cast<long long>(num_faces(tm));
    if(chi != 2) {
      res.message = "the mesh is not a topological sphere (Euler characteristic "
                    + std::to_string(chi) + " instead of 2)";
      return res;
    }
    std::vector<char> seen(n, 0);
    std::vector<int> stack(1, lm[0]);
    seen[lm[0]] = 1;
    std::size_t reached = 1;
    while(!stack.empty()) {
      const int u = stack.back();
      stack.pop_back();
      for(std::size_t e = g.offsets[u]; e < g.offsets[u + 1]; ++e) {
        const int v = g.nbrs[e];
        if(!seen[v]) { seen[v] = 1; ++reached; stack.push_back(v); }
      }
    }
    if(reached != n) {
      res.message = "the mesh is not connected";
      return res;
    }
  }

  const std::size_t n_paths = k - 1;
  const double penalty = options.chord_penalty > 0. ? options.chord_penalty : 0.;
  const std::size_t max_attempts = options.max_attempts > 0 ? options.max_attempts : k;

  // Per-vertex state, reset at each attempt.
  //  is_landmark[v]: landmark vertices are blocked except as path endpoints.
  //  on_cut[v]:      interior vertex of an already computed piece.
  //  near[v]:        number of (current or future) cut vertices adjacent to v,
  //                  counted per adjacency slot; drives the chord penalty.
  std::vector<char> is_landmark(n, 0), on_cut(n, 0);
  std::vector<int> near(n, 0);
  for(int v : lm) is_landmark[v] = 1;

  auto add_near = [&](int c, int delta) {
    for(std::size_t e = g.offsets[c]; e < g.offsets[c + 1]; ++e) near[g.nbrs[e]] += delta;
  };

  Dijkstra_workspace ws;
  ws.init(n);

  std::vector<std::size_t> order(n_paths);
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::vector<std::vector<int> > path_vertices(n_paths);
  std::vector<int> buffer;

  std::size_t failed = n_paths;
  for(std::size_t attempt = 1; attempt <= max_attempts; ++attempt) {
    res.number_of_attempts = attempt;
    std::fill(on_cut.begin(), on_cut.end(), char(0));
    std::fill(near.begin(), near.end(), 0);
    for(int v : lm) add_near(v, 1); // landmarks always end up on the cut
    for(auto& p : path_vertices) p.clear();

    failed = n_paths;
    std::size_t failed_pos = 0;
    for(std::size_t pos = 0; pos < n_paths; ++pos) {
      const std::size_t i = order[pos];
      const int s = lm[i], t = lm[i + 1];

      // Adjacency to the path's own endpoints is not a chord: discount it.
      add_near(s, -1);
      add_near(t, -1);
      auto passable = [&](int v) { return !is_landmark[v] && !on_cut[v]; };
      auto factor = [&](int v) { return near[v] > 0 ? 1. + penalty : 1.; };
      const bool found = shortest_path_a_star(g, ws, s, t, passable, factor, buffer);
      add_near(s, 1);
      add_near(t, 1);

      if(!found) { failed = i; failed_pos = pos; break; }

      path_vertices[i] = buffer;
      for(std::size_t j = 1; j + 1 < buffer.size(); ++j) {
        on_cut[buffer[j]] = 1;
        add_near(buffer[j], 1);
      }
    }

    if(failed == n_paths) break;  // success
    if(failed_pos == 0) break;    // only landmarks are in the way
    // Give the failing piece the first pick and recompute everything.
    order.erase(order.begin() + failed_pos);
    order.insert(order.begin(), failed);
  }

  if(failed != n_paths) {
    std::ostringstream os;
    os << "no path from " << describe_landmark(failed, lm[failed])
       << " to " << describe_landmark(failed + 1, lm[failed + 1])
       << " avoiding the other landmarks and the rest of the cut ("
       << res.number_of_attempts << " computation order(s) tried)";
    res.message = os.str();
    return res;
  }

  res.paths.resize(n_paths);
  for(std::size_t i = 0; i < n_paths; ++i) {
    const std::vector<int>& pv = path_vertices[i];
    res.paths[i].reserve(pv.size() - 1);
    for(std::size_t j = 0; j + 1 < pv.size(); ++j) {
      const vertex_descriptor a = g.verts[pv[j]], b = g.verts[pv[j + 1]];
      res.paths[i].push_back(halfedge_from_to(a, b, tm));
    }
  }
  res.ok = true;
  res.message.clear();
  return res;
}

/// Same as above with default `Cut_options`.
template <class TriangleMesh, class VertexPointMap>
Cut_result<TriangleMesh>
compute_cut_through_landmarks(
  const TriangleMesh& tm,
  const std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>& landmarks,
  VertexPointMap vpm)
{
  return compute_cut_through_landmarks(tm, landmarks, vpm, Cut_options());
}

/// Number of edges of `tm` that are not on the cut but whose two endpoints
/// are on the cut ("chords").  Returns 0 for a failed cut.
template <class TriangleMesh>
std::size_t count_cut_chords(const TriangleMesh& tm, const Cut_result<TriangleMesh>& cut)
{
  typedef boost::graph_traits<TriangleMesh>         GT;
  typedef typename GT::vertex_descriptor            vertex_descriptor;
  typedef typename GT::halfedge_descriptor          halfedge_descriptor;

  if(!cut.ok) return 0;
  std::unordered_set<vertex_descriptor> cut_vertices;
  std::unordered_set<halfedge_descriptor> cut_halfedges;
  for(const auto& path : cut.paths) {
    for(halfedge_descriptor h : path) {
      cut_vertices.insert(source(h, tm));
      cut_vertices.insert(target(h, tm));
      cut_halfedges.insert(h);
      cut_halfedges.insert(opposite(h, tm));
    }
  }
  // Every chord is seen once from each endpoint.
  std::size_t twice = 0;
  for(vertex_descriptor v : cut_vertices) {
    for(halfedge_descriptor h : halfedges_around_target(v, tm)) {
      if(cut_halfedges.count(h) == 0 && cut_vertices.count(source(h, tm)) != 0) ++twice;
    }
  }
  return twice / 2;
}

// ---------------------------------------------------------------------------
// Landmark ordering (Aigerman & Lipman 2016, section 7)
// ---------------------------------------------------------------------------

/// Length of the closed tour `tour` (a permutation of 0..k-1) under `D`.
inline double tour_length(const std::vector<std::vector<double> >& D,
                          const std::vector<std::size_t>& tour)
{
  double len = 0.;
  for(std::size_t i = 0; i < tour.size(); ++i)
    len += D[tour[i]][tour[(i + 1) % tour.size()]];
  return len;
}

inline std::vector<std::size_t>
shortest_tour_heuristic(const std::vector<std::vector<double> >& D);

/// Exact shortest closed tour by Held-Karp dynamic programming,
/// O(2^k k^2) time and O(2^k k) memory: meant for k <= 12 or so (above 20
/// it would need gigabytes, so it falls back to the heuristic).
/// The tour starts at 0.  Ties are broken towards smaller indices.
inline std::vector<std::size_t>
shortest_tour_held_karp(const std::vector<std::vector<double> >& D)
{
  const std::size_t k = D.size();
  std::vector<std::size_t> tour;
  if(k == 0) return tour;
  if(k > 20) return shortest_tour_heuristic(D);
  if(k <= 3) {
    for(std::size_t i = 0; i < k; ++i) tour.push_back(i);
    return tour;
  }
  // Node 0 is the fixed start; subsets are over nodes 1..k-1 (bit j-1).
  const std::size_t m = k - 1;
  const std::size_t n_sets = std::size_t(1) << m;
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<double> dp(n_sets * m, inf);
  std::vector<unsigned char> parent(n_sets * m, 0); // 0 means "from node 0"
  for(std::size_t j = 0; j < m; ++j) dp[(std::size_t(1) << j) * m + j] = D[0][j + 1];

  for(std::size_t set = 1; set < n_sets; ++set) {
    for(std::size_t j = 0; j < m; ++j) {
      if(!(set & (std::size_t(1) << j))) continue;
      const double cur = dp[set * m + j];
      if(cur == inf) continue;
      for(std::size_t l = 0; l < m; ++l) {
        if(set & (std::size_t(1) << l)) continue;
        const std::size_t nset = set | (std::size_t(1) << l);
        const double cand = cur + D[j + 1][l + 1];
        // Sets and predecessors are enumerated in increasing order and only a
        // strict improvement replaces, so ties keep the smaller predecessor.
        if(cand < dp[nset * m + l]) {
          dp[nset * m + l] = cand;
          parent[nset * m + l] = static_cast<unsigned char>(j + 1);
        }
      }
    }
  }
  const std::size_t full = n_sets - 1;
  std::size_t last = 0;
  double best = inf;
  for(std::size_t j = 0; j < m; ++j) {
    const double cand = dp[full * m + j] + D[j + 1][0];
    if(cand < best) { best = cand; last = j; }
  }
  // Walk back from the last node.
  std::vector<std::size_t> rev;
  std::size_t set = full, j = last;
  while(true) {
    rev.push_back(j + 1);
    const std::size_t p = parent[set * m + j];
    set &= ~(std::size_t(1) << j);
    if(p == 0) break;
    j = p - 1;
  }
  tour.push_back(0);
  for(std::size_t i = rev.size(); i-- > 0;) tour.push_back(rev[i]);
  return tour;
}

/// Heuristic shortest closed tour: nearest-neighbour tour from every start,
/// each improved by 2-opt, keeping the best.  O(k^3) per 2-opt pass; meant
/// for the k > 12 case where Held-Karp is too expensive.  Deterministic.
inline std::vector<std::size_t>
shortest_tour_heuristic(const std::vector<std::vector<double> >& D)
{
  const std::size_t k = D.size();
  std::vector<std::size_t> best_tour;
  if(k <= 3) {
    for(std::size_t i = 0; i < k; ++i) best_tour.push_back(i);
    return best_tour;
  }
  double scale = 0.;
  for(const auto& row : D) for(double d : row) scale = (std::max)(scale, d);
  const double eps = 1e-12 * (scale > 0. ? scale : 1.);

  double best_len = std::numeric_limits<double>::infinity();
  std::vector<std::size_t> tour(k);
  std::vector<char> used(k);
  for(std::size_t start = 0; start < k; ++start) {
    std::fill(used.begin(), used.end(), char(0));
    tour[0] = start;
    used[start] = 1;
    for(std::size_t i = 1; i < k; ++i) {
      const std::size_t prev = tour[i - 1];
      std::size_t next = k;
      for(std::size_t c = 0; c < k; ++c) // strict '<': smallest index on ties
        if(!used[c] && (next == k || D[prev][c] < D[prev][next])) next = c;
      tour[i] = next;
      used[next] = 1;
    }
    // 2-opt: replace edges (a,b),(c,d) by (a,c),(b,d) while it shortens the
    // tour by more than eps (the eps guarantees termination).
    bool improved = true;
    while(improved) {
      improved = false;
      for(std::size_t i = 0; i + 2 < k; ++i) {
        for(std::size_t j = i + 2; j < k; ++j) {
          if(i == 0 && j == k - 1) continue; // the two edges are adjacent
          const std::size_t a = tour[i], b = tour[i + 1], c = tour[j], d = tour[(j + 1) % k];
          const double delta = D[a][c] + D[b][d] - D[a][b] - D[c][d];
          if(delta < -eps) {
            std::reverse(tour.begin() + i + 1, tour.begin() + j + 1);
            improved = true;
          }
        }
      }
    }
    const double len = tour_length(D, tour);
    if(len < best_len - eps) { best_len = len; best_tour = tour; }
  }
  // Rotate so that the tour starts at 0.
  std::rotate(best_tour.begin(),
              std::find(best_tour.begin(), best_tour.end(), std::size_t(0)),
              best_tour.end());
  return best_tour;
}

/// Shortest closed tour: exact (Held-Karp) for k <= 12, heuristic otherwise.
inline std::vector<std::size_t>
shortest_tour(const std::vector<std::vector<double> >& D)
{
  return D.size() <= 12 ? shortest_tour_held_karp(D) : shortest_tour_heuristic(D);
}

/// Opens the closed tour at its longest edge.  Ties between equally long
/// edges are broken by the smallest (min index, max index) pair.  The open
/// path starts at the endpoint of the removed edge with the smaller index and
/// ends at the other one, so the result does not depend on how the tour was
/// rotated or oriented.
inline std::vector<std::size_t>
open_tour_at_longest_edge(const std::vector<std::vector<double> >& D,
                          const std::vector<std::size_t>& tour)
{
  const std::size_t k = tour.size();
  if(k <= 1) return tour;
  std::size_t best = 0;
  for(std::size_t i = 1; i < k; ++i) {
    const std::size_t a = tour[i], b = tour[(i + 1) % k];
    const std::size_t ba = tour[best], bb = tour[(best + 1) % k];
    const double l = D[a][b], bl = D[ba][bb];
    const std::pair<std::size_t, std::size_t> key((std::min)(a, b), (std::max)(a, b));
    const std::pair<std::size_t, std::size_t> bkey((std::min)(ba, bb), (std::max)(ba, bb));
    if(l > bl || (l == bl && key < bkey)) best = i;
  }
  // Removed edge: tour[best] -- tour[best+1].
  const std::size_t a = tour[best], b = tour[(best + 1) % k];
  std::vector<std::size_t> path;
  path.reserve(k);
  if(a < b) {
    // start at a and walk away from b, i.e. backwards along the tour
    for(std::size_t i = 0; i < k; ++i) path.push_back(tour[(best + k - i) % k]);
  } else {
    // start at b and walk away from a, i.e. forwards along the tour
    for(std::size_t i = 0; i < k; ++i) path.push_back(tour[(best + 1 + i) % k]);
  }
  return path;
}

/// Pairwise geodesic (shortest edge path) distances between the landmarks,
/// one Dijkstra per landmark, each stopped once the remaining landmarks are
/// settled.  Returns an empty matrix on invalid landmarks; unreachable pairs
/// get +infinity.  O(k n log n): each run usually sweeps most of the mesh,
/// so this dominates the pipeline on big meshes (about 0.6 s per landmark on
/// a 2.6M-vertex mesh), far more than the cut itself.
template <class TriangleMesh, class VertexPointMap>
std::vector<std::vector<double> >
compute_landmark_distance_matrix(
  const TriangleMesh& tm,
  const std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>& landmarks,
  VertexPointMap vpm)
{
  using namespace cut_graph_detail;
  std::vector<std::vector<double> > D;
  Mesh_graph<TriangleMesh> g;
  g.build(tm, vpm);
  std::vector<int> lm;
  if(!landmark_indices(g, landmarks, lm).empty()) return D;

  const std::size_t k = lm.size();
  D.assign(k, std::vector<double>(k, 0.));
  // one run per landmark, independent of each other (in parallel where TBB is available,
  // each with its own scratch arrays: the same distances whatever the number of threads)
  auto runs = [&](std::size_t begin, std::size_t end) {
    Dijkstra_workspace ws;
    ws.init(g.size());
    std::vector<char> targets(g.size(), 0);
    for(std::size_t i = begin; i < end; ++i) {
      // D is symmetric: from landmark i we only need landmarks i+1..k-1.
      std::fill(targets.begin(), targets.end(), char(0));
      for(std::size_t j = i + 1; j < k; ++j) targets[lm[j]] = 1;
      dijkstra_to_targets(g, ws, lm[i], targets, k - 1 - i);
      for(std::size_t j = i + 1; j < k; ++j) D[i][j] = D[j][i] = ws.distance(lm[j]);
    }
  };
  if(k < 2) return D;
#ifdef CGAL_LINKED_WITH_TBB
  if(g.size() > 20000) {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, k - 1, 1),
                      [&](const tbb::blocked_range<std::size_t>& r) { runs(r.begin(), r.end()); });
    return D;
  }
#endif
  runs(0, k - 1);
  return D;
}

/// Landmark order of Aigerman & Lipman 2016, section 7: shortest closed tour
/// through the landmarks under geodesic distance (exact for k <= 12,
/// nearest neighbour + 2-opt otherwise), cut at its longest edge.  Returns
/// the permutation of indices into `landmarks` giving p1..pk; it starts at
/// the endpoint of the removed edge with the smaller landmark index.
/// Returns an empty vector if a landmark is not a vertex of `tm`, is
/// duplicated, or if some landmarks are not connected to each other.
template <class TriangleMesh, class VertexPointMap>
std::vector<std::size_t>
compute_tsp_landmark_order(
  const TriangleMesh& tm,
  const std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>& landmarks,
  VertexPointMap vpm)
{
  const std::vector<std::vector<double> > D = compute_landmark_distance_matrix(tm, landmarks, vpm);
  if(D.size() != landmarks.size()) return std::vector<std::size_t>();
  for(const auto& row : D)
    for(double d : row)
      if(!(d < std::numeric_limits<double>::infinity())) return std::vector<std::size_t>();
  return open_tour_at_longest_edge(D, shortest_tour(D));
}

// ---------------------------------------------------------------------------
// Seam mesh
// ---------------------------------------------------------------------------

/// Marks every edge of `cut` as a seam of `mesh` (a `CGAL::Seam_mesh` built
/// on `tm`).  Returns true iff the cut is valid and every edge was newly
/// marked (`Seam_mesh::add_seam` refuses border edges and edges already
/// marked, so the seam property maps should start all-false).
/// `add_seam` takes two vertices, so on a mesh with parallel edges it may
/// pick another edge between the same vertices than the cut's halfedge.
///
/// About `num_vertices(mesh)` (CGAL 5.5): `Seam_mesh` caches the number of
/// its vertices in a private mutable member, computed lazily on the first
/// call to `num_vertices()` and never invalidated by `add_seam()`; there is no
/// public member to reset it (`set_seam_edges_number()` only sets the seam
/// edge counter).  Hence:
///  - add all seams (call this function) BEFORE anything calls
///    `num_vertices(mesh)` (the parameterizers do, to size their systems);
///    this function itself never calls it, so a fresh `Seam_mesh` is left
///    in a state where the cached count, once computed, is correct;
///  - if the cache was already filled, build a new `Seam_mesh` on the same
///    (now filled) seam property maps and call
///    `set_seam_edges_number(cut.number_of_cut_edges())` on it, since the
///    seam edge counter also lives in the `Seam_mesh` object.
/// `count_seam_mesh_vertices()` counts the vertices by iteration and does not
/// depend on the cache.
template <class SeamMesh, class TriangleMesh>
bool add_cut_to_seam_mesh(SeamMesh& mesh, const TriangleMesh& tm,
                          const Cut_result<TriangleMesh>& cut)
{
  if(!cut.ok) return false;
  bool all_added = true;
  for(const auto& path : cut.paths)
    for(const auto& h : path)
      if(!mesh.add_seam(source(h, tm), target(h, tm))) all_added = false;
  return all_added;
}

/// Number of vertices of a seam mesh, counted by iterating over `vertices()`
/// (immune to the stale `num_vertices()` cache described above).  For a cut
/// that is a simple path with V_c vertices on a mesh with n vertices, this is
/// n + V_c - 2: every interior cut vertex is duplicated once.
template <class SeamMesh>
std::size_t count_seam_mesh_vertices(const SeamMesh& mesh)
{
  std::size_t n = 0;
  for(auto v : vertices(mesh)) { (void)v; ++n; }
  return n;
}

} // namespace internal
} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_CUT_GRAPH_H
