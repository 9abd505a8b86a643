// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_SINGLE_PRECISION_FACTOR_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_SINGLE_PRECISION_FACTOR_H

// Solves with a CHOLMOD supernodal factor of a complex Hermitian matrix, P A P^T = L L^*,
// whose entries have been rounded to single precision in place.
//
// Why: the preconditioner of the solver is applied 20-40 times per embedding, and each
// application reads the whole factor twice. Rounding L to float halves that memory; the
// arithmetic stays in double. The solve is then exactly (to double rounding) a solve with
// the fixed matrix L~ L~^*, L~ = fl32(L): a Hermitian positive definite operator (a Gram
// matrix with a positive diagonal) within a relative 6e-8 |L| |L^*| of A, so conjugate
// gradients keep their theory; only the preconditioner is a little different from A^-1.
//
// The loops are ours, single-threaded and in a fixed order of operations, so the result is
// the same whatever the number of threads; a version compiled for AVX2 (no FMA: no
// contraction, the same roundings) is taken where the processor has it, giving the same bits.

#ifdef CGAL_HOT_USE_CHOLMOD

#include <cholmod.h>

#include <complex>
#include <cstddef>
#include <cstring>
#include <vector>

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {
namespace internal {

// The parts of a supernodal factor the solves read (CHOLMOD's layout: supernode q holds
// the columns super[q] .. super[q+1]-1 as a dense column-major block of pi[q+1]-pi[q] rows,
// their row indices s[pi[q]] ..., values from px[q]; the diagonal block on top)
struct Supernodal_float_factor
{
  int n = 0, nsuper = 0;
  const int *super = nullptr, *pi = nullptr, *px = nullptr, *s = nullptr, *perm = nullptr;
  const float* x = nullptr; // interleaved real and imaginary parts
};

// Rounds the values of a complex, double, supernodal factor to float in place: afterwards
// the first half of F->x holds interleaved floats (CHOLMOD must not solve with F any more;
// a new numeric factorisation overwrites the values, it does not read them).
inline bool round_supernodal_factor_to_float(cholmod_factor* F, Supernodal_float_factor& out)
{
  if(F == nullptr || !F->is_super || F->xtype != CHOLMOD_COMPLEX || F->dtype != CHOLMOD_DOUBLE || F->x == nullptr ||
     F->Perm == nullptr || F->itype != CHOLMOD_INT)
    return false;
  const int* px = static_cast<const int*>(F->px);
  const std::size_t count = 2 * static_cast<std::size_t>(px[F->nsuper]); // doubles
  char* bytes = static_cast<char*>(F->x);
  // in chunks, through memcpy (the same bytes change type): a float written at position i
  // only overwrites doubles at positions below i, already read
  const std::size_t chunk = 1024;
  double d[chunk];
  float f[chunk];
  for(std::size_t i = 0; i < count; i += chunk) {
    const std::size_t m = count - i < chunk ? count - i : chunk;
    std::memcpy(d, bytes + i * sizeof(double), m * sizeof(double));
    for(std::size_t k = 0; k < m; ++k)
      f[k] = static_cast<float>(d[k]);
    std::memcpy(bytes + i * sizeof(float), f, m * sizeof(float));
  }
  out.n = static_cast<int>(F->n);
  out.nsuper = static_cast<int>(F->nsuper);
  out.super = static_cast<const int*>(F->super);
  out.pi = static_cast<const int*>(F->pi);
  out.px = px;
  out.s = static_cast<const int*>(F->s);
  out.perm = static_cast<const int*>(F->Perm);
  out.x = static_cast<const float*>(F->x);
  return true;
}

namespace supernodal_detail {

// y := L~^-1 y (y: interleaved complex, in the factor's order; w: workspace of 2n)
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
inline void forward(const Supernodal_float_factor& F, double* Y, double* W)
{
  for(int q = 0; q < F.nsuper; ++q) {
    const int k1 = F.super[q], nc = F.super[q + 1] - k1, nr = F.pi[q + 1] - F.pi[q];
    const float* X = F.x + 2 * static_cast<std::size_t>(F.px[q]);
    const int* rows = F.s + F.pi[q];
    const std::size_t ld = 2 * static_cast<std::size_t>(nr);
    for(int i = 0; i < nc; ++i) {
      W[2 * i] = Y[2 * (k1 + i)];
      W[2 * i + 1] = Y[2 * (k1 + i) + 1];
    }
    for(int i = nc; i < nr; ++i)
      W[2 * i] = W[2 * i + 1] = 0.0;
    int j = 0;
    for(; j + 4 <= nc; j += 4) { // four columns at a time: one pass over the rows below
      const float* c0 = X + j * ld;
      for(int jj = j; jj < j + 4; ++jj) { // the four columns' triangle
        const float* c = X + jj * ld;
        const double d = c[2 * jj], a = W[2 * jj] / d, b = W[2 * jj + 1] / d;
        W[2 * jj] = a;
        W[2 * jj + 1] = b;
        for(int i = jj + 1; i < j + 4; ++i) {
          const double cr = c[2 * i], ci = c[2 * i + 1];
          W[2 * i] -= cr * a - ci * b;
          W[2 * i + 1] -= cr * b + ci * a;
        }
      }
      const float *c1 = c0 + ld, *c2 = c1 + ld, *c3 = c2 + ld;
      const double a0 = W[2 * j], b0 = W[2 * j + 1], a1 = W[2 * j + 2], b1 = W[2 * j + 3];
      const double a2 = W[2 * j + 4], b2 = W[2 * j + 5], a3 = W[2 * j + 6], b3 = W[2 * j + 7];
      for(int i = j + 4; i < nr; ++i) {
        const std::size_t re = 2 * static_cast<std::size_t>(i), im = re + 1;
        double r = W[re], m = W[im];
        r -= double(c0[re]) * a0 - double(c0[im]) * b0;
        m -= double(c0[re]) * b0 + double(c0[im]) * a0;
        r -= double(c1[re]) * a1 - double(c1[im]) * b1;
        m -= double(c1[re]) * b1 + double(c1[im]) * a1;
        r -= double(c2[re]) * a2 - double(c2[im]) * b2;
        m -= double(c2[re]) * b2 + double(c2[im]) * a2;
        r -= double(c3[re]) * a3 - double(c3[im]) * b3;
        m -= double(c3[re]) * b3 + double(c3[im]) * a3;
        W[re] = r;
        W[im] = m;
      }
    }
    for(; j < nc; ++j) {
      const float* c = X + j * ld;
      const double d = c[2 * j], a = W[2 * j] / d, b = W[2 * j + 1] / d;
      W[2 * j] = a;
      W[2 * j + 1] = b;
      for(int i = j + 1; i < nr; ++i) {
        const double cr = c[2 * i], ci = c[2 * i + 1];
        W[2 * i] -= cr * a - ci * b;
        W[2 * i + 1] -= cr * b + ci * a;
      }
    }
    for(int i = 0; i < nc; ++i) {
      Y[2 * (k1 + i)] = W[2 * i];
      Y[2 * (k1 + i) + 1] = W[2 * i + 1];
    }
    for(int i = nc; i < nr; ++i) {
      Y[2 * rows[i]] += W[2 * i];
      Y[2 * rows[i] + 1] += W[2 * i + 1];
    }
  }
}

// y := L~^-* y
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
inline void backward(const Supernodal_float_factor& F, double* Y, double* W)
{
  for(int q = F.nsuper - 1; q >= 0; --q) {
    const int k1 = F.super[q], nc = F.super[q + 1] - k1, nr = F.pi[q + 1] - F.pi[q];
    const float* X = F.x + 2 * static_cast<std::size_t>(F.px[q]);
    const int* rows = F.s + F.pi[q];
    for(int i = 0; i < nc; ++i) {
      W[2 * i] = Y[2 * (k1 + i)];
      W[2 * i + 1] = Y[2 * (k1 + i) + 1];
    }
    for(int i = nc; i < nr; ++i) {
      W[2 * i] = Y[2 * rows[i]];
      W[2 * i + 1] = Y[2 * rows[i] + 1];
    }
    for(int j = nc - 1; j >= 0; --j) {
      const float* c = X + 2 * static_cast<std::size_t>(j) * nr;
      // sum over the rows below j of conj(L_ij) w_i, in four partial sums (a fixed order)
      double r[4] = {0, 0, 0, 0}, m[4] = {0, 0, 0, 0};
      int i = j + 1;
      for(; i + 4 <= nr; i += 4)
        for(int l = 0; l < 4; ++l) {
          const double cr = c[2 * (i + l)], ci = c[2 * (i + l) + 1], wr = W[2 * (i + l)], wi = W[2 * (i + l) + 1];
          r[l] += cr * wr + ci * wi;
          m[l] += cr * wi - ci * wr;
        }
      for(int l = 0; i < nr; ++i, ++l) {
        const double cr = c[2 * i], ci = c[2 * i + 1], wr = W[2 * i], wi = W[2 * i + 1];
        r[l] += cr * wr + ci * wi;
        m[l] += cr * wi - ci * wr;
      }
      const double d = c[2 * j];
      W[2 * j] = (W[2 * j] - ((r[0] + r[1]) + (r[2] + r[3]))) / d;
      W[2 * j + 1] = (W[2 * j + 1] - ((m[0] + m[1]) + (m[2] + m[3]))) / d;
    }
    for(int i = 0; i < nc; ++i) {
      Y[2 * (k1 + i)] = W[2 * i];
      Y[2 * (k1 + i) + 1] = W[2 * i + 1];
    }
  }
}

// y := L~^-1 y; with `lead` >= 0 the entries from `lead` on are then set to 0 (the leading
// block's solve: see Laplacian_factorization::solve_leading); then y := L~^-* y
inline void solve_generic(const Supernodal_float_factor& F, double* Y, double* W, int lead)
{
  forward(F, Y, W);
  if(lead >= 0)
    std::memset(Y + 2 * static_cast<std::size_t>(lead), 0, 2 * sizeof(double) * static_cast<std::size_t>(F.n - lead));
  backward(F, Y, W);
}

#if defined(__GNUC__) && (defined(__x86_64__) || defined(__i386__))
#define CGAL_HOT_SUPERNODAL_AVX2 1
__attribute__((target("avx2"))) inline void solve_avx2(const Supernodal_float_factor& F, double* Y, double* W, int lead)
{
  forward(F, Y, W);
  if(lead >= 0)
    std::memset(Y + 2 * static_cast<std::size_t>(lead), 0, 2 * sizeof(double) * static_cast<std::size_t>(F.n - lead));
  backward(F, Y, W);
}
inline bool has_avx2()
{
  static const bool yes = __builtin_cpu_supports("avx2");
  return yes;
}
#endif

} // namespace supernodal_detail

// x = P^T L~^-* L~^-1 P b (x and b of size n); with `lead` >= 0: b and x of size lead, the
// solve with the leading lead x lead block (P keeps those rows first). y, w: workspace.
// `avx2`: false forces the portable loops (tests compare both).
template <class Vector>
void solve_with_float_factor(const Supernodal_float_factor& F, const Vector& b, Vector& x, int lead,
                             std::vector<double>& y, std::vector<double>& w, bool avx2 = true)
{
  const int n = F.n;
  y.assign(2 * static_cast<std::size_t>(n), 0.0);
  w.resize(2 * static_cast<std::size_t>(n));
  const int m = lead >= 0 ? lead : n;
  for(int k = 0; k < m; ++k) {
    const std::complex<double> v = b[F.perm[k]];
    y[2 * k] = v.real();
    y[2 * k + 1] = v.imag();
  }
#ifdef CGAL_HOT_SUPERNODAL_AVX2
  if(avx2 && supernodal_detail::has_avx2())
    supernodal_detail::solve_avx2(F, y.data(), w.data(), lead);
  else
#endif
    supernodal_detail::solve_generic(F, y.data(), w.data(), lead);
  (void)avx2;
  x.resize(m);
  for(int k = 0; k < m; ++k)
    x[F.perm[k]] = std::complex<double>(y[2 * k], y[2 * k + 1]);
}

} // namespace internal
} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#endif // CGAL_HOT_USE_CHOLMOD

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_SINGLE_PRECISION_FACTOR_H
