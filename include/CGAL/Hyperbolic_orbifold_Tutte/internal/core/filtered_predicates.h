// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_CORE_FILTERED_PREDICATES_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_CORE_FILTERED_PREDICATES_H

#include <CGAL/Exact_rational.h>
#include <CGAL/Interval_nt.h>
#include <CGAL/Uncertain.h>
#include <CGAL/determinant.h>
#include <CGAL/enum.h>
#include <CGAL/number_utils.h>

#include <cmath>
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

// The first stage of the filter: the same determinant in double precision, with a
// rigorous bound on its rounding error; true and the sign in `s` when the sign is certain.
//
// With r's row kept and a3 = wp - wr written a1 (px + rx) + a2 (py + ry) (likewise b3),
// every difference of inputs is a leaf computed with one rounding (relative error u = 2^-53
// of its own value), so the bound scales with the triangle: a tiny triangle is decided here
// as well as a large one.  Expanded, fl(det) is a sum of monomials each multiplied by at
// most 10 factors (1 + delta), |delta| <= u (rx m1: rx exact, m1's monomials carry 7: the
// leaves a2 or a1, s1 (2), their product and sum (2), b3's leaf and the product (2), the
// difference (1); then the product, the difference and the sum: 10), so
// |fl(det) - det| <= gamma_10 E, E the sum of the monomials' absolute values: the same tree
// on the absolute values of the leaves with every difference made a sum.  E computed in
// double (every term positive) is at least E (1 - u)^10.  The test |fl(det)| > 12 u fl(E)
// therefore decides the sign (a fused multiply-add only removes roundings).  Inputs are
// bounded by 4 (no overflow; points of the disk and their images in a walk are well
// inside) and E above 1e-250 (underflowed products, below 1e-300 in all, cannot matter);
// otherwise, or for NaN: not certain.
inline bool poincare_orientation_sign_semi_static(double px, double py, double qx, double qy, double rx, double ry,
                                                  Sign& s)
{
  const double lim = 4.0;
  if(!(std::abs(px) <= lim && std::abs(py) <= lim && std::abs(qx) <= lim && std::abs(qy) <= lim &&
       std::abs(rx) <= lim && std::abs(ry) <= lim))
    return false; // also NaN
  const double a1 = px - rx, a2 = py - ry, b1 = qx - rx, b2 = qy - ry;
  const double s1 = px + rx, s2 = py + ry, t1 = qx + rx, t2 = qy + ry;
  const double a3 = a1 * s1 + a2 * s2; // = wp - wr
  const double b3 = b1 * t1 + b2 * t2; // = wq - wr
  const double wr = 1.0 + rx * rx + ry * ry;
  const double m1 = a2 * b3 - a3 * b2;
  const double m2 = a1 * b3 - a3 * b1;
  const double m3 = a1 * b2 - a2 * b1;
  const double det = (rx * m1 - ry * m2) + wr * m3;
  const double A1 = std::abs(a1), A2 = std::abs(a2), B1 = std::abs(b1), B2 = std::abs(b2);
  const double A3 = A1 * std::abs(s1) + A2 * std::abs(s2);
  const double B3 = B1 * std::abs(t1) + B2 * std::abs(t2);
  const double E = (std::abs(rx) * (A2 * B3 + A3 * B2) + std::abs(ry) * (A1 * B3 + A3 * B1)) + wr * (A1 * B2 + A2 * B1);
  if(!(E > 1e-250))
    return false;
  const double bound = 12.0 * 1.1102230246251565e-16 * E; // 12 u E
  if(det > bound) {
    s = POSITIVE;
    return true;
  }
  if(det < -bound) {
    s = NEGATIVE;
    return true;
  }
  return false;
}

// Filtered, exact evaluation on double input: a semi-static filter first, then interval
// arithmetic, exact rationals (GMP) only when the interval result is uncertain.
inline Sign poincare_orientation_sign_filtered(double px, double py, double qx, double qy,
                                               double rx, double ry)
{
  {
    Sign s;
    if(poincare_orientation_sign_semi_static(px, py, qx, qy, rx, ry, s))
      return s;
  }
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

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_CORE_FILTERED_PREDICATES_H
