// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_INPUT_LANDMARK_DISTANCES_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_INPUT_LANDMARK_DISTANCES_H

// The geodesic distances between the landmarks (one Dijkstra search per landmark) and the
// landmark order of Aigerman & Lipman 2016, section 7, on them: the steps of
// compute_landmark_tour() and rank_landmark_tours() (landmark_tour.h), and the input stage's
// order (input_stage.h).

#include <CGAL/disable_warnings.h>

#include <CGAL/Hyperbolic_orbifold_Tutte/internal/core/mesh_graph.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/input/shortest_tour.h>

#include <boost/graph/graph_traits.hpp>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#endif

#include <algorithm>
#include <cstddef>
#include <limits>
#include <vector>

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {
namespace internal {

// Pairwise geodesic (shortest edge path) distances between the landmarks,
// one Dijkstra per landmark, each stopped once the remaining landmarks are
// settled.  Returns an empty matrix on invalid landmarks; unreachable pairs
// get +infinity.  O(k n log n): each run usually sweeps most of the mesh,
// so this dominates the pipeline on big meshes (about 0.6 s per landmark on
// a 2.6M-vertex mesh), far more than the cut itself.
template <class TriangleMesh, class VertexPointMap>
std::vector<std::vector<double> >
compute_landmark_distance_matrix(
  const TriangleMesh& tm,
  const std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>& landmarks,
  VertexPointMap vpm)
{
  std::vector<std::vector<double> > D;
  const Mesh_graph<TriangleMesh> g(tm, vpm);
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
      const std::size_t n_targets = k - 1 - i;
      std::size_t settled = 0;
      ws.begin_run();
      dijkstra(g, ws, lm[i], [&](int u) { if(targets[u]) ++settled; },
               [&]() { return settled >= n_targets; });
      for(std::size_t j = i + 1; j < k; ++j) D[i][j] = D[j][i] = ws.distance(lm[j]);
    }
  };
  if(k < 2) return D;
#ifdef CGAL_LINKED_WITH_TBB
  if(g.size() * (k - 1) > 200000) { // (tens of milliseconds of searches)
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, k - 1, 1),
                      [&](const tbb::blocked_range<std::size_t>& r) { runs(r.begin(), r.end()); });
    return D;
  }
#endif
  runs(0, k - 1);
  return D;
}

// Whether `D` is a square matrix of finite distances (every landmark reaches every other).
inline bool is_finite_distance_matrix(const std::vector<std::vector<double> >& D)
{
  for(const auto& row : D) {
    if(row.size() != D.size()) return false;
    for(double d : row)
      if(!(d < std::numeric_limits<double>::infinity())) return false;
  }
  return true;
}

// The paper's order from the landmark distances: the shortest closed tour, opened at its
// longest edge. Empty if `D` is not a square matrix of finite distances.
inline std::vector<std::size_t>
landmark_tour_of_distances(const std::vector<std::vector<double> >& D)
{
  if(!is_finite_distance_matrix(D)) return std::vector<std::size_t>();
  return open_tour_at_longest_edge(D, shortest_tour(D));
}

// Length of the open path through the landmarks in `order` under `D` (the length of the cut
// of a sphere-type mesh through them in that order).
inline double path_length(const std::vector<std::vector<double> >& D, const std::vector<std::size_t>& order)
{
  double len = 0.;
  for(std::size_t i = 1; i < order.size(); ++i)
    len += D[order[i - 1]][order[i]];
  return len;
}

// compute_landmark_tour() (landmark_tour.h): the order of the landmarks along the shortest
// closed tour under geodesic distance, opened at its longest edge; empty on invalid landmarks
// or when some are not connected
template <class TriangleMesh, class VertexPointMap>
std::vector<std::size_t>
landmark_tour(const TriangleMesh& tm,
              const std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>& landmarks,
              VertexPointMap vpm)
{
  const std::vector<std::vector<double> > D = compute_landmark_distance_matrix(tm, landmarks, vpm);
  if(D.size() != landmarks.size()) return std::vector<std::size_t>();
  return landmark_tour_of_distances(D);
}

} // namespace internal

} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_INPUT_LANDMARK_DISTANCES_H
