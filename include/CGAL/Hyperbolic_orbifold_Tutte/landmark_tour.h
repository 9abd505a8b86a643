// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_LANDMARK_TOUR_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_LANDMARK_TOUR_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Hyperbolic_orbifold_Tutte/error_code.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/input/landmark_distances.h>

#include <CGAL/boost/graph/properties.h>

#include <boost/graph/graph_traits.hpp>

#include <cstddef>
#include <vector>

/// \file landmark_tour.h
/// The landmark order of Aigerman & Lipman 2016, section 7, and the choice of one order for
/// several meshes.

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {
/*!
\ingroup PkgHyperbolicOrbifoldTutteHelperFunctions

computes the geodesic distances (lengths of the shortest edge paths) between the landmarks,
those `compute_landmark_tour()` orders them by; `rank_landmark_tours()` takes one such matrix
per mesh.

\tparam TriangleMesh a model of `FaceListGraph` and `HalfedgeListGraph`
\tparam VertexPointMap a model of `ReadablePropertyMap` with
        `boost::graph_traits<TriangleMesh>::%vertex_descriptor` as key type and a point of a
        CGAL kernel as value type

\return the symmetric matrix `D`, `D[i][j]` the distance between `landmarks[i]` and
        `landmarks[j]` (+infinity if they are not connected); empty if a landmark is not a
        vertex of `tm` or is given twice.

Cost: as `compute_landmark_tour()`, one Dijkstra search per landmark.
*/
template <class TriangleMesh, class VertexPointMap>
std::vector<std::vector<double> >
compute_landmark_distances(
  const TriangleMesh& tm,
  const std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>& landmarks,
  VertexPointMap vpm)
{
  return internal::compute_landmark_distance_matrix(tm, landmarks, vpm);
}

/*!
\ingroup PkgHyperbolicOrbifoldTutteHelperFunctions
a landmark order for several meshes with corresponding landmarks, as `rank_landmark_tours()`
proposes it.
*/
struct Landmark_order_candidate
{
  /// the order: landmark `order[c]` of every mesh is at cone `c`
  std::vector<std::size_t> order;
  /// the first mesh whose tour (`compute_landmark_tour()`) this order is
  std::size_t mesh = 0;
  /// the longest, over the meshes, of the length of the path through the landmarks in this
  /// order divided by the length of that mesh's own tour (1 on the mesh it comes from)
  double longest_ratio = 0;
};

/*!
\ingroup PkgHyperbolicOrbifoldTutteHelperFunctions

proposes landmark orders for several sphere-type meshes with corresponding landmarks
(landmark `i` of every mesh is the same feature), best first, for embedding all of them in
one order (maps between the meshes need one order). The candidates are the meshes' own tours
(`compute_landmark_tour()`). A tour that is short on one mesh can run back and forth on
another, whose cut through the landmarks is then long and may squeeze the embedding below
what double resolves; so each candidate is measured on every mesh, by the length of the path
through the landmarks in its order (the cut) divided by the length of that mesh's own tour
(how much longer than its best cut is this order's on this mesh: a ratio, so that meshes of
different sizes weigh the same), and the candidates are ranked by the longest of these ratios
over the meshes. Ties go to the mesh listed first, and an order that equals an earlier one or
its reverse (the same cut) is left out, so that the first candidate is mesh 0's tour whenever
no other tour is strictly better on the worst mesh.

\param distances one matrix per mesh, the geodesic distances between its landmarks
       (`compute_landmark_distances()`)

\return the candidates, best first: at least one and at most one per mesh; empty if
         `distances` is empty, if a matrix is not square with finite entries, or if the
         matrices differ in size.

Cost: a tour per mesh (`compute_landmark_tour()` from the distances) and \f$ O(N^2 k) \f$
for `N` meshes with `k` landmarks.
*/
inline std::vector<Landmark_order_candidate>
rank_landmark_tours(const std::vector<std::vector<std::vector<double> > >& distances)
{
  std::vector<Landmark_order_candidate> r;
  const std::size_t N = distances.size();
  if(N == 0) return r;
  std::vector<std::vector<std::size_t> > tours(N);
  std::vector<double> own(N, 0.); // each mesh's own tour's path length
  for(std::size_t m = 0; m < N; ++m) {
    if(distances[m].size() != distances[0].size()) return r;
    tours[m] = internal::landmark_tour_of_distances(distances[m]);
    if(tours[m].size() != distances[m].size()) return std::vector<Landmark_order_candidate>();
    own[m] = internal::path_length(distances[m], tours[m]);
  }
  for(std::size_t m = 0; m < N; ++m) {
    const std::vector<std::size_t>& t = tours[m];
    bool seen = false;
    for(const Landmark_order_candidate& c : r)
      seen = seen || c.order == t || std::equal(c.order.begin(), c.order.end(), t.rbegin());
    if(seen) continue;
    Landmark_order_candidate c;
    c.order = t;
    c.mesh = m;
    for(std::size_t o = 0; o < N; ++o) {
      const double len = internal::path_length(distances[o], t);
      // (a mesh whose own tour has length 0 has all its landmarks at one point: refused later)
      const double ratio = own[o] > 0 ? len / own[o] : (len > 0 ? std::numeric_limits<double>::infinity() : 1.);
      c.longest_ratio = (std::max)(c.longest_ratio, ratio);
    }
    r.push_back(c);
  }
  std::stable_sort(r.begin(), r.end(), [](const Landmark_order_candidate& a, const Landmark_order_candidate& b) {
    return a.longest_ratio < b.longest_ratio;
  });
  return r;
}

/*!
\ingroup PkgHyperbolicOrbifoldTutteHelperFunctions

tells whether an embedding's failure may depend on the order of the landmarks along the cut
(the cut itself, the solver, the certificate: another order may succeed), rather than on the
input (its topology, its landmarks, its coordinates: every order fails alike).
*/
inline bool is_landmark_order_failure(Error_code code)
{
  return code == ERROR_CUT_FAILED || code == ERROR_CANNOT_SOLVE_LINEAR_SYSTEM || code == ERROR_NOT_CONVERGED ||
         code == ERROR_NO_1_TO_1_MAPPING;
}

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
  return internal::landmark_tour(tm, landmarks, vpm);
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
