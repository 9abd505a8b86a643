// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_MAP_RELIABILITY_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_MAP_RELIABILITY_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Hyperbolic_orbifold_Tutte/Embedding_locator.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/Hyperbolic_isometry_2.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/surface_maps.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/core/dense_index.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/maps/embedding_scale.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstddef>
#include <limits>
#include <vector>

/// \file map_reliability.h
/// Which vertices of a surface map cannot be trusted: where the map shrinks or stretches
/// lengths far from what an isometry would (a protrusion without a landmark, collapsed by the
/// two embeddings below their own disagreement), or where `double` cannot resolve it.

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {

/*!
\ingroup PkgHyperbolicOrbifoldTutteMainClasses

the thresholds of `map_reliability()`.
*/
struct Map_reliability_options
{
  /// \name The scale test (a map that shrinks or stretches a neighbourhood)
  //@{
  /// a vertex is unreliable when the map's 3D scale at it (the ratio of the two embeddings'
  /// conformal factors at the vertex and at its image) differs from the reference scale (the
  /// square root of the ratio of the areas of `B` and `A`) by more than this factor, either way
  /// (the absolute natural logarithm of the ratio above `std::log(scale_factor)`)
  double scale_factor = 6;
  /// rounds of smoothing of the logarithm of each embedding's conformal factor over the
  /// one-rings (area-weighted mean of a vertex and its neighbours) before the scale test: the
  /// per-vertex factor of a sliver or of a noisy vertex is itself noisy
  int smoothing_rounds = 2;
  //@}

  /// \name The rounding test (a neighbourhood below what `double` resolves)
  //@{
  /// a vertex is unresolved when its hyperbolic one-ring size in `A`'s embedding, or the size of
  /// the face of `B` its image lies in, is below this many units in the last place of `double`
  /// at its position (converted to a hyperbolic length); it is unreliable unless it lies in a
  /// squeezed region holding a landmark, which both embeddings collapse onto the same cone
  double rounding_ulps = 16;
  //@}

  /// \name The protrusion test (squeezed regions without a landmark)
  //@{
  /// a vertex is squeezed when the hyperbolic length of its edges per unit of 3D length is
  /// below this fraction of the mesh's average (the square root of the sum of the squared
  /// hyperbolic edge lengths over the sum of the squared 3D edge lengths)
  double squeeze_ratio = 1e-2;
  /// a squeezed region is unresolved when the distance between the point it collapses to
  /// in the source's embedding, carried to the target, and the point the target's region
  /// collapses to exceeds this many times the larger hyperbolic one-ring size of the two
  /// collapse vertices (below it the two differ by about a triangle: an ordinary offset), and
  /// the map fails the scale or the rounding test at its collapse vertex (the map does collapse there)
  double noise_factor = 4;
  /// in an unresolved region, a vertex is unreliable when its uncertainty (how far its
  /// image on the target moves when the two collapse points are made to correspond)
  /// exceeds this fraction of the target's bounding-box diagonal, its scale disagreement
  /// exceeds `noise_multiple` times the scale noise of the map (see `Map_reliability::scale_noise`),
  /// and it lies on the protrusion in both embeddings (the basins of the two collapse
  /// vertices, see `map_reliability()`; no threshold)
  double error_fraction = 0.01;
  /// see `error_fraction`
  double noise_multiple = 3;
  //@}
};

/*!
\ingroup PkgHyperbolicOrbifoldTutteMainClasses

a squeezed region of the source mesh and what `map_reliability()` found out about it. Vertex
numbers are positions in `vertices(A)` and `vertices(B)` order.
*/
struct Squeezed_region
{
  std::size_t number_of_vertices = 0; ///< the squeezed vertices of the region in `A`
  std::size_t source_vertex = 0;      ///< the vertex of `A` it collapses to (a landmark if it holds one, else the most squeezed)
  std::size_t target_vertex = 0;      ///< the same for the region of `B` where the map sends it (not for a region at a landmark)
  bool at_landmark = false;           ///< the region of `A` holds a landmark: both embeddings collapse onto its cone (not flagged)
  double discrepancy = 0;             ///< hyperbolic distance between the image of `source_vertex` and `target_vertex` in `B`'s embedding
  double source_size = 0;             ///< hyperbolic one-ring size of `source_vertex` in `A`'s embedding
  double target_size = 0;             ///< hyperbolic one-ring size of `target_vertex` in `B`'s embedding
  bool unresolved = false;            ///< `discrepancy` exceeds `noise_factor` times the larger size, and the map fails the scale or rounding test at `source_vertex`
  double scale_disagreement = 0;      ///< `Map_reliability::scale_disagreement` at `source_vertex` (not for a region at a landmark)
  std::size_t unreliable_vertices = 0; ///< the vertices flagged in this region
};

/*!
\ingroup PkgHyperbolicOrbifoldTutteMainClasses

the answer of `map_reliability()`.
*/
struct Map_reliability
{
  /// the vertices of `A` whose image cannot be trusted, as positions in `vertices(A)` order, increasing
  std::vector<std::size_t> unreliable_vertices;
  /// the squeezed regions of `A` (connected sets of squeezed vertices)
  std::vector<Squeezed_region> regions;
  /// per vertex of `A`, in `vertices(A)` order, its uncertainty (a length on `B`, see
  /// `map_reliability()`) if it was checked by the protrusion test: the vertices it flagged
  /// and those of their neighbours on the protrusion whose scale disagrees beyond the noise;
  /// zero for the others
  std::vector<double> uncertainty;
  /// per vertex of `A`, in `vertices(A)` order, the natural logarithm of the map's 3D scale
  /// at it over `reference_scale` (negative: the map shrinks its neighbourhood); 0 for a
  /// vertex not located or whose conformal factors are not resolved (see `map_reliability()`)
  std::vector<double> scale_disagreement;
  /// the reference 3D scale of the map: the square root of the ratio of the areas of `B` and
  /// `A` (what a map between isometric surfaces scales every length by)
  double reference_scale = 1;
  /// the scale noise of the map: 1.4826 times the median over the vertices of the absolute
  /// difference between a vertex's scale disagreement and the mean of its neighbours' (the
  /// standard deviation of Gaussian noise on it; the variation along the surface does not count)
  double scale_noise = 0;
  /// the vertices flagged by the scale test (a vertex can fail several tests)
  std::size_t scale_flagged = 0;
  /// the vertices flagged by the rounding test
  std::size_t rounding_flagged = 0;
  /// the vertices flagged by the protrusion test
  std::size_t protrusion_flagged = 0;
};


namespace internal {

// map_reliability()'s scale test: the map's 3D scale at each located vertex, rho_A /
// rho_B(image) (the image's log rho interpolated in its face), against the reference; and
// its rounding test
template <class TriangleMeshA, class TriangleMeshB, class Locator>
void reliability_scale_test(const TriangleMeshA& A, const Embedding_scale<TriangleMeshA>& a,
                            const Embedding_scale<TriangleMeshB>& b, const Locator& locB,
                            const std::vector<typename Locator::Location>& locations,
                            const Map_reliability_options& options, Map_reliability& result,
                            std::vector<char>& scale_fails, std::vector<char>& rounding_fails)
{
  typedef typename boost::graph_traits<TriangleMeshA>::vertex_descriptor vertex_descriptor_A;
  const std::size_t n = a.verts.size();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::vector<double> lambda(n, nan);
  for(std::size_t i = 0; i < n; ++i) {
    const typename Locator::Location& l = locations[i];
    if(!l.success)
      continue;
    bool image_unresolved = false, image_at_landmark = false;
    double log_rho_b = 0;
    for(int j = 0; j < 3; ++j) {
      const std::size_t v = locB.corner_vertex_index(l.face_index, j);
      image_unresolved = image_unresolved || b.unresolved[v];
      image_at_landmark = image_at_landmark || (b.squeezed(v) && b.cone[b.collapse[b.region[v]]]);
      log_rho_b += l.barycentric[j] * b.log_rho[v];
    }
    const bool at_landmark = a.squeezed(i) && a.cone[a.collapse[a.region[i]]];
    // below double in either embedding: its image is not resolved, unless both embeddings
    // collapse its neighbourhood onto a landmark's cone (where the charts resolve it)
    if(a.unresolved[i] || image_unresolved) {
      rounding_fails[i] = !(at_landmark || image_at_landmark);
      continue;
    }
    lambda[i] = a.log_rho[i] - log_rho_b;
  }
  // the reference: the ratio of the sizes of the two surfaces (sqrt of the ratio of their
  // areas), what a map between isometric surfaces scales every length by (a median over the
  // vertices would follow a protrusion that most vertices are on)
  const double reference = (a.total_area > 0 && b.total_area > 0) ? 0.5 * std::log(b.total_area / a.total_area) : 0.0;
  // the noise: the fluctuation of lambda between neighbours (robust standard deviation of
  // lambda minus the mean over its neighbours), not its variation along the surface
  {
    std::vector<double> fluctuation;
    for(std::size_t i = 0; i < n; ++i) {
      if(!std::isfinite(lambda[i]))
        continue;
      double sum = 0;
      std::size_t count = 0;
      for(vertex_descriptor_A w : vertices_around_target(halfedge(a.verts[i], A), A))
        if(std::isfinite(lambda[a.index(w)])) {
          sum += lambda[a.index(w)];
          ++count;
        }
      if(count > 0)
        fluctuation.push_back(std::abs(lambda[i] - sum / double(count)));
    }
    if(!fluctuation.empty()) {
      std::nth_element(fluctuation.begin(), fluctuation.begin() + fluctuation.size() / 2, fluctuation.end());
      result.scale_noise = 1.4826 * fluctuation[fluctuation.size() / 2];
    }
  }
  result.reference_scale = std::exp(reference);
  const double limit = std::log(options.scale_factor);
  for(std::size_t i = 0; i < n; ++i)
    if(std::isfinite(lambda[i])) {
      result.scale_disagreement[i] = lambda[i] - reference;
      scale_fails[i] = std::abs(result.scale_disagreement[i]) > limit;
    }
}

// the diagonal of the bounding box of `B`'s points
template <class TriangleMeshB, class VertexPointMapB>
double bounding_box_diagonal(const TriangleMeshB& B, VertexPointMapB vpmB)
{
  CGAL::Bbox_3 box;
  for(typename boost::graph_traits<TriangleMeshB>::vertex_descriptor v : vertices(B))
    box += get(vpmB, v).bbox();
  return std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin()) +
                   CGAL::square(box.zmax() - box.zmin()));
}

