// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_MATCH_EXTREMITIES_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_MATCH_EXTREMITIES_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Hyperbolic_orbifold_Tutte/check_input.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/error_code.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/parameters.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/core/mesh_graph.h>

#include <CGAL/boost/graph/named_params_helper.h>

#include <boost/graph/graph_traits.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <limits>
#include <string>
#include <utility>
#include <vector>

/// \file match_extremities.h

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {

/*!
\ingroup PkgHyperbolicOrbifoldTutteHelperFunctions
what `match_extremities()` found: the pairs of matched extremities, to be added to the
landmarks of both meshes (`pairs[i].first` on the source, `pairs[i].second` on the target), the
farthest from the landmarks first.
\tparam VertexDescriptor the meshes' `vertex_descriptor`
*/
template <class VertexDescriptor>
struct Extremity_matching
{
  std::vector<std::pair<VertexDescriptor, VertexDescriptor> > pairs; ///< (source vertex, target vertex)
  std::vector<double> source_tipness;        ///< per pair: the source extremity's tipness (below the threshold)
  std::vector<double> target_tipness;        ///< per pair: the target extremity's tipness
  std::vector<double> descriptor_difference; ///< per pair: the relative difference of the two descriptors
  std::size_t source_extremities = 0;        ///< the thin tips found on the source (matched or not)
  std::size_t target_extremities = 0;        ///< the thin tips found on the target
  double seconds = 0;                        ///< the time taken
  std::string message;                       ///< on failure, why (one line)
};

namespace internal {
namespace extremities {

// a ratio test: the best candidate's descriptor difference is at most 1/kRatio of the second's,
// and the second's is at least kRatio * kIndistinct (descriptors within 1% of each other cannot
// tell two tips apart: edge path distances are off by more than that)
constexpr double kRatio = 1.5;
constexpr double kIndistinct = 0.01;
// an extremity is at least this fraction of the largest distance to the landmarks away from them
constexpr double kFarthest = 0.2;

// one mesh's thin tips (dense vertex indices, farthest from the landmarks first), their
// tipness and their descriptors (geodesic distances to the landmarks over sqrt(area)); after
// the `tips` tips, the rivals: the mesh's other distinct maxima (see distinct_maxima()), with
// their descriptors (tipness 0), which a tip of the other mesh must not be nearer to
struct Tips
{
  std::size_t tips = 0;
  std::vector<int> vertex;
  std::vector<double> tipness;
  std::vector<std::vector<double> > descriptor;
};

// The distinct maxima of `f` (a vertex function; `candidate[v]`: v is a local maximum worth
// looking at) and, for every vertex, the distinct maximum whose feature holds it. Superlevel
// sets {f >= t} are swept down (union-find over the vertices in decreasing f): where two
// components meet, the one with the lower top dies, and its top's persistence is how far f
// dropped from it, f(top) - t. A maximum whose persistence is below `noise` is not a feature
// of its own: its feature is the one it merged into. The highest maximum never dies.
template <class Graph>
std::vector<int> distinct_maxima(const Graph& g, const std::vector<double>& f, const std::vector<char>& candidate,
                                 double noise, std::vector<int>& feature)
{
  const std::size_t n = g.size();
  std::vector<int> order(n);
  for(std::size_t i = 0; i < n; ++i) order[i] = static_cast<int>(i);
  const auto higher = [&](int a, int b) { return f[a] > f[b] || (f[a] == f[b] && a < b); };
  std::sort(order.begin(), order.end(), higher);
  // (owner: the top of the component that a vertex joined when it was swept, or that a maximum
  // merged into when it died with a persistence below `noise`; -1 for the distinct maxima)
  std::vector<int> parent(n, -1), top(n, -1), owner(n, -1);
  const auto find = [&](int x) {
    while(parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  for(int u : order) {
    parent[u] = top[u] = u;
    for(std::size_t e = g.offsets[u]; e < g.offsets[u + 1]; ++e) {
      const int v = g.nbrs[e];
      if(parent[v] < 0) continue; // (not swept yet)
      const int a = find(u), b = find(v);
      if(a == b) continue;
      const bool a_higher = higher(top[a], top[b]);
      const int survivor = a_higher ? top[a] : top[b], dead = a_higher ? top[b] : top[a];
      if(f[dead] - f[u] < noise) owner[dead] = survivor;
      parent[a_higher ? b : a] = a_higher ? a : b;
    }
  }
  feature.assign(n, -1);
  std::vector<int> distinct;
  for(int u : order) { // (an owner is higher: settled before)
    if(owner[u] >= 0)
      feature[u] = feature[owner[u]];
    else {
      feature[u] = u;
      if(candidate[u]) distinct.push_back(u);
    }
  }
  return distinct;
}

template <class Graph, class TriangleMesh>
std::vector<double> vertex_areas(const Graph& g, const TriangleMesh& tm, double& total)
{
  std::vector<double> area(g.size(), 0.);
  total = 0;
  for(auto f : faces(tm)) {
    int c[3], n = 0;
    for(auto v : vertices_around_face(halfedge(f, tm), tm))
      if(n < 3) c[n++] = static_cast<int>(g.index(v));
    if(n < 3) continue;
    const double* p = &g.xyz[3 * c[0]];
    const double* q = &g.xyz[3 * c[1]];
    const double* r = &g.xyz[3 * c[2]];
    const double u[3] = {q[0] - p[0], q[1] - p[1], q[2] - p[2]}, w[3] = {r[0] - p[0], r[1] - p[1], r[2] - p[2]};
    const double x = u[1] * w[2] - u[2] * w[1], y = u[2] * w[0] - u[0] * w[2], z = u[0] * w[1] - u[1] * w[0];
    const double a = 0.5 * std::sqrt(x * x + y * y + z * z);
    total += a;
    for(int i = 0; i < 3; ++i) area[c[i]] += a / 3;
  }
  return area;
}

// the vertices within geodesic (edge path) distance `r` of `s`
template <class Graph>
std::vector<int> geodesic_ball(const Graph& g, Dijkstra_workspace& ws, int s, double r)
{
  std::vector<int> ball;
  bool beyond = false;
  ws.begin_run();
  dijkstra(g, ws, s, [&](int u) { if(ws.distance(u) <= r) ball.push_back(u); else beyond = true; },
           [&]() { return beyond; });
  return ball;
}

// The thin tips of a mesh: the local maxima of the geodesic distance to the landmarks (at least
// kFarthest of its largest value), each the largest within its geodesic ball of radius
// `radius` times that largest value, whose ball has an area under `threshold` times the flat
// disk's pi r^2 (a cone of half-angle alpha gives sin(alpha); a flat or convex region about 1).
template <class Graph, class TriangleMesh>
Tips thin_tips(const Graph& g, const TriangleMesh& tm, const std::vector<int>& landmarks, double radius, double threshold)
{
  Tips tips;
  const std::size_t n = g.size();
  double total_area = 0;
  const std::vector<double> area = vertex_areas(g, tm, total_area);
  Dijkstra_distances nearest(n); // to the nearest landmark
  for(int l : landmarks)
    dijkstra(g, nearest, l, [](int) {}, []() { return false; });
  double dmax = 0;
  for(double d : nearest.dist) dmax = (std::max)(dmax, d);
  std::vector<std::pair<double, int> > candidates; // (-distance, vertex)
  std::vector<char> is_candidate(n, 0);
  for(std::size_t i = 0; i < n; ++i) {
    const double d = nearest.dist[i];
    bool top = d >= kFarthest * dmax;
    for(std::size_t e = g.offsets[i]; top && e < g.offsets[i + 1]; ++e)
      top = nearest.dist[g.nbrs[e]] <= d;
    if(top) candidates.emplace_back(-d, static_cast<int>(i));
    is_candidate[i] = top;
  }
  // the distinct maxima: edge path distances place a maximum only to about an edge, so a drop
  // of less than the mean edge length between two maxima does not make them two features
  double mean_edge = 0;
  for(double l : g.lengths) mean_edge += l / g.lengths.size();
  std::vector<int> feature;
  const std::vector<int> distinct = distinct_maxima(g, nearest.dist, is_candidate, mean_edge, feature);
  std::sort(candidates.begin(), candidates.end());
  Dijkstra_workspace ws;
  ws.init(n);
  std::vector<char> covered(n, 0);
  const double r = radius * dmax;
  for(const std::pair<double, int>& c : candidates) {
    if(covered[c.second]) continue;
    double a = 0;
    for(int u : geodesic_ball(g, ws, c.second, r)) {
      covered[u] = 1;
      a += area[u];
    }
    const double tipness = a / (CGAL_PI * r * r);
    if(tipness < threshold) {
      tips.vertex.push_back(c.second);
      tips.tipness.push_back(tipness);
    }
  }
  // the rivals: the distinct maxima that are no tip's feature
  tips.tips = tips.vertex.size();
  std::vector<char> is_tip(n, 0);
  for(int t : tips.vertex) is_tip[feature[t]] = 1;
  for(int m : distinct)
    if(!is_tip[m]) {
      tips.vertex.push_back(m);
      tips.tipness.push_back(0.);
    }
  // the descriptors: one search per landmark, stopped once every tip and rival is settled
  tips.descriptor.assign(tips.vertex.size(), std::vector<double>(landmarks.size()));
  std::fill(is_tip.begin(), is_tip.end(), 0);
  for(int t : tips.vertex) is_tip[t] = 1;
  const double scale = 1 / std::sqrt(total_area);
  for(std::size_t j = 0; j < landmarks.size() && !tips.vertex.empty(); ++j) {
    std::size_t settled = 0;
    ws.begin_run();
    dijkstra(g, ws, landmarks[j], [&](int u) { settled += is_tip[u]; }, [&]() { return settled == tips.vertex.size(); });
    for(std::size_t t = 0; t < tips.vertex.size(); ++t)
      tips.descriptor[t][j] = ws.distance(tips.vertex[t]) * scale;
  }
  return tips;
}

// the relative difference of two descriptors, sqrt(2 |x - y|^2 / (|x|^2 + |y|^2))
inline double descriptor_difference(const std::vector<double>& x, const std::vector<double>& y)
{
  double num = 0, den = 0;
  for(std::size_t j = 0; j < x.size(); ++j) {
    num += (x[j] - y[j]) * (x[j] - y[j]);
    den += x[j] * x[j] + y[j] * y[j];
  }
  return den > 0 ? std::sqrt(2 * num / den) : 0.;
}

// the tip of `to` whose descriptor is the nearest to `x`: its position, and the differences of
// the nearest and the second nearest
inline std::size_t nearest_tip(const Tips& to, const std::vector<double>& x, double& first, double& second)
{
  std::size_t best = 0;
  first = second = std::numeric_limits<double>::infinity();
  for(std::size_t t = 0; t < to.vertex.size(); ++t) {
    const double d = descriptor_difference(to.descriptor[t], x);
    if(d < first) { second = first; first = d; best = t; }
    else if(d < second) second = d;
  }
  return best;
}

} // namespace extremities
} // namespace internal

/*!
\ingroup PkgHyperbolicOrbifoldTutteHelperFunctions

finds the thin tips (extremities) of `A` and of `B` that the landmarks leave out, and matches
them across the two meshes, so that adding the matched pairs to the landmarks lets the map
follow protrusions that no landmark holds (a tail, a heel: without a landmark the orbifold map
squeezes such a protrusion onto a small region of the other shape).

An extremity is a local maximum of the geodesic (shortest edge path) distance to the
landmarks, at least 0.2 times its largest value \f$d_{max}\f$ and the largest within its
geodesic ball of radius \f$r = \rho\, d_{max}\f$, and it is a thin tip: that ball's area is
below \f$\tau\, \pi r^2\f$ (a cone of half-angle \f$\alpha\f$ gives \f$\sin\alpha\f$, a flat or
convex region about 1; the default \f$\tau = 0.65\f$ keeps tips sharper than a cone of
half-angle 40 degrees at that scale). Each mesh is looked at alone: an extremity's descriptor
is its geodesic distances to the landmarks divided by the square root of the mesh's area, and
an extremity of `A` and one of `B` are matched when each is the other's nearest by the relative
difference of descriptors \f$\sqrt{2\|x-y\|^2/(\|x\|^2+\|y\|^2)}\f$, that difference is below
the tolerance, and the second nearest on either side is at least 1.5 times farther and at
least 0.015 away (two tips whose descriptors differ by less cannot be told apart; the map
between the meshes is not used: near a protrusion without a landmark it is what is wrong).
Both tests run over the other mesh's tips and its *rivals*: its other distinct maxima of the
distance (at least 0.2 \f$d_{max}\f$; distinct: sweeping the distance down, the distance
drops from it by at least the mean edge length before its region meets a higher maximum's)
that are no tip's own; a tip nearest to a rival is not matched. So a tip whose ball hides a
second feature almost as far (a claw beside a claw), which a deformation can make the
farthest on the other mesh, is left out rather than matched onto the wrong one.
The descriptors tell left from right as far as the landmarks do: mirror twins that the
landmarks do not tell apart are left out, not guessed. A maximum on a ridge around a limb
whose both ends hold landmarks can pass the area test too; it is matched by its descriptor
like a tip, which places it around the limb less precisely.

\tparam TriangleMesh a model of `FaceListGraph` (the vertex points: `get(CGAL::vertex_point, mesh)`)
\tparam NamedParameters a sequence of named parameters

\param A the source mesh, closed
\param landmarks_A its landmarks (at least 3)
\param B the target mesh, closed
\param landmarks_B its landmarks, `landmarks_B[i]` corresponding to `landmarks_A[i]`
\param result the matched pairs and the counts
\param np optional named parameters among:
  - `extremity_radius` (`double`, default 0.25): \f$\rho\f$, in (0, 1]
  - `tip_threshold` (`double`, default 0.65): \f$\tau\f$, in (0, 1]
  - `descriptor_tolerance` (`double`, default 0.1): the largest relative difference of the
    descriptors of a matched pair, in (0, 1]

\return `OK` (possibly with no pair), or the failure of `check_mesh()` (sphere type) or
`check_landmark_vertices()` on either mesh, `ERROR_WRONG_PARAMETER` for landmark lists of
different sizes or a parameter out of its range; `result.message` says why.

Time: \f$O((k + m)\, n \log n)\f$ for \f$k\f$ landmarks and \f$m\f$ local maxima examined, in
practice a few full searches per landmark (0.01 to 0.03 s for 7 or 21 landmarks on 4,344 vertices).
*/
template <class TriangleMesh, class NamedParameters = CGAL::parameters::Default_named_parameters>
Error_code match_extremities(const TriangleMesh& A,
                             const std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>& landmarks_A,
                             const TriangleMesh& B,
                             const std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>& landmarks_B,
                             Extremity_matching<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>& result,
                             const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  namespace X = internal::extremities;
  const auto t0 = std::chrono::steady_clock::now();
  result = Extremity_matching<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>();
  const double radius = choose_parameter(get_parameter(np, internal_np::extremity_radius), 0.25);
  const double threshold = choose_parameter(get_parameter(np, internal_np::tip_threshold), 0.65);
  const double tolerance = choose_parameter(get_parameter(np, internal_np::descriptor_tolerance), 0.1);
  const auto fail = [&](const Status& s, const char* which) {
    result.message = std::string(which) + s.message;
    return s.code;
  };
  const auto in_range = [](double x) { return x > 0 && x <= 1; }; // (false for NaN)
  if(!in_range(radius) || !in_range(threshold) || !in_range(tolerance))
    return fail(Status::failure(ERROR_WRONG_PARAMETER, "extremity_radius, tip_threshold and descriptor_tolerance must lie in (0, 1]"), "");
  if(landmarks_A.size() != landmarks_B.size())
    return fail(Status::failure(ERROR_WRONG_PARAMETER, std::to_string(landmarks_A.size()) + " landmarks on the source and " +
                                                         std::to_string(landmarks_B.size()) + " on the target"), "");
  const TriangleMesh* mesh[2] = {&A, &B};
  const std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>* lm[2] = {&landmarks_A, &landmarks_B};
  X::Tips tips[2];
  std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor> verts[2];
  for(int m = 0; m < 2; ++m) {
    const char* which = m == 0 ? "the source: " : "the target: ";
    Status s = check_mesh(*mesh[m], Sphere_type);
    if(s)
      s = check_landmark_vertices(*mesh[m], *lm[m], Sphere_type, 3);
    if(!s)
      return fail(s, which);
    const internal::Mesh_graph<TriangleMesh> g(*mesh[m], get(CGAL::vertex_point, *mesh[m]));
    std::vector<int> ids;
    internal::landmark_indices(g, *lm[m], ids); // (checked above)
    tips[m] = X::thin_tips(g, *mesh[m], ids, radius, threshold);
    verts[m] = g.verts;
  }
  result.source_extremities = tips[0].tips;
  result.target_extremities = tips[1].tips;
  std::vector<char> taken(tips[1].vertex.size(), 0);
  for(std::size_t a = 0; a < tips[0].tips && tips[1].tips > 0; ++a) {
    double d1, d2, e1, e2;
    const std::size_t b = X::nearest_tip(tips[1], tips[0].descriptor[a], d1, d2);
    if(b >= tips[1].tips || d1 > tolerance || d2 < X::kRatio * (std::max)(d1, X::kIndistinct) || taken[b])
      continue; // (nearest to a rival: not a tip of the other mesh)
    if(X::nearest_tip(tips[0], tips[1].descriptor[b], e1, e2) != a || e2 < X::kRatio * (std::max)(e1, X::kIndistinct))
      continue;
    taken[b] = 1;
    result.pairs.emplace_back(verts[0][tips[0].vertex[a]], verts[1][tips[1].vertex[b]]);
    result.source_tipness.push_back(tips[0].tipness[a]);
    result.target_tipness.push_back(tips[1].tipness[b]);
    result.descriptor_difference.push_back(d1);
  }
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return OK;
}

} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_MATCH_EXTREMITIES_H
