// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_CERTIFIER_CORNER_EMBEDDING_CHARTS_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_CERTIFIER_CORNER_EMBEDDING_CHARTS_H

// The numbers of certify_corner_embedding() for embeddings written partly in charts around
// cone images (Corner_embedding::charts): the chart table's checks, the chart points'
// consistency with their tile points, and every face's corners in the frame it is written
// in, with a rigorous bound on the error of the corners brought into a chart from the tile.
// Written for the certificate alone (it shares the isometries and the tile with the solver,
// nothing else).
//
// The model. Chart I is given by doubles (a, b) and a tile corner c (the corner's double
// coordinates in the tile of make_orbifold_tile()). The stored map S(z) = (a z + b) /
// (conj(b) z + conj(a)) is an exact isometry R o T_{c'} with c' = -b / a, T_p(z) = (z - p) /
// (1 - conj(p) z) and R a rotation about the origin. The certified embedding uses the ideal
// chart Phi = R o T_c, which moves the corner exactly to the origin: a chart point w is the
// tile point Phi^-1(w), a cone written as w = 0 is exactly at its corner, and the side
// pairing between two corners of one cone is, between their ideal charts, exactly a rotation
// about the origin. S is checked to be Phi up to rounding (|c' - c| <= 64 u, see
// check_chart_table()); the difference matters only where a tile point is brought into a
// chart (mixed faces, bounded per corner: chart_coordinates()) and for the angle of a seam
// rotation (seam_rotation()).

#include <CGAL/Hyperbolic_orbifold_Tutte/Hyperbolic_isometry_2.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/certifier/corner_embedding_geometry.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/core/filtered_predicates.h>