// the corner of `B` around `v` whose point is nearest to `image` (hyperbolic distance):
// its distance (infinity when there is none) and its point
template <class TriangleMeshB, class HalfedgeUVMapB, class Point_2, class Distance>
double nearest_corner_point(const TriangleMeshB& B, HalfedgeUVMapB uvB,
                            typename boost::graph_traits<TriangleMeshB>::vertex_descriptor v, const Point_2& image,
                            const Distance& distance, std::complex<double>& target)
{
  typedef std::complex<double> C;
  double discrepancy = std::numeric_limits<double>::infinity();
  for(typename boost::graph_traits<TriangleMeshB>::halfedge_descriptor h : halfedges_around_target(halfedge(v, B), B))
    if(!is_border(h, B)) {
      const auto p = get(uvB, h);
      const C q(CGAL::to_double(p.x()), CGAL::to_double(p.y()));
      const double d = CGAL::to_double(distance(image, Point_2(q.real(), q.imag())));
      if(d < discrepancy) {
        discrepancy = d;
        target = q;
      }
    }
  return discrepancy;
}

// the counts and the list of the unreliable vertices
inline void tally_unreliable_vertices(const std::vector<char>& flagged, const std::vector<char>& scale_fails,
                                      const std::vector<char>& rounding_fails, Map_reliability& result)
{
  for(std::size_t i = 0; i < flagged.size(); ++i) {
    result.protrusion_flagged += flagged[i];
    result.scale_flagged += scale_fails[i];
    result.rounding_flagged += rounding_fails[i];
    if(flagged[i] || scale_fails[i] || rounding_fails[i])
      result.unreliable_vertices.push_back(i);
  }
}

