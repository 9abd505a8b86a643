// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_COMPLEX_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_COMPLEX_H

#include <cmath>

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {
namespace internal {

// A minimal complex number over any field type NT with the usual operators
// (std::complex is only specified for float, double and long double, and
// we want the same code to run on extended-precision types later).
template <class NT>
struct Complex
{
  NT re, im;
  Complex() : re(0), im(0) {}
  Complex(const NT& r) : re(r), im(0) {}
  Complex(const NT& r, const NT& i) : re(r), im(i) {}

  friend Complex operator+(const Complex& a, const Complex& b) { return Complex(a.re + b.re, a.im + b.im); }
  friend Complex operator-(const Complex& a, const Complex& b) { return Complex(a.re - b.re, a.im - b.im); }
  friend Complex operator-(const Complex& a) { return Complex(-a.re, -a.im); }
  friend Complex operator*(const Complex& a, const Complex& b)
  { return Complex(a.re * b.re - a.im * b.im, a.re * b.im + a.im * b.re); }
  friend Complex operator*(const NT& s, const Complex& a) { return Complex(s * a.re, s * a.im); }
  friend Complex operator*(const Complex& a, const NT& s) { return Complex(s * a.re, s * a.im); }
  friend Complex operator/(const Complex& a, const NT& s) { return Complex(a.re / s, a.im / s); }
  friend Complex operator/(const Complex& a, const Complex& b)
  {
    const NT d = b.re * b.re + b.im * b.im;
    return Complex((a.re * b.re + a.im * b.im) / d, (a.im * b.re - a.re * b.im) / d);
  }
  Complex& operator+=(const Complex& b) { re += b.re; im += b.im; return *this; }
  Complex& operator-=(const Complex& b) { re -= b.re; im -= b.im; return *this; }
  friend bool operator==(const Complex& a, const Complex& b) { return a.re == b.re && a.im == b.im; }
  friend bool operator!=(const Complex& a, const Complex& b) { return !(a == b); }
};

template <class NT> inline Complex<NT> conj(const Complex<NT>& z) { return Complex<NT>(z.re, -z.im); }
// squared modulus |z|^2
template <class NT> inline NT norm(const Complex<NT>& z) { return z.re * z.re + z.im * z.im; }
template <class NT> inline NT abs(const Complex<NT>& z) { using std::hypot; return hypot(z.re, z.im); }
template <class NT> inline NT arg(const Complex<NT>& z) { using std::atan2; return atan2(z.im, z.re); }
template <class NT> inline Complex<NT> polar(const NT& r, const NT& theta)
{ using std::cos; using std::sin; return Complex<NT>(r * cos(theta), r * sin(theta)); }

} // namespace internal
} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_COMPLEX_H
