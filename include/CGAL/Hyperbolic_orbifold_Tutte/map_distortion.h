// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_MAP_DISTORTION_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_MAP_DISTORTION_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Hyperbolic_orbifold_Tutte/surface_maps.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/core/dense_index.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/number_utils.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <limits>
#include <vector>

/// \file map_distortion.h
/// The per-face distortion of a map between surfaces: the singular values of the
/// differential of the piecewise-linear map on every face of the source, its conformal and
/// area distortion, and their percentiles.

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {

/*!
\ingroup PkgHyperbolicOrbifoldTutteMainClasses

the statistics of one per-face figure of `Map_distortion` over the faces it measures (each
face counts once, whatever its area). A percentile is the nearest-rank one: the \f$p\f$-th
percentile of \f$n\f$ values is the \f$\lceil p n / 100\rceil\f$-th smallest, a value of
some face. With no face measured every figure is 0.
*/
struct Distortion_summary
{
  std::size_t number_of_faces = 0; ///< the faces measured
  double p50 = 0;                  ///< the median
  double p90 = 0;                  ///< the 90th percentile
  double p99 = 0;                  ///< the 99th percentile
  double max = 0;                  ///< the largest value
  double mean = 0;                 ///< the mean (\f$+\infty\f$ when a value is)
};

/*!
\ingroup PkgHyperbolicOrbifoldTutteMainClasses

the answer of `map_distortion()`: per face of the source mesh `A`, in `faces(A)` order, the
singular values \f$\sigma_1 \geq \sigma_2 \geq 0\f$ of the differential of the
piecewise-linear map that sends the face's corners to their images, the conformal
distortion \f$\sigma_1/\sigma_2\f$ and the normalised area distortion
\f$\sigma_1\sigma_2 / (\mathrm{area}(f(A))/\mathrm{area}(A))\f$, with their summaries
(\ref HOT_Distortion).

Degenerate faces give no NaN:
- a face whose image is degenerate (\f$\sigma_2 = 0\f$: its three images collinear, two of
  them equal, to the precision of `double`) has conformal distortion \f$+\infty\f$ and area
  distortion 0; it is counted in `degenerate_image_faces` and measured by the summaries
  (their `max`, and `mean`, are then \f$+\infty\f$);
- a face of `A` of zero area (collinear corners) has no differential: it gets
  \f$\sigma_1 = +\infty\f$, \f$\sigma_2 = 0\f$ and both distortions \f$+\infty\f$, is counted
  in `degenerate_source_faces`, and is not measured by the summaries nor in the areas;
- a face with a corner that has no image (a location that failed, a non-finite point) gets
  the same values, is counted in `unmapped_faces` and is not measured either.
*/
struct Map_distortion
{
  /// \name Per face of `A`, in `faces(A)` order
  /// @{
  std::vector<double> sigma1;    ///< the larger singular value \f$\sigma_1\f$ (the largest stretch)
  std::vector<double> sigma2;    ///< the smaller singular value \f$\sigma_2\f$ (the smallest stretch)
  std::vector<double> conformal; ///< \f$\sigma_1/\sigma_2 \geq 1\f$ (\f$+\infty\f$ when \f$\sigma_2 = 0\f$)
  std::vector<double> area;      ///< \f$\sigma_1\sigma_2\f$ divided by `image_area / source_area` (1 for a map that scales every area alike)
  /// the symmetric Dirichlet density \f$s_1^2 + s_2^2 + s_1^{-2} + s_2^{-2}\f$ of the singular values
  /// scaled to the total areas, \f$s_i = \sigma_i / \sqrt{\mathrm{image\_area} / \mathrm{source\_area}}\f$:
  /// 4 for an isometry up to that one scale, larger otherwise (\f$2(\kappa + 1/\kappa)\f$ for a
  /// linear map of conformal distortion \f$\kappa\f$ that keeps the areas; \f$+\infty\f$ when \f$\sigma_2 = 0\f$)
  std::vector<double> symmetric_dirichlet;
  /// @}

  /// \name Summaries (over the faces measured: all but the degenerate source faces and the unmapped ones)
  /// @{
  Distortion_summary conformal_summary; ///< of `conformal`
  Distortion_summary area_summary;      ///< of `area`
  Distortion_summary symmetric_dirichlet_summary; ///< of `symmetric_dirichlet`
  /// the symmetric Dirichlet energy: the mean of `symmetric_dirichlet` weighted by the faces'
  /// areas in `A` (4 for an isometry up to scale; \f$+\infty\f$ when a measured image face is degenerate)
  double symmetric_dirichlet_energy = 0;
  /// @}

  /// \name Counts and areas
  /// @{
  std::size_t degenerate_image_faces = 0;  ///< faces with \f$\sigma_2 = 0\f$ (measured)
  std::size_t degenerate_source_faces = 0; ///< faces of `A` of zero area (not measured)
  std::size_t unmapped_faces = 0;          ///< faces with a corner without image (not measured)
  double source_area = 0;                  ///< the area of the measured faces of `A`
  double image_area = 0;                   ///< the area of their images (the triangles of the images of their corners)
  /// @}

  /// the degenerate faces: `degenerate_image_faces + degenerate_source_faces`
  std::size_t number_of_degenerate_faces() const { return degenerate_image_faces + degenerate_source_faces; }
};

namespace internal {

// the singular values of the linear map of the plane of the triangle (p0, p1, p2) onto the
// plane of (q0, q1, q2) sending p_i to q_i, each plane in an orthonormal frame: sigma1,
// sigma2 and their product (the ratio of the areas); false when (p0, p1, p2) has zero area
inline bool triangle_singular_values(const std::array<double, 3>* p, const std::array<double, 3>* q, double& sigma1,
                                     double& sigma2, double& det, double& source_area2, double& image_area2)
{
  auto sub = [](const std::array<double, 3>& a, const std::array<double, 3>& b) {
    return std::array<double, 3>{{a[0] - b[0], a[1] - b[1], a[2] - b[2]}};
  };
  auto dot = [](const std::array<double, 3>& a, const std::array<double, 3>& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; };
  auto cross_norm = [](const std::array<double, 3>& a, const std::array<double, 3>& b) {
    return std::hypot(std::hypot(a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2]), a[0] * b[1] - a[1] * b[0]);
  };
  const std::array<double, 3> e1 = sub(p[1], p[0]), e2 = sub(p[2], p[0]);
  const std::array<double, 3> f1 = sub(q[1], q[0]), f2 = sub(q[2], q[0]);
  const double le1 = std::sqrt(dot(e1, e1)), lf1 = std::sqrt(dot(f1, f1));
  source_area2 = cross_norm(e1, e2);
  image_area2 = cross_norm(f1, f2);
  if(!(source_area2 > 0) || !(le1 > 0) || !std::isfinite(source_area2))
    return false;
  // source frame: u = e1 / |e1|, v in the plane, orthogonal to u, on e2's side:
  // e1 = (|e1|, 0), e2 = (a, b) with b > 0; image frame likewise: f1 = (|f1|, 0), f2 = (c, d),
  // d >= 0. The map J with J e1 = f1, J e2 = f2 is then upper triangular.
  const double a = dot(e1, e2) / le1, b = source_area2 / le1;
  const double c = lf1 > 0 ? dot(f1, f2) / lf1 : 0.0;
  const double d = lf1 > 0 ? image_area2 / lf1 : std::sqrt(dot(f2, f2)); // (f1 = 0: J e2 = f2 along the frame's first axis)
  const double j11 = lf1 / le1, j22 = lf1 > 0 ? d / b : 0.0;
  const double j12 = lf1 > 0 ? (c - j11 * a) / b : d / b;
  // 2x2 singular values, stably: with M = [[j11, j12], [0, j22]],
  // sigma1 = |(j11 + j22, -j12)|/2 + |(j11 - j22, j12)|/2, sigma2 = det / sigma1
  sigma1 = 0.5 * (std::hypot(j11 + j22, j12) + std::hypot(j11 - j22, j12));
  det = j11 * j22;
  sigma2 = sigma1 > 0 && std::isfinite(sigma1) ? det / sigma1 : 0.0;
  if(!(sigma2 >= 0)) // (NaN from overflow)
    sigma2 = 0;
  sigma2 = (std::min)(sigma2, sigma1); // (rounding)
  if(!std::isfinite(det))
    det = std::numeric_limits<double>::infinity();
  return true;
}

// the statistics of `values` (reordered)
inline Distortion_summary summarize_distortion(std::vector<double>& values)
{
  Distortion_summary s;
  const std::size_t n = values.size();
  s.number_of_faces = n;
  if(n == 0)
    return s;
  double sum = 0;
  for(double v : values)
    sum += v;
  s.mean = sum / static_cast<double>(n);
  // nearest rank: the ceil(p n / 100)-th smallest
  auto rank = [n](std::size_t p) { return (std::max)((p * n + 99) / 100, std::size_t(1)) - 1; };
  const std::size_t k50 = rank(50), k90 = rank(90), k99 = rank(99);
  std::nth_element(values.begin(), values.begin() + k50, values.end());
  s.p50 = values[k50];
  std::nth_element(values.begin() + k50, values.begin() + k90, values.end());
  s.p90 = values[k90];
  std::nth_element(values.begin() + k90, values.begin() + k99, values.end());
  s.p99 = values[k99];
  s.max = *std::max_element(values.begin() + k99, values.end());
  return s;
}

// map_distortion() from the images of the vertices (vertices(A) order), `mapped[i]` false for
// a vertex without image
template <class TriangleMesh, class VertexPointMap>
Map_distortion map_distortion(const TriangleMesh& A, VertexPointMap vpm, const std::vector<std::array<double, 3> >& images,
                              const std::vector<char>& mapped)
{
  typedef typename boost::graph_traits<TriangleMesh>::face_descriptor face_descriptor;
  typedef typename boost::graph_traits<TriangleMesh>::halfedge_descriptor halfedge_descriptor;
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  const Dense_index<vertex_descriptor> index(vertices(A));
  const double inf = std::numeric_limits<double>::infinity();
  Map_distortion r;
  const std::size_t nf = static_cast<std::size_t>(std::distance(faces(A).begin(), faces(A).end()));
  r.sigma1.assign(nf, inf);
  r.sigma2.assign(nf, 0.0);
  r.conformal.assign(nf, inf);
  r.area.assign(nf, inf);
  r.symmetric_dirichlet.assign(nf, inf);
  std::vector<char> measured(nf, 0);
  std::vector<double> face_area(nf, 0.0);
  std::size_t i = 0;
  for(face_descriptor f : faces(A)) {
    const std::size_t fi = i++;
    std::array<std::array<double, 3>, 3> p, q;
    bool ok = true;
    int j = 0;
    for(halfedge_descriptor h : halfedges_around_face(halfedge(f, A), A)) {
      if(j == 3) {
        ok = false; // (not a triangle)
        break;
      }
      const vertex_descriptor v = target(h, A);
      const std::size_t vi = index(v);
      const auto& pt = get(vpm, v);
      p[j] = {{CGAL::to_double(pt.x()), CGAL::to_double(pt.y()), CGAL::to_double(pt.z())}};
      if(vi >= images.size() || !mapped[vi])
        ok = false;
      else
        q[j] = images[vi];
      ++j;
    }
    if(!ok || j != 3) {
      ++r.unmapped_faces;
      continue;
    }
    double s1, s2, det, sa2, ia2;
    if(!triangle_singular_values(p.data(), q.data(), s1, s2, det, sa2, ia2)) {
      ++r.degenerate_source_faces;
      continue;
    }
    measured[fi] = 1;
    r.sigma1[fi] = s1;
    r.sigma2[fi] = s2;
    r.conformal[fi] = s2 > 0 ? (std::max)(s1 / s2, 1.0) : inf;
    r.area[fi] = det; // normalised below
    if(!(s2 > 0))
      ++r.degenerate_image_faces;
    r.source_area += 0.5 * sa2;
    r.image_area += 0.5 * ia2;
    face_area[fi] = 0.5 * sa2;
  }
  // normalisation: a map that scales every area alike has area distortion 1 (ratio 1 when
  // either area is 0 or not finite)
  const double ratio = r.source_area > 0 && r.image_area > 0 && std::isfinite(r.image_area) && std::isfinite(r.source_area)
                         ? r.image_area / r.source_area : 1.0;
  std::vector<double> conformal, area, symmetric;
  conformal.reserve(nf);
  area.reserve(nf);
  symmetric.reserve(nf);
  double weighted = 0;
  for(std::size_t k = 0; k < nf; ++k)
    if(measured[k]) {
      r.area[k] = r.area[k] / ratio;
      if(r.sigma2[k] > 0) { // (s1^2 + s2^2 + 1/s1^2 + 1/s2^2, s_i = sigma_i / sqrt(ratio))
        const double a = r.sigma1[k] * r.sigma1[k] / ratio, b = r.sigma2[k] * r.sigma2[k] / ratio;
        r.symmetric_dirichlet[k] = a + b + 1 / a + 1 / b;
      }
      weighted += face_area[k] * r.symmetric_dirichlet[k];
      conformal.push_back(r.conformal[k]);
      area.push_back(r.area[k]);
      symmetric.push_back(r.symmetric_dirichlet[k]);
    }
  r.symmetric_dirichlet_energy = r.source_area > 0 ? weighted / r.source_area : 0;
  r.conformal_summary = summarize_distortion(conformal);
  r.area_summary = summarize_distortion(area);
  r.symmetric_dirichlet_summary = summarize_distortion(symmetric);
  return r;
}

} // namespace internal

