// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_MATCH_EXTREMITIES_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_MATCH_EXTREMITIES_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Hyperbolic_orbifold_Tutte/Embedding_locator.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/check_input.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/error_code.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/hyperbolic_orbifold_Tutte_embedding.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/map_reliability.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/parameters.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/core/mesh_graph.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/maps/extremity_tips.h>

#include <CGAL/Dynamic_property_map.h>
#include <CGAL/Kernel_traits.h>

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
  std::size_t matched_along_map = 0;         ///< of the pairs, those matched along the map (the last ones)
  bool embedded_along_map = false;           ///< whether the matching along the map embedded both meshes (only when it could add a pair: a tip left unmatched on one mesh, a thin maximum on the other)
  double seconds = 0;                        ///< the time taken
  std::string message;                       ///< on failure, why (one line)
};

namespace internal {
namespace extremities {

// One mesh of the matching along the map: its graph, landmarks (dense indices), field, tips,
// the vertices already matched, its embedding and locator.
template <class TriangleMesh>
struct Side
{
  typedef typename boost::property_map<TriangleMesh, CGAL::vertex_point_t>::const_type Vertex_point_map;
  typedef typename CGAL::Kernel_traits<typename boost::property_traits<Vertex_point_map>::value_type>::Kernel::Point_2 Point_2;
  typedef typename boost::property_map<TriangleMesh, CGAL::dynamic_halfedge_property_t<Point_2> >::const_type UV_map;
  typedef Embedding_locator<TriangleMesh, UV_map> Locator;

  const TriangleMesh* mesh = nullptr;
  const Mesh_graph<TriangleMesh>* g = nullptr;
  std::vector<int> landmarks;
  Distance_field field;
  Tips tips;
  std::vector<char> used; // per vertex: in a pair
  UV_map uv;
  Locator locator;