// map_reliability(): the corner of B's face holding `loc` nearest to it (largest barycentric
// coordinate), as a vertex index of B
template <class Locator>
std::size_t landing_vertex(const Locator& locB, const typename Locator::Location& loc)
{
  int j = 0;
  for(int k = 1; k < 3; ++k)
    if(loc.barycentric[k] > loc.barycentric[j])
      j = k;
  return locB.corner_vertex_index(loc.face_index, j);
}

// map_reliability(): how far on B the image of a vertex of A (its location `loc`) moves under
// the isometry `to_target` after `to_origin`: 0 when it was not located, infinity when the
// moved image is not on the embedding
template <class Locator, class VertexPointMapB>
double moved_image_distance(const Locator& locB, const VertexPointMapB& vpmB, const typename Locator::Location& loc,
                            const Hyperbolic_isometry_2<double>& to_origin, const Hyperbolic_isometry_2<double>& to_target)
{
  typedef typename Locator::Point_2 Point_2;
  typedef std::complex<double> C;
  if(!loc.success)
    return 0.0;
  const Point_2 z = locB.disk_point(loc);
  const C w = to_target.apply(to_origin.apply(C(CGAL::to_double(z.x()), CGAL::to_double(z.y()))));
  const typename Locator::Location moved = locB.locate(Point_2(w.real(), w.imag()));
  if(!moved.success)
    return std::numeric_limits<double>::infinity();
  return std::sqrt(CGAL::to_double(CGAL::squared_distance(surface_point(loc, locB, vpmB), surface_point(moved, locB, vpmB))));
}

} // namespace internal

