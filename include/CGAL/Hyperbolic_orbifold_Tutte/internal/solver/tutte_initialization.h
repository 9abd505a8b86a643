// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_SOLVER_TUTTE_INITIALIZATION_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_SOLVER_TUTTE_INITIALIZATION_H

#include <CGAL/disable_warnings.h>

/// \file tutte_initialization.h
// The initial embedding: the border on the tile, the interior by a Tutte embedding in the
// Klein model (solve_interior_tutte(), declared in solver_doors.h, defined in
// tutte_interior_solve.h).

#include <CGAL/Hyperbolic_orbifold_Tutte/Hyperbolic_isometry_2.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/error_code.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/solver/flat_problem.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/linear_algebra/interior_laplacian.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/solver/solver_doors.h>

#include <Eigen/Dense>
#include <Eigen/Sparse>

#include <cmath>
#include <complex>
#include <cstddef>
#include <memory>
#include <vector>

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {
namespace internal {

// The fraction of the 3D arc length between its side's corners at each border vertex (0 at
// the corners and off the border)
template <class Point3>
std::vector<double> side_arc_fractions(const Flat_problem& P, const std::vector<Point3>& base_points)
{
  const std::vector<int>& loop = P.border_loop;
  const int L = static_cast<int>(loop.size());
  auto dist3 = [&](int a, int b) {
    const Point3& p = base_points[P.base[a]];
    const Point3& q = base_points[P.base[b]];
    const double dx = CGAL::to_double(p.x()) - CGAL::to_double(q.x()), dy = CGAL::to_double(p.y()) - CGAL::to_double(q.y()),
                 dz = CGAL::to_double(p.z()) - CGAL::to_double(q.z());
    return std::sqrt(dx * dx + dy * dy + dz * dz);
  };
  std::vector<double> frac(P.n, 0.0);
  int i = 0;
  while(i < L) {
    int j = i + 1;
    while(j < L && P.corner[loop[j]] < 0)
      ++j;
    // corners at loop[i] and loop[j % L]
    std::vector<double> acc(1, 0.0);
    for(int q = i; q < j; ++q)
      acc.push_back(acc.back() + dist3(loop[q], loop[(q + 1) % L]));
    const double total = acc.back() > 0 ? acc.back() : 1.0;
    for(int q = i + 1; q < j; ++q)
      frac[loop[q]] = acc[q - i] / total;
    i = j;
  }
  return frac;
}

// The border's variables in x and its positions z: cone copies at their corners, sphere
// p-side vertices on their side's geodesic (their twins follow by the pairing), disk-border
// vertices at the parameter t of their Klein segment, all at their arc-length fraction
template <class Tile>
void place_border(const Flat_problem& P, const Tile& tile, const std::vector<double>& frac, std::vector<double>& x,
                  std::vector<std::complex<double> >& z)
{
  typedef std::complex<double> C;
  typedef Hyperbolic_isometry_2<double> Isometry;
  const std::vector<int>& loop = P.border_loop;
  for(int v : loop) {
    if(P.corner[v] >= 0) { // (a free corner: a node of a genus-g cut graph, started at its corner)
      z[v] = P.fixed[v];
      if(P.kind[v] == Free) {
        x[P.var[v]] = z[v].real();
        x[P.var[v] + 1] = z[v].imag();
      }
    } else if(P.kind[v] == Free) { // sphere p-side: on the side's geodesic
      const int s = P.side[v];
      const auto& a = tile.corner(tile.side_source(s));
      const auto& b = tile.corner(tile.side_target(s));
      const C ca(CGAL::to_double(a.x()), CGAL::to_double(a.y())), cb(CGAL::to_double(b.x()), CGAL::to_double(b.y()));
      const Isometry to0 = Isometry::translation_to_origin(ca);
      const C b0 = to0.apply(cb);
      const double r = std::abs(b0);
      const double rr = std::tanh(frac[v] * std::atanh(r));
      z[v] = to0.inverse().apply(b0 * (rr / r));
      x[P.var[v]] = z[v].real();
      x[P.var[v] + 1] = z[v].imag();
    } else if(P.kind[v] == On_line) {
      x[P.var[v]] = frac[v];
    }
  }
  for(int v : loop)
    if(P.kind[v] == Transformed || P.kind[v] == On_line)
      z[v] = position(P, x, v);
}

// Places the border: cone copies at their corners, other border vertices along their
// tile side at the fraction of the 3D arc length between the side's corners (sphere:
// p-side vertices on the side's geodesic, their twins follow by the pairing; disk: the
// parameter t of the Klein segment). Interior vertices: Euclidean Tutte embedding in the
// Klein model with the same weights (paper, section 5), mapped back to Poincare.
template <class Point3, class Tile>
Error_code initialize_embedding(const Flat_problem& P, const Tile& tile, const std::vector<Point3>& base_points,
                                std::vector<double>& x, Interior_laplacian* keep = nullptr)
{
  Interior_laplacian local;
  Interior_laplacian& lap = keep ? *keep : local;
  typedef std::complex<double> C;
  x.assign(P.n_vars, 0.0);
  std::vector<C> z(P.n);
  place_border(P, tile, side_arc_fractions(P, base_points), x, z);
  return solve_interior_tutte(P, z, x, lap);
}

} // namespace internal
} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_SOLVER_TUTTE_INITIALIZATION_H
