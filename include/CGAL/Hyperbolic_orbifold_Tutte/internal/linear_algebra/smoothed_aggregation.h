// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_LINEAR_ALGEBRA_SMOOTHED_AGGREGATION_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_LINEAR_ALGEBRA_SMOOTHED_AGGREGATION_H

#include <CGAL/disable_warnings.h>

/// \file smoothed_aggregation.h
// Algebraic multigrid by smoothed aggregation (Vanek, Mandel and Brezina, "Algebraic multigrid
// by smoothed aggregation for second and fourth order elliptic problems", Computing 56, 1996)
// for the Hermitian positive definite Laplacians of the solver: the real Laplacian of the
// interior (the border fixed) and the complex connection Laplacian, whose off-diagonal entries
// are -w conj(rho_a) rho_b with |rho| = 1. Its work and memory are linear in the size, where a
// sparse factorisation's work grows like n^1.5 on a surface.
//
// Per level: aggregates of strongly connected nodes (the paper's three phases); a tentative
// prolongator with one column per aggregate holding the near-kernel on it (real: the constant,
// carried to the coarse levels as the columns' norms; complex: the section that makes each
// strong edge's energy w |u_a - t_ab u_b|^2 vanish, found by a search from the aggregate's
// root, t_ab the phase of -a_ab); the prolongator smoothed by one damped Jacobi step,
// P = (I - 4/3 D^-1 A / lambda_max) P0; the coarse matrix P^* A P (Galerkin: Hermitian positive
// definite again). The coarsest level is factored (sparse LDL^T).
//
// The cycle is a V-cycle with the same Chebyshev polynomial in D^-1 A (degree `smoothing`) as
// pre- and post-smoother. That smoother is Hermitian in the A inner product and contracting
// (its interval covers D^-1 A's spectrum: an upper bound by power iteration, capped by
// Gershgorin's), so the cycle is a Hermitian positive definite preconditioner for conjugate
// gradients. Products with the matrices run in parallel (TBB) over rows.

#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#endif

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdint>
#include <memory>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {
namespace internal {

// f(begin, end) over [0, n) in blocks of about `grain`: in parallel with TBB, else one call
template <class F>
void for_each_row_block(Eigen::Index n, Eigen::Index grain, const F& f)
{
#ifdef CGAL_LINKED_WITH_TBB
  tbb::parallel_for(tbb::blocked_range<Eigen::Index>(0, n, grain),
                    [&](const tbb::blocked_range<Eigen::Index>& r) { f(r.begin(), r.end()); });
#else
  (void)grain;
  f(Eigen::Index(0), n);
#endif
}

// y_i = sum over the stored entries k of outer-index i of val[k] x[inner[k]], in parallel over
// i, each sum in storage order (the same bits on any number of threads). For a row-major
// matrix y = A x; for a column-major one y = A^T x (= A x when A is symmetric). `nnz`: the
// entries per outer index of an uncompressed matrix (else null).
// (store(i, y_i) receives each sum: the caller's use of it fused into the same pass)
template <class Entry, class V, class Store>
void sparse_outer_products(Eigen::Index n, const int* outer, const int* nnz, const int* inner, const Entry* val, const V& x,
                           const Store& store)
{
  for_each_row_block(n, 8192, [&](Eigen::Index b, Eigen::Index e) {
    for(Eigen::Index i = b; i < e; ++i) {
      const int end = nnz ? outer[i] + nnz[i] : outer[i + 1];
      typename V::Scalar s(0);
      for(int k = outer[i]; k < end; ++k)
        s += val[k] * x[inner[k]];
      store(i, s);
    }
  });
}

template <class Entry, class V>
void sparse_outer_products(Eigen::Index n, const int* outer, const int* nnz, const int* inner, const Entry* val, const V& x, V& y)
{
  y.resize(n);
  sparse_outer_products(n, outer, nnz, inner, val, x, [&y](Eigen::Index i, const typename V::Scalar& s) { y[i] = s; });
}

// f(i) for i in [0, n), in parallel
template <class F>
void for_each_row(Eigen::Index n, const F& f)
{
  for_each_row_block(n, 16384, [&](Eigen::Index b, Eigen::Index e) {
    for(Eigen::Index i = b; i < e; ++i)
      f(i);
  });
}

// Scalar: the matrix's entries; Value: the vectors' (complex with real entries: a pair of
// real vectors, solved at once at the price of one pass over the matrices)
template <class Scalar, class Value = Scalar>
class Smoothed_aggregation
{
public:
  typedef Eigen::SparseMatrix<Scalar, Eigen::RowMajor, int> Matrix;
  typedef Eigen::Matrix<Value, Eigen::Dynamic, 1> Vector;
  typedef Eigen::Matrix<Scalar, Eigen::Dynamic, 1> Scalar_vector;
  typedef Eigen::VectorXd Real_vector;