/*!
\ingroup PkgHyperbolicOrbifoldTutteHelperFunctions

computes the per-face distortion of a map of the mesh `A` given by the image of each of its
vertices (\ref HOT_Distortion): on every face, the singular values \f$\sigma_1 \geq \sigma_2\f$
of the linear map from the face's plane to the plane of the image triangle (each in an
orthonormal frame) that sends the face's corners to their images, the conformal distortion
\f$\sigma_1/\sigma_2\f$, the area distortion \f$\sigma_1\sigma_2\f$ normalised by the
ratio of the total areas, the symmetric Dirichlet density of the singular values scaled to
that ratio, their percentiles, and the symmetric Dirichlet energy (the density's mean
weighted by area). This variant takes the images as points
(e.g. from another program, or `surface_point()` of each location);
`map_distortion(A, B, locB, locations)` computes them from a vertex map.

Computed in `double`, in time linear in the size of `A` (plus the selection of the
percentiles). The singular values come from a closed form that is exact for the identity
(\f$\sigma_1 = \sigma_2 = 1\f$ to the last bit when the images are the vertices themselves)
and stable for nearly conformal maps (no square root of a difference). The frames are each
triangle's own: the figures do not depend on the orientation of the image triangle (a face
folded over onto the other side has the same figures as its mirror image).

\tparam TriangleMesh a model of `FaceListGraph` and `VertexListGraph`, triangles only (a
        face with more corners is counted as unmapped)
\tparam PointRange a random-access range of points with `x()`, `y()` and `z()` (e.g. a
        `std::vector<Kernel::Point_3>`)
\tparam NamedParameters a sequence of named parameters

\param A the source mesh
\param images the image of each vertex of `A`, in `vertices(A)` order; a point with a
       non-finite coordinate (e.g. NaN) means "no image" (its faces are unmapped)
\param np optional named parameter: `vertex_point_map` of `A` (default `get(CGAL::vertex_point, A)`)

\pre `images.size() == num_vertices(A)` (the faces of vertices beyond are unmapped)

\return the per-face figures, their summaries, the counts of degenerate and unmapped faces
        (`Map_distortion` says how degenerate faces are reported)

\sa `map_vertices()`, `surface_point()`, `map_reliability()`
*/
template <class TriangleMesh, class PointRange, class NamedParameters = CGAL::parameters::Default_named_parameters>
Map_distortion map_distortion(const TriangleMesh& A, const PointRange& images,
                              const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point), get_const_property_map(vertex_point, A));
  CGAL_precondition(static_cast<std::size_t>(std::distance(std::begin(images), std::end(images))) == num_vertices(A));
  std::vector<std::array<double, 3> > points;
  std::vector<char> mapped;
  for(const auto& p : images) {
    const std::array<double, 3> q{{CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())}};
    points.push_back(q);
    mapped.push_back(std::isfinite(q[0]) && std::isfinite(q[1]) && std::isfinite(q[2]));
  }
  return internal::map_distortion(A, vpm, points, mapped);
}

