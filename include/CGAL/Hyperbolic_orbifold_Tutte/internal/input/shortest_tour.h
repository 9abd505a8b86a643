// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_INPUT_SHORTEST_TOUR_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_INPUT_SHORTEST_TOUR_H

// Shortest closed tour through k points given their distance matrix D (the travelling
// salesman problem, for the landmark order of Aigerman & Lipman 2016, section 7): exact by
// Held-Karp for small k, nearest neighbour + 2-opt above, and the opening of the tour at its
// longest edge. Deterministic; ties are broken towards smaller indices.

#include <algorithm>
#include <cstddef>
#include <limits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {
namespace internal {

// Length of the closed tour `tour` (a permutation of 0..k-1) under `D`.
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

// Exact shortest closed tour by Held-Karp dynamic programming,
// O(2^k k^2) time and O(2^k k) memory: meant for k <= 12 or so (above 20
// it would need gigabytes, so it falls back to the heuristic).
// The tour starts at 0.  Ties are broken towards smaller indices.
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

// Heuristic shortest closed tour: nearest-neighbour tour from every start,
// each improved by 2-opt, keeping the best.  O(k^3) per 2-opt pass; meant
// for the k > 12 case where Held-Karp is too expensive.  Deterministic.
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

// Shortest closed tour: exact (Held-Karp) for k <= 12, heuristic otherwise.
inline std::vector<std::size_t>
shortest_tour(const std::vector<std::vector<double> >& D)
{
  return D.size() <= 12 ? shortest_tour_held_karp(D) : shortest_tour_heuristic(D);
}

// Opens the closed tour at its longest edge.  Ties between equally long
// edges are broken by the smallest (min index, max index) pair.  The open
// path starts at the endpoint of the removed edge with the smaller index and
// ends at the other one, so the result does not depend on how the tour was
// rotated or oriented.
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

} // namespace internal
} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_INPUT_SHORTEST_TOUR_H