  struct Options
  {
    Eigen::Index coarsest_rows = 3000; // factored at or below this size
    int max_levels = 16;
    double strength = 0.08;            // strong connection: |a_ij| > strength sqrt(a_ii a_jj), halved per level
    int smoothing = 2;                 // degree of the Chebyshev smoother
    double smoothing_range = 30;       // the smoother's interval: [lambda_max / range, lambda_max]
  };

  // Builds the hierarchy of A (Hermitian positive definite, both triangles stored). False if
  // the coarsest level does not factor as definite.
  bool compute(Matrix A, const Options& opt = Options())
  {
    opt_ = opt;
    levels_.clear();
    levels_.reserve(opt.max_levels); // (no reallocation: a level's matrices stay where they are)
    coarse_.reset();
    A.makeCompressed();
    levels_.emplace_back();
    levels_.back().A = std::move(A);
    Real_vector B = Real_vector::Ones(levels_.back().A.rows()); // the near-kernel's magnitudes
    double theta = opt.strength;
    while(levels_.back().A.rows() > opt.coarsest_rows && static_cast<int>(levels_.size()) < opt.max_levels) {
      Level& L = levels_.back();
      set_diagonal(L);
      std::vector<int> agg;
      const int nc = aggregate(L.A, L.inv_diag, theta, agg);
      if(nc <= 0 || nc >= L.A.rows() * 0.85) // (no coarsening left: factor this level)
        break;
      Real_vector Bc;
      std::vector<Scalar> p0; // P0's entry in each row (column agg[i])
      tentative_prolongator(L.A, L.inv_diag, theta, agg, nc, B, p0, Bc);
      L.lambda = spectral_bound(L);
      // P = (I - omega D^-1 A) P0
      const double omega = (4.0 / 3.0) / L.lambda;
      const Matrix& A = L.A;
      const Real_vector& inv_diag = L.inv_diag;
      L.P = build_rows(A.rows(), nc, [&](Eigen::Index i, const auto& add) {
        add(agg[i], p0[i]);
        const double s = -omega * inv_diag[i];
        for(typename Matrix::InnerIterator it(A, i); it; ++it)
          add(agg[it.index()], s * it.value() * p0[it.index()]);
      });
      L.R = L.P.adjoint();
      L.R.makeCompressed();
      Matrix Ac = multiply(L.R, multiply(L.A, L.P));
      Ac.makeCompressed();
      levels_.emplace_back();
      levels_.back().A = std::move(Ac);
      B.swap(Bc);
      theta *= 0.5;
    }
    Level& last = levels_.back();
    set_diagonal(last);
    coarse_.reset(new Coarse_solver);
    coarse_->compute(Eigen::SparseMatrix<Scalar>(last.A));
    if(coarse_->info() != Eigen::Success)
      return false;
    for(Eigen::Index i = 0; i < coarse_->vectorD().size(); ++i)
      if(!(std::real(coarse_->vectorD()[i]) > 0))
        return false;
    for(Level& L : levels_) {
      L.b.resize(L.A.rows());
      L.x.resize(L.A.rows());
      L.res.resize(L.A.rows());
      L.t.resize(L.A.rows());
      L.d.resize(L.A.rows());
    }
    return true;
  }

  std::size_t number_of_levels() const { return levels_.size(); }
  Eigen::Index rows(std::size_t level) const { return levels_[level].A.rows(); }
  // the stored entries of all levels' matrices over the finest's
  double operator_complexity() const
  {
    double s = 0;
    for(const Level& L : levels_)
      s += static_cast<double>(L.A.nonZeros());
    return levels_.empty() ? 0 : s / static_cast<double>(levels_[0].A.nonZeros());
  }
  const Matrix& matrix() const { return levels_[0].A; }

