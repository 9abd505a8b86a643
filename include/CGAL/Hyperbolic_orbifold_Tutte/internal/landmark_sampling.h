// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_LANDMARK_SAMPLING_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_LANDMARK_SAMPLING_H

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <queue>
#include <unordered_map>
#include <vector>

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {
namespace internal {

// Well-spread landmark choices, deterministic, as indices in the order of vertices(tm).
//  - closed meshes: farthest-point sampling on graph distance (Dijkstra over edges weighted
//    by their length), starting from the vertex farthest from vertex 0;
//  - meshes with a border: k border vertices of the longest border loop spread evenly by
//    arc length, starting at its vertex of smallest index, in border order.
template <class TriangleMesh, class VertexPointMap>
std::vector<std::size_t> sample_landmarks(const TriangleMesh& tm, VertexPointMap vpm, std::size_t k)
{
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename GT::vertex_descriptor vertex_descriptor;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  std::vector<vertex_descriptor> verts;
  std::unordered_map<vertex_descriptor, std::size_t, boost::hash<vertex_descriptor> > index;
  for(vertex_descriptor v : vertices(tm)) {
    index.emplace(v, verts.size());
    verts.push_back(v);
  }
  const std::size_t n = verts.size();
  std::vector<std::size_t> result;
  if(n == 0 || k == 0)
    return result;
  auto len = [&](halfedge_descriptor h) {
    return std::sqrt(CGAL::to_double(CGAL::squared_distance(get(vpm, source(h, tm)), get(vpm, target(h, tm)))));
  };
  // border loops
  std::vector<std::vector<halfedge_descriptor> > loops;
  {
    std::unordered_map<halfedge_descriptor, bool, boost::hash<halfedge_descriptor> > done;
    for(halfedge_descriptor h : halfedges(tm)) {
      if(!is_border(h, tm) || done.count(h))
        continue;
      std::vector<halfedge_descriptor> loop;
      halfedge_descriptor g = h;
      do {
        done[g] = true;
        loop.push_back(g);
        g = next(g, tm);
      } while(g != h && loop.size() <= num_halfedges(tm));
      loops.push_back(loop);
    }
  }
  if(!loops.empty()) {
    std::size_t best = 0;
    double best_len = -1;
    for(std::size_t l = 0; l < loops.size(); ++l) {
      double s = 0;
      for(halfedge_descriptor h : loops[l]) s += len(h);
      if(s > best_len) { best_len = s; best = l; }
    }
    std::vector<halfedge_descriptor> loop = loops[best];
    // start at the loop's vertex of smallest index (target of the halfedge)
    std::size_t start = 0;
    for(std::size_t i = 0; i < loop.size(); ++i)
      if(index[target(loop[i], tm)] < index[target(loop[start], tm)]) start = i;
    std::rotate(loop.begin(), loop.begin() + start, loop.end());
    std::vector<double> acc(1, 0.0);
    for(std::size_t i = 1; i < loop.size(); ++i)
      acc.push_back(acc.back() + len(loop[i]));
    const double total = acc.back() + len(loop[0]);
    std::size_t j = 0;
    for(std::size_t i = 0; i < k; ++i) {
      const double s = total * double(i) / double(k);
      while(j + 1 < loop.size() && acc[j + 1] <= s) ++j;
      const std::size_t v = index[target(loop[j], tm)];
      if(result.empty() || result.back() != v) result.push_back(v);
    }
    return result;
  }
  // closed: farthest-point sampling
  std::vector<double> d(n, std::numeric_limits<double>::infinity());
  typedef std::pair<double, std::size_t> Q;
  auto dijkstra = [&](std::size_t src, bool reset) {
    if(reset) std::fill(d.begin(), d.end(), std::numeric_limits<double>::infinity());
    std::priority_queue<Q, std::vector<Q>, std::greater<Q> > q;
    d[src] = 0;
    q.push(Q(0, src));
    while(!q.empty()) {
      const Q t = q.top();
      q.pop();
      if(t.first > d[t.second]) continue;
      for(halfedge_descriptor h : halfedges_around_target(halfedge(verts[t.second], tm), tm)) {
        const std::size_t u = index[source(h, tm)];
        const double nd = t.first + len(h);
        if(nd < d[u]) { d[u] = nd; q.push(Q(nd, u)); }
      }
    }
  };
  auto farthest = [&]() {
    std::size_t b = 0;
    for(std::size_t i = 0; i < n; ++i)
      if(d[i] < std::numeric_limits<double>::infinity() && (d[b] == std::numeric_limits<double>::infinity() || d[i] > d[b])) b = i;
    return b;
  };
  dijkstra(0, true);
  result.push_back(farthest());
  std::fill(d.begin(), d.end(), std::numeric_limits<double>::infinity());
  while(result.size() < std::min(k, n)) {
    dijkstra(result.back(), false); // distances to the nearest chosen landmark
    result.push_back(farthest());
  }
  return result;
}

} // namespace internal
} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_LANDMARK_SAMPLING_H