#include <CGAL/Exact_rational.h>
#include <CGAL/FPU.h>
#include <CGAL/Interval_nt.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <limits>

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {
namespace internal {
namespace corner_certificate {

// the unit roundoff of double
constexpr double unit_roundoff = 1.1102230246251565e-16;
// the bound on a chart's origin offset |c' - c| (disk coordinates): a chart whose
// coefficients are each within 16 u (|a| + |b|) of R o T_c has |c' - c| <= (|db| + |c'| |da|)
// / |a| <= 32 u (|a| + |b|) / |a| < 64 u (|b| < |a|); the package's charts
// (translation_to_origin(c): a = 1/s, b = -c/s, rescaled) are within 4.1 u |c| of it
constexpr double chart_origin_bound = 64 * unit_roundoff;
// the bound on |a|^2 - |b|^2 - 1 relative to (|a| + |b|)^2: coefficients within 16 u (|a| + |b|)
// of a normalized map change it by at most 2 x 16 u (|a| + |b|)^2 (+ its rounding)
constexpr double chart_normalization_bound = 64 * unit_roundoff;

inline double upper(const I& x) { return x.sup(); }

inline I_complex i_complex(const C& z) { return I_complex{I(z.real()), I(z.imag())}; }
inline I_complex i_mul(const I_complex& x, const I_complex& y)
{
  return I_complex{x.re * y.re - x.im * y.im, x.re * y.im + x.im * y.re};
}
inline I_complex i_add(const I_complex& x, const I_complex& y) { return I_complex{x.re + y.re, x.im + y.im}; }
inline I_complex i_sub(const I_complex& x, const I_complex& y) { return I_complex{x.re - y.re, x.im - y.im}; }
inline I_complex i_conj(const I_complex& x) { return I_complex{x.re, -x.im}; }
inline I i_norm(const I_complex& x) { return CGAL::square(x.re) + CGAL::square(x.im); }
// x / y (y's box must not contain 0: the result is then an enclosure)
inline I_complex i_div(const I_complex& x, const I_complex& y)
{
  const I d = i_norm(y);
  return I_complex{(x.re * y.re + x.im * y.im) / d, (x.im * y.re - x.re * y.im) / d};
}
// the centre of a box and the half length of its diagonal, rounded up (the caller's rounding
// mode is upwards)
inline void centre_and_radius(const I_complex& x, C& centre, double& radius)
{
  centre = C(0.5 * (x.re.inf() + x.re.sup()), 0.5 * (x.im.inf() + x.im.sup()));
  const double wx = (std::max)(x.re.sup() - centre.real(), centre.real() - x.re.inf());
  const double wy = (std::max)(x.im.sup() - centre.imag(), centre.imag() - x.im.inf());
  radius = std::sqrt(wx * wx + wy * wy) * (1 + 4 * unit_roundoff);
}

// One chart as read: its coefficients, its corner and what check_chart_table() found.
struct Chart_model
{
  C a, b;               // the stored map S(z) = (a z + b) / (conj(b) z + conj(a))
  int corner = -1;      // the tile corner at its origin
  C c;                  // that corner (the tile's double coordinates)
  bool ok = false;      // well formed and centred at its corner
  double offset = 0;    // an upper bound of |c' - c|, c' = -b/a the preimage of the origin
  double abs_a = 0, abs_b = 0;
};

// |a|^2 > |b|^2, decided exactly
inline bool is_disk_automorphism(const C& a, const C& b)
{
  const double d = std::norm(a) - std::norm(b);
  const double e = 4 * unit_roundoff * (std::norm(a) + std::norm(b));
  if(d > e)
    return true;
  if(d < -e)
    return false;
  const Exact_rational ar(a.real()), ai(a.imag()), br(b.real()), bi(b.imag());
  return ar * ar + ai * ai - br * br - bi * bi > Exact_rational(0);
}

// an upper bound of |(-b/a) - c| (exact -b/a enclosed in interval arithmetic)
inline double origin_offset(const C& a, const C& b, const C& c)
{
  Protect_FPU_rounding<true> protection;
  const I_complex o = i_div(i_sub(I_complex{I(0), I(0)}, i_complex(b)), i_complex(a));
  const I dx = o.re - I(c.real()), dy = o.im - I(c.imag());
  const double mx = (std::max)(std::abs(dx.inf()), std::abs(dx.sup())), my = (std::max)(std::abs(dy.inf()), std::abs(dy.sup()));
  const I r = CGAL::sqrt(CGAL::square(I(mx)) + CGAL::square(I(my)));
  return r.sup();
}

// an upper bound of ||a|^2 - |b|^2 - 1|
inline double normalization_defect(const C& a, const C& b)
{
  Protect_FPU_rounding<true> protection;
  const I d = i_norm(i_complex(a)) - i_norm(i_complex(b)) - I(1);
  return (std::max)(std::abs(d.inf()), std::abs(d.sup()));
}

// The tile point of chart point w, S^-1(w) = (conj(a) w - b) / (a - conj(b) w): an enclosure of
// the exact value (centre and radius), and the bound of the writer's rounding when it
// computed it in double (Hyperbolic_isometry_2::inverse().apply(): a complex product and a sum
// in the numerator and in the denominator, then a division: each component's error is below
// 4 u of the sum of the magnitudes of its terms, the division's below 4 u of the quotient:
// |dz| <= 4 u (|a| |w| + |b| + (|b| |w| + |a|) |z|) / |D| + 4 u |z| to first order; the bound
// is twice that, for other orders of the same operations)
inline void tile_point_of_chart_point(const Chart_model& ch, const C& w, C& z, double& radius, double& writer_rounding)
{
  {
    Protect_FPU_rounding<true> protection;
    const I_complex W = i_complex(w), A = i_complex(ch.a), B = i_complex(ch.b);
    const I_complex N = i_sub(i_mul(i_conj(A), W), B), D = i_sub(A, i_mul(i_conj(B), W));
    centre_and_radius(i_div(N, D), z, radius);
  }
  const double aw = std::abs(w), az = std::abs(z);
  const double D = std::abs(ch.a - std::conj(ch.b) * w) * (1 - 8 * unit_roundoff);
  writer_rounding = 2 * (4 * unit_roundoff * (ch.abs_a * aw + ch.abs_b + (ch.abs_b * aw + ch.abs_a) * az) / D + 4 * unit_roundoff * az) *
                    (1 + 1e-6);
}

// The coordinates in chart `ch` of the tile point z, and an upper bound of their distance to
// the ideal chart's image Phi(z): the exact S(z) enclosed in interval arithmetic (the centre;
// the radius bounds its distance to S(z)), plus |S(z) - Phi(z)| = |T_{c'}(z) - T_c(z)| <=
// |c' - c| sup |dT_p(z)/dp| + |dT_p(z)/d conj(p)| over p in the segment [c, c'], where
// dT/dp = -1 / (1 - conj(p) z) and dT/d conj(p) = z T_p(z) / (1 - conj(p) z): at most
// 2 |c' - c| / (1 - |p| |z|) <= 2 |c' - c| / (1 - |c| - |c' - c|) (|z|, |T_p(z)| < 1).
inline C chart_coordinates(const Chart_model& ch, const C& z, double& error)
{
  C w;
  double radius = 0;
  {
    Protect_FPU_rounding<true> protection;
    const I_complex Z = i_complex(z), A = i_complex(ch.a), B = i_complex(ch.b);
    centre_and_radius(i_div(i_add(i_mul(A, Z), B), i_add(i_mul(i_conj(B), Z), i_conj(A))), w, radius);
  }
  const double gap = 1 - std::abs(ch.c) * (1 + 4 * unit_roundoff) - ch.offset;
  const double stretch = gap > 0 ? 2 * ch.offset / gap : std::numeric_limits<double>::infinity();
  error = (radius + stretch) * (1 + 1e-6) + std::numeric_limits<double>::denorm_min();
  return w;
}

// Orientation of the triangle (p, q, r) of the Poincare disk for every choice of its corners
// within e[i] of the given points (boxes of half width e[i]: they contain the discs), in
// interval arithmetic: POSITIVE or NEGATIVE when certain, ZERO when it cannot be decided.
inline Sign robust_orientation(const std::array<C, 3>& t, const std::array<double, 3>& e)
{
  if(e[0] == 0 && e[1] == 0 && e[2] == 0)
    return poincare_orientation_sign_filtered(t[0].real(), t[0].imag(), t[1].real(), t[1].imag(), t[2].real(), t[2].imag());
  Protect_FPU_rounding<true> protection;
  typedef Interval_nt_advanced J;
  auto box = [](double x, double r) { return J(x) + J(-r, r); };
  const Uncertain<Sign> s = poincare_orientation_sign<J>(box(t[0].real(), e[0]), box(t[0].imag(), e[0]), box(t[1].real(), e[1]),
                                                         box(t[1].imag(), e[1]), box(t[2].real(), e[2]), box(t[2].imag(), e[2]));
  return is_certain(s) ? get_certain(s) : ZERO;
}

// The angle of each corner of a triangle moves by at most `widening(...)` when every corner
// moves by at most e: the geodesic direction at a towards b is arg((b - a)(1 - conj(a) b)), and
// |1 - conj(a) b| >= |b - a| (their squares differ by (1 - |a|^2)(1 - |b|^2) > 0), so moving a
// or b by e turns each factor by at most asin(e / (|b - a| - 2e)): a direction by at most
// 4 asin(...), an angle (two directions) by at most 8 asin(...) <= 8.1 e / (l - 2e) for
// e <= l / 100 (l the shortest side); pi otherwise.
inline double angle_widening(const std::array<C, 3>& t, const std::array<double, 3>& e)
{
  const double em = (std::max)(e[0], (std::max)(e[1], e[2]));
  if(em == 0)
    return 0;
  const double l = (std::min)(std::abs(t[0] - t[1]), (std::min)(std::abs(t[1] - t[2]), std::abs(t[2] - t[0]))) * (1 - 4 * unit_roundoff);
  if(!(em <= 0.01 * l))
    return CGAL_PI;
  return 8.1 * em / (l - 2 * em) * (1 + 1e-6);
}

// The rotation between two charts I and J of one cone glued by the tile's side pairing g
// (g maps corner c_I onto c_J): between the ideal charts it is Phi_J o g o Phi_I^-1, exactly a
// rotation about the origin (for the exact tile, in which g maps c_I onto c_J); its angle
// beta is arg of the derivative at the origin. Computed from the stored charts: H =
// S_J o g o S_I^-1 in long double, whose derivative at the origin has the argument
// -2 arg(1 - conj(c'_J) g(c'_I)) - 2 arg(conj(b_g) c'_I + conj(a_g)) (T_p' (z) = (1 - |p|^2) /
// (1 - conj(p) z)^2, g'(z) = 1 / (conj(b_g) z + conj(a_g))^2); the ideal one the same with
// c_I, c_J and the exact tile. Changing the arguments of those factors by the offsets bounds
// the angle's error:
//   |d beta| <= 2 (d_J + |g'(c_I)| d_I + eta) / (1 - |c_J| (|c_J| + d_J + eta) - ...)
//             + 2 (|b_g| d_I + 4 u (|a_g| + |b_g|)) / |conj(b_g) c_I + conj(a_g)|,
// d_I, d_J the charts' origin offsets, eta = |g(c_I) - c_J| (the double tile's own rounding,
// enclosed) + 8 u; plus the long double evaluation (below 64 u_ld |beta|-scale, 1e-17).
// Returns the rotation e^{i beta} and the bound on |d beta| in `angle_error`.
inline C seam_rotation(const Chart_model& I_, const Chart_model& J_, const Hyperbolic_isometry_2<double>& g, double& angle_error)
{
  typedef Hyperbolic_isometry_2<long double> Iso;
  typedef std::complex<long double> CL;
  const Iso SI(CL(I_.a.real(), I_.a.imag()), CL(I_.b.real(), I_.b.imag())), SJ(CL(J_.a.real(), J_.a.imag()), CL(J_.b.real(), J_.b.imag()));
  const Iso H = SJ * Iso(g) * SI.inverse();
  // H = R_beta o T_q: a = e^{i beta / 2} / sqrt(1 - |q|^2)
  const CL u = H.a() / std::abs(H.a());
  const CL rot = u * u;
  // the bound
  const double dI = I_.offset, dJ = J_.offset;
  double eta = 0;
  {
    Protect_FPU_rounding<true> protection;
    const I_complex Z = i_complex(I_.c), A = i_complex(g.a()), B = i_complex(g.b());
    const I_complex gz = i_div(i_add(i_mul(A, Z), B), i_add(i_mul(i_conj(B), Z), i_conj(A)));
    const I_complex d = i_sub(gz, i_complex(J_.c));
    eta = CGAL::sqrt(i_norm(d)).sup();
  }
  eta += 8 * unit_roundoff;
  const double ag = std::abs(g.a()), bg = std::abs(g.b());
  const double den_g = std::abs(std::conj(g.b()) * I_.c + std::conj(g.a())) * (1 - 8 * unit_roundoff) - bg * dI;
  const double dg = den_g > 0 ? 1 / (den_g * den_g) : std::numeric_limits<double>::infinity(); // |g'| near c_I
  const double cj = std::abs(J_.c);
  const double gap = 1 - cj * (cj + dJ + eta + dg * dI) * (1 + 8 * unit_roundoff) - (dJ + eta + dg * dI);
  const double t1 = gap > 0 ? 2 * (dJ + dg * dI + eta) / gap : std::numeric_limits<double>::infinity();
  const double t2 = den_g > 0 ? 2 * (bg * dI + 4 * unit_roundoff * (ag + bg)) / den_g : std::numeric_limits<double>::infinity();
  angle_error = (t1 + t2) * (1 + 1e-6) + 1e-17;
  return C(static_cast<double>(rot.real()), static_cast<double>(rot.imag()));
}

} // namespace corner_certificate
} // namespace internal
} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_CERTIFIER_CORNER_EMBEDDING_CHARTS_H