  // z = M r, one V-cycle from zero (M: the preconditioner, Hermitian positive definite).
  // Not reentrant: the levels' work vectors are shared.
  void apply(const Vector& r, Vector& z) const
  {
    const Level& L = levels_[0];
    const Eigen::Index n = L.A.rows();
    for_each_row(n, [&](Eigen::Index i) { L.b[i] = r[i]; }); // (L.b has n rows: see compute)
    cycle(0);
    z.resize(n);
    for_each_row(n, [&](Eigen::Index i) { z[i] = L.x[i]; });
  }

  // Conjugate gradients preconditioned by the V-cycle, from x (resized to zero if its size is
  // not b's), until |b - A x| <= tolerance |b|. Returns the iterations, or -1 if they ran out
  // or broke down.
  int solve(const Vector& b, Vector& x, double tolerance, int max_iterations) const
  {
    const Matrix& A = levels_[0].A;
    const Eigen::Index n = A.rows();
    if(x.size() != n)
      x = Vector::Zero(n);
    Vector& r = cg_[0]; // (kept between solves: a fresh vector of this size costs its pages' first touch)
    Vector& z = cg_[1];
    Vector& p = cg_[2];
    Vector& q = cg_[3];
    multiply(A, x, q);
    r = b - q;
    const double bnorm = b.norm();
    if(!(bnorm > 0)) {
      x.setZero();
      return 0;
    }
    if(r.norm() <= tolerance * bnorm)
      return 0;
    apply(r, z);
    p = z;
    double rz = std::real(r.dot(z));
    for(int it = 1; it <= max_iterations; ++it) {
      multiply(A, p, q);
      const double pq = std::real(p.dot(q));
      if(!(pq > 0) || !(rz > 0))
        return -1;
      const double alpha = rz / pq;
      x += alpha * p;
      r -= alpha * q;
      const double rn = r.norm();
      if(!std::isfinite(rn))
        return -1;
      if(rn <= tolerance * bnorm)
        return it;
      apply(r, z);
      const double rz1 = std::real(r.dot(z));
      p = z + (rz1 / rz) * p;
      rz = rz1;
    }
    return -1;
  }

  // y = A x, in parallel over A's rows
  template <class V>
  static void multiply(const Matrix& A, const V& x, V& y)
  {
    sparse_outer_products(A.rows(), A.outerIndexPtr(), A.innerNonZeroPtr(), A.innerIndexPtr(), A.valuePtr(), x, y);
  }
  // store(i, (A x)_i), in parallel over A's rows
  template <class V, class Store>
  static void multiply_into(const Matrix& A, const V& x, const Store& store)
  {
    sparse_outer_products(A.rows(), A.outerIndexPtr(), A.innerNonZeroPtr(), A.innerIndexPtr(), A.valuePtr(), x, store);
  }

private:
  typedef Eigen::SimplicialLDLT<Eigen::SparseMatrix<Scalar>, Eigen::Lower, Eigen::AMDOrdering<int> > Coarse_solver;

  struct Level
  {
    Matrix A, P, R;          // P: this level's unknowns from the next level's; R = P^*
    Real_vector inv_diag;
    double lambda = 2;       // upper bound of the spectrum of D^-1 A
    mutable Vector b, x, res, t, d; // work vectors of the cycle
  };

  static double squared_modulus(const Scalar& a) { return std::norm(a); }

  void set_diagonal(Level& L) const
  {
    const Eigen::Index n = L.A.rows();
    L.inv_diag.resize(n);
    for(Eigen::Index i = 0; i < n; ++i) {
      const double d = std::real(L.A.coeff(i, i));
      L.inv_diag[i] = d > 0 ? 1.0 / d : 0.0;
    }
  }

