// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_CERTIFIER_CORNER_EMBEDDING_GEOMETRY_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_CERTIFIER_CORNER_EMBEDDING_GEOMETRY_H

// The numbers of certify_corner_embedding(), written for it alone (it shares no code with the
// solver beyond the traits, the isometries and the tile): the exact test of the open unit disk,
// certified enclosures of hyperbolic angles, the distance of a point to a tile side and to its
// segment, and the fit of a seam edge's two copies by the tile's side pairings.

#include <CGAL/Hyperbolic_orbifold_Tutte/Hyperbolic_isometry_2.h>

#include <CGAL/Exact_rational.h>
#include <CGAL/FPU.h>
#include <CGAL/Interval_nt.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <limits>
#include <vector>

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {
namespace internal {
namespace corner_certificate {

typedef std::complex<double> C;

// x^2 + y^2 < 1, decided exactly for finite x, y: in double when the rounded sum is farther
// from 1 than its error bound (two products and a sum: below 2.3e-16 near 1), exactly otherwise
inline bool strictly_inside_unit_disk(double x, double y)
{
  const double s = x * x + y * y;
  if(s < 1.0 - 1e-15)
    return true;
  if(s > 1.0 + 1e-15)
    return false;
  const Exact_rational X(x), Y(y);
  return X * X + Y * Y < Exact_rational(1);
}

// An enclosure [lo, hi] of a real number.
struct Enclosure
{
  double lo = 0, hi = 0;
};

// The box of u_c conj(u_b), whose argument is the angle at `a` of the triangle (a, b, c):
// the geodesic direction at a towards b is arg m_a(b), m_a(z) = (z - a) / (1 - conj(a) z),
// and arg m_a(b) = arg((b - a)(1 - a conj(b))) (the denominator's argument changes sign).
// Evaluated in interval arithmetic (the caller has set the rounding mode upwards); each
// direction vector is rescaled by a power of two (exact) so that the product cannot underflow
// for tiny triangles.
struct Angle_box
{
  double x_lo, x_hi, y_lo, y_hi;
};

typedef Interval_nt_advanced I;

struct I_complex
{
  I re, im;
};

inline I_complex direction_vector(const C& a, const C& b)
{
  const I ax(a.real()), ay(a.imag()), bx(b.real()), by(b.imag());
  const I dx = bx - ax, dy = by - ay;                   // b - a
  const I ex = I(1) - (ax * bx + ay * by), ey = ax * by - ay * bx; // 1 - a conj(b)
  I_complex u{dx * ex - dy * ey, dx * ey + dy * ex};
  const double m = (std::max)((std::max)(std::abs(u.re.inf()), std::abs(u.re.sup())),
                              (std::max)(std::abs(u.im.inf()), std::abs(u.im.sup())));
  if(m > 0 && std::isfinite(m)) {
    int e = 0;
    std::frexp(m, &e);
    const I s(std::ldexp(1.0, -e)); // exact power of two: u keeps its direction
    u.re = u.re * s;
    u.im = u.im * s;
  }
  return u;
}

inline Angle_box angle_box(const C& a, const C& b, const C& c)
{
  const I_complex ub = direction_vector(a, b), uc = direction_vector(a, c);
  const I x = uc.re * ub.re + uc.im * ub.im;
  const I y = uc.im * ub.re - uc.re * ub.im;
  return Angle_box{x.inf(), x.sup(), y.inf(), y.sup()};
}

// An enclosure of the argument of every point of the box, known to lie in (0, pi) (the
// triangle is positively oriented, decided exactly): the argument of the box's centre m,
// plus or minus asin(r / |m|) <= 1.16 r / |m| for r <= |m| / 2 (r the half diagonal),
// plus atan2's error (within an ulp of pi); [0, pi] when the box is too wide for that.
inline Enclosure angle_enclosure(const Angle_box& box)
{
  const double pi_up = std::nextafter(CGAL_PI, 4.0);
  Enclosure e{0.0, pi_up};
  if(!(std::isfinite(box.x_lo) && std::isfinite(box.x_hi) && std::isfinite(box.y_lo) && std::isfinite(box.y_hi)))
    return e;
  const double mx = 0.5 * (box.x_lo + box.x_hi), my = 0.5 * (box.y_lo + box.y_hi);
  // (the box's coordinates are below 4 in magnitude after rescaling: no overflow in the squares)
  const double wx = box.x_hi - box.x_lo, wy = box.y_hi - box.y_lo;
  const double r = 0.5 * std::sqrt(wx * wx + wy * wy) * (1.0 + 1e-12) + std::numeric_limits<double>::denorm_min();
  const double rho = std::sqrt(mx * mx + my * my) * (1.0 - 1e-12);
  if(!(r <= 0.5 * rho))
    return e;
  const double theta = std::atan2(my, mx);
  const double delta = 1.16 * (r / rho) + 2e-15;
  e.lo = (std::max)(0.0, theta - delta);
  e.hi = (std::min)(pi_up, theta + delta);
  return e;
}

// The angles of positively oriented triangles (a, b, c), certified: the interval part of all
// of them in one block with the rounding mode set upwards (switching it is not free), then
// the arguments, rounded to nearest.
inline void triangle_angles(const std::vector<std::array<C, 3> >& triangles, std::vector<std::array<Enclosure, 3> >& angles)
{
  std::vector<std::array<Angle_box, 3> > boxes(triangles.size());
  {
    Protect_FPU_rounding<true> protection;
    for(std::size_t i = 0; i < triangles.size(); ++i) {
      const std::array<C, 3>& t = triangles[i];
      boxes[i] = {{angle_box(t[0], t[1], t[2]), angle_box(t[1], t[2], t[0]), angle_box(t[2], t[0], t[1])}};
    }
  }
  angles.resize(triangles.size());
  for(std::size_t i = 0; i < triangles.size(); ++i)
    for(int c = 0; c < 3; ++c)
      angles[i][c] = angle_enclosure(boxes[i][c]);
}

// Adds a term to a running enclosure of a sum (rounded to nearest, so the caller widens
// the result by its rounding bound: see widen_sum()).
inline void add(Enclosure& s, const Enclosure& t)
{
  s.lo += t.lo;
  s.hi += t.hi;
}

// A sum of n terms of magnitude at most `magnitude` each, accumulated in double, is within
// n u (sum of magnitudes) of the exact sum (u = 2^-53): widen both ends by that.
inline Enclosure widen_sum(const Enclosure& s, std::size_t n, double total_magnitude)
{
  const double w = (static_cast<double>(n) + 2.0) * 1.12e-16 * total_magnitude;
  return Enclosure{s.lo - w, s.hi + w};
}

// Homogeneous Klein coordinates (x, y, (1 + |z|^2) / 2) of a Poincare point: geodesics are the
// lines of the Klein model, so the geodesic through two points is the cross product.
inline std::array<long double, 3> klein_homogeneous(const C& z)
{
  const long double x = z.real(), y = z.imag();
  return {{x, y, 0.5L * (1.0L + x * x + y * y)}};
}

// The Euclidean (Poincare-disk coordinates) distance of `p` to the geodesic through `c0`, `c1`,
// to first order: |f(p)| / |grad f(p)| for f(z) = L . (x, y, (1 + |z|^2)/2), whose zero set is
// the geodesic (a circle orthogonal to the unit circle, or a diameter); exact for a diameter,
// within a factor (|p - centre| + R) / (2 |p - centre|) of the exact distance for a circle.
inline double distance_to_geodesic(const C& p, const C& c0, const C& c1)
{
  const std::array<long double, 3> A = klein_homogeneous(c0), B = klein_homogeneous(c1), P = klein_homogeneous(p);
  const long double L0 = A[1] * B[2] - A[2] * B[1], L1 = A[2] * B[0] - A[0] * B[2], L2 = A[0] * B[1] - A[1] * B[0];
  const long double f = L0 * P[0] + L1 * P[1] + L2 * P[2];
  const long double gx = L0 + L2 * P[0], gy = L1 + L2 * P[1];
  const long double g = std::sqrt(gx * gx + gy * gy);
  if(!(g > 0))
    return std::numeric_limits<double>::infinity();
  return static_cast<double>(std::abs(f) / g);
}

// How far `p` lies beyond the segment [c0, c1] of its geodesic (0 when its projection falls
// in it): the Klein model's straight segment, the overshoot converted to Poincare-disk
// coordinates with the least stretch of the Klein map at p, 2 (1 - |p|^2) / (1 + |p|^2)^2,
// which overestimates it (a conservative test).
inline double distance_beyond_segment(const C& p, const C& c0, const C& c1)
{
  auto klein = [](const C& z) {
    const long double x = z.real(), y = z.imag(), w = 1.0L + x * x + y * y;
    return std::array<long double, 2>{{2 * x / w, 2 * y / w}};
  };
  const std::array<long double, 2> K0 = klein(c0), K1 = klein(c1), Kp = klein(p);
  const long double dx = K1[0] - K0[0], dy = K1[1] - K0[1];
  const long double len2 = dx * dx + dy * dy;
  if(!(len2 > 0))
    return std::numeric_limits<double>::infinity();
  const long double t = ((Kp[0] - K0[0]) * dx + (Kp[1] - K0[1]) * dy) / len2;
  const long double over = t < 0 ? -t : (t > 1 ? t - 1 : 0);
  if(over == 0)
    return 0.0;
  const long double n = static_cast<long double>(p.real()) * p.real() + static_cast<long double>(p.imag()) * p.imag();
  const long double stretch = 2 * (1 - n) / ((1 + n) * (1 + n));
  return static_cast<double>(over * std::sqrt(len2) / stretch);
}

// The orientation-preserving isometry computed from a seam edge's two copies: it maps a1 to
// a2 and the geodesic direction at a1 towards b1 to the one at a2 towards b2,
// h = m_{a2}^{-1} o (rotation) o m_{a1}.
inline Hyperbolic_isometry_2<long double> isometry_from_copies(const C& a1, const C& b1, const C& a2, const C& b2)
{
  typedef Hyperbolic_isometry_2<long double> Iso;
  typedef std::complex<long double> CL;
  auto direction = [](const C& a, const C& b) {
    const CL A(a.real(), a.imag()), B(b.real(), b.imag());
    return std::arg((B - A) * (CL(1) - A * std::conj(B)));
  };
  const long double theta = direction(a2, b2) - direction(a1, b1);
  return Iso::translation_from_origin(CL(a2.real(), a2.imag())) * Iso::rotation(theta) *
         Iso::translation_to_origin(CL(a1.real(), a1.imag()));
}

// |g(z) - w| with g applied in long double
inline double image_distance(const Hyperbolic_isometry_2<long double>& g, const C& z, const C& w)
{
  typedef std::complex<long double> CL;
  const CL gz = g.apply(CL(z.real(), z.imag()));
  const CL d = gz - CL(w.real(), w.imag());
  return static_cast<double>(std::sqrt(d.real() * d.real() + d.imag() * d.imag()));
}

// the distance of two isometries' normalized coefficients, up to their common sign, relative
// to their size (0 for the same map)
inline double coefficient_distance(const Hyperbolic_isometry_2<long double>& f, const Hyperbolic_isometry_2<long double>& g)
{
  auto n2 = [](const std::complex<long double>& z) { return z.real() * z.real() + z.imag() * z.imag(); };
  const long double scale = std::sqrt(n2(f.a()) + n2(f.b()));
  const long double dp = std::sqrt(n2(f.a() - g.a()) + n2(f.b() - g.b()));
  const long double dm = std::sqrt(n2(f.a() + g.a()) + n2(f.b() + g.b()));
  return static_cast<double>((dp < dm ? dp : dm) / scale);
}

} // namespace corner_certificate
} // namespace internal
} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_CERTIFIER_CORNER_EMBEDDING_GEOMETRY_H