/*!
\ingroup PkgHyperbolicOrbifoldTutteHelperFunctions

computes the per-face distortion of the vertex map `locations` of `A` onto `B` (computed by
`map_vertices(A, uvA, locB)`): `map_distortion(A, images)` with the image of each vertex
the point of `B`'s surface at its location (`surface_point()`). A vertex whose location failed
has no image: its faces are unmapped.

\tparam TriangleMeshA a model of `FaceListGraph` and `VertexListGraph`, triangles only
\tparam TriangleMeshB a model of `FaceListGraph` and `VertexListGraph`
\tparam Locator the `Embedding_locator` of `B` that computed `locations`
\tparam NamedParametersA a sequence of named parameters for `A`
\tparam NamedParametersB a sequence of named parameters for `B`

\param A the source mesh
\param B the target mesh
\param locB the locator of `B`'s embedding
\param locations the vertex map, one location per vertex of `A` in `vertices(A)` order
\param npA named parameters for `A`: `vertex_point_map` (default `get(CGAL::vertex_point, A)`)
\param npB named parameters for `B`: `vertex_point_map` (default `get(CGAL::vertex_point, B)`)

\pre `locations.size() == num_vertices(A)` (the faces of vertices beyond are unmapped)

\sa `map_vertices()`, `map_reliability()`
*/
template <class TriangleMeshA, class TriangleMeshB, class Locator,
          class NamedParametersA = CGAL::parameters::Default_named_parameters,
          class NamedParametersB = CGAL::parameters::Default_named_parameters>
