// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_SOLVER_HYPERBOLIC_ENERGY_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_SOLVER_HYPERBOLIC_ENERGY_H

#include <CGAL/Hyperbolic_orbifold_Tutte/Hyperbolic_isometry_2.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/core/disk_models.h>

#include <cmath>

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {
namespace internal {

// Squared hyperbolic distance f = d(z, w)^2 of two points of the Poincare disk, with
// its gradient and Hessian with respect to (z.real(), z.imag(), w.real(), w.imag()).
//
// With A = 1 - |z|^2, B = 1 - |w|^2, N = |z - w|^2 and delta = N / (A B):
//   cosh d = 1 + 2 delta (paper eq. (6)),  d = 2 asinh(sqrt(delta)) (no cancellation),
//   u = cosh d = 1 + s N with s = 2 / (A B),
//   f = phi(u) = acosh(u)^2,  phi'(u) = 2 d / sinh d,
//   phi''(u) = 2 (sinh d - d cosh d) / sinh^3 d,
//   grad u = s (grad N + N c),  c = (2z / A, 2w / B),
//   hess u = s (hess N + c grad N^T + grad N c^T + N c c^T + N grad c),
//   grad c = diag((2/A) I + (4/A^2) z z^T, (2/B) I + (4/B^2) w w^T).
struct Squared_distance_derivatives
{
  double f;          // d^2
  double d;          // d
  double g[4];       // gradient
  double H[4][4];    // Hessian
};

inline void squared_hyperbolic_distance(const std::complex<double>& z, const std::complex<double>& w,
                                        Squared_distance_derivatives& out, bool want_hessian = true)
{
  const double A = 1.0 - squared_modulus(z), B = 1.0 - squared_modulus(w);
  const double dx = z.real() - w.real(), dy = z.imag() - w.imag();
  const double N = dx * dx + dy * dy;
  const double delta = N / (A * B);
  const double d = 2.0 * std::asinh(std::sqrt(delta));
  out.d = d;
  out.f = d * d;
  // sinh d = 2 sqrt(delta) sqrt(1 + delta), cosh d = 1 + 2 delta
  const double sinh_d = 2.0 * std::sqrt(delta) * std::sqrt(1.0 + delta);
  const double cosh_d = 1.0 + 2.0 * delta;
  double phi1, phi2;
  if(d < 1e-4) {
    // limits of 2 d / sinh d and 2 (sinh d - d cosh d) / sinh^3 d at 0 (Taylor series)
    phi1 = 2.0 * (1.0 - d * d / 6.0);
    phi2 = -2.0 / 3.0 + 4.0 / 15.0 * d * d;
  } else {
    phi1 = 2.0 * d / sinh_d;
    phi2 = 2.0 * (sinh_d - d * cosh_d) / (sinh_d * sinh_d * sinh_d);
  }
  const double s = 2.0 / (A * B);
  const double gN[4] = {2 * dx, 2 * dy, -2 * dx, -2 * dy};
  const double c[4] = {2 * z.real() / A, 2 * z.imag() / A, 2 * w.real() / B, 2 * w.imag() / B};
  double gu[4];
  for(int i = 0; i < 4; ++i) {
    gu[i] = s * (gN[i] + N * c[i]);
    out.g[i] = phi1 * gu[i];
  }
  if(!want_hessian)
    return;
  // hess N
  static const double HN[4][4] = {{2, 0, -2, 0}, {0, 2, 0, -2}, {-2, 0, 2, 0}, {0, -2, 0, 2}};
  double Gc[4][4] = {{0}};
  Gc[0][0] = 2 / A + 4 / (A * A) * z.real() * z.real();
  Gc[0][1] = Gc[1][0] = 4 / (A * A) * z.real() * z.imag();
  Gc[1][1] = 2 / A + 4 / (A * A) * z.imag() * z.imag();
  Gc[2][2] = 2 / B + 4 / (B * B) * w.real() * w.real();
  Gc[2][3] = Gc[3][2] = 4 / (B * B) * w.real() * w.imag();
  Gc[3][3] = 2 / B + 4 / (B * B) * w.imag() * w.imag();
  for(int i = 0; i < 4; ++i)
    for(int j = i; j < 4; ++j) {
      const double hu = s * (HN[i][j] + c[i] * gN[j] + gN[i] * c[j] + N * c[i] * c[j] + N * Gc[i][j]);
      out.H[i][j] = out.H[j][i] = phi2 * gu[i] * gu[j] + phi1 * hu;
    }
}

// A vertex position as a function of the solver's variables:
//  - Fixed:      no variable (cones);
//  - Free:       z = x (two variables);
//  - Transformed z = m(x) for an isometry m (a seam twin, two variables of its twin);
//  - On_line:    z = Poincare(k0 + t (k1 - k0)), one variable t (disk-type boundary,
//                where the tile's side is straight in the Klein model).
enum Position_kind { Fixed, Free, Transformed, On_line };

// first and second derivatives of a position with respect to its variables
struct Position_jet
{
  std::complex<double> z;
  int dim;                 // 0, 1 or 2
  std::complex<double> dz[2];   // dz / dx_k
  std::complex<double> ddz[2][2];
};

// z = m(x), m a Mobius map (orientation preserving): dz/dx = m'(x), dz/dy = i m'(x),
// second derivatives m'', i m'', -m''.
inline void transformed_jet(const Hyperbolic_isometry_2<double>& m, const std::complex<double>& x, Position_jet& jet)
{
  const std::complex<double> den = std::conj(m.b()) * x + std::conj(m.a());
  const std::complex<double> num = m.a() * x + m.b();
  jet.z = divide(num, den);
  // (a x + b)/(conj(b) x + conj(a)) has derivative det / den^2 and second derivative
  // -2 conj(b) det / den^3, det = |a|^2 - |b|^2 (1 for a normalized map)
  const double det = squared_modulus(m.a()) - squared_modulus(m.b());
  const std::complex<double> d1 = divide(std::complex<double>(det), den * den);
  const std::complex<double> d2 = divide(std::complex<double>(-2.0 * det) * std::conj(m.b()), den * den * den);
  const std::complex<double> I(0.0, 1.0);
  jet.dim = 2;
  jet.dz[0] = d1;
  jet.dz[1] = I * d1;
  jet.ddz[0][0] = d2;
  jet.ddz[0][1] = jet.ddz[1][0] = I * d2;
  jet.ddz[1][1] = -d2;
}

// z(t) = k / (1 + sqrt(1 - |k|^2)), k = k0 + t D (klein_to_poincare of disk_models.h) and its derivatives in t.
inline void on_line_jet(const std::complex<double>& k0, const std::complex<double>& D, double t, Position_jet& jet)
{
  const std::complex<double> k = k0 + t * D;
  const double r2 = squared_modulus(k);
  const double s = std::sqrt(1.0 - r2);
  const double kD = k.real() * D.real() + k.imag() * D.imag();
  const double D2 = squared_modulus(D);
  const double q = 1.0 + s;
  const double s1 = -kD / s;
  const double s2 = -D2 / s - kD * kD / (s * s * s);
  jet.z = k / q;
  jet.dim = 1;
  jet.dz[0] = D / q - k * (s1 / (q * q));
  jet.ddz[0][0] = D * (-2.0 * s1 / (q * q)) - k * (s2 / (q * q)) + k * (2.0 * s1 * s1 / (q * q * q));
}

} // namespace internal
} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_SOLVER_HYPERBOLIC_ENERGY_H
