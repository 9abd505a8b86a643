// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_LINEAR_ALGEBRA_LAPLACIAN_FACTORIZATION_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_LINEAR_ALGEBRA_LAPLACIAN_FACTORIZATION_H

#include <CGAL/disable_warnings.h>

/// \file laplacian_factorization.h
// Sparse Cholesky factorisations of the Laplacians (Eigen or CHOLMOD), with a kept leading
// block and a factor rounded to single precision.

#include <CGAL/assertions.h>
#include <CGAL/use.h>

#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>

#include <CGAL/Hyperbolic_orbifold_Tutte/internal/linear_algebra/simplicial_float_factor.h>

#ifdef CGAL_HOT_USE_CHOLMOD
#include <Eigen/CholmodSupport>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/linear_algebra/nested_dissection.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/linear_algebra/single_precision_factor.h>
#endif

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/parallel_invoke.h>
#endif

#include <complex>
#include <cstddef>
#include <limits>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {
namespace internal {

// Sparse Cholesky factorisations of the (real or complex Hermitian) Laplacians: CHOLMOD's
// supernodal LL^T for large matrices where the build found SuiteSparse (CGAL_HOT_USE_CHOLMOD;
// 3-5x faster beyond 100K vertices), else Eigen's simplicial LDL^T with AMD ordering. Both are definite
// factorisations: `definite()` tells whether the matrix was found positive definite.
//
// With `keep_leading_block(m, max_fill)` before `analyze()` (CHOLMOD only, see
// `can_keep_leading_block`), the matrix is factored, whatever its size, in a constrained
// minimum-degree order (CAMD) that keeps its first m rows first (from
// `nested_dissection_threshold` rows on, CAMD within the sets of a nested dissection of the
// block: see nested_dissection.h; a minimum-degree order's fill grows faster): the factor's first m
// columns are then the factor of the leading m x m block, and `solve_leading()` solves with
// that block alone. (P A P^T = L L^*, P keeping the first m rows first; with b = (r, 0):
// y = L^-1 P b = (L11^-1 r, *); its tail set to 0, L^-* y = (L11^-* L11^-1 r, 0).)
template <class Scalar>
class Laplacian_factorization
{
public:
  typedef Eigen::SparseMatrix<Scalar> Matrix;
  // below this size Eigen's simplicial factorisation is as fast (no supernode overhead)
  static constexpr Eigen::Index cholmod_threshold = 50000;
  // from this size on, a kept leading block is ordered by nested dissection
  // (nested_dissection.h) down to parts of `nested_dissection_leaf` rows, each ordered by CAMD.
  // Measured on generated blobs, 7 landmarks (complex factor's flops, CAMD's -> nested
  // dissection's): 60K 9.1e8 -> 6.5e8, 120K 2.9e9 -> 2.0e9 (same times, within noise), 1M
  // 9.0e10 -> 4.5e10 (the initialisation 12.0 s -> 10.6 s); leaves of 1K to 8K rows give
  // flops within 2% of each other.
  static constexpr Eigen::Index nested_dissection_threshold = 200000;
  static constexpr std::size_t nested_dissection_leaf = 4096;
#ifdef CGAL_HOT_USE_CHOLMOD
  static constexpr bool can_keep_leading_block = true;
#else
  static constexpr bool can_keep_leading_block = false;
#endif

  void keep_leading_block(Eigen::Index m, double max_fill) { lead_ = m; max_fill_ = max_fill; }
  // the size from which a kept leading block is ordered by nested dissection (default:
  // nested_dissection_threshold; the tests take it lower)
  void nested_dissection_from(Eigen::Index rows) { nested_dissection_from_ = rows; }