Map_distortion map_distortion(const TriangleMeshA& A, const TriangleMeshB& B, const Locator& locB,
                              const std::vector<typename Locator::Location>& locations,
                              const NamedParametersA& npA = CGAL::parameters::default_values(),
                              const NamedParametersB& npB = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const auto vpmA = choose_parameter(get_parameter(npA, CGAL::internal_np::vertex_point), get_const_property_map(vertex_point, A));
  const auto vpmB = choose_parameter(get_parameter(npB, CGAL::internal_np::vertex_point), get_const_property_map(vertex_point, B));
  CGAL_precondition(locations.size() == num_vertices(A));
  std::vector<std::array<double, 3> > points(locations.size(), std::array<double, 3>{{0.0, 0.0, 0.0}});
  std::vector<char> mapped(locations.size(), 0);
  for(std::size_t i = 0; i < locations.size(); ++i) {
    const typename Locator::Location& l = locations[i];
    if(!l.success || l.face_index >= locB.number_of_faces())
      continue;
    const auto p = surface_point(l, locB, vpmB);
    points[i] = {{CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())}};
    mapped[i] = std::isfinite(points[i][0]) && std::isfinite(points[i][1]) && std::isfinite(points[i][2]);
  }
  return internal::map_distortion(A, vpmA, points, mapped);
}

} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_MAP_DISTORTION_H
