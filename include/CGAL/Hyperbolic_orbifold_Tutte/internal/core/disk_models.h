// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_CORE_DISK_MODELS_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_CORE_DISK_MODELS_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Hyperbolic_orbifold_Tutte/internal/core/filtered_predicates.h>

#include <array>
#include <cmath>
#include <complex>
#include <limits>

// The geometry core: the Poincare <-> Klein conversions, the hyperboloid and conformal
// factors and the Klein barycentric coordinates, in double precision, written once here and
// used by the traits (Poincare_disk_traits_2.h) and by every internal computation; the exact
// orientation of three Poincare points is in filtered_predicates.h, included here.

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {
namespace internal {

// Complex numbers are std::complex. Two operations keep their textbook formulas here, because
// the standard library's differ in the last bits (libstdc++'s std::norm goes through hypot,
// complex/complex division is scaled): the squared modulus re^2 + im^2 and the division
// (a conj(b)) / |b|^2. Use them for every |z|^2 and every complex/complex quotient; sums,
// products, conj, abs (hypot), arg (atan2), polar and the operations with a real are std's.
template <class NT>
NT squared_modulus(const std::complex<NT>& z)
{
  return z.real() * z.real() + z.imag() * z.imag();
}

template <class NT>
std::complex<NT> divide(const std::complex<NT>& a, const std::complex<NT>& b)
{
  const NT d = squared_modulus(b);
  return std::complex<NT>((a.real() * b.real() + a.imag() * b.imag()) / d,
                          (a.imag() * b.real() - a.real() * b.imag()) / d);
}

// the Klein point 2z / (1 + |z|^2) of a Poincare point
inline std::complex<double> poincare_to_klein(const std::complex<double>& z)
{
  return z * (2.0 / (1.0 + squared_modulus(z)));
}

// the Poincare point k / (1 + sqrt(1 - |k|^2)) of a Klein point (|k| >= 1 clamped to the circle)
inline std::complex<double> klein_to_poincare(const std::complex<double>& k)
{
  const double s = 1.0 - squared_modulus(k);
  return k / (1.0 + std::sqrt(s > 0 ? s : 0.0));
}

// sinh^2(d/2) of the hyperbolic distance d of two Poincare points: a monotone function of d
inline double hyperbolic_proximity(const std::complex<double>& a, const std::complex<double>& b)
{
  const double den = (1.0 - squared_modulus(a)) * (1.0 - squared_modulus(b));
  return squared_modulus(a - b) / (den > 0 ? den : std::numeric_limits<double>::min());
}

// Barycentric coordinates of q in the triangle (a, b, c), all Poincare points, computed in
// the Klein model. Independent of the triangle's orientation. When q is bitwise one of the
// corners the result is exactly the corresponding unit vector.
inline std::array<double, 3> klein_barycentric(const std::complex<double>& a, const std::complex<double>& b,
                                               const std::complex<double>& c, const std::complex<double>& q)
{
  typedef std::complex<double> C;
  const C K[3] = {poincare_to_klein(a), poincare_to_klein(b), poincare_to_klein(c)};
  const C kq = poincare_to_klein(q);
  auto cross = [](const C& u, const C& v) { return u.real() * v.imag() - u.imag() * v.real(); };
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
inline double hyperboloid_weight(const std::complex<double>& z)
{
  const double n = squared_modulus(z);
  return (1.0 - n) / (1.0 + n);
}

// the conformal factor 2 / (1 - |z|^2) of the Poincare metric at z
inline double conformal_factor(const std::complex<double>& z)
{
  return 2.0 / (1.0 - squared_modulus(z));
}

} // namespace internal
} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_CORE_DISK_MODELS_H