  // The m x nc matrix whose row i is what row(i, add) adds up (add(j, value): value into
  // column j), built in parallel over chunks of rows (Gustavson's row-by-row scheme)
  template <class Row>
  static Matrix build_rows(Eigen::Index m, Eigen::Index nc, const Row& row)
  {
    const Eigen::Index chunk = 4096;
    const Eigen::Index nchunks = (m + chunk - 1) / chunk;
    std::vector<std::vector<int> > cols(nchunks);
    std::vector<std::vector<Scalar> > vals(nchunks);
    std::vector<std::vector<int> > counts(nchunks);
    struct Scratch
    {
      std::vector<int> mark;
      std::vector<Scalar> acc;
      std::vector<int> touched;
    };
#ifdef CGAL_LINKED_WITH_TBB
    tbb::enumerable_thread_specific<Scratch> scratch; // (one per thread, not per task)
#else
    struct { Scratch s; Scratch& local() { return s; } } scratch;
#endif
    for_each_row_block(nchunks, 1, [&](Eigen::Index c0, Eigen::Index c1) {
      Scratch& sc = scratch.local();
      if(sc.mark.empty()) {
        sc.mark.assign(nc, -1);
        sc.acc.assign(nc, Scalar(0));
      }
      for(Eigen::Index c = c0; c < c1; ++c) {
        const Eigen::Index i0 = c * chunk, i1 = std::min(m, i0 + chunk);
        for(Eigen::Index i = i0; i < i1; ++i) {
          sc.touched.clear();
          row(i, [&](Eigen::Index jj, const Scalar& v) {
            const int j = static_cast<int>(jj);
            if(sc.mark[j] != static_cast<int>(i)) {
              sc.mark[j] = static_cast<int>(i);
              sc.acc[j] = Scalar(0);
              sc.touched.push_back(j);
            }
            sc.acc[j] += v;
          });
          std::sort(sc.touched.begin(), sc.touched.end());
          for(int j : sc.touched) {
            cols[c].push_back(j);
            vals[c].push_back(sc.acc[j]);
          }
          counts[c].push_back(static_cast<int>(sc.touched.size()));
        }
      }
    });
    std::size_t total = 0;
    for(const auto& cc : cols)
      total += cc.size();
    Matrix Z(m, nc);
    Z.resizeNonZeros(static_cast<Eigen::Index>(total));
    int* outer = Z.outerIndexPtr();
    Eigen::Index r = 0;
    std::size_t pos = 0;
    outer[0] = 0;
    for(Eigen::Index c = 0; c < nchunks; ++c) {
      std::copy(cols[c].begin(), cols[c].end(), Z.innerIndexPtr() + pos);
      std::copy(vals[c].begin(), vals[c].end(), Z.valuePtr() + pos);
      for(int k : counts[c]) {
        pos += static_cast<std::size_t>(k);
        outer[++r] = static_cast<int>(pos);
      }
      std::vector<int>().swap(cols[c]);
      std::vector<Scalar>().swap(vals[c]);
    }
    return Z;
  }

  // X Y
  static Matrix multiply(const Matrix& X, const Matrix& Y)
  {
    return build_rows(X.rows(), Y.cols(), [&](Eigen::Index i, const auto& add) {
      for(typename Matrix::InnerIterator a(X, i); a; ++a)
        for(typename Matrix::InnerIterator b(Y, a.index()); b; ++b)
          add(b.index(), a.value() * b.value());
    });
  }

  static bool strong(const Scalar& a, const Real_vector& inv_diag, Eigen::Index i, Eigen::Index j, double theta)
  {
    // |a_ij|^2 > theta^2 a_ii a_jj
    return squared_modulus(a) * inv_diag[i] * inv_diag[j] > theta * theta;
  }

