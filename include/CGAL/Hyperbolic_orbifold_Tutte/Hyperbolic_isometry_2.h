// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_HYPERBOLIC_ISOMETRY_2_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_HYPERBOLIC_ISOMETRY_2_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Hyperbolic_orbifold_Tutte/internal/core/disk_models.h>
#include <CGAL/number_utils.h>

#include <cmath>
#include <iostream>

/// \file Hyperbolic_isometry_2.h

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {

/*!
\ingroup PkgHyperbolicOrbifoldTutteMainClasses

An isometry of the Poincar&eacute; disk: a M&ouml;bius map
\f$ z \mapsto \frac{a z + b}{\bar b z + \bar a} \f$ (orientation preserving) or an
anti-M&ouml;bius map \f$ z \mapsto \frac{a \bar z + b}{\bar b \bar z + \bar a} \f$
(orientation reversing), with \f$ |a|^2 - |b|^2 = 1 \f$.
The pair \f$(a,b)\f$ is defined up to a common sign.

\tparam FT `float`, `double` (the default) or `long double`: the number types of `std::complex`.
Images of points are constructions: they are rounded.
*/
template <class FT_ = double>
class Hyperbolic_isometry_2
{
public:
  /// the number type
  typedef FT_ FT;
  /// complex numbers over `FT`: `std::complex<FT>` (`FT` is `float`, `double` or `long double`)
  typedef std::complex<FT> Complex;

private:
  Complex a_, b_;
  bool reversing_;

  // Products and inverses of normalized maps are normalized in exact arithmetic; they are
  // built raw, because recomputing |a|^2 - |b|^2 cancels about log10(|a|^2) digits when
  // the coefficients are large (far translations) and rescaling by it would perturb the map.
  struct Raw {};
  Hyperbolic_isometry_2(const Complex& a, const Complex& b, bool reversing, Raw)
    : a_(a), b_(b), reversing_(reversing) {}

  void normalize()
  {
    using std::sqrt;
    const FT d = internal::squared_modulus(a_) - internal::squared_modulus(b_);
    if(d > FT(0) && d != FT(1)) {
      const FT s = sqrt(d);
      a_ = a_ / s;
      b_ = b_ / s;
    }
  }

public:
  /// \name Creation
  /// @{

  /// the identity
  Hyperbolic_isometry_2() : a_(FT(1)), b_(FT(0)), reversing_(false) {}

  /// the map with coefficients `a`, `b`, rescaled so that \f$ |a|^2 - |b|^2 = 1 \f$.
  /// \pre \f$ |a| > |b| \f$
  Hyperbolic_isometry_2(const Complex& a, const Complex& b, bool orientation_reversing = false)
    : a_(a), b_(b), reversing_(orientation_reversing)
  {
    normalize();
  }

  /// the same map over another number type (coefficients converted, not renormalized)
  template <class FT2>
  explicit Hyperbolic_isometry_2(const Hyperbolic_isometry_2<FT2>& other)
    : a_(FT(other.a().real()), FT(other.a().imag())), b_(FT(other.b().real()), FT(other.b().imag())),
      reversing_(!other.is_orientation_preserving())
  {}

  /// the identity
  static Hyperbolic_isometry_2 identity() { return Hyperbolic_isometry_2(); }

  /// the map with coefficients `a` and `b` exactly as given, not rescaled: for coefficients
  /// of a normalized map read back from a file (written with 17 significant digits they are
  /// the same numbers, while the constructor's rescaling could change their last bits).
  /// \pre \f$ |a|^2 - |b|^2 = 1 \f$ up to rounding
  static Hyperbolic_isometry_2 from_coefficients(const Complex& a, const Complex& b, bool orientation_reversing = false)
  {
    return Hyperbolic_isometry_2(a, b, orientation_reversing, Raw());
  }

  /// the rotation about the origin by `angle` (counterclockwise, radians)
  static Hyperbolic_isometry_2 rotation(const FT& angle)
  {
    return Hyperbolic_isometry_2(std::polar(FT(1), angle / FT(2)), Complex(), false);
  }

  /// the map \f$ m_p(z) = (z - p)/(1 - \bar p z) \f$, which moves `p` to the origin
  /// (paper eq. (8), as corrected in the notes).
  /// \pre \f$ |p| < 1 \f$
  static Hyperbolic_isometry_2 translation_to_origin(const Complex& p)
  {
    using std::sqrt;
    const FT s = sqrt(FT(1) - internal::squared_modulus(p));
    return Hyperbolic_isometry_2(Complex(FT(1) / s), -p / s, false);
  }

  /// the inverse of `translation_to_origin(p)`: it moves the origin to `p`.
  static Hyperbolic_isometry_2 translation_from_origin(const Complex& p)
  {
    using std::sqrt;
    const FT s = sqrt(FT(1) - internal::squared_modulus(p));
    return Hyperbolic_isometry_2(Complex(FT(1) / s), p / s, false);
  }

  /// the rotation about `p` by `angle` (counterclockwise, as seen in the model, which is conformal)
  static Hyperbolic_isometry_2 rotation_about(const Complex& p, const FT& angle)
  {
    return translation_from_origin(p) * rotation(angle) * translation_to_origin(p);
  }

  /// the complex conjugation \f$ z \mapsto \bar z \f$: the reflection in the real diameter
  static Hyperbolic_isometry_2 complex_conjugation()
  {
    return Hyperbolic_isometry_2(Complex(FT(1)), Complex(), true);
  }

  /// the reflection in the diameter through the origin with direction angle `angle`
  static Hyperbolic_isometry_2 reflection_in_diameter(const FT& angle)
  {
    return Hyperbolic_isometry_2(std::polar(FT(1), angle), Complex(), true);
  }

  /// the reflection in the geodesic through `p` and `q`
  /// \pre `p != q`, both in the open unit disk
  static Hyperbolic_isometry_2 reflection_in_geodesic(const Complex& p, const Complex& q)
  {
    const Hyperbolic_isometry_2 to0 = translation_to_origin(p);
    const Complex q0 = to0.apply(q);
    return translation_from_origin(p) * reflection_in_diameter(std::arg(q0)) * to0;
  }
  /// @}

  /// \name Access
  /// @{

  /// the coefficient \f$ a \f$
  const Complex& a() const { return a_; }
  /// the coefficient \f$ b \f$
  const Complex& b() const { return b_; }
  /// `true` for M&ouml;bius maps, `false` for anti-M&ouml;bius maps
  bool is_orientation_preserving() const { return !reversing_; }
  /// @}

  /// \name Operations
  /// @{

  /// the image of `z`
  Complex apply(const Complex& z) const
  {
    const Complex w = reversing_ ? std::conj(z) : z;
    return internal::divide(a_ * w + b_, std::conj(b_) * w + std::conj(a_));
  }

  /// the image of a point given by Cartesian coordinates `(x, y)`
  template <class Point_2>
  Point_2 operator()(const Point_2& p) const
  {
    const Complex z(FT(CGAL::to_double(p.x())), FT(CGAL::to_double(p.y())));
    const Complex w = apply(z);
    return Point_2(w.real(), w.imag());
  }

  /// the composition `f * g` \f$ = f \circ g \f$ (apply `g` first)
  friend Hyperbolic_isometry_2 operator*(const Hyperbolic_isometry_2& f, const Hyperbolic_isometry_2& g)
  {
    // f(g(z)): if f reverses orientation, conj(M_g(u)) = M_{conj g}(conj u).
    const Complex ga = f.reversing_ ? std::conj(g.a_) : g.a_;
    const Complex gb = f.reversing_ ? std::conj(g.b_) : g.b_;
    // [a b; conj(b) conj(a)] matrices multiply within the same form.
    const Complex a = f.a_ * ga + f.b_ * std::conj(gb);
    const Complex b = f.a_ * gb + f.b_ * std::conj(ga);
    return Hyperbolic_isometry_2(a, b, f.reversing_ != g.reversing_, Raw());
  }

  /// the inverse map
  Hyperbolic_isometry_2 inverse() const
  {
    if(!reversing_)
      return Hyperbolic_isometry_2(std::conj(a_), -b_, false, Raw());
    return Hyperbolic_isometry_2(a_, -std::conj(b_), true, Raw());
  }

  /// the complex derivative at `z` of an orientation-preserving map
  /// (for an anti-M&ouml;bius map: the derivative with respect to \f$ \bar z \f$).
  Complex derivative(const Complex& z) const
  {
    const Complex w = reversing_ ? std::conj(z) : z;
    const Complex d = std::conj(b_) * w + std::conj(a_);
    return internal::divide(Complex(FT(1)), d * d);
  }

  /// `true` when `*this` and `other` are the same map up to `tolerance` on the normalized coefficients
  bool is_close(const Hyperbolic_isometry_2& other, const FT& tolerance = FT(1e-9)) const
  {
    if(reversing_ != other.reversing_)
      return false;
    using std::sqrt;
    const FT scale = sqrt(internal::squared_modulus(a_) + internal::squared_modulus(b_));
    const FT dplus = sqrt(internal::squared_modulus(a_ - other.a_) + internal::squared_modulus(b_ - other.b_));
    const FT dminus = sqrt(internal::squared_modulus(a_ + other.a_) + internal::squared_modulus(b_ + other.b_));
    return (dplus < dminus ? dplus : dminus) <= tolerance * scale;
  }

  /// `true` for the identity, up to `tolerance`
  bool is_identity(const FT& tolerance = FT(1e-9)) const { return is_close(identity(), tolerance); }
  /// @}

  /// writes the kind of map and its coefficients
  friend std::ostream& operator<<(std::ostream& os, const Hyperbolic_isometry_2& f)
  {
    return os << (f.reversing_ ? "anti-Mobius" : "Mobius") << " a=(" << f.a_.real() << "," << f.a_.imag()
              << ") b=(" << f.b_.real() << "," << f.b_.imag() << ")";
  }
};

} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_HYPERBOLIC_ISOMETRY_2_H
