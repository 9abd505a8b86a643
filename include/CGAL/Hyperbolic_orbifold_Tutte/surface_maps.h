// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_SURFACE_MAPS_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_SURFACE_MAPS_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Hyperbolic_orbifold_Tutte/Embedding_locator.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/interpolation_model.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/barycenter.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <Eigen/Sparse>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#endif

#include <cstddef>
#include <type_traits>
#include <vector>

/// \file surface_maps.h
/// Maps between surfaces embedded into one orbifold (paper, section 7): the vertex map of a
/// mesh `A` onto a mesh `B` through `B`'s `Embedding_locator`, and what it transfers.

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {

namespace internal {

// map_vertices(): `chart_of(h)` the chart of corner h of A (-1: the tile's coordinates) and
// `chart_point(h)` its point there
template <class TriangleMeshA, class HalfedgeUVMapA, class Locator, class ChartOf,
          class ChartPoint = std::nullptr_t>
std::vector<typename Locator::Location> map_vertices(const TriangleMeshA& A, HalfedgeUVMapA uvA, const Locator& locB,
                                                     const ChartOf& chart_of,
                                                     const std::vector<Hyperbolic_isometry_2<double> >& charts,
                                                     const ChartPoint& chart_point = nullptr)
{
  typedef typename boost::graph_traits<TriangleMeshA>::vertex_descriptor vertex_descriptor;
  typedef typename boost::graph_traits<TriangleMeshA>::halfedge_descriptor halfedge_descriptor;
  typedef typename Locator::Point_2 Point_2;
  // the point of one corner of each vertex (none for an isolated vertex: not located), and its chart
  std::vector<Point_2> points;
  std::vector<int> chart; // -2: no point
  points.reserve(num_vertices(A));
  chart.reserve(num_vertices(A));
  for(vertex_descriptor v : vertices(A)) {
    halfedge_descriptor corner = boost::graph_traits<TriangleMeshA>::null_halfedge();
    const halfedge_descriptor h0 = halfedge(v, A);
    if(h0 != boost::graph_traits<TriangleMeshA>::null_halfedge())
      for(halfedge_descriptor h : halfedges_around_target(h0, A))
        if(!is_border(h, A)) {
          corner = h;
          break;
        }
    if(corner == boost::graph_traits<TriangleMeshA>::null_halfedge()) {
      points.push_back(Point_2(0, 0));
      chart.push_back(-2);
      continue;
    }
    const int c = chart_of(corner);
    if constexpr(!std::is_same<ChartPoint, std::nullptr_t>::value)
      if(c >= 0) {
        const auto p = chart_point(corner);
        points.push_back(Point_2(CGAL::to_double(p.x()), CGAL::to_double(p.y())));
        chart.push_back(c);
        continue;
      }
    const auto p = get(uvA, corner);
    points.push_back(Point_2(CGAL::to_double(p.x()), CGAL::to_double(p.y())));
    chart.push_back(-1);
  }
  std::vector<typename Locator::Location> result(points.size());
  auto run = [&](std::size_t i) {
    if(chart[i] == -1)
      result[i] = locB.locate(points[i]);
    else if(chart[i] >= 0)
      result[i] = locB.locate(points[i], charts[chart[i]]);
  };
#ifdef CGAL_LINKED_WITH_TBB
  if(points.size() > 10000) {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, points.size(), 1024), [&](const tbb::blocked_range<std::size_t>& r) {
      for(std::size_t i = r.begin(); i != r.end(); ++i)
        run(i);
    });
    return result;
  }
#endif
  for(std::size_t i = 0; i < points.size(); ++i)
    run(i);
  return result;
}

} // namespace internal

/*!
\ingroup PkgHyperbolicOrbifoldTutteHelperFunctions

computes the vertex map \f$f_{AB}\f$ of the paper's section 7: for every vertex of `A`, in
`vertices(A)` order, where it lands on `B`: the face of `B` (`face_index` in `faces(B)` order)
and the barycentric coordinates there.

The vertex's point is the point of one of its corners in `uvA` (the corners of a cut vertex
are in one orbit, so any one will do); `A` and `B` must be embedded into the same orbifold with
corresponding landmarks (landmark `i` at cone `i`). The vertices are located in parallel when
CGAL is linked with TBB (each location is independent of the others: the same result whatever
the number of threads). An isolated vertex is not located (`success` is `false`).

\tparam TriangleMeshA a model of `FaceGraph`
\tparam HalfedgeUVMapA a model of `ReadablePropertyMap` from the halfedges of `A` to a point type with `x()` and `y()`
\tparam Locator an `Embedding_locator` of `B`

\param A the mesh whose vertices are mapped
\param uvA the embedding of `A` (per-corner map written by `hyperbolic_orbifold_Tutte_embedding()`)
\param locB the locator of the embedding of `B`

\return one `Locator::Location` per vertex of `A`
*/
template <class TriangleMeshA, class HalfedgeUVMapA, class Locator>
std::vector<typename Locator::Location> map_vertices(const TriangleMeshA& A, HalfedgeUVMapA uvA, const Locator& locB)
{
  return internal::map_vertices(A, uvA, locB, [](const auto&) { return -1; }, std::vector<Hyperbolic_isometry_2<double> >());
}