/*!
\ingroup PkgHyperbolicOrbifoldTutteHelperFunctions

finds the vertices of `A` whose image under the vertex map `locations` (computed by
`map_vertices(A, uvA, locB)`) cannot be trusted, from the two embeddings alone: where the map
is not what a map between (nearly) isometric surfaces would be, or where the embeddings do not
resolve it. Every quantity is measured on the two embeddings and the two meshes; none is
relative to a mesh average, so varied resolution, tiny triangles and noise (scans) do not move
the thresholds. A vertex is unreliable when it fails one of three tests:

1. **Scale.** The conformal factor of a vertex in an embedding is the hyperbolic length of its
   edges per unit of their 3D length (root mean square over the edges of its faces); its
   logarithm is smoothed over the one-rings (`options.smoothing_rounds` rounds of area-weighted
   means: slivers and noisy vertices have noisy factors). The map's 3D scale at a vertex is
   its factor in `A`'s embedding over `B`'s factor at its image (interpolated in the face of
   `B` it lies in, in logarithm): how much the map stretches lengths there. A map between
   isometric surfaces is an isometry exactly where it scales every length by the ratio of their
   sizes, the reference scale \f$\sqrt{\mathrm{area}(B)/\mathrm{area}(A)}\f$. The vertex fails when
   the map's scale differs from the reference by more than `options.scale_factor` either way:
   the map squeezes a neighbourhood of `A` into a part of `B` that many times smaller (the
   collapse of a protrusion without a landmark: most of the tube of `A` lands on a ring of `B`),
   or stretches it. `Map_reliability::scale_disagreement` holds the logarithm of the ratio.
2. **Rounding.** The vertex's one-ring in `A`'s embedding, or a corner's one-ring of the face
   of `B` its image lies in, is smaller than `options.rounding_ulps` units in the last place of
   `double` at its position (as a hyperbolic length): the embedding cannot resolve where it
   is. Not counted where both embeddings collapse the neighbourhood onto a landmark's cone (a
   squeezed region, as in 3., holding a landmark): the cone is the same exact point in both,
   and the charts around cone images resolve the map there.
3. **Protrusion.** A vertex is squeezed when its conformal factor is below
   `options.squeeze_ratio` times the mesh's average; the squeezed regions are the connected
   sets of squeezed vertices. A region collapses onto a landmark's cone if it holds a landmark
   (a vertex with a corner at a corner of the tile); such regions are not checked. For
   another, its collapse vertex is its vertex of least conformal factor; the image in `B`'s
   embedding of that vertex lies in a squeezed region of `B` (or the walk down `B`'s conformal
   factor from it reaches one, or a local minimum), whose collapse vertex is found likewise.
   The discrepancy \f$\delta\f$ is the hyperbolic distance between the two points. The region
   is unresolved when \f$\delta\f$ exceeds `options.noise_factor` times the larger hyperbolic
   one-ring size of the two collapse vertices *and* the map fails the scale or the rounding
   test at the collapse vertex (it does collapse there: a squeezed region that a sliver or a
   noisy vertex makes, and that the map carries at the right scale, is not one). In an
   unresolved region, the uncertainty of a vertex is how far (in 3D, on `B`) its image moves
   when the isometry of the disk that takes the image of `A`'s collapse point onto `B`'s (a
   translation by \f$\delta\f$) is applied to it before it is located: for a vertex far from
   the collapse point that is \f$\delta\f$ over its conformal factor; the vertices closer to it
   than \f$\delta\f$ are sent near `B`'s collapse point instead of a ring near the base. The
   vertices whose uncertainty exceeds `options.error_fraction` times `B`'s bounding-box diagonal
   are flagged, found from the collapse vertex outwards along the edges, through the vertices
   whose scale disagreement exceeds `options.noise_multiple` times the map's scale noise
   (`Map_reliability::scale_noise`, the fluctuation of the scale disagreement between
   neighbours) and that lie on the protrusion in both embeddings: the vertex is in the basin
   of `A`'s collapse vertex (the walk from it to its neighbour of least conformal factor,
   repeated, reaches the region of that collapse vertex) and its image is in the basin of
   `B`'s collapse vertex (the same walk on `B` from the corner nearest to the image reaches
   `B`'s). The translation is a model of the map on the collapsed protrusion only: the part of
   each surface that its embedding squeezes towards the collapse point (its conformal factor
   decreases all the way there). The search does not go on where the map's scale is as
   expected, nor past the rim of either basin, where the conformal factor rises again towards
   another squeezed region or a local minimum: there the surface is not collapsed onto this
   point, and moving its image by the translation says nothing about its error. The basins
   need no threshold (a vertex of a smooth protrusion's tube descends to its tip); on a noisy
   mesh they are cut by the local minima of the noisy conformal factor, which keeps the search
   near the collapse point, where the model holds.
   Measured (`bench_reliability`, TOSCA wolf 2 -> 1 with a region of slivers and noise of
   0.05% of the diagonal): the search restricted to `A`'s basin flags 5.7% of the vertices,
   restricted to both basins 4.99% (before: 9.75%), all of the worst 1% flagged either way;
   every flagged vertex there is more than 1% of the diagonal off.

What it guarantees, measured against ground truth (vertex `i` of `A` corresponds to vertex `i`
of `B`; `benchmark/bench_reliability.cpp`, tests `test_maps.unreliable_vertices_of_*` and
`test_maps.reliability_of_good_maps_between_scan_like_copies`): on capsules mapped onto bent
copies without a landmark at the tip, every vertex off by more than 5% of the diagonal is
flagged, no vertex of the landmark cap is, and the unflagged vertices are within 2% of the
diagonal; on good maps (mean error under 1% of the diagonal) of TOSCA's wolves (7 landmarks)
and of noisy, twisted or sliver-refined copies of hand and bull, at most 5% of the vertices are
flagged and the flagged vertices hold more than half (mostly all) of the worst 1% (the closest
case: a wolf with a region of slivers and noise, 4.99% flagged; its map has 9.7% of the vertices
more than 2% of the diagonal off, and the flag keeps the worst of them). Limits: errors that
keep the map's scale (a rotation about a landmark, a slide along a tube of constant width, a
left-right swap) are not seen; between surfaces that are not nearly isometric the scale test
flags where their shapes differ by more than `options.scale_factor` (that is what a
correspondence there cannot be sure of); protrusions joined through a squeezed part form one
region, and only its deepest point is checked by the protrusion test; where the collapse vertex
of `B` lies on the cut, the discrepancy is measured to the nearest of its corners.

\tparam TriangleMeshA a model of `FaceGraph` and `VertexListGraph`
\tparam HalfedgeUVMapA a model of `ReadablePropertyMap` from the halfedges of `A` to a point type with `x()` and `y()`
\tparam TriangleMeshB a model of `FaceGraph` and `VertexListGraph`
\tparam HalfedgeUVMapB the same for `B`
\tparam Locator the `Embedding_locator` of `B` built from `uvB`
\tparam NamedParametersA a sequence of named parameters for `A`
\tparam NamedParametersB a sequence of named parameters for `B`

\param A the source mesh
\param uvA its embedding (per-corner map written by `hyperbolic_orbifold_Tutte_embedding()`)
\param B the target mesh
\param uvB its embedding, into the same orbifold with corresponding landmarks
\param locB the locator of `uvB`
\param locations the vertex map, `map_vertices(A, uvA, locB)`
\param options the thresholds
\param npA named parameters for `A`: `vertex_point_map` (default `get(CGAL::vertex_point, A)`)
\param npB named parameters for `B`: `vertex_point_map` (default `get(CGAL::vertex_point, B)`)

\pre `locations` has one location per vertex of `A` and `locB` is a valid locator of `uvB`
     (otherwise the result is empty)

\return the unreliable vertices, the squeezed regions and the uncertainties. Linear in the
        sizes of `A` and `B`, plus a point location per vertex checked; vertices that were not
        located are not flagged (their location says so).
*/
template <class TriangleMeshA, class HalfedgeUVMapA, class TriangleMeshB, class HalfedgeUVMapB, class Locator,
          class NamedParametersA = CGAL::parameters::Default_named_parameters,
          class NamedParametersB = CGAL::parameters::Default_named_parameters>
