// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_SOLVER_CONE_CHARTS_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_SOLVER_CONE_CHARTS_H

#include <CGAL/Hyperbolic_orbifold_Tutte/Hyperbolic_isometry_2.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/solver/flat_problem.h>

#include <array>
#include <complex>
#include <vector>

// Charts around cone images: the data of an embedding whose faces near a cone are written
// in a frame centred at the cone's image (cone_chart_solve.h computes them).
//
// A part of the mesh that converges onto a cone (a long protrusion ending at a landmark)
// shrinks exponentially towards the cone's image in the tile, below what double resolves
// there (1e-16 of the coordinates' size). In the frame that moves the cone's image to the
// origin, double resolves it to 1e-16 of each point's own distance to the cone: the
// region's faces are written there. Each tile corner of such a cone has its chart
// (Phi(z) = translation_to_origin(corner)(z)); the side pairing between two corners of one
// cone is, between their charts, a rotation about the origin, kept exact (no translation
// part): seam twins near the cone stay consistent at any depth.

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {
namespace internal {

struct Cone_charts
{
  typedef std::complex<double> C;
  typedef Hyperbolic_isometry_2<double> Isometry;

  std::vector<Isometry> chart;          // chart i: the tile's coordinates to the chart's
  std::vector<int> chart_corner;        // chart i: the tile corner at its origin
  // The charted region as a flat problem of its own, every position in its vertex's chart:
  // the region's vertices (free, seam copies with exact rotations, cone copies at the origin,
  // disk-border vertices on their side's chart segment) and, held fixed, a copy per chart of
  // each neighbour outside it, at its tile position moved into the chart.
  Flat_problem Q;
  std::vector<int> q_source;            // per Q vertex: its vertex of the tile's problem P
  std::vector<int> q_chart;             // per Q vertex: its chart
  std::vector<char> q_region;           // per Q vertex: in the region (1) or a fixed outside copy (0)
  std::vector<C> q_position;            // per Q vertex: its position in its chart (after the solve)
  std::vector<int> region_q;            // per P vertex: its Q vertex if in the region, else -1
  std::vector<int> face_chart;          // per P face: its chart, or -1 (the tile's coordinates)
  std::vector<int> face_q;              // per P face: its face in Q, or -1

  bool empty() const { return chart.empty(); }

  // the corner `i` of P's face `f` in the coordinates the face is written in: its chart's, or
  // the tile's (`uv`, one point per P vertex)
  C face_point(const Flat_problem& P, const std::vector<C>& uv, std::size_t f, int i) const
  {
    if(!empty() && face_chart[f] >= 0)
      return q_position[Q.faces[face_q[f]][i]];
    return uv[P.faces[f][i]];
  }
};

} // namespace internal
} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_SOLVER_CONE_CHARTS_H