  // The aggregates (agg[i]: aggregate of node i), returns their number
  static int aggregate(const Matrix& A, const Real_vector& inv_diag, double theta, std::vector<int>& agg)
  {
    const Eigen::Index n = A.rows();
    agg.assign(n, -1);
    int nc = 0;
    // 1. a node and its strong neighbours, all free
    for(Eigen::Index i = 0; i < n; ++i) {
      if(agg[i] >= 0)
        continue;
      bool free = true, any = false;
      for(typename Matrix::InnerIterator it(A, i); it && free; ++it)
        if(it.index() != i && strong(it.value(), inv_diag, i, it.index(), theta)) {
          any = true;
          free = agg[it.index()] < 0;
        }
      if(!free || !any)
        continue;
      agg[i] = nc;
      for(typename Matrix::InnerIterator it(A, i); it; ++it)
        if(it.index() != i && strong(it.value(), inv_diag, i, it.index(), theta))
          agg[it.index()] = nc;
      ++nc;
    }
    // 2. the others join the aggregate of phase 1 they are most strongly connected to
    const std::vector<int> first(agg);
    for(Eigen::Index i = 0; i < n; ++i) {
      if(agg[i] >= 0)
        continue;
      double best = 0;
      for(typename Matrix::InnerIterator it(A, i); it; ++it)
        if(it.index() != i && first[it.index()] >= 0 && strong(it.value(), inv_diag, i, it.index(), theta)) {
          const double s = squared_modulus(it.value()) * inv_diag[it.index()];
          if(s > best) {
            best = s;
            agg[i] = first[it.index()];
          }
        }
    }
    // 3. what is left: a node and its free strong neighbours (a node alone if none)
    for(Eigen::Index i = 0; i < n; ++i) {
      if(agg[i] >= 0)
        continue;
      agg[i] = nc;
      for(typename Matrix::InnerIterator it(A, i); it; ++it)
        if(it.index() != i && agg[it.index()] < 0 && strong(it.value(), inv_diag, i, it.index(), theta))
          agg[it.index()] = nc;
      ++nc;
    }
    return nc;
  }

  // how the near-kernel's phase passes from node i to its strong neighbour j (a_ij = A(i, j)):
  // 1 for real matrices, the phase of -conj(a_ij) for complex ones
  static Scalar transport(const Scalar& a_ij, std::false_type) { (void)a_ij; return Scalar(1); }
  static Scalar transport(const Scalar& a_ij, std::true_type)
  {
    const double m = std::abs(a_ij);
    return m > 0 ? -std::conj(a_ij) / m : Scalar(1);
  }

  // P0: one column per aggregate, the near-kernel on it (norm 1): p0[i] in row i, column
  // agg[i]; Bc the columns' norms
  static void tentative_prolongator(const Matrix& A, const Real_vector& inv_diag, double theta, const std::vector<int>& agg,
                                    int nc, const Real_vector& B, std::vector<Scalar>& p0, Real_vector& Bc)
  {
    typedef std::integral_constant<bool, !std::is_same<Scalar, typename Eigen::NumTraits<Scalar>::Real>::value> Is_complex;
    const Eigen::Index n = A.rows();
    Scalar_vector u(n);
    std::vector<char> seen(n, 0);
    std::vector<Eigen::Index> queue;
    for(Eigen::Index s = 0; s < n; ++s) { // searches from each aggregate's first node
      if(seen[s])
        continue;
      seen[s] = 1;
      u[s] = Scalar(B[s]);
      queue.assign(1, s);
      for(std::size_t q = 0; q < queue.size(); ++q) {
        const Eigen::Index i = queue[q];
        for(typename Matrix::InnerIterator it(A, i); it; ++it) {
          const Eigen::Index j = it.index();
          if(j == i || seen[j] || agg[j] != agg[i] || !strong(it.value(), inv_diag, i, j, theta))
            continue;
          seen[j] = 1;
          const double mi = std::abs(u[i]);
          u[j] = (mi > 0 ? u[i] / mi : Scalar(1)) * transport(it.value(), Is_complex()) * B[j];
          queue.push_back(j);
        }
      }
    }
    Bc = Real_vector::Zero(nc);
    for(Eigen::Index i = 0; i < n; ++i)
      Bc[agg[i]] += squared_modulus(u[i]);
    for(int c = 0; c < nc; ++c)
      Bc[c] = std::sqrt(Bc[c]);
    p0.resize(n);
    for(Eigen::Index i = 0; i < n; ++i)
      p0[i] = Bc[agg[i]] > 0 ? u[i] / Bc[agg[i]] : Scalar(0);
  }

