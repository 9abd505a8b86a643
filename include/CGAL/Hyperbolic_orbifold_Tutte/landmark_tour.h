// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_LANDMARK_TOUR_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_LANDMARK_TOUR_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Hyperbolic_orbifold_Tutte/internal/mesh_graph.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/shortest_tour.h>

#include <CGAL/boost/graph/properties.h>

#include <boost/graph/graph_traits.hpp>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#endif

#include <cstddef>
#include <limits>
#include <vector>

/// \file landmark_tour.h
/// The landmark order of Aigerman & Lipman 2016, section 7.

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

} // namespace internal

/*!
\ingroup PkgHyperbolicOrbifoldTutteHelperFunctions

computes the landmark order of Aigerman & Lipman 2016, section 7: the shortest closed tour
through the landmarks under geodesic distance (the length of the shortest edge path), cut
open at its longest edge. The tour is exact (Held-Karp) for at most 12 landmarks, and found
by nearest neighbour and 2-opt above. Cutting a sphere-type mesh through the landmarks in
this order (`compute_cut_through_landmarks()`) gives a short cut that rarely fails.

The result is deterministic: ties are broken towards smaller indices, and the order starts
at the endpoint of the removed edge with the smaller landmark index.

\tparam TriangleMesh a model of `FaceListGraph` and `HalfedgeListGraph`
\tparam VertexPointMap a model of `ReadablePropertyMap` with
        `boost::graph_traits<TriangleMesh>::%vertex_descriptor` as key type and a point of a
        CGAL kernel as value type

\param tm the mesh
\param landmarks the landmarks
\param vpm the vertex points

\return the permutation `p` of the indices into `landmarks` such that `landmarks[p[0]]`,
        `landmarks[p[1]]`, ... is the order; empty if a landmark is not a vertex of `tm`, is
        given twice, or if some landmarks are not connected to each other.

Cost: one Dijkstra search per landmark, \f$ O(k\, n \log n) \f$ for `k` landmarks on `n`
vertices (parallel with TBB, one search per task, from about 200000 vertex visits in all:
20 landmarks on 10000 vertices, or 50 on 4000).
*/
template <class TriangleMesh, class VertexPointMap>
std::vector<std::size_t>
compute_landmark_tour(
  const TriangleMesh& tm,
  const std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>& landmarks,
  VertexPointMap vpm)
{
  const std::vector<std::vector<double> > D = internal::compute_landmark_distance_matrix(tm, landmarks, vpm);
  if(D.size() != landmarks.size()) return std::vector<std::size_t>();
  for(const auto& row : D)
    for(double d : row)
      if(!(d < std::numeric_limits<double>::infinity())) return std::vector<std::size_t>();
  return internal::open_tour_at_longest_edge(D, internal::shortest_tour(D));
}

/*!
\ingroup PkgHyperbolicOrbifoldTutteHelperFunctions
same as above with the vertex points `get(CGAL::vertex_point, tm)`.
*/
template <class TriangleMesh>
std::vector<std::size_t>
compute_landmark_tour(
  const TriangleMesh& tm,
  const std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>& landmarks)
{
  return compute_landmark_tour(tm, landmarks, get(CGAL::vertex_point, tm));
}

} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_LANDMARK_TOUR_H
