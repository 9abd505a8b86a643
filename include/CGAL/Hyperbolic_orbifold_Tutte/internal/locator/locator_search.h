// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_LOCATOR_LOCATOR_SEARCH_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_LOCATOR_LOCATOR_SEARCH_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Hyperbolic_orbifold_Tutte/internal/locator/lifted_triangulation.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/locator/locator_walk.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <queue>
#include <unordered_set>
#include <utility>
#include <vector>

// The point locator's safety net (Embedding_locator.h, step 4): an exhaustive best-first
// search over the lifted triangles.

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {
namespace internal {

// Best-first search over lifted triangles (face, element), by distance from q to the
// triangle's centroid, with a visited set keyed by the face and the image of a probe point.
template <class Traits, class Location>
void search_lifted(const Lifted_triangulation<Traits>& lt, const std::complex<double>& q, int start, Location& loc,
                   Hyperbolic_isometry_2<double>& h_out)
{
  typedef std::complex<double> C;
  typedef Hyperbolic_isometry_2<double> Isometry;
  struct Node
  {
    double prio;
    int f;
    Isometry h;
  };
  struct Cmp
  {
    bool operator()(const std::pair<double, std::size_t>& a, const std::pair<double, std::size_t>& b) const
    {
      return a.first > b.first;
    }
  };
  const C probe(0.0123, 0.0456);
  auto node_key = [&](int f, const Isometry& h) {
    const C w = h.apply(probe);
    Point_key k;
    k.a = static_cast<std::uint64_t>(static_cast<std::int64_t>(std::llround(w.real() * 1e9))) * 1000003u +
          static_cast<std::uint64_t>(f);
    k.b = static_cast<std::uint64_t>(static_cast<std::int64_t>(std::llround(w.imag() * 1e9)));
    return k;
  };
  std::vector<Node> nodes;
  std::priority_queue<std::pair<double, std::size_t>, std::vector<std::pair<double, std::size_t> >, Cmp> heap;
  std::unordered_set<Point_key, Point_key_hash> visited;
  auto push = [&](int f, const Isometry& h) {
    if(!visited.insert(node_key(f, h)).second)
      return;
    const double pr = hyperbolic_proximity(q, h.apply(lt.centroids[f]));
    nodes.push_back(Node{pr, f, h});
    heap.push(std::make_pair(pr, nodes.size() - 1));
  };
  push(start, Isometry());
  const std::size_t max_nodes = 64 * lt.faces.size() + 100000;
  double best_min = -std::numeric_limits<double>::infinity();
  Location best;
  Isometry best_h;
  std::size_t expanded = 0;
  while(!heap.empty() && expanded < max_nodes) {
    const Node nd = nodes[heap.top().second];
    heap.pop();
    ++expanded;
    const Lifted_face& F = lt.faces[nd.f];
    C D[3];
    const bool id = nd.h.is_identity(0.0);
    for(int j = 0; j < 3; ++j)
      D[j] = id ? F.z[j] : nd.h.apply(F.z[j]);
    const int o = lt.orient(D[0], D[1], D[2]);
    if(o != 0) {
      bool inside = true;
      for(int j = 0; j < 3 && inside; ++j)
        inside = o * lt.orient(D[j], D[(j + 1) % 3], q) >= 0;
      Location l;
      finish_location(lt, q, nd.f, D, id, nd.h, l);
      if(inside) {
        loc = l;
        loc.success = true;
        loc.steps = expanded;
        h_out = nd.h;
        return;
      }
      if(l.min_raw_barycentric > best_min) {
        best_min = l.min_raw_barycentric;
        best = l;
        best_h = nd.h;
      }
    }
    for(int j = 0; j < 3; ++j) {
      const int t = F.tr[j];
      if(t < 0)
        continue;
      push(F.nf[j], t == 0 ? nd.h : nd.h * lt.transitions[t]);
    }
  }
  // not found exactly (an embedding that is not bijective, or rounding gaps between
  // copies): the best candidate, accepted if within rounding
  loc = best;
  loc.steps = expanded;
  loc.success = best.face_index != Lifted_triangulation<Traits>::no_face && best_min > -1e-9;
  h_out = best_h;
}

} // namespace internal
} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_LOCATOR_LOCATOR_SEARCH_H
