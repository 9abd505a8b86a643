// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_SIMPLICIAL_FLOAT_FACTOR_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_SIMPLICIAL_FLOAT_FACTOR_H

// Solves with Eigen's simplicial LDL^* factor of a complex Hermitian matrix,
// P A P^T = L D L^*, its L rounded to single precision: the small meshes' counterpart of
// single_precision_factor.h (CHOLMOD's supernodal factors of 50K rows and more).
//
// The preconditioner's solves (20 to 90 per embedding, more with many landmarks) read the
// whole of L twice; its entries as float pairs and 32-bit row indices take 12 bytes instead
// of 20. The arithmetic is in double, D is kept in double: each solve is, to double
// rounding, exactly one with L~ D L~^*, L~ = fl32(L), a Hermitian positive definite matrix
// (D > 0) within a relative 6e-8 |L| D |L^*| of A, so conjugate gradients keep their
// guarantees. One thread, a fixed order of operations, no BLAS: the same bits on every
// machine, as Eigen's own solve.

#include <Eigen/Core>
#include <Eigen/SparseCholesky>

#include <complex>
#include <vector>

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {
namespace internal {

class Simplicial_float_factor
{
public:
  typedef std::complex<double> C;
  typedef Eigen::SparseMatrix<C> Matrix;

  // from a successful factorisation `f` (L strictly lower, column by column; D real)
  template <class Ordering>
  void assign(const Eigen::SimplicialLDLT<Matrix, Eigen::Lower, Ordering>& f)
  {
    const Matrix& L = f.matrixL().nestedExpression();
    n_ = static_cast<int>(L.cols());
    outer_.assign(L.outerIndexPtr(), L.outerIndexPtr() + n_ + 1);
    const int nnz = outer_[n_] - outer_[0];
    inner_.resize(nnz);
    re_im_.resize(2 * static_cast<std::size_t>(nnz));
    // (Eigen's factor is compressed; were it not, each column ends at outer + innerNonZeros)
    for(int j = 0; j < n_; ++j) {
      const int b = L.outerIndexPtr()[j];
      const int e = L.isCompressed() ? L.outerIndexPtr()[j + 1] : b + L.innerNonZeroPtr()[j];
      outer_[j + 1] = outer_[j] + (e - b);
      for(int p = b, q = outer_[j]; p < e; ++p, ++q) {
        inner_[q] = L.innerIndexPtr()[p];
        re_im_[2 * q] = static_cast<float>(L.valuePtr()[p].real());
        re_im_[2 * q + 1] = static_cast<float>(L.valuePtr()[p].imag());
      }
    }
    const Eigen::Matrix<C, Eigen::Dynamic, 1> D = f.vectorD(); // (a copy: Eigen returns it by value)
    inv_d_.resize(n_);
    for(int j = 0; j < n_; ++j)
      inv_d_[j] = 1.0 / D[j].real();
    perm_ = f.permutationP().indices();
  }

  bool empty() const { return n_ == 0 && perm_.size() == 0; }
  void clear()
  {
    n_ = 0;
    outer_.clear();
    inner_.clear();
    re_im_.clear();
    inv_d_.clear();
    perm_.resize(0);
  }

  // x = P^T L~^-* D^-1 L~^-1 P b
  void solve(const Eigen::Matrix<C, Eigen::Dynamic, 1>& b, Eigen::Matrix<C, Eigen::Dynamic, 1>& x) const
  {
    const int n = n_;
    y_.resize(2 * static_cast<std::size_t>(n));
    double* y = y_.data();
    if(perm_.size() == n) // y = P b: (P b)[perm[i]] = b[i]
      for(int i = 0; i < n; ++i) {
        y[2 * perm_[i]] = b[i].real();
        y[2 * perm_[i] + 1] = b[i].imag();
      }
    else
      for(int i = 0; i < n; ++i) {
        y[2 * i] = b[i].real();
        y[2 * i + 1] = b[i].imag();
      }
    const int* outer = outer_.data();
    const int* inner = inner_.data();
    const float* v = re_im_.data();
    // L~ y = y (unit diagonal), column by column: y_i -= l_ij y_j
    for(int j = 0; j < n; ++j) {
      const double yr = y[2 * j], yi = y[2 * j + 1];
      for(int p = outer[j]; p < outer[j + 1]; ++p) {
        const double lr = v[2 * p], li = v[2 * p + 1];
        double* t = y + 2 * inner[p];
        t[0] -= lr * yr - li * yi;
        t[1] -= lr * yi + li * yr;
      }
    }
    for(int j = 0; j < n; ++j) {
      y[2 * j] *= inv_d_[j];
      y[2 * j + 1] *= inv_d_[j];
    }
    // L~^* y = y: y_j -= sum_i conj(l_ij) y_i, from the last column
    for(int j = n - 1; j >= 0; --j) {
      double sr = y[2 * j], si = y[2 * j + 1];
      for(int p = outer[j]; p < outer[j + 1]; ++p) {
        const double lr = v[2 * p], li = v[2 * p + 1];
        const double* t = y + 2 * inner[p];
        sr -= lr * t[0] + li * t[1];
        si -= lr * t[1] - li * t[0];
      }
      y[2 * j] = sr;
      y[2 * j + 1] = si;
    }
    x.resize(n);
    if(perm_.size() == n) // x = P^T y
      for(int i = 0; i < n; ++i)
        x[i] = C(y[2 * perm_[i]], y[2 * perm_[i] + 1]);
    else
      for(int i = 0; i < n; ++i)
        x[i] = C(y[2 * i], y[2 * i + 1]);
  }

private:
  int n_ = 0;
  std::vector<int> outer_, inner_;
  std::vector<float> re_im_; // interleaved real and imaginary parts
  std::vector<double> inv_d_;
  Eigen::VectorXi perm_;
  mutable std::vector<double> y_;
};

} // namespace internal
} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_SIMPLICIAL_FLOAT_FACTOR_H
