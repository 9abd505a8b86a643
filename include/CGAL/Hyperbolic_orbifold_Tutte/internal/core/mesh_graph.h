// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_CORE_MESH_GRAPH_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_CORE_MESH_GRAPH_H

// The package's graph walks on a mesh, each written once: the vertex graph with Euclidean
// edge lengths (vertices numbered by `Dense_index`, their position in `vertices(tm)`),
// Dijkstra's shortest paths on it, and the walk along a cycle of `next()` (border loops).
// Everything works on any `FaceListGraph` / `HalfedgeListGraph` through BGL free functions.

#include <CGAL/Hyperbolic_orbifold_Tutte/internal/core/dense_index.h>

#include <CGAL/boost/graph/helpers.h>          // is_border
#include <CGAL/boost/graph/iterator.h>         // halfedges_around_target
#include <CGAL/boost/graph/properties.h>
#include <CGAL/squared_distance_3.h>           // squared_distance
#include <CGAL/number_utils.h>                 // to_double

#include <boost/graph/graph_traits.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <functional>
#include <limits>
#include <sstream>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {
namespace internal {

// ---------------------------------------------------------------------------
// The vertex graph
// ---------------------------------------------------------------------------

// Compressed adjacency of the mesh vertices (vertex i is the i-th of `vertices(tm)`), with
// Euclidean edge lengths, so that the shortest-path loops touch only flat arrays. The
// neighbours of a vertex are in the order of `halfedges_around_target(v, tm)`.
template <class TriangleMesh>
struct Mesh_graph
{
  typedef boost::graph_traits<TriangleMesh>          GT;
  typedef typename GT::vertex_descriptor             vertex_descriptor;
  typedef typename GT::halfedge_descriptor           halfedge_descriptor;

  std::vector<vertex_descriptor> verts;      // dense index -> descriptor
  Dense_index<vertex_descriptor> index;      // descriptor -> dense index
  std::vector<std::size_t> offsets;          // CSR offsets, size n+1
  std::vector<int> nbrs;                     // neighbour indices
  std::vector<double> lengths;               // matching edge lengths
  std::vector<double> xyz;                   // coordinates (A* lower bound)

  template <class VertexPointMap>
  Mesh_graph(const TriangleMesh& tm, VertexPointMap vpm)
    : verts(vertices(tm).begin(), vertices(tm).end()), index(vertices(tm))
  {
    const std::size_t n = verts.size();
    xyz.resize(3 * n);
    for(std::size_t i = 0; i < n; ++i) {
      const auto& p = get(vpm, verts[i]);
      xyz[3 * i]     = CGAL::to_double(p.x());
      xyz[3 * i + 1] = CGAL::to_double(p.y());
      xyz[3 * i + 2] = CGAL::to_double(p.z());
    }

    offsets.assign(n + 1, 0);
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
          const std::size_t j = index(u);
          if(j == index.npos) continue; // cannot happen on a valid mesh
          nbrs.push_back(static_cast<int>(j));
          lengths.push_back(std::sqrt(CGAL::to_double(CGAL::squared_distance(pv, get(vpm, u)))));
        }
      }
      offsets[i + 1] = nbrs.size();
    }
  }

  std::size_t size() const { return verts.size(); }

  double euclidean_distance(int a, int b) const
  {
    const double dx = xyz[3 * a] - xyz[3 * b];
    const double dy = xyz[3 * a + 1] - xyz[3 * b + 1];
    const double dz = xyz[3 * a + 2] - xyz[3 * b + 2];
    return std::sqrt(dx * dx + dy * dy + dz * dz);
  }
};