Map_reliability map_reliability(const TriangleMeshA& A, HalfedgeUVMapA uvA, const TriangleMeshB& B, HalfedgeUVMapB uvB,
                                const Locator& locB, const std::vector<typename Locator::Location>& locations,
                                const Map_reliability_options& options = Map_reliability_options(),
                                const NamedParametersA& npA = CGAL::parameters::default_values(),
                                const NamedParametersB& npB = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef typename boost::graph_traits<TriangleMeshA>::vertex_descriptor vertex_descriptor_A;
  typedef typename Locator::Point_2 Point_2;
  typedef Hyperbolic_isometry_2<double> Isometry;
  typedef std::complex<double> C;

  Map_reliability result;
  const auto vpmA = choose_parameter(get_parameter(npA, CGAL::internal_np::vertex_point), get_const_property_map(vertex_point, A));
  const auto vpmB = choose_parameter(get_parameter(npB, CGAL::internal_np::vertex_point), get_const_property_map(vertex_point, B));
  const internal::Embedding_scale<TriangleMeshA> a(A, uvA, vpmA, locB, options.squeeze_ratio, options.smoothing_rounds, options.rounding_ulps);
  const internal::Embedding_scale<TriangleMeshB> b(B, uvB, vpmB, locB, options.squeeze_ratio, options.smoothing_rounds, options.rounding_ulps);
  const std::size_t n = a.verts.size();
  result.uncertainty.assign(n, 0.0);
  result.scale_disagreement.assign(n, 0.0);
  if(locations.size() != n || !locB.is_valid())
    return result;

  // 1. the scale test and the rounding test
  std::vector<char> scale_fails(n, 0), rounding_fails(n, 0);
  internal::reliability_scale_test(A, a, b, locB, locations, options, result, scale_fails, rounding_fails);

  // 2. the protrusion test
  const double diagonal = internal::bounding_box_diagonal(B, vpmB);
  const double max_uncertainty = options.error_fraction * diagonal;
  const double min_disagreement = options.noise_multiple * result.scale_noise;
  const auto distance = typename Locator::Traits().compute_hyperbolic_distance_2_object();

  std::vector<char> flagged(n, 0), visited(n, 0);
  // per vertex of A (of B), where the walk down A's (B's) conformal factor from it ends: the
  // collapse vertex of the squeezed region it reaches, or a local minimum (computed on demand)
  std::vector<std::size_t> basin_a(n, internal::Embedding_scale<TriangleMeshA>::npos),
                           basin_b(b.verts.size(), internal::Embedding_scale<TriangleMeshB>::npos);
  // the corner of B's face holding a location nearest to it (largest barycentric coordinate)
  auto landing = [&](const typename Locator::Location& loc) { return internal::landing_vertex(locB, loc); };
  std::vector<std::size_t> stack, seen;
  for(std::size_t r = 0; r < a.collapse.size(); ++r) {
    Squeezed_region region;
    region.number_of_vertices = a.region_size[r];
    region.source_vertex = a.collapse[r];
    region.source_size = a.size[region.source_vertex];
    region.at_landmark = a.cone[region.source_vertex] != 0;
    const typename Locator::Location& l = locations[region.source_vertex];
    if(region.at_landmark || !l.success) {
      result.regions.push_back(region);
      continue;
    }
    region.scale_disagreement = result.scale_disagreement[region.source_vertex];
    // the region of B the collapse vertex's image lies in, and where that region collapses
    region.target_vertex = b.basin(B, landing(l), basin_b);
    region.target_size = b.size[region.target_vertex];
    const Point_2 image = locB.disk_point(l);
    C target;
    region.discrepancy = internal::nearest_corner_point(B, uvB, b.verts[region.target_vertex], image, distance, target);
    // unresolved: the collapse points differ by more than a few triangles, and the map does
    // collapse (or cannot resolve) the region there
    region.unresolved = region.discrepancy > options.noise_factor * (std::max)(region.source_size, region.target_size) &&
                        (scale_fails[region.source_vertex] || rounding_fails[region.source_vertex]);
    if(region.unresolved) {
      // the isometry that moves the image of A's collapse point onto B's, applied to the
      // image of each vertex: how far on B its image moves (from the collapse vertex
      // outwards, through the vertices that move too far, whose scale disagrees beyond the
      // map's noise, and that lie on the protrusion in both embeddings: A's conformal factor
      // descends from the vertex to A's collapse vertex, B's from its image to B's; the
      // isometry is a model of the map on the collapsed protrusion only)
      const C from(CGAL::to_double(image.x()), CGAL::to_double(image.y()));
      const Isometry to_origin = Isometry::translation_to_origin(from), to_target = Isometry::translation_from_origin(target);
      auto uncertainty = [&](std::size_t i) {
        return internal::moved_image_distance(locB, vpmB, locations[i], to_origin, to_target);
      };
      stack.clear();
      seen.clear();
      auto visit = [&](std::size_t i) {
        visited[i] = 1;
        seen.push_back(i);
        if(!(rounding_fails[i] || scale_fails[i] || std::abs(result.scale_disagreement[i]) > min_disagreement))
          return;
        if(i != region.source_vertex && (a.basin(A, i, basin_a) != region.source_vertex || !locations[i].success ||
                                         b.basin(B, landing(locations[i]), basin_b) != region.target_vertex))
          return;
        result.uncertainty[i] = (std::max)(result.uncertainty[i], uncertainty(i));
        if(result.uncertainty[i] > max_uncertainty) {
          if(!flagged[i])
            ++region.unreliable_vertices;
          flagged[i] = 1;
          stack.push_back(i);
        }
      };
      visit(region.source_vertex);
      while(!stack.empty()) {
        const std::size_t i = stack.back();
        stack.pop_back();
        for(vertex_descriptor_A w : vertices_around_target(halfedge(a.verts[i], A), A))
          if(!visited[a.index(w)])
            visit(a.index(w));
      }
      for(std::size_t i : seen)
        visited[i] = 0;
    }
    result.regions.push_back(region);
  }
  internal::tally_unreliable_vertices(flagged, scale_fails, rounding_fails, result);
  return result;
}

} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_MAP_RELIABILITY_H