/*!
\ingroup PkgHyperbolicOrbifoldTutteHelperFunctions

`map_vertices()` for an embedding of `A` written partly in charts around cone images
(\ref HOT_Charts): a vertex written in a chart is located in `B`'s chart with the same
isometry (a chart centred at the same tile corner) at its own scale, where `B` has one (see
`Embedding_locator::locate(const Point_2&, const Isometry&)`). `locB` is built with `B`'s
charts when `B` has some.

\tparam TriangleMeshA a model of `FaceGraph`
\tparam HalfedgeUVMapA a model of `ReadablePropertyMap` from the halfedges of `A` to a point type with `x()` and `y()`
\tparam HalfedgeChartMapA a model of `ReadablePropertyMap` from the halfedges of `A` to `Chart_point`
\tparam Locator an `Embedding_locator` of `B`
\param A the mesh whose vertices are mapped
\param uvA the embedding of `A` (its tile points)
\param chart_mapA the chart points of `A`'s corners
\param chartsA the charts of `A` (`Embedding_statistics::charts`)
\param locB the locator of the embedding of `B`
\return one `Locator::Location` per vertex of `A`
*/
template <class TriangleMeshA, class HalfedgeUVMapA, class HalfedgeChartMapA, class Locator>
std::vector<typename Locator::Location> map_vertices(const TriangleMeshA& A, HalfedgeUVMapA uvA, HalfedgeChartMapA chart_mapA,
                                                     const std::vector<Hyperbolic_isometry_2<double> >& chartsA,
                                                     const Locator& locB)
{
  return internal::map_vertices(A, uvA, locB, [&](const auto& h) { return get(chart_mapA, h).chart; }, chartsA,
                                [&](const auto& h) { return get(chart_mapA, h).point; });
}

/*!
\ingroup PkgHyperbolicOrbifoldTutteHelperFunctions

`map_vertices()` from an embedding result of `A` (`Orbifold_embedding`): its corner coordinates,
and its charts when it is written partly in charts. `A` must not be recentred (its points
would be in a moved frame; `CGAL_precondition`).

\tparam TriangleMeshA, HalfedgeUVMapA, HalfedgeChartMapA the parameters of `A`'s `Orbifold_embedding`
\tparam Locator an `Embedding_locator` of `B` (e.g. built from `B`'s `Orbifold_embedding`)
\return one `Locator::Location` per vertex of `A`
*/
template <class TriangleMeshA, class HalfedgeUVMapA, class HalfedgeChartMapA, class Locator>
std::vector<typename Locator::Location> map_vertices(const Orbifold_embedding<TriangleMeshA, HalfedgeUVMapA, HalfedgeChartMapA>& A,
                                                     const Locator& locB)
{
  CGAL_precondition(A.is_valid() && !A.layout().recentred);
  if constexpr(Orbifold_embedding<TriangleMeshA, HalfedgeUVMapA, HalfedgeChartMapA>::has_chart_map)
    return map_vertices(A.mesh(), A.uv_map(), A.chart_map(), A.layout().charts, locB);
  else
    return map_vertices(A.mesh(), A.uv_map(), locB);
}

/*!
\ingroup PkgHyperbolicOrbifoldTutteHelperFunctions

computes the sparse transfer matrix `T` of a vertex map computed by `map_vertices()`: one row
per vertex of `A`, one column per vertex of `B` (in `vertices(B)` order), the three barycentric
coordinates of the row's location at the columns of the face's corners (summed when corners
coincide). Attributes transfer as `attr_A = T * attr_B`. Rows of locations that failed are empty.

\tparam Locator an `Embedding_locator` of `B`
\param locations the vertex map, as returned by `map_vertices(A, uvA, locB)`
\param locB the locator of `B` that computed it
*/
template <class Locator>
Eigen::SparseMatrix<double> transfer_matrix(const std::vector<typename Locator::Location>& locations, const Locator& locB)
{
  std::vector<Eigen::Triplet<double> > triplets;
  triplets.reserve(3 * locations.size());
  for(std::size_t i = 0; i < locations.size(); ++i) {
    const typename Locator::Location& l = locations[i];
    if(!l.success)
      continue;
    for(int j = 0; j < 3; ++j)
      if(l.barycentric[j] != 0.0)
        triplets.emplace_back(static_cast<int>(i), static_cast<int>(locB.corner_vertex_index(l.face_index, j)),
                              l.barycentric[j]);
  }
  Eigen::SparseMatrix<double> T(static_cast<Eigen::Index>(locations.size()),
                                static_cast<Eigen::Index>(locB.number_of_vertices()));
  T.setFromTriplets(triplets.begin(), triplets.end());
  T.makeCompressed();
  return T;
}

