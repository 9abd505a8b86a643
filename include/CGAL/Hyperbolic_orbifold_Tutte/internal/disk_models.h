// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_DISK_MODELS_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_DISK_MODELS_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Hyperbolic_orbifold_Tutte/internal/Complex.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/filtered_predicates.h>

#include <array>
#include <cmath>
#include <limits>

// The geometry core: the Poincare <-> Klein conversions, the hyperboloid and conformal
// factors and the Klein barycentric coordinates, in double precision, written once here and
// used by the traits (Poincare_disk_traits_2.h) and by every internal computation; the exact
// orientation of three Poincare points is in filtered_predicates.h, included here.

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {
namespace internal {

// the Klein point 2z / (1 + |z|^2) of a Poincare point
inline Complex<double> poincare_to_klein(const Complex<double>& z)
{
  return z * (2.0 / (1.0 + norm(z)));
}

// the Poincare point k / (1 + sqrt(1 - |k|^2)) of a Klein point (|k| >= 1 clamped to the circle)
inline Complex<double> klein_to_poincare(const Complex<double>& k)
{
  const double s = 1.0 - norm(k);
  return k / (1.0 + std::sqrt(s > 0 ? s : 0.0));
}

// sinh^2(d/2) of the hyperbolic distance d of two Poincare points: a monotone function of d
inline double hyperbolic_proximity(const Complex<double>& a, const Complex<double>& b)
{
  const double den = (1.0 - norm(a)) * (1.0 - norm(b));
  return norm(a - b) / (den > 0 ? den : std::numeric_limits<double>::min());
}

// Barycentric coordinates of q in the triangle (a, b, c), all Poincare points, computed in
// the Klein model. Independent of the triangle's orientation. When q is bitwise one of the
// corners the result is exactly the corresponding unit vector.
inline std::array<double, 3> klein_barycentric(const Complex<double>& a, const Complex<double>& b,
                                               const Complex<double>& c, const Complex<double>& q)
{
  typedef Complex<double> C;
  const C K[3] = {poincare_to_klein(a), poincare_to_klein(b), poincare_to_klein(c)};
  const C kq = poincare_to_klein(q);
  auto cross = [](const C& u, const C& v) { return u.re * v.im - u.im * v.re; };
  std::array<double, 3> l;
  for(int i = 0; i < 3; ++i) {
    const C& u = K[(i + 1) % 3];
    const C& v = K[(i + 2) % 3];
    // the sub-triangle opposite corner i, over the whole triangle (same expression when q = K[i])
    l[i] = cross(u - kq, v - kq) / cross(u - K[i], v - K[i]);
  }
  return l;
}

// 1 / (hyperboloid height) of a Poincare point: (1 - |z|^2) / (1 + |z|^2)
inline double hyperboloid_weight(const Complex<double>& z)
{
  const double n = norm(z);
  return (1.0 - n) / (1.0 + n);
}

// the conformal factor 2 / (1 - |z|^2) of the Poincare metric at z
inline double conformal_factor(const Complex<double>& z)
{
  return 2.0 / (1.0 - norm(z));
}

} // namespace internal
} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_DISK_MODELS_H
