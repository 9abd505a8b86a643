// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_CHART_POINT_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_CHART_POINT_H

#include <CGAL/Hyperbolic_orbifold_Tutte/Hyperbolic_isometry_2.h>

#include <complex>
#include <vector>

/// \file Chart_point.h

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {

/*!
\ingroup PkgHyperbolicOrbifoldTutteMainClasses

Where a corner of an embedding lies when a part of it is written in charts around cone
images (\ref HOT_Charts). A part of the mesh that converges onto a cone's image (a long
protrusion ending at a landmark) shrinks exponentially towards it in the tile, below what
`double` resolves there; such faces are written in a chart: the tile's coordinates moved by
the isometry `Embedding_statistics::charts[chart]`, which takes a tile corner of the cone to
the origin, where `double` resolves each point to 1e-16 of its own distance to the cone.

`chart` is -1 for a corner written in the tile's own coordinates (every corner of an
embedding without charts, `Embedding_statistics::charted_faces == 0`). A face is written in
the chart of any of its corners whose `chart` is not -1 (there is at most one); its other
corners are then `chart_coordinates()` of their tile points.

\tparam Point_2 the point type of the Poincar&eacute; disk
*/
template <class Point_2>
struct Chart_point
{
  int chart = -1;   ///< the chart, or -1 for the tile's own coordinates
  Point_2 point;    ///< the coordinates in that chart (unused when `chart` is -1)
};

/*!
\ingroup PkgHyperbolicOrbifoldTutteMainClasses
the coordinates in chart `c` of a corner whose tile point is `tile_point` and whose chart
point is `cp`: `cp.point` if it is written in chart `c`, else `charts[c]` applied to its tile
point (in `double`, bit for bit as the package computes them).
*/
template <class Point_2>
Point_2 chart_coordinates(const std::vector<Hyperbolic_isometry_2<double> >& charts, int c, const Chart_point<Point_2>& cp,
                          const Point_2& tile_point)
{
  if(c < 0)
    return tile_point;
  if(cp.chart == c)
    return cp.point;
  const std::complex<double> w =
    charts[c].apply(std::complex<double>(CGAL::to_double(tile_point.x()), CGAL::to_double(tile_point.y())));
  return Point_2(w.real(), w.imag());
}

namespace internal {
// the chart map of the overloads that do not allow charts
struct No_chart_map
{};
} // namespace internal

} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_CHART_POINT_H