/*!
\ingroup PkgHyperbolicOrbifoldTutteHelperFunctions

computes the value of a vertex property of `B` at a location: the barycentric combination
`b0 * value(v0) + b1 * value(v1) + b2 * value(v2)` of the face's corners.

\tparam Locator an `Embedding_locator` of `B`
\tparam VertexMapB a model of `ReadablePropertyMap` with the vertices of `B` as key type; its
        value type needs `+` and multiplication by a `double` on the left (e.g. `double`,
        `Vector_3`, Eigen vectors)
\param l a successful location on `B`
\param locB the locator of `B` that computed it
\param valuesB the property of `B`
*/
template <class Locator, class VertexMapB>
typename boost::property_traits<VertexMapB>::value_type
interpolate_vertex_property(const typename Locator::Location& l, const Locator& locB, VertexMapB valuesB)
{
  typedef typename boost::property_traits<VertexMapB>::value_type Value;
  const Value v0 = get(valuesB, locB.vertex(locB.corner_vertex_index(l.face_index, 0)));
  const Value v1 = get(valuesB, locB.vertex(locB.corner_vertex_index(l.face_index, 1)));
  const Value v2 = get(valuesB, locB.vertex(locB.corner_vertex_index(l.face_index, 2)));
  return l.barycentric[0] * v0 + l.barycentric[1] * v1 + l.barycentric[2] * v2;
}

/*!
\ingroup PkgHyperbolicOrbifoldTutteHelperFunctions

transfers a vertex property of `B` to `A` through a vertex map computed by
`map_vertices(A, uvA, locB)`: `put(valuesA, v, interpolate_vertex_property(location of v, locB, valuesB))`
for every vertex `v` of `A` whose location succeeded.

\tparam TriangleMeshA a model of `FaceGraph`
\tparam Locator an `Embedding_locator` of `B`
\tparam VertexMapB a model of `ReadablePropertyMap` with the vertices of `B` as key type (see `interpolate_vertex_property()`)
\tparam VertexMapA a model of `WritablePropertyMap` with the vertices of `A` as key type and the same value type
\return the number of vertices written
*/
template <class TriangleMeshA, class Locator, class VertexMapB, class VertexMapA>
std::size_t transfer_vertex_property(const TriangleMeshA& A, const std::vector<typename Locator::Location>& locations,
                                     const Locator& locB, VertexMapB valuesB, VertexMapA valuesA)
{
  std::size_t i = 0, written = 0;
  for(auto v : vertices(A)) {
    if(i >= locations.size())
      break;
    const typename Locator::Location& l = locations[i++];
    if(!l.success)
      continue;
    put(valuesA, v, interpolate_vertex_property(l, locB, valuesB));
    ++written;
  }
  return written;
}

/*!
\ingroup PkgHyperbolicOrbifoldTutteHelperFunctions

computes the point of `B`'s surface at a location: `CGAL::barycenter()` of the face's corners
with the location's barycentric coordinates.

\tparam Locator an `Embedding_locator` of `B`
\tparam VertexPointMapB a model of `ReadablePropertyMap` from the vertices of `B` to the points
        of a CGAL kernel
\param l a successful location on `B`
\param locB the locator of `B` that computed it
\param vpmB the vertex point map of `B`
*/
template <class Locator, class VertexPointMapB>
typename boost::property_traits<VertexPointMapB>::value_type
surface_point(const typename Locator::Location& l, const Locator& locB, VertexPointMapB vpmB)
{
  const auto& p0 = get(vpmB, locB.vertex(locB.corner_vertex_index(l.face_index, 0)));
  const auto& p1 = get(vpmB, locB.vertex(locB.corner_vertex_index(l.face_index, 1)));
  const auto& p2 = get(vpmB, locB.vertex(locB.corner_vertex_index(l.face_index, 2)));
  return CGAL::barycenter(p0, l.barycentric[0], p1, l.barycentric[1], p2, l.barycentric[2]);
}

} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_SURFACE_MAPS_H