  // an upper bound of the spectrum of D^-1 A: 1.15 times the power iteration's estimate,
  // at most Gershgorin's bound
  static double spectral_bound(const Level& L)
  {
    const Matrix& A = L.A;
    const Eigen::Index n = A.rows();
    double gershgorin = 0;
    for(Eigen::Index i = 0; i < n; ++i) {
      double s = 0;
      for(typename Matrix::InnerIterator it(A, i); it; ++it)
        s += std::abs(it.value());
      gershgorin = std::max(gershgorin, s * L.inv_diag[i]);
    }
    // power iteration on D^-1/2 A D^-1/2 (Hermitian), from a fixed pseudo-random start
    const Real_vector s = L.inv_diag.cwiseSqrt();
    Scalar_vector v(n), w(n);
    std::uint64_t seed = 0x9e3779b97f4a7c15ull;
    for(Eigen::Index i = 0; i < n; ++i) {
      seed = seed * 6364136223846793005ull + 1442695040888963407ull;
      v[i] = Scalar(static_cast<double>(seed >> 11) / 9007199254740992.0 - 0.5);
    }
    double lambda = 0;
    for(int k = 0; k < 12; ++k) {
      const double vn = v.norm();
      if(!(vn > 0))
        break;
      v /= vn;
      Scalar_vector t = v.cwiseProduct(s.template cast<Scalar>());
      multiply(A, t, w);
      w = w.cwiseProduct(s.template cast<Scalar>());
      lambda = std::real(v.dot(w));
      v.swap(w);
    }
    return std::min(gershgorin, 1.15 * lambda);
  }

  // x += p(D^-1 A) D^-1 (b - A x): Chebyshev's polynomial of degree `smoothing` for
  // [lambda / range, lambda] (`from_zero`: x is 0, the residual is b). Each step's vector
  // updates run in the pass of its product, in parallel over the rows.
  void smooth(const Level& L, bool from_zero) const
  {
    const double hi = L.lambda, lo = hi / opt_.smoothing_range;
    const double theta = (hi + lo) / 2, delta = (hi - lo) / 2, sigma = theta / delta;
    double rho = 1 / sigma;
    const Eigen::Index n = L.A.rows();
    Vector &x = L.x, &res = L.res, &d = L.d, &t = L.t;
    const Real_vector& inv_diag = L.inv_diag;
    if(from_zero) {
      for_each_row(n, [&](Eigen::Index i) {
        res[i] = L.b[i];
        d[i] = res[i] * (inv_diag[i] / theta);
      });
    } else { // res = b - A x
      multiply_into(L.A, x, [&](Eigen::Index i, const Value& s) {
        res[i] = L.b[i] - s;
        d[i] = res[i] * (inv_diag[i] / theta);
      });
    }
    for(int k = 1; k < opt_.smoothing; ++k) {
      // x += d; res -= A d; the next d into t (d is read by the other rows' products)
      const double rho1 = 1 / (2 * sigma - rho), a = rho1 * rho, c = 2 * rho1 / delta;
      multiply_into(L.A, d, [&](Eigen::Index i, const Value& s) {
        x[i] += d[i];
        res[i] -= s;
        t[i] = a * d[i] + c * inv_diag[i] * res[i];
      });
      d.swap(t);
      rho = rho1;
    }
    for_each_row(n, [&](Eigen::Index i) { x[i] += d[i]; });
  }

  void coarse_solve(const Vector& b, Vector& x, std::true_type) const { x = coarse_->solve(b); }
  void coarse_solve(const Vector& b, Vector& x, std::false_type) const // (a real matrix, complex vectors)
  {
    const Scalar_vector re = coarse_->solve(Scalar_vector(b.real())), im = coarse_->solve(Scalar_vector(b.imag()));
    x.resize(b.size());
    x.real() = re;
    x.imag() = im;
  }

  void cycle(std::size_t l) const
  {
    const Level& L = levels_[l];
    if(l + 1 == levels_.size()) {
      coarse_solve(L.b, L.x, std::is_same<Scalar, Value>());
      return;
    }
    for_each_row(L.A.rows(), [&](Eigen::Index i) { L.x[i] = Value(0); });
    smooth(L, true);
    multiply_into(L.A, L.x, [&](Eigen::Index i, const Value& s) { L.res[i] = L.b[i] - s; });
    const Level& C = levels_[l + 1];
    multiply(L.R, L.res, C.b);
    cycle(l + 1);
    multiply_into(L.P, C.x, [&](Eigen::Index i, const Value& s) { L.x[i] += s; });
    smooth(L, false);
  }

  Options opt_;
  mutable Vector cg_[4];
  std::vector<Level> levels_;
  std::unique_ptr<Coarse_solver> coarse_;
};

} // namespace internal
} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_LINEAR_ALGEBRA_SMOOTHED_AGGREGATION_H
