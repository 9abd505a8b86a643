// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_FILTERED_PREDICATES_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_FILTERED_PREDICATES_H

#include <CGAL/Exact_rational.h>
#include <CGAL/Interval_nt.h>
#include <CGAL/Uncertain.h>
#include <CGAL/determinant.h>
#include <CGAL/enum.h>
#include <CGAL/number_utils.h>

#include <type_traits>

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {
namespace internal {

// Orientation of the geodesic triangle (p, q, r) of the Poincare disk.
//
// Geodesics are straight chords in the Klein model, k = 2z / (1 + |z|^2), so the
// orientation is the Euclidean orientation of the Klein images: the sign of the
// 3x3 determinant with rows (k_x, k_y, 1).  Multiplying each row by the positive
// number (1 + |z|^2) / 2 gives rows (x, y, (1 + x^2 + y^2) / 2); doubling the
// last column gives rows (x, y, 1 + x^2 + y^2).  This is a polynomial of degree 4
// in the Poincare coordinates: no square root, so it can be evaluated exactly.
template <class NT>
typename Same_uncertainty_nt<Sign, NT>::type
poincare_orientation_sign(const NT& px, const NT& py, const NT& qx, const NT& qy,
                          const NT& rx, const NT& ry)
{
  const NT one(1);
  const NT wp = one + px * px + py * py;
  const NT wq = one + qx * qx + qy * qy;
  const NT wr = one + rx * rx + ry * ry;
  // Subtracting row r from rows p and q keeps the determinant and reduces
  // cancellation: det = | px-rx  py-ry  wp-wr |
  //                     | qx-rx  qy-ry  wq-wr |  expanded along the
  //                     | rx     ry     wr    |  third row.
  const NT a1 = px - rx, a2 = py - ry, a3 = wp - wr;
  const NT b1 = qx - rx, b2 = qy - ry, b3 = wq - wr;
  const NT m1 = a2 * b3 - a3 * b2;
  const NT m2 = a1 * b3 - a3 * b1;
  const NT m3 = a1 * b2 - a2 * b1;
  const NT det = rx * m1 - ry * m2 + wr * m3;
  return CGAL::sign(det);
}

// Filtered, exact evaluation on double input: interval arithmetic first,
// exact rationals (GMP) only when the interval result is uncertain.
inline Sign poincare_orientation_sign_filtered(double px, double py, double qx, double qy,
                                               double rx, double ry)
{
  {
    Protect_FPU_rounding<true> protection;
    typedef Interval_nt_advanced I;
    const Uncertain<Sign> s = poincare_orientation_sign<I>(I(px), I(py), I(qx), I(qy), I(rx), I(ry));
    if(is_certain(s))
      return get_certain(s);
  }
  typedef Exact_rational Q;
  return poincare_orientation_sign<Q>(Q(px), Q(py), Q(qx), Q(qy), Q(rx), Q(ry));
}

// Dispatch on the kernel's number type: double is filtered; exact number types
// (Epeck's lazy numbers, rationals) are evaluated directly, which is exact.
template <class FT>
Sign poincare_orientation_sign_exact(const FT& px, const FT& py, const FT& qx, const FT& qy,
                                     const FT& rx, const FT& ry)
{
  if constexpr(std::is_same<FT, double>::value) {
    return poincare_orientation_sign_filtered(px, py, qx, qy, rx, ry);
  } else {
    static_assert(Algebraic_structure_traits<FT>::Is_exact::value,
                  "Hyperbolic_orbifold_Tutte: exact predicates need a kernel whose FT is double "
                  "(filtered) or an exact number type");
    return poincare_orientation_sign<FT>(px, py, qx, qy, rx, ry);
  }
}

} // namespace internal
} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_FILTERED_PREDICATES_H