// Maps landmarks to the graph's dense indices; returns an empty string on success or the
// reason of failure (unknown vertex, duplicate).
template <class Graph, class VD>
std::string landmark_indices(const Graph& g, const std::vector<VD>& landmarks,
                             std::vector<int>& idx)
{
  idx.assign(landmarks.size(), -1);
  std::unordered_map<int, std::size_t> seen;
  for(std::size_t i = 0; i < landmarks.size(); ++i) {
    const std::size_t found = g.index(landmarks[i]);
    if(found == g.index.npos) {
      std::ostringstream os;
      os << "landmark #" << i << " is not a vertex of the mesh";
      return os.str();
    }
    const int id = static_cast<int>(found);
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

// ---------------------------------------------------------------------------
// Shortest paths
// ---------------------------------------------------------------------------

// Binary min-heap of (key, vertex): smallest key first, ties broken by the smallest vertex
// index, which makes the searches independent of the order in which neighbours are
// enumerated (Surface_mesh vs Polyhedron_3).
struct Vertex_heap
{
  std::vector<std::pair<double, int> > items;

  bool empty() const { return items.empty(); }
  void clear() { items.clear(); }
  void push(double key, int v)
  {
    items.emplace_back(key, v);
    std::push_heap(items.begin(), items.end(), std::greater<std::pair<double, int> >());
  }
  std::pair<double, int> pop()
  {
    std::pop_heap(items.begin(), items.end(), std::greater<std::pair<double, int> >());
    std::pair<double, int> top = items.back();
    items.pop_back();
    return top;
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
  Vertex_heap heap;

  void init(std::size_t n)
  {
    dist.assign(n, 0.);
    pred.assign(n, -1);
    stamp.assign(n, 0u);
    current = 0;
    heap.clear();
    heap.items.reserve(1024);
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
};

// Distances kept from one run to the next (no predecessors): a run from a new source only
// lowers them, so after several runs each vertex has its distance to the nearest source.
struct Dijkstra_distances
{
  std::vector<double> dist;
  Vertex_heap heap;

  explicit Dijkstra_distances(std::size_t n) : dist(n, std::numeric_limits<double>::infinity()) {}
  void reset() { std::fill(dist.begin(), dist.end(), std::numeric_limits<double>::infinity()); }
  double distance(int v) const { return dist[v]; }
  void set(int v, double d, int) { dist[v] = d; }
};

// Dijkstra from `s` on the graph `g` (edge costs `g.lengths`), with the distances in `store`
// (a `Dijkstra_workspace` after `begin_run()`, or `Dijkstra_distances`; its heap empty).
// Stale heap entries are skipped; `settled(u)` is called for every vertex when it is
// settled, before its edges are relaxed. The search stops when the heap is empty or, before
// a pop, when `done()` is true.
template <class Graph, class Store, class Settled, class Done>
void dijkstra(const Graph& g, Store& store, int s, Settled settled, Done done)
{
  store.set(s, 0., -1);
  store.heap.push(0., s);
  while(!store.heap.empty() && !done()) {
    const std::pair<double, int> top = store.heap.pop();
    const int u = top.second;
    if(top.first > store.distance(u)) continue; // stale entry
    settled(u);
    for(std::size_t e = g.offsets[u]; e < g.offsets[u + 1]; ++e) {
      const int v = g.nbrs[e];
      const double dv = top.first + g.lengths[e];
      if(dv < store.distance(v)) {
        store.set(v, dv, u);
        store.heap.push(dv, v);
      }
    }
  }
}

// ---------------------------------------------------------------------------
// Cycles of next() (border loops, face cycles)
// ---------------------------------------------------------------------------

// Follows next() from h: visit(h), visit(next(h)), ...  It stops when visit returns false,
// when next() comes back to h, or after `max_length` visits. Returns true iff it came back
// to h (so a cycle longer than `max_length` gives false).
template <class Graph, class Visit>
bool walk_next_cycle(typename boost::graph_traits<Graph>::halfedge_descriptor h, const Graph& g,
                     std::size_t max_length, Visit visit)
{
  typename boost::graph_traits<Graph>::halfedge_descriptor c = h;
  for(std::size_t n = 0; n < max_length; ++n) {
    if(!visit(c))
      return false;
    c = next(c, g);
    if(c == h)
      return true;
  }
  return false;
}

// The border loops of `g`, in the order of their first halfedge in `halfedges(g)`, each from
// that halfedge along next(). A walk stops at a halfedge that is not a border halfedge or is
// already in a loop, so each halfedge is visited once at most: on a valid polygon mesh these
// are the boundary cycles; an invalid mesh gives wrong loops but never a hang. Expected
// linear time.
template <class Graph>
std::vector<std::vector<typename boost::graph_traits<Graph>::halfedge_descriptor> >
border_loops(const Graph& g)
{
  typedef typename boost::graph_traits<Graph>::halfedge_descriptor halfedge_descriptor;
  std::vector<std::vector<halfedge_descriptor> > loops;
  std::unordered_set<halfedge_descriptor> border; // not yet in a loop
  for(halfedge_descriptor h : halfedges(g))
    if(is_border(h, g))
      border.insert(h);
  for(halfedge_descriptor h : halfedges(g)) {
    if(border.empty())
      break;
    if(border.count(h) == 0)
      continue;
    loops.emplace_back();
    std::vector<halfedge_descriptor>& loop = loops.back();
    walk_next_cycle(h, g, (std::numeric_limits<std::size_t>::max)(), [&](halfedge_descriptor c) {
      if(border.erase(c) != 1)
        return false;
      loop.push_back(c);
      return true;
    });
  }
  return loops;
}

} // namespace internal
} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_CORE_MESH_GRAPH_H
