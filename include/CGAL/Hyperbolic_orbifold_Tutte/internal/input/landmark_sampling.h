// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_INPUT_LANDMARK_SAMPLING_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_INPUT_LANDMARK_SAMPLING_H

#include <CGAL/Hyperbolic_orbifold_Tutte/internal/core/dense_index.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/core/mesh_graph.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {
namespace internal {

// k border vertices of the longest of the border loops `loops` (the first on ties), spread
// evenly by arc length, starting at its vertex of smallest index, in border order.
template <class TriangleMesh, class VertexPointMap, class HalfedgeLoops>
std::vector<std::size_t> spread_on_longest_border_loop(const TriangleMesh& tm, VertexPointMap vpm,
                                                       const HalfedgeLoops& loops, std::size_t k)
{
  typedef boost::graph_traits<TriangleMesh> GT;
  const Dense_index<typename GT::vertex_descriptor> index(vertices(tm));
  auto len = [&](typename GT::halfedge_descriptor h) {
    return std::sqrt(CGAL::to_double(CGAL::squared_distance(get(vpm, source(h, tm)), get(vpm, target(h, tm)))));
  };
  std::size_t best = 0;
  double best_len = -1;
  for(std::size_t l = 0; l < loops.size(); ++l) {
    double s = 0;
    for(auto h : loops[l]) s += len(h);
    if(s > best_len) { best_len = s; best = l; }
  }
  auto loop = loops[best];
  // start at the loop's vertex of smallest index (target of the halfedge)
  std::size_t start = 0;
  for(std::size_t i = 0; i < loop.size(); ++i)
    if(index(target(loop[i], tm)) < index(target(loop[start], tm))) start = i;
  std::rotate(loop.begin(), loop.begin() + start, loop.end());
  std::vector<double> acc(1, 0.0);
  for(std::size_t i = 1; i < loop.size(); ++i)
    acc.push_back(acc.back() + len(loop[i]));
  const double total = acc.back() + len(loop[0]);
  std::vector<std::size_t> result;
  std::size_t j = 0;
  for(std::size_t i = 0; i < k; ++i) {
    const double s = total * double(i) / double(k);
    while(j + 1 < loop.size() && acc[j + 1] <= s) ++j;
    const std::size_t v = index(target(loop[j], tm));
    if(result.empty() || result.back() != v) result.push_back(v);
  }
  return result;
}

// Farthest-point sampling of min(k, n) vertices on graph distance (Dijkstra over edges
// weighted by their length), starting from the vertex farthest from vertex 0.
template <class TriangleMesh, class VertexPointMap>
std::vector<std::size_t> farthest_point_sampling(const TriangleMesh& tm, VertexPointMap vpm, std::size_t k)
{
  const Mesh_graph<TriangleMesh> g(tm, vpm);
  const std::size_t n = g.size();
  const double inf = std::numeric_limits<double>::infinity();
  Dijkstra_distances d(n);
  auto run = [&](std::size_t src) { // lowers d to the distances to src where shorter
    d.heap.clear();
    dijkstra(g, d, static_cast<int>(src), [](int) {}, []() { return false; });
  };
  auto farthest = [&]() {
    std::size_t b = 0;
    for(std::size_t i = 0; i < n; ++i)
      if(d.dist[i] < inf && (d.dist[b] == inf || d.dist[i] > d.dist[b])) b = i;
    return b;
  };
  std::vector<std::size_t> result;
  run(0);
  result.push_back(farthest());
  d.reset();
  while(result.size() < std::min(k, n)) {
    run(result.back()); // distances to the nearest chosen landmark
    result.push_back(farthest());
  }
  return result;
}

// Well-spread landmark choices, deterministic, as indices in the order of vertices(tm).
//  - closed meshes: farthest-point sampling on graph distance (Dijkstra over edges weighted
//    by their length), starting from the vertex farthest from vertex 0;
//  - meshes with a border: k border vertices of the longest border loop spread evenly by
//    arc length, starting at its vertex of smallest index, in border order.
template <class TriangleMesh, class VertexPointMap>
std::vector<std::size_t> sample_landmarks(const TriangleMesh& tm, VertexPointMap vpm, std::size_t k)
{
  if(vertices(tm).begin() == vertices(tm).end() || k == 0)
    return std::vector<std::size_t>();
  const auto loops = border_loops(tm);
  if(!loops.empty())
    return spread_on_longest_border_loop(tm, vpm, loops, k);
  return farthest_point_sampling(tm, vpm, k);
}

} // namespace internal
} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_INPUT_LANDMARK_SAMPLING_H