  // With a leading block to keep: false if it could not be kept, or if keeping it would fill
  // the factor more than `max_fill` (see keep_leading_block) times CHOLMOD's own AMD order
  // does (every solve would pay for it); the factorisation is then in that AMD order, usable
  // as a whole.
  bool analyze(const Matrix& A)
  {
    simplicial_single_.clear();
#ifdef CGAL_HOT_USE_CHOLMOD
    use_cholmod_ = A.rows() >= cholmod_threshold || lead_ >= 0;
    single_ = false;
    full_xsize_ = 0; // (the analysis below frees any factor: CHOLMOD knows its shrunk size)
    if(use_cholmod_) {
      if(lead_ < 0) {
        cholmod_.analyzePattern(A);
        return true;
      }
      return analyze_keeping_leading_block(A);
    }
#endif
    const bool wanted = lead_ >= 0;
    lead_ = -1;
    simplicial_.analyzePattern(A);
    return !wanted;
  }
  void factorize(const Matrix& A)
  {
    simplicial_single_.clear();
#ifdef CGAL_HOT_USE_CHOLMOD
    single_ = false; // (the factorisation writes double values anew)
    if(use_cholmod_) {
      if(!restore_double_storage()) { // (out of memory: reported as a failed factorisation,
        cholmod_.fail();              // and solves give NaN until a factorisation succeeds)
        return;
      }
      cholmod_.factorize(A);
      return;
    }
#endif
    simplicial_.factorize(A);
  }
  // Rounds a complex supernodal (CHOLMOD) factor to single precision, in place: every solve
  // until the next factorize() is then a solve with that rounded factor (in double
  // arithmetic): see single_precision_factor.h. The floats take the first half of CHOLMOD's
  // value array; the second half is given back (the factor's memory halves: 1 GB at a
  // million vertices) and taken again by the next factorize(). A complex simplicial (Eigen)
  // factor gets a rounded copy of its L (simplicial_float_factor.h; its own solve is kept
  // for nothing else, and the copy is dropped by the next factorize()). False, and nothing
  // changed, for a real factor, one not factored, or a simplicial one with `simplicial` false.
  bool round_to_single_precision(bool simplicial = true)
  {
    if constexpr(std::is_same<Scalar, std::complex<double> >::value) {
      if(!simplicial_single_.empty())
        return true;
#ifdef CGAL_HOT_USE_CHOLMOD
      if(!use_cholmod_)
#endif
      {
        if(!simplicial || simplicial_.info() != Eigen::Success || !definite())
          return false;
        simplicial_single_.assign(simplicial_);
        return true;
      }
    }
#ifdef CGAL_HOT_USE_CHOLMOD
    if constexpr(std::is_same<Scalar, std::complex<double> >::value) {
      if(!single_ && use_cholmod_ && cholmod_.info() == Eigen::Success) {
        cholmod_factor* F = cholmod_.mutable_factor();
        single_ = round_supernodal_factor_to_float(F, single_factor_);
        const std::size_t entries = single_ ? static_cast<std::size_t>(static_cast<const int*>(F->px)[F->nsuper]) : 0;
        if(single_ && entries <= F->xsize) {
          // complex entries of x: `entries` floats pairs fit in (entries + 1) / 2 double pairs
          const std::size_t full = F->xsize, half = (entries + 1) / 2;
          std::size_t n = 2 * full; // (doubles)
          void* p = cholmod_realloc(2 * half, sizeof(double), F->x, &n, &cholmod_.cholmod());
          if(n == 2 * half) { // (else unchanged: the whole array is kept)
            F->x = p;
            F->xsize = half;
            single_factor_.x = static_cast<const float*>(p);
            full_xsize_ = full;
          }
        }
      }
      return single_;
    }
#endif
    return false;
  }
#ifdef CGAL_HOT_USE_CHOLMOD
  // the bytes CHOLMOD has allocated for this factorisation, by its own count
  std::size_t cholmod_memory_in_use() const { return cholmod_.common().memory_inuse; }
  // sets how much CHOLMOD prints (cholmod_common::print: 0 nothing, 3 its errors and warnings
  // to stdout, its default), returns the former level
  int cholmod_print_level(int level)
  {
    const int former = cholmod_.common().print;
    cholmod_.common().print = level;
    return former;
  }
#endif
  bool single_precision() const
  {
    if(!simplicial_single_.empty())
      return true;
#ifdef CGAL_HOT_USE_CHOLMOD
    return single_;
#else
    return false;
#endif
  }
#ifdef CGAL_HOT_USE_CHOLMOD
  const Supernodal_float_factor& single_precision_factor() const { return single_factor_; }
#endif
  void compute(const Matrix& A) { analyze(A); factorize(A); }
  Eigen::ComputationInfo info() const
  {
#ifdef CGAL_HOT_USE_CHOLMOD
    if(use_cholmod_) return cholmod_.info();
#endif
    return simplicial_.info();
  }
  bool definite() const
  {
#ifdef CGAL_HOT_USE_CHOLMOD
    if(use_cholmod_) return cholmod_.info() == Eigen::Success; // LL^T fails on an indefinite matrix
#endif
    return simplicial_.info() == Eigen::Success && (simplicial_.vectorD().array().real() > 0).all();
  }
  // one right-hand side or several (columns)
  template <class Rhs>
  Eigen::Matrix<Scalar, Eigen::Dynamic, Rhs::ColsAtCompileTime> solve(const Rhs& b) const
  {
    typedef Eigen::Matrix<Scalar, Eigen::Dynamic, Rhs::ColsAtCompileTime> Result;
    if constexpr(std::is_same<Scalar, std::complex<double> >::value) {
      // a rounded factor: its own one-column solve, column by column
      auto by_columns = [&b](auto&& solve_column) {
        Result x(b.rows(), b.cols());
        Eigen::Matrix<Scalar, Eigen::Dynamic, 1> bj, xj;
        for(Eigen::Index j = 0; j < b.cols(); ++j) {
          bj = b.col(j);
          solve_column(bj, xj);
          x.col(j) = xj;
        }
        return x;
      };
      if(!simplicial_single_.empty())
        return by_columns([this](const auto& bj, auto& xj) { simplicial_single_.solve(bj, xj); });
#ifdef CGAL_HOT_USE_CHOLMOD
      if(single_)
        return by_columns([this](const auto& bj, auto& xj) { solve_with_float_factor(single_factor_, bj, xj, -1, work_); });
#endif
    }
#ifdef CGAL_HOT_USE_CHOLMOD
    if(use_cholmod_ && full_xsize_ != 0) // (its values are floats, and half of them gone: NaN)
      return Result::Constant(b.rows(), b.cols(), Scalar(std::numeric_limits<double>::quiet_NaN()));
    if(use_cholmod_) return cholmod_.solve(b);
#endif
    return simplicial_.solve(b);
  }
  bool keeps_leading_block() const { return lead_ >= 0; }
  // with the leading block kept (and factored): solves with that block, b of its size
  Eigen::Matrix<Scalar, Eigen::Dynamic, 1> solve_leading(const Eigen::Matrix<Scalar, Eigen::Dynamic, 1>& b) const
  {
    Eigen::Matrix<Scalar, Eigen::Dynamic, 1> x;
#ifdef CGAL_HOT_USE_CHOLMOD
    CGAL_precondition(lead_ >= 0 && b.size() == lead_);
    if constexpr(std::is_same<Scalar, std::complex<double> >::value) {
      if(single_) {
        solve_with_float_factor(single_factor_, b, x, static_cast<int>(lead_), work_);
        return x;
      }
    }
    if(full_xsize_ != 0) // (a failed factorisation left the shrunk float values: see factorize())
      return Eigen::Matrix<Scalar, Eigen::Dynamic, 1>::Constant(b.size(), Scalar(std::numeric_limits<double>::quiet_NaN()));
    const cholmod_factor* F = cholmod_.factor();
    const int* perm = static_cast<const int*>(F->Perm);
    const Eigen::Index n = static_cast<Eigen::Index>(F->n);
    Eigen::Matrix<Scalar, Eigen::Dynamic, 1> y = Eigen::Matrix<Scalar, Eigen::Dynamic, 1>::Zero(n);
    for(Eigen::Index k = 0; k < lead_; ++k) // y = P (b, 0)
      y[k] = b[perm[k]];
    cholmod_dense* z = cholmod_.solve_system(CHOLMOD_L, y);
    if(z == nullptr)
      return x;
    Scalar* zx = static_cast<Scalar*>(z->x);
    for(Eigen::Index k = 0; k < lead_; ++k) // (the tail of y stays 0)
      y[k] = zx[k];
    cholmod_.free_dense(z);
    z = cholmod_.solve_system(CHOLMOD_Lt, y);
    if(z == nullptr)
      return x;
    zx = static_cast<Scalar*>(z->x);
    x.resize(lead_);
    for(Eigen::Index k = 0; k < lead_; ++k) // P^T
      x[perm[k]] = zx[k];
    cholmod_.free_dense(z);
#else
    CGAL_USE(b);
#endif
    return x;
  }

private:
#ifdef CGAL_HOT_USE_CHOLMOD
  // CHOLMOD's factor itself, for the triangular solves of `solve_leading()`
  struct Cholmod : Eigen::CholmodSupernodalLLT<Matrix, Eigen::Lower>
  {
    const cholmod_factor* factor() const { return this->m_cholmodFactor; }
    cholmod_factor* mutable_factor() { return this->m_cholmodFactor; }
    cholmod_dense* solve_system(int sys, Eigen::Matrix<Scalar, Eigen::Dynamic, 1>& b) const
    {
      cholmod_dense bd = Eigen::viewAsCholmod(b);
      return cholmod_solve(sys, this->m_cholmodFactor, &bd, &common());
    }
    void free_dense(cholmod_dense*& d) const { cholmod_free_dense(&d, &common()); }
    // AMD's order of A (c.lnz: its fill), without the symbolic analysis
    bool order_free(const Matrix& A, int* perm, cholmod_common& c) const
    {
      cholmod_sparse a = Eigen::viewAsCholmod(A.template selfadjointView<Eigen::Lower>());
      return cholmod_amd(&a, nullptr, 0, perm, &c);
    }
    // CAMD's order (`member`: the constraint set of each row; c.lnz: its fill)
    bool order_constrained(const Matrix& A, int* member, int* perm)
    {
      cholmod_sparse a = Eigen::viewAsCholmod(A.template selfadjointView<Eigen::Lower>());
      return cholmod_camd(&a, nullptr, 0, member, perm, &common());
    }
    bool analyze_given(const Matrix& A, int* perm)
    {
      cholmod_common& c = common();
      if(this->m_cholmodFactor)
        cholmod_free_factor(&this->m_cholmodFactor, &c);
      cholmod_sparse a = Eigen::viewAsCholmod(A.template selfadjointView<Eigen::Lower>());
      const int ordering = c.method[0].ordering, methods = c.nmethods;
      c.nmethods = 1;
      c.method[0].ordering = CHOLMOD_GIVEN;
      this->m_cholmodFactor = cholmod_analyze_p(&a, perm, nullptr, 0, &c);
      c.method[0].ordering = ordering;
      c.nmethods = methods;
      this->m_isInitialized = true;
      this->m_info = Eigen::Success;
      this->m_analysisIsOk = this->m_cholmodFactor != nullptr;
      this->m_factorizationIsOk = false;
      return this->m_cholmodFactor != nullptr;
    }
    cholmod_common& common() const { return const_cast<Cholmod*>(this)->cholmod(); } // (mutable in Eigen)
    void fail()
    {
      this->m_info = Eigen::NumericalIssue;
      this->m_factorizationIsOk = false;
    }
  };
  // CHOLMOD, the leading block to keep: see analyze()
  bool analyze_keeping_leading_block(const Matrix& A)
  {
    // the fills of both orders, from the orderings alone (AMD's and CAMD's counts, the two
    // at once where TBB is available: each with its own CHOLMOD workspace); then one
    // symbolic analysis, in the order chosen
    cholmod_common& c = cholmod_.cholmod();
    c.nmethods = 1; // (where an order is not given: AMD alone)
    c.method[0].ordering = CHOLMOD_AMD;
    std::vector<int> amd_perm(A.rows()), camd_perm(A.rows()), member;
    cholmod_common c_amd;
    cholmod_start(&c_amd);
    bool amd_ok = false, camd_ok = false;
    auto free_order = [&]() { amd_ok = cholmod_.order_free(A, amd_perm.data(), c_amd); };
    auto constrained_order = [&]() {
      if(A.rows() >= nested_dissection_from_ && lead_ >= 2 * static_cast<Eigen::Index>(nested_dissection_leaf)) {
        nested_dissection_sets(A, lead_, member, nested_dissection_leaf);
      } else { // constrained minimum degree: the leading rows first
        member.resize(A.rows());
        for(Eigen::Index i = 0; i < A.rows(); ++i)
          member[i] = i < lead_ ? 0 : 1;
      }
      camd_ok = cholmod_.order_constrained(A, member.data(), camd_perm.data());
    };
#ifdef CGAL_LINKED_WITH_TBB
    tbb::parallel_invoke(free_order, constrained_order);
#else
    free_order();
    constrained_order();
#endif
    const double amd_fill = c_amd.lnz, camd_fill = c.lnz;
    cholmod_finish(&c_amd);
    if(!amd_ok) {
      cholmod_.analyzePattern(A);
      lead_ = -1;
      return false;
    }
    bool ordered = camd_ok && camd_fill <= max_fill_ * amd_fill;
    c.postorder = 1; // keeps the order's fill, groups supernodes
    if(ordered) {
      ordered = cholmod_.analyze_given(A, camd_perm.data());
      if(ordered && !leading_block_kept()) {
        c.postorder = 0; // the order exactly as found
        ordered = cholmod_.analyze_given(A, camd_perm.data());
        c.postorder = 1;
      }
      ordered = ordered && leading_block_kept();
    }
    if(!ordered) {
      if(!cholmod_.analyze_given(A, amd_perm.data()))
        cholmod_.analyzePattern(A);
      lead_ = -1;
      return false;
    }
    return true;
  }
  // the value array of a factor shrunk by round_to_single_precision() to its full size again,
  // before CHOLMOD writes double values into it; false if that memory is not available
  bool restore_double_storage()
  {
    cholmod_factor* F = cholmod_.mutable_factor();
    if(full_xsize_ == 0 || F == nullptr)
      return true;
    std::size_t n = 2 * F->xsize;
    void* p = cholmod_realloc(2 * full_xsize_, sizeof(double), F->x, &n, &cholmod_.cholmod());
    if(n != 2 * full_xsize_)
      return false;
    F->x = p;
    F->xsize = full_xsize_;
    full_xsize_ = 0;
    return true;
  }
  bool leading_block_kept() const
  {
    const cholmod_factor* F = cholmod_.factor();
    if(F == nullptr || F->Perm == nullptr)
      return false;
    const int* perm = static_cast<const int*>(F->Perm);
    for(Eigen::Index k = 0; k < lead_; ++k)
      if(perm[k] >= lead_)
        return false;
    return true;
  }
#endif

  Eigen::SimplicialLDLT<Matrix, Eigen::Lower, Eigen::AMDOrdering<int> > simplicial_;
  Simplicial_float_factor<std::complex<double> > simplicial_single_; // (complex only) simplicial_'s L rounded to float, or empty
#ifdef CGAL_HOT_USE_CHOLMOD
  Cholmod cholmod_;
  bool use_cholmod_ = false;
  bool single_ = false;                    // the factor rounded to float (round_to_single_precision)
  std::size_t full_xsize_ = 0;             // its value array's size before it was shrunk (0: not shrunk)
  Supernodal_float_factor single_factor_;  // (a view of it)
  mutable std::vector<double> work_;     // (the solves' workspace: one solve at a time per object)
#endif
  Eigen::Index lead_ = -1;
  double max_fill_ = 1;
  Eigen::Index nested_dissection_from_ = nested_dissection_threshold;
};

} // namespace internal
} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_LINEAR_ALGEBRA_LAPLACIAN_FACTORIZATION_H