  // the vertex nearest to the image of vertex v of `from` (landing_vertex(): the corner with the
  // largest barycentric coordinate of the face where one of v's corners lands), -1 if it is not located
  int image(const Side& from, int v) const
  {
    const TriangleMesh& tm = *from.mesh;
    for(auto h : halfedges_around_target(halfedge(from.g->verts[v], tm), tm))
      if(!is_border(h, tm)) {
        const typename Locator::Location loc = locator.locate(get(from.uv, h));
        return loc.success ? static_cast<int>(landing_vertex(locator, loc)) : -1;
      }
    return -1;
  }
};

// embeds both meshes with their landmarks (the source in the tour order, the target in the same
// order) into the side's dynamic maps and builds their locators; false if either is refused
template <class TriangleMesh>
bool embed_sides(Side<TriangleMesh>& A, const std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>& la,
                 Side<TriangleMesh>& B, const std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>& lb)
{
  typedef typename Side<TriangleMesh>::Point_2 Point_2;
  A.uv = get(CGAL::dynamic_halfedge_property_t<Point_2>(), *A.mesh);
  B.uv = get(CGAL::dynamic_halfedge_property_t<Point_2>(), *B.mesh);
  Embedding_statistics sa, sb;
  // (cones of order 2, or of order 4 below the 5 landmarks that order 2 needs on a sphere)
  const std::vector<int> orders(la.size(), la.size() < 5 ? 4 : 2);
  if(hyperbolic_orbifold_Tutte_embedding(*A.mesh, la, A.uv, parameters::embedding_statistics(&sa, parameters::landmark_order(Tsp_order, parameters::cone_orders(orders)))) != OK)
    return false;
  std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor> oa, ob;
  for(std::size_t i : sa.landmark_order) {
    oa.push_back(la[i]);
    ob.push_back(lb[i]);
  }
  if(hyperbolic_orbifold_Tutte_embedding(*B.mesh, ob, B.uv, parameters::embedding_statistics(&sb, parameters::cone_orders(orders))) != OK ||
     !sa.charts.empty() || !sb.charts.empty())
    return false;
  A.locator = typename Side<TriangleMesh>::Locator(*A.mesh, A.uv, sa.signature());
  B.locator = typename Side<TriangleMesh>::Locator(*B.mesh, B.uv, sb.signature());
  return A.locator.is_valid() && B.locator.is_valid();
}

// The matching along the map, from the tips of `from` left unmatched to `to`: the thin maximum
// m of `to`'s distance nearest to the tip's image (nearest_thin_maximum(), within the ball
// radius r) is matched to the tip if its descriptor is within `tolerance` of the tip's and no
// tip or rival of `to` farther than r / 4 from m is nearer to it by more than kIndistinct (the
// descriptors would clearly prefer another feature: the map is wrong there), no pair holds a vertex
// within r / 2 of m, and the way back (m's image, then the nearest thin maximum of `from`)
// ends within r / 4 of the tip. Calls `add(tip, m, tipness of m, descriptor difference)` for
// each such pair (which marks both vertices used and paired).
template <class TriangleMesh, class Add>
void match_from(const Side<TriangleMesh>& from, const Side<TriangleMesh>& to, const std::vector<int>& paired_to,
                double threshold, double tolerance, const Add& add)
{
  Dijkstra_workspace ws;
  ws.init((std::max)(from.g->size(), to.g->size()));
  const auto within = [&](const Mesh_graph<TriangleMesh>& g, int s, double r, const std::vector<int>& targets) {
    const std::vector<int> ball = geodesic_ball(g, ws, s, r);
    for(int t : targets)
      if(std::find(ball.begin(), ball.end(), t) != ball.end()) return true;
    return false;
  };
  for(std::size_t t = 0; t < from.tips.tips; ++t) {
    const int a = from.tips.vertex[t];
    if(from.used[a]) continue;
    const int v = to.image(from, a);
    double tipness = 0, back_tipness = 0;
    const int m = v < 0 ? -1 : nearest_thin_maximum(*to.g, to.field, v, threshold, tipness);
    if(m < 0 || within(*to.g, m, 0.5 * to.field.r, paired_to)) continue;
    const int w = from.image(to, m);
    const int back = w < 0 ? -1 : nearest_thin_maximum(*from.g, from.field, w, threshold, back_tipness);
    if(back < 0 || !within(*from.g, back, 0.25 * from.field.r, {a})) continue;
    const std::vector<double>& x = from.tips.descriptor[t];
    const double d = descriptor_difference(x, descriptor_at(*to.g, ws, to.field, to.landmarks, m));
    bool nearest = d <= tolerance;
    const std::vector<int> same = geodesic_ball(*to.g, ws, m, 0.25 * to.field.r);
    for(std::size_t k = 0; nearest && k < to.tips.vertex.size(); ++k)
      nearest = descriptor_difference(x, to.tips.descriptor[k]) >= d - kIndistinct ||
                std::find(same.begin(), same.end(), to.tips.vertex[k]) != same.end();
    if(nearest)
      add(t, m, tipness, d);
  }
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
The descriptors tell left from right only as far as the landmarks do: mirror twins that the
landmarks tell apart weakly or not at all are left out by these tests.

The orbifold map tells them apart: it never reverses orientation. So, unless
`match_along_map` is `false`, the tips still unmatched on either mesh are then matched
*along the map*: both meshes are embedded with the landmarks and the pairs found (cones of order
2, or 4 below 5 landmarks; the source in its tour order), and a tip is matched to the thin
maximum m of the other mesh's distance nearest to the tip's image (a local maximum, at least 0.2
\f$d_{max}\f$, whose ball's area is below the threshold; within geodesic distance \f$r\f$ of the
image), when their descriptors differ by at most the tolerance and no other tip or rival of
that mesh has a descriptor nearer by more than 0.01 (near a protrusion without a landmark the
map can be wrong: a horn's image beside the ear), no pair already holds a vertex
within \f$r/2\f$ of m, and the way back (m's image, then the nearest thin maximum there) ends
within \f$r/4\f$ of the tip. The maxima that the balls of other tips hid (an ear beside an ear)
are found this way too. If either embedding is refused, nothing is matched along the map. The
embeddings are computed only when a pair can be added this way: a tip left unmatched on one mesh
and a thin maximum anywhere on the other (`result.embedded_along_map`). A maximum on a ridge around a limb
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
  - `match_along_map` (`bool`, default `true`): whether the tips left unmatched are matched
    along the map

\return `OK` (possibly with no pair), or the failure of `check_mesh()` (sphere type) or
`check_landmark_vertices()` on either mesh, `ERROR_WRONG_PARAMETER` for landmark lists of
different sizes or a parameter out of its range; `result.message` says why.

Time: \f$O((k + m)\, n \log n)\f$ for \f$k\f$ landmarks and \f$m\f$ local maxima examined, in
practice a few full searches per landmark (0.01 to 0.03 s for 7 or 21 landmarks on 4,344
vertices), and, when a tip left unmatched on one mesh has a thin maximum to go to on the other,
the embeddings of both meshes (0.2 to 0.3 s there).
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
  const bool along_map = choose_parameter(get_parameter(np, internal_np::match_along_map), true);
  const TriangleMesh* mesh[2] = {&A, &B};
  const std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>* lm[2] = {&landmarks_A, &landmarks_B};
  for(int m = 0; m < 2; ++m) {
    Status s = check_mesh(*mesh[m], Sphere_type);
    if(s)
      s = check_landmark_vertices(*mesh[m], *lm[m], Sphere_type, 3);
    if(!s)
      return fail(s, m == 0 ? "the source: " : "the target: ");
  }
  const internal::Mesh_graph<TriangleMesh> gA(A, get(CGAL::vertex_point, A)), gB(B, get(CGAL::vertex_point, B));
  X::Side<TriangleMesh> side[2];
  const internal::Mesh_graph<TriangleMesh>* graph[2] = {&gA, &gB};
  for(int m = 0; m < 2; ++m) {
    X::Side<TriangleMesh>& S = side[m];
    S.mesh = mesh[m];
    S.g = graph[m];
    internal::landmark_indices(*S.g, *lm[m], S.landmarks); // (checked above)
    S.tips = X::thin_tips(*S.g, *S.mesh, S.landmarks, radius, threshold, S.field);
    S.used.assign(S.g->size(), 0);
  }
  const X::Tips* tips[2] = {&side[0].tips, &side[1].tips};
  result.source_extremities = tips[0]->tips;
  result.target_extremities = tips[1]->tips;
  std::vector<int> paired[2];
  const auto add = [&](int a, int b, double ta, double tb, double d) {
    side[0].used[a] = side[1].used[b] = 1;
    paired[0].push_back(a);
    paired[1].push_back(b);
    result.pairs.emplace_back(gA.verts[a], gB.verts[b]);
    result.source_tipness.push_back(ta);
    result.target_tipness.push_back(tb);
    result.descriptor_difference.push_back(d);
  };
  std::vector<char> taken(tips[1]->vertex.size(), 0);
  for(std::size_t a = 0; a < tips[0]->tips && tips[1]->tips > 0; ++a) {
    double d1, d2, e1, e2;
    const std::size_t b = X::nearest_tip(*tips[1], tips[0]->descriptor[a], d1, d2);
    if(b >= tips[1]->tips || d1 > tolerance || d2 < X::kRatio * (std::max)(d1, X::kIndistinct) || taken[b])
      continue; // (nearest to a rival: not a tip of the other mesh)
    if(X::nearest_tip(*tips[0], tips[1]->descriptor[b], e1, e2) != a || e2 < X::kRatio * (std::max)(e1, X::kIndistinct))
      continue;
    taken[b] = 1;
    add(tips[0]->vertex[a], tips[1]->vertex[b], tips[0]->tipness[a], tips[1]->tipness[b], d1);
  }
  // the tips left unmatched, along the map computed with the landmarks and the pairs found;
  // the embeddings only when a way can add a pair: a tip left on one mesh, a thin maximum on the
  // other (the only vertices match_from() matches a tip to; on SHREC'07's four-legged animals
  // half of the ordered pairs have none on one side, where the embeddings took as long as the map)
  bool left[2] = {false, false};
  for(int m = 0; m < 2; ++m)
    for(std::size_t t = 0; t < tips[m]->tips; ++t)
      left[m] = left[m] || !side[m].used[tips[m]->vertex[t]];
  const auto can_add = [&](int from) {
    return left[from] && X::has_thin_maximum(*side[1 - from].g, side[1 - from].field, side[1 - from].tips, threshold);
  };
  if(along_map && (can_add(0) || can_add(1))) {
    result.embedded_along_map = true;
    std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor> la = landmarks_A, lb = landmarks_B;
    for(const auto& p : result.pairs) {
      la.push_back(p.first);
      lb.push_back(p.second);
    }
    const std::size_t before = result.pairs.size();
    if(X::embed_sides(side[0], la, side[1], lb)) {
      X::match_from(side[0], side[1], paired[1], threshold, tolerance, [&](std::size_t t, int b, double tb, double d) {
        add(tips[0]->vertex[t], b, tips[0]->tipness[t], tb, d);
      });
      X::match_from(side[1], side[0], paired[0], threshold, tolerance, [&](std::size_t t, int a, double ta, double d) {
        add(a, tips[1]->vertex[t], ta, tips[1]->tipness[t], d);
      });
    }
    result.matched_along_map = result.pairs.size() - before;
  }
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return OK;
}

} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_MATCH_EXTREMITIES_H
