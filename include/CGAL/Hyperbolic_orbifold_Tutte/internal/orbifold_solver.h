// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_ORBIFOLD_SOLVER_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_ORBIFOLD_SOLVER_H

#include <CGAL/Hyperbolic_orbifold_Tutte/internal/flat_problem.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/weight_type.h>

#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>

#ifdef CGAL_HOT_USE_CHOLMOD
#include <Eigen/CholmodSupport>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/single_precision_factor.h>
#endif

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>
#endif

#include <algorithm>
#include <array>
#include <chrono>
#include <complex>
#include <limits>
#include <cmath>
#include <memory>
#include <type_traits>
#include <unordered_map>
#include <vector>

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {


namespace internal {

// Edge weights from the 3D geometry, accumulated face by face on the cut mesh, so that
// the two copies of a seam edge together carry the base edge's weight (each base edge
// counts once in the energy). Cotangent sums are clamped below at epsilon per base edge.
template <class Point3>
void compute_edge_weights(Flat_problem& P, const std::vector<Point3>& base_points, Weight_type type, double epsilon)
{
  const std::size_t m = P.edges.size();
  P.edge_weight.assign(m, 0.0);
  // edge ids by vertex pair: per vertex, its edges (compressed rows; valences are small)
  std::vector<int> first(P.n + 1, 0), other(2 * m), id(2 * m);
  for(const auto& e : P.edges) { ++first[e[0] + 1]; ++first[e[1] + 1]; }
  for(int v = 0; v < P.n; ++v) first[v + 1] += first[v];
  {
    std::vector<int> fill(first.begin(), first.end() - 1);
    for(std::size_t e = 0; e < m; ++e) {
      const int a = P.edges[e][0], b = P.edges[e][1];
      other[fill[a]] = b; id[fill[a]++] = static_cast<int>(e);
      other[fill[b]] = a; id[fill[b]++] = static_cast<int>(e);
    }
  }
  auto edge_id = [&](int a, int b) {
    for(int k = first[a]; k < first[a + 1]; ++k)
      if(other[k] == b) return id[k];
    return -1;
  };
  // the copies of a base edge (two along a seam, one elsewhere): only an edge with both ends
  // on the border loop can have two; those are sorted by base pair
  std::vector<char> on_loop(P.n, 0);
  for(int v : P.border_loop)
    on_loop[v] = 1;
  auto key = [](int a, int b) { return (static_cast<long long>(std::min(a, b)) << 32) | static_cast<long long>(std::max(a, b)); };
  std::vector<std::pair<long long, int> > by_base;
  for(std::size_t e = 0; e < m; ++e)
    if(on_loop[P.edges[e][0]] && on_loop[P.edges[e][1]])
      by_base.emplace_back(key(P.base[P.edges[e][0]], P.base[P.edges[e][1]]), static_cast<int>(e));
  std::sort(by_base.begin(), by_base.end());

  for(const auto& t : P.faces) {
    double q[3][3]; // the corners' coordinates
    for(int i = 0; i < 3; ++i) {
      const Point3& p = base_points[P.base[t[i]]];
      q[i][0] = CGAL::to_double(p.x());
      q[i][1] = CGAL::to_double(p.y());
      q[i][2] = CGAL::to_double(p.z());
    }
    // at corner i, between the edges to corners i+1 and i+2: cotangent dot / |cross|, and
    // tan(angle / 2) = |cross| / (|u| |v| + dot) (no trigonometric function)
    double cot[3], half_tan[3], len[3]; // len[i]: length of the edge opposite corner i
    for(int i = 0; i < 3; ++i) {
      const double* o = q[i];
      const double* a = q[(i + 1) % 3];
      const double* b = q[(i + 2) % 3];
      const double u[3] = {a[0] - o[0], a[1] - o[1], a[2] - o[2]};
      const double v[3] = {b[0] - o[0], b[1] - o[1], b[2] - o[2]};
      const double dot = u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
      const double cx = u[1] * v[2] - u[2] * v[1], cy = u[2] * v[0] - u[0] * v[2], cz = u[0] * v[1] - u[1] * v[0];
      const double cr = std::sqrt(cx * cx + cy * cy + cz * cz);
      const double lu = std::sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
      const double lv = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
      cot[i] = dot / cr; // +-infinity for a flat corner (exactly degenerate faces are refused before)
      half_tan[i] = cr / (lu * lv + dot);
      const double w[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
      len[i] = std::sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
    }
    for(int i = 0; i < 3; ++i) {
      // edge opposite corner i: vertices i+1, i+2
      const int a = t[(i + 1) % 3], b = t[(i + 2) % 3];
      double w = 0;
      switch(type) {
        case Cotangent: w = 0.5 * cot[i]; break;
        case Uniform: w = 0.5; break;
        case Mean_value: w = 0.5 * (half_tan[(i + 1) % 3] + half_tan[(i + 2) % 3]) / len[i]; break;
      }
      const int e = edge_id(a, b);
      if(e >= 0)
        P.edge_weight[e] += w;
    }
  }
  // Per base edge (its copies): the total over its copies. Uniform: 1 per base edge;
  // cotangent sums below epsilon are clamped (degenerate geometry); a seam copy with a
  // negative half shares the total with its twin copy.
  auto settle = [&](const int* copy, std::size_t copies) {
    double sum = 0;
    for(std::size_t k = 0; k < copies; ++k)
      sum += P.edge_weight[copy[k]];
    bool rebalanced = false;
    for(std::size_t k = 0; k < copies; ++k) {
      double& w = P.edge_weight[copy[k]];
      if(type == Uniform) w = 1.0 / static_cast<double>(copies);
      else if(!(sum >= epsilon)) w = epsilon / static_cast<double>(copies);
      else if(!(w > 0)) { w = sum / static_cast<double>(copies); rebalanced = true; }
    }
    if(rebalanced) { // keep the total of the copies
      double total = 0;
      for(std::size_t k = 0; k < copies; ++k) total += P.edge_weight[copy[k]];
      for(std::size_t k = 0; k < copies; ++k) P.edge_weight[copy[k]] *= sum / total;
    }
  };
  for(std::size_t e = 0; e < m; ++e)
    if(!(on_loop[P.edges[e][0]] && on_loop[P.edges[e][1]])) {
      const int c = static_cast<int>(e);
      settle(&c, 1);
    }
  std::vector<int> group;
  for(std::size_t i = 0; i < by_base.size();) {
    std::size_t j = i;
    group.clear();
    while(j < by_base.size() && by_base[j].first == by_base[i].first)
      group.push_back(by_base[j++].second);
    settle(group.data(), group.size());
    i = j;
  }
}

// Sparse Cholesky factorisations of the (real or complex Hermitian) Laplacians: CHOLMOD's
// supernodal LL^T for large matrices where the build found SuiteSparse (CGAL_HOT_USE_CHOLMOD;
// 3-5x faster beyond 100K vertices), else Eigen's simplicial LDL^T with AMD ordering. Both are definite
// factorisations: `definite()` tells whether the matrix was found positive definite.
//
// With `keep_leading_block(m, max_fill)` before `analyze()` (CHOLMOD only, see
// `can_keep_leading_block`), the matrix is factored, whatever its size, in a constrained
// minimum-degree order (CAMD) that keeps its first m rows first: the factor's first m
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
#ifdef CGAL_HOT_USE_CHOLMOD
  static constexpr bool can_keep_leading_block = true;
#else
  static constexpr bool can_keep_leading_block = false;
#endif

  void keep_leading_block(Eigen::Index m, double max_fill) { lead_ = m; max_fill_ = max_fill; }

  // With a leading block to keep: false if it could not be kept, or if keeping it would fill
  // the factor more than `max_fill` (see keep_leading_block) times CHOLMOD's own AMD order
  // does (every solve would pay for it); the factorisation is then in that AMD order, usable
  // as a whole.
  bool analyze(const Matrix& A)
  {
#ifdef CGAL_HOT_USE_CHOLMOD
    use_cholmod_ = A.rows() >= cholmod_threshold || lead_ >= 0;
    single_ = false;
    full_xsize_ = 0; // (the analysis below frees any factor: CHOLMOD knows its shrunk size)
    if(use_cholmod_) {
      if(lead_ < 0) {
        cholmod_.analyzePattern(A);
        return true;
      }
      // the fills of both orders, from the orderings alone (AMD's and CAMD's counts, the two
      // at once where TBB is available: each with its own CHOLMOD workspace); then one
      // symbolic analysis, in the order chosen
      cholmod_common& c = cholmod_.cholmod();
      c.nmethods = 1; // (where an order is not given: AMD alone)
      c.method[0].ordering = CHOLMOD_AMD;
      std::vector<int> amd_perm(A.rows()), camd_perm(A.rows()), member(A.rows());
      for(Eigen::Index i = 0; i < A.rows(); ++i) // constrained minimum degree: the leading rows first
        member[i] = i < lead_ ? 0 : 1;
      cholmod_common c_amd;
      cholmod_start(&c_amd);
      bool amd_ok = false, camd_ok = false;
      auto free_order = [&]() { amd_ok = cholmod_.order_free(A, amd_perm.data(), c_amd); };
      auto constrained_order = [&]() { camd_ok = cholmod_.order_constrained(A, member.data(), camd_perm.data()); };
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
#endif
    const bool wanted = lead_ >= 0;
    lead_ = -1;
    simplicial_.analyzePattern(A);
    return !wanted;
  }
  void factorize(const Matrix& A)
  {
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
  // million vertices) and taken again by the next factorize(). False, and nothing changed,
  // for a simplicial or real factor or one not factored.
  bool round_to_single_precision()
  {
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
#ifdef CGAL_HOT_USE_CHOLMOD
    if constexpr(std::is_same<Scalar, std::complex<double> >::value) {
      if(single_) {
        Eigen::Matrix<Scalar, Eigen::Dynamic, Rhs::ColsAtCompileTime> x(b.rows(), b.cols());
        Eigen::Matrix<Scalar, Eigen::Dynamic, 1> bj, xj;
        for(Eigen::Index j = 0; j < b.cols(); ++j) {
          bj = b.col(j);
          solve_with_float_factor(single_factor_, bj, xj, -1, work_);
          x.col(j) = xj;
        }
        return x;
      }
    }
    if(use_cholmod_ && full_xsize_ != 0) // (its values are floats, and half of them gone: NaN)
      return Eigen::Matrix<Scalar, Eigen::Dynamic, Rhs::ColsAtCompileTime>::Constant(
        b.rows(), b.cols(), Scalar(std::numeric_limits<double>::quiet_NaN()));
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
};

class Connection_laplacian_preconditioner;

// The weighted Laplacian of the cut mesh's interior vertices (the border held fixed), for the
// initialisation and the preconditioner's gauge. Either a factorisation of its own (`solver`)
// or, where CHOLMOD keeps the leading block
// (see Laplacian_factorization), the leading block of the solver's connection Laplacian,
// factored once for both (`connection`; the initialisation then needs no factorisation of
// its own, and the solver takes that preconditioner over). Sharing starts where CHOLMOD
// takes over anyway (`share_from` cut-mesh vertices): below, Eigen's simplicial
// factorisations give the same bits on every machine, CHOLMOD's BLAS may not (its results
// can change in the last bits with the BLAS's threads and the arrays' alignment).
struct Interior_laplacian
{
  std::vector<int> index;   // interior index of each cut-mesh vertex, -1 on the border
  int size = 0;
  Laplacian_factorization<double> solver;
  bool own_factor = false;  // `solver` factored (definite or not)
  bool share = Laplacian_factorization<double>::can_keep_leading_block; // try `connection` first
  Eigen::Index share_from = Laplacian_factorization<double>::cholmod_threshold;
  // ... unless the order it needs (the cut last, CAMD) fills the factor more than this many
  // times CHOLMOD's free AMD order does: sharing saves the interior Laplacian's factorisation,
  // but each gauge solve then costs a complex solve instead of a real one, and extra fill
  // costs every solve. Measured on the blob of 100K vertices: 5% saved with 7 landmarks (fill
  // ratio 0.96), 7% lost with 23 (ratio 1.008: 39 CG iterations and 7 gauge solves to pay).
  double share_max_fill = 1.0;
  std::shared_ptr<Connection_laplacian_preconditioner> connection;
};

struct Solver_options
{
  double gradient_tolerance = 1e-10; // force imbalance (relative hyperbolic gradient norm)
  int max_iterations = 200;
  int max_cg_iterations = 400;       // per Newton step
  int refactor_cg_iterations = 25;   // refactor the preconditioner after a Newton step that needed more
  // Preconditioned gradient steps before Newton (phase 1 of minimize_energy). Off: Newton
  // from the start is as fast with 7 landmarks and up to 1.8x faster with 50, where the
  // gradient steps' long moves need the preconditioner factored again two or three times.
  bool gradient_steps = false;
  double newton_threshold = 1e-2;    // with gradient steps: relative gradient norm below which Newton takes over
  int max_model_refactorizations = 8; // preconditioner refactorisations during the gradient steps
  bool geodesic_steps = true;        // move free vertices along geodesics (exponential map)
  bool direct_solver = false;        // factor every Newton system instead of conjugate gradients
  // Newton steps from the start, until rounding stops them (the tolerance is ignored): for a
  // converged embedding whose small regions need the last digits (see the parameterizer)
  bool polish = false;
  bool riemannian_hessian = true;    // Newton with the Riemannian Hessian (see minimize_energy)
  // the preconditioner's CHOLMOD factor rounded to float for its solves (single_precision_factor.h)
  bool single_precision_preconditioner = true;
  // converged also means: no vertex's own forces are out of balance by more than this
  // fraction of their sizes, unless rounding explains it (else Newton goes on to the floor)
  double vertex_imbalance = 1e-8;
  bool verbose = false;
};

struct Solver_statistics
{
  int iterations = 0;
  double initial_energy = 0, energy = 0;
  double initial_gradient = 0, gradient = 0, relative_gradient = 0;
  double time_assemble = 0, time_factor = 0, time_line_search = 0;
  int cg_iterations = 0, cg_failures = 0, preconditioner_factorizations = 0;
  double rounding_floor = 0;   // Energy_evaluator::rounding_floor() at the result
  int polishing_iterations = 0; // Newton steps to balance every vertex (after convergence)
  bool at_rounding_floor = false; // stopped by rounding (stagnation) within 10x that floor
  bool converged = false;
};

// Dirichlet energy (1/2) sum w d^2; gradient and projected Hessian if requested.
class Energy_evaluator
{
public:
  typedef Complex<double> C;
  explicit Energy_evaluator(const Flat_problem& P) : P_(P) { build_pattern(); }

  // The Hessian's sparsity pattern (every entry any edge can touch, symmetric, compressed
  // column storage) and, per edge, the positions of its local block's entries in it: the
  // values are accumulated in place, no triplets, no sorting per iteration. The pattern is
  // handed over to the first Hessian asked for (one copy in memory), built again for another.

  // returns +infinity for infeasible x (a point on or outside the unit circle)
  double energy(const std::vector<double>& x) const
  {
    const std::size_t m = P_.edges.size();
    terms_x_.clear(); // the per-edge terms no longer belong to one point
    edge_energy_.resize(m);
    for_each_edge([&](std::size_t e) {
      const C a = position(P_, x, P_.edges[e][0]), b = position(P_, x, P_.edges[e][1]);
      const double A = 1 - norm(a), B = 1 - norm(b);
      if(!(A > 0 && B > 0)) {
        edge_energy_[e] = std::numeric_limits<double>::infinity();
        return;
      }
      const double dx = a.re - b.re, dy = a.im - b.im;
      const double d = 2.0 * std::asinh(std::sqrt((dx * dx + dy * dy) / (A * B)));
      edge_energy_[e] = 0.5 * P_.edge_weight[e] * d * d;
    });
    double E = 0;
    for(std::size_t e = 0; e < m; ++e)
      E += edge_energy_[e];
    return E;
  }

  bool feasible(const std::vector<double>& x) const
  {
    for(int v = 0; v < P_.n; ++v) {
      if(P_.kind[v] == Free) {
        if(!(x[P_.var[v]] * x[P_.var[v]] + x[P_.var[v] + 1] * x[P_.var[v] + 1] < 1.0))
          return false;
      } else if(P_.kind[v] == On_line) {
        const C k = P_.line_k0[v] + x[P_.var[v]] * P_.line_D[v];
        if(!(norm(k) < 1.0))
          return false;
      }
    }
    return true;
  }

  // gradient g (size n_vars) and, if H != nullptr, the Hessian with each edge's block
  // projected onto the positive semi-definite cone
  double evaluate(const std::vector<double>& x, std::vector<double>& g,
                  Eigen::SparseMatrix<double>* H, bool project = true) const
  {
    const std::size_t m = P_.edges.size();
    edge_energy_.resize(m);
    edge_gradient_.resize(4 * m);
    // each edge's terms independently (in parallel where TBB is available)...
    if(!H) {
      for_each_edge([&](std::size_t e) { edge_terms(x, e, false, project); });
    } else {
      if(H->nonZeros() != pattern_nnz_ || H->rows() != P_.n_vars || H->cols() != P_.n_vars) {
        if(pattern_given_) // rare (tests): build the pattern again
          build_pattern();
        // (swapped, not assigned: Eigen 3.4's SparseMatrix has no move assignment, so
        // `*H = std::move(pattern_)` would copy it and keep both: 336 MB at a million vertices)
        H->swap(pattern_);
        Eigen::SparseMatrix<double>().swap(pattern_); // H's former storage freed
        pattern_given_ = true;
      }
      double* hv = H->valuePtr();
      std::fill(hv, hv + H->nonZeros(), 0.0);
      // the Hessian blocks a chunk of edges at a time (a small buffer, not 16 doubles per
      // edge: 0.4 GB at a million vertices), added in edge order: bit for bit the same
      const std::size_t chunk = 65536;
      for(std::size_t c = 0; c < m; c += chunk) {
        const std::size_t c_end = (std::min)(m, c + chunk);
        hessian_offset_ = static_cast<std::size_t>(slot_begin_[c]);
        edge_hessian_.resize(static_cast<std::size_t>(slot_begin_[c_end]) - hessian_offset_);
        for_each_edge(c, c_end, [&](std::size_t e) { edge_terms(x, e, true, project); });
        for(std::size_t k = hessian_offset_; k < static_cast<std::size_t>(slot_begin_[c_end]); ++k)
          hv[slots_[k]] += edge_hessian_[k - hessian_offset_];
      }
      hessian_offset_ = 0;
    }
    terms_x_ = x;
    noise_.clear();
    // ...then summed in edge order: the same result bit for bit whatever the number of threads
    g.assign(P_.n_vars, 0.0);
    g_abs_.assign(P_.n_vars, 0.0);
    double E = 0;
    int gi[4];
    for(std::size_t e = 0; e < m; ++e) {
      E += edge_energy_[e];
      const int n = local_variables(e, gi);
      for(int i = 0; i < n; ++i) {
        g[gi[i]] += edge_gradient_[4 * e + i];
        g_abs_[gi[i]] += std::abs(edge_gradient_[4 * e + i]);
      }
    }
    return E;
  }

  // hyperbolic (Riemannian) norm of the gradient: per vertex |grad| (1 - |z|^2) / 2,
  // per boundary parameter |dE/dt| / |dz/dt|_hyperbolic. With `relative`, divided by the
  // same norm of the sums of the absolute values of the edges' contributions (the
  // "forces" on each vertex, from the last call of evaluate() at x): the remaining
  // imbalance of the forces, a scale-free measure whose floor is the rounding error.
  double hyperbolic_gradient_norm(const std::vector<double>& x, const std::vector<double>& g, bool relative = false) const
  {
    double s = 0, sa = 0;
    Position_jet j;
    for(int v = 0; v < P_.n; ++v) {
      if(P_.kind[v] == Free) {
        const int i = P_.var[v];
        const double r = (1 - (x[i] * x[i] + x[i + 1] * x[i + 1])) / 2;
        s += (g[i] * g[i] + g[i + 1] * g[i + 1]) * r * r;
        sa += (g_abs_[i] * g_abs_[i] + g_abs_[i + 1] * g_abs_[i + 1]) * r * r;
      } else if(P_.kind[v] == On_line) {
        position_jet(P_, x, v, j);
        const double speed = abs(j.dz[0]) * 2 / (1 - norm(j.z));
        const double gt = g[P_.var[v]] / speed, ga = g_abs_[P_.var[v]] / speed;
        s += gt * gt;
        sa += ga * ga;
      }
    }
    if(!relative)
      return std::sqrt(s);
    return sa > 0 ? std::sqrt(s / sa) : 0.0;
  }

  // The force imbalance that rounding the coordinates to double alone causes, relative like
  // hyperbolic_gradient_norm(x, g, true), at x (evaluates the gradient there). An edge's length
  // d is known to about u (|a|/r_a + |b|/r_b) (u the unit roundoff, r = (1 - |z|^2)/2 the
  // scale of the metric; seam copies and border parameters add a few roundings: factor 8),
  // so each of its forces to a relative d_err / d. Stiff edges (cotangent weights of 1e5
  // on needle triangles) or vertices near the circle raise this floor well above 1e-16.
  double rounding_floor(const std::vector<double>& x) const
  {
    std::vector<double> noise;
    rounding_noise(x, noise);
    const double num = hyperbolic_gradient_norm(x, noise); // in the same (hyperbolic) norm
    const double den = hyperbolic_gradient_norm(x, g_abs_);
    return den > 0 ? num / den : 0.0;
  }

  // Vertices whose own forces are out of balance by more than `relative` of their sizes and
  // by more than ten times what rounding explains there, for the gradient g at x. The global
  // imbalance cannot see a region squeezed to 1e-12 (a protrusion without landmarks): its
  // forces are that small; such a region is solved only when this count is zero.
  int unbalanced_vertices(const std::vector<double>& x, const std::vector<double>& g, double relative) const
  {
    std::vector<double> noise;
    rounding_noise(x, noise); // (evaluates at x again: g_abs_ is x's)
    int count = 0;
    for(int v = 0; v < P_.n; ++v) {
      double a = 0, b = 0, c = 0;
      if(P_.kind[v] == Free) {
        const int i = P_.var[v];
        a = std::hypot(g[i], g[i + 1]);
        b = std::hypot(g_abs_[i], g_abs_[i + 1]);
        c = std::hypot(noise[i], noise[i + 1]);
      } else if(P_.kind[v] == On_line) {
        a = std::abs(g[P_.var[v]]);
        b = g_abs_[P_.var[v]];
        c = noise[P_.var[v]];
      }
      if(a > relative * b && a > 10 * c)
        ++count;
    }
    return count;
  }

private:
  // per variable, the size of the forces' change that rounding the coordinates may cause
  void rounding_noise(const std::vector<double>& x, std::vector<double>& noise) const
  {
    const double u = std::numeric_limits<double>::epsilon() / 2;
    if(terms_x_ != x || terms_x_.empty())
      evaluate(x, noise, nullptr); // the per-edge terms and forces at x
    else if(!noise_.empty()) { // at the point of the last evaluation, and computed there already
      noise = noise_;
      return;
    }
    noise.assign(P_.n_vars, 0.0);
    int gi[4];
    for(std::size_t e = 0; e < P_.edges.size(); ++e) {
      const C a = position(P_, x, P_.edges[e][0]), b = position(P_, x, P_.edges[e][1]);
      const double ra = (1 - norm(a)) / 2, rb = (1 - norm(b)) / 2;
      const double d = std::sqrt(2 * edge_energy_[e] / P_.edge_weight[e]);
      const double err = 8 * u * (abs(a) / ra + abs(b) / rb);
      const double rel = d > err ? err / d : 1.0;
      const int n = local_variables(e, gi);
      for(int i = 0; i < n; ++i)
        noise[gi[i]] += std::abs(edge_gradient_[4 * e + i]) * rel;
    }
    noise_ = noise;
  }

private:
  template <class F>
  void for_each_edge(const F& f) const
  {
    for_each_edge(0, P_.edges.size(), f);
  }

  // edges [begin, end); in parallel on meshes of more than 20000 edges
  template <class F>
  void for_each_edge(std::size_t begin, std::size_t end, const F& f) const
  {
#ifdef CGAL_LINKED_WITH_TBB
    if(P_.edges.size() > 20000) {
      tbb::parallel_for(tbb::blocked_range<std::size_t>(begin, end, 4096), [&](const tbb::blocked_range<std::size_t>& r) {
        for(std::size_t e = r.begin(); e != r.end(); ++e)
          f(e);
      });
      return;
    }
#endif
    for(std::size_t e = begin; e < end; ++e)
      f(e);
  }

  // energy, gradient and (projected) Hessian block of edge e, into the per-edge buffers
  void edge_terms(const std::vector<double>& x, std::size_t e, bool want_hessian, bool project) const
  {
    Position_jet ja, jb;
    Squared_distance_derivatives sd;
    const int a = P_.edges[e][0], b = P_.edges[e][1];
    position_jet(P_, x, a, ja);
    position_jet(P_, x, b, jb);
    const double hw = 0.5 * P_.edge_weight[e];
    const int n = ja.dim + jb.dim;
    squared_hyperbolic_distance(ja.z, jb.z, sd, want_hessian && n > 0);
    edge_energy_[e] = hw * sd.f; // constant when n == 0, but part of the energy that energy() returns
    if(n == 0)
      return;
    // local variables: first ja.dim of a, then jb.dim of b;
    // dz_i as real 2-vectors, per local variable, with its offset in the 4-vector (0: z, 2: w)
    double J[4][2];
    int off[4];
    for(int i = 0; i < ja.dim; ++i) {
      J[i][0] = ja.dz[i].re; J[i][1] = ja.dz[i].im; off[i] = 0;
    }
    for(int i = 0; i < jb.dim; ++i) {
      J[ja.dim + i][0] = jb.dz[i].re; J[ja.dim + i][1] = jb.dz[i].im; off[ja.dim + i] = 2;
    }
    for(int i = 0; i < n; ++i)
      edge_gradient_[4 * e + i] = hw * (sd.g[off[i]] * J[i][0] + sd.g[off[i] + 1] * J[i][1]);
    if(!want_hessian)
      return;
    Eigen::Matrix4d M = Eigen::Matrix4d::Zero();
    for(int i = 0; i < n; ++i)
      for(int j = i; j < n; ++j) {
        double h = 0;
        for(int p = 0; p < 2; ++p)
          for(int q = 0; q < 2; ++q)
            h += J[i][p] * sd.H[off[i] + p][off[j] + q] * J[j][q];
        // second derivatives of the position (same vertex only)
        if(off[i] == off[j]) {
          const Position_jet& jj = (off[i] == 0) ? ja : jb;
          const int ii = (off[i] == 0) ? i : i - ja.dim, kk = (off[j] == 0) ? j : j - ja.dim;
          h += sd.g[off[i]] * jj.ddz[ii][kk].re + sd.g[off[i] + 1] * jj.ddz[ii][kk].im;
        }
        M(i, j) = M(j, i) = hw * h;
      }
    if(project)
      project_psd(M, n);
    double* out = &edge_hessian_[slot_begin_[e] - hessian_offset_];
    for(int i = 0; i < n; ++i)
      for(int j = 0; j < n; ++j)
        out[i * n + j] = M(i, j);
  }

  // local variables of edge e: those of its first end, then those of its second
  int local_variables(std::size_t e, int* gi) const
  {
    int n = 0;
    for(int s = 0; s < 2; ++s) {
      const int v = P_.edges[e][s];
      const int o = variable_owner(P_, v);
      const int dim = P_.kind[v] == Fixed ? 0 : (P_.kind[v] == On_line ? 1 : 2);
      for(int i = 0; i < dim; ++i)
        gi[n++] = o + i;
    }
    return n;
  }

  // Every edge's block is dense over the variables of its two ends' owners, so the pattern
  // is built per owner: an owner's columns hold the rows of its neighbouring owners
  // (itself included: the diagonal), in variable order; no triplets, no sorting of entries.
  void build_pattern() const
  {
    const int nv = P_.n_vars;
    const std::size_t m = P_.edges.size();
    // owners as groups of consecutive variables: group of each variable, its start and size
    std::vector<int> group_of(nv, -1), gstart, gdim;
    for(int v = 0; v < P_.n; ++v)
      if(P_.kind[v] == Free || P_.kind[v] == On_line) {
        const int d = P_.kind[v] == Free ? 2 : 1;
        for(int i = 0; i < d; ++i)
          group_of[P_.var[v] + i] = static_cast<int>(gstart.size());
        gstart.push_back(P_.var[v]);
        gdim.push_back(d);
      }
    const int ng = static_cast<int>(gstart.size());
    auto group_of_end = [&](std::size_t e, int s) {
      const int v = P_.edges[e][s];
      return P_.kind[v] == Fixed ? -1 : group_of[variable_owner(P_, v)];
    };
    // neighbouring groups (compressed rows, sorted by first variable, duplicates removed)
    std::vector<int> first(ng + 1, 0);
    for(std::size_t e = 0; e < m; ++e) {
      const int ga = group_of_end(e, 0), gb = group_of_end(e, 1);
      if(ga >= 0 && gb >= 0 && ga != gb) { ++first[ga + 1]; ++first[gb + 1]; }
    }
    for(int g = 0; g < ng; ++g)
      first[g + 1] += first[g] + 1; // + itself
    std::vector<int> nb(first[ng]);
    {
      std::vector<int> fill(first.begin(), first.end() - 1);
      for(int g = 0; g < ng; ++g)
        nb[fill[g]++] = g;
      for(std::size_t e = 0; e < m; ++e) {
        const int ga = group_of_end(e, 0), gb = group_of_end(e, 1);
        if(ga >= 0 && gb >= 0 && ga != gb) { nb[fill[ga]++] = gb; nb[fill[gb]++] = ga; }
      }
    }
    // (groups are numbered in vertex order, their variables need not be: sort by variable)
    std::vector<int> row_first(ng + 1, 0), row_offset(nb.size()); // per neighbour: its first row in the column
    {
      std::size_t w = 0;
      for(int g = 0; g < ng; ++g) {
        const std::size_t b = w;
        std::sort(nb.begin() + first[g], nb.begin() + first[g + 1], [&](int p, int q) { return gstart[p] < gstart[q]; });
        for(int k = first[g]; k < first[g + 1]; ++k)
          if(w == b || nb[w - 1] != nb[k]) nb[w++] = nb[k];
        first[g] = static_cast<int>(b);
        int off = 0;
        for(std::size_t k = b; k < w; ++k) {
          row_offset[k] = off;
          off += gdim[nb[k]];
        }
        row_first[g + 1] = off; // rows per column of this group
      }
      first[ng] = static_cast<int>(w);
      nb.resize(w);
      row_offset.resize(w);
    }
    // compressed columns
    pattern_.resize(nv, nv);
    std::vector<int> outer(nv + 1, 0);
    for(int c = 0; c < nv; ++c)
      outer[c + 1] = outer[c] + row_first[group_of[c] + 1];
    pattern_.resizeNonZeros(outer[nv]);
    std::copy(outer.begin(), outer.end(), pattern_.outerIndexPtr());
    int* inner = pattern_.innerIndexPtr();
    for(int c = 0; c < nv; ++c) {
      const int g = group_of[c];
      int k = outer[c];
      for(int q = first[g]; q < first[g + 1]; ++q)
        for(int i = 0; i < gdim[nb[q]]; ++i)
          inner[k++] = gstart[nb[q]] + i;
    }
    std::fill(pattern_.valuePtr(), pattern_.valuePtr() + pattern_.nonZeros(), 0.0);
    pattern_nnz_ = pattern_.nonZeros();
    // per edge, the position of each entry of its block
    slot_begin_.assign(m + 1, 0);
    int gi[4];
    for(std::size_t e = 0; e < m; ++e) {
      const int n = local_variables(e, gi);
      slot_begin_[e + 1] = slot_begin_[e] + n * n;
    }
    slots_.resize(slot_begin_.back());
    auto offset_in_column = [&](int g, int h) { // first row of group h in the columns of group g
      const auto it = std::lower_bound(nb.begin() + first[g], nb.begin() + first[g + 1], h,
                                       [&](int p, int q) { return gstart[p] < gstart[q]; });
      return row_offset[it - nb.begin()];
    };
    for(std::size_t e = 0; e < m; ++e) {
      const int n = local_variables(e, gi);
      if(n == 0)
        continue;
      const int g0 = group_of[gi[0]], g1 = group_of[gi[n - 1]];
      const int off[2][2] = {{offset_in_column(g0, g0), offset_in_column(g0, g1)},
                             {offset_in_column(g1, g0), offset_in_column(g1, g1)}};
      for(int j = 0; j < n; ++j) {
        const int col = gi[j], gc = group_of[col];
        for(int i = 0; i < n; ++i) {
          const int gr = group_of[gi[i]];
          slots_[slot_begin_[e] + i * n + j] = outer[col] + off[gc == g1][gr == g1] + (gi[i] - gstart[gr]);
        }
      }
    }
  }

  static void project_psd(Eigen::Matrix4d& M, int n)
  {
    if(n == 1) {
      if(M(0, 0) < 0) M(0, 0) = 0;
      return;
    }
    if(n == 4) { // most blocks are definite already: a Cholesky attempt is much cheaper than eigenvalues
      Eigen::LLT<Eigen::Matrix4d> llt(M);
      if(llt.info() == Eigen::Success)
        return;
    }
    if(n == 2) {
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> es(M.topLeftCorner<2, 2>());
      if(es.eigenvalues().minCoeff() >= 0) return;
      Eigen::Vector2d l = es.eigenvalues().cwiseMax(0.0);
      M.topLeftCorner<2, 2>() = es.eigenvectors() * l.asDiagonal() * es.eigenvectors().transpose();
      return;
    }
    if(n == 3) {
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(M.topLeftCorner<3, 3>());
      if(es.eigenvalues().minCoeff() >= 0) return;
      Eigen::Vector3d l = es.eigenvalues().cwiseMax(0.0);
      M.topLeftCorner<3, 3>() = es.eigenvectors() * l.asDiagonal() * es.eigenvectors().transpose();
      return;
    }
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix4d> es(M);
    if(es.eigenvalues().minCoeff() >= 0) return;
    Eigen::Vector4d l = es.eigenvalues().cwiseMax(0.0);
    M = es.eigenvectors() * l.asDiagonal() * es.eigenvectors().transpose();
  }

  const Flat_problem& P_;
  mutable std::vector<double> g_abs_;
  mutable Eigen::SparseMatrix<double> pattern_;
  mutable Eigen::Index pattern_nnz_ = 0;
  mutable bool pattern_given_ = false;
  mutable std::vector<int> slot_begin_, slots_;
  mutable std::vector<double> edge_energy_, edge_gradient_, edge_hessian_;
  mutable std::size_t hessian_offset_ = 0; // slot of the first edge of the chunk in edge_hessian_
  mutable std::vector<double> terms_x_;     // the point of the last evaluate(): the per-edge terms are its
  mutable std::vector<double> noise_;       // rounding_noise() there, once computed
};

// Preconditioner of the Newton systems: the Hessian of E = (1/2) sum w d^2 is, for short
// edges, close to the Hermitian form sum_e w |xi_a - xi_b|^2 of the tangent vectors
// xi = lambda(z) dz measured in the hyperbolic metric (lambda = 2 / (1 - |z|^2)); a seam
// copy z' = m(z) moves by m'(z) dz, i.e. by the same hyperbolic length turned by
// rho = m'/|m'|, and a disk-border vertex moves along its side, xi = lambda z'(t) dt.
// So H ~ S^T A S, with S the diagonal metric scaling and A the complex "connection
// Laplacian" (one complex unknown per vertex owning variables; entries -w conj(rho_a) rho_b).
// A is factored once (complex LDL^T, n x n: the size of the scalar Laplacian) and applied as
// S^-1 A^-1 S^-T, the scaling at the current iterate. A one-dimensional border variable
// takes the real part of its solution (the preconditioner stays symmetric positive definite).
class Connection_laplacian_preconditioner
{
public:
  typedef std::complex<double> Cd;
  typedef Eigen::SparseMatrix<Cd> CMat;

  // `interior`: the initialisation's factored interior Laplacian, used for the gauge (else
  // the preconditioner factors a real Laplacian of its own for it)
  //
  // `share_interior`: the vertices off the border loop are numbered first, the border's nodes
  // after them, and the factorisation keeps the first before the others (constrained AMD).
  // There is no rotation between two interior vertices, so the leading block is
  // the Laplacian of the interior with the border fixed, and its factor the leading block of
  // the factor: `solve_interior()` serves the initialisation and the gauge with no
  // factorisation of their own. Where that order cannot be kept or fills the factor too much
  // (a long cut, many landmarks: see Laplacian_factorization::analyze) the first `factor()`
  // returns false without factoring: the caller then factors the interior Laplacian itself.
  explicit Connection_laplacian_preconditioner(const Flat_problem& P, const Interior_laplacian* interior = nullptr,
                                               bool share_interior = false, double max_fill = 1.0)
    : P_(P), interior_(interior)
  {
    node_.assign(P.n, -1);
    copy_.assign(P.n, -1);
    std::vector<char> on_loop(P.n, 0);
    for(int v : P.border_loop)
      on_loop[v] = 1;
    for(int v = 0; v < P.n; ++v) {
      if(P.kind[v] == Transformed) {
        copy_[P.twin[v]] = v;
        has_seams_ = true;
      } else if(!on_loop[v] && P.kind[v] != Free) {
        share_interior = false; // (not met: the vertices off the loop are all free)
      }
    }
    if(share_interior) {
      for(int v = 0; v < P.n; ++v)
        if(!on_loop[v])
          node_[v] = n_interior_++;
      n_nodes_ = n_interior_;
      solver_.keep_leading_block(n_interior_, max_fill); // (ordered by constrained AMD there)
    }
    for(int v = 0; v < P.n; ++v)
      if((P.kind[v] == Free || P.kind[v] == On_line) && node_[v] < 0)
        node_[v] = n_nodes_++;
    owner_.assign(n_nodes_, -1);
    for(int v = 0; v < P.n; ++v)
      if(node_[v] >= 0)
        owner_[node_[v]] = v;
    shares_ = share_interior;
    if(interior_ && (interior_->index.size() != static_cast<std::size_t>(P.n) || !interior_->own_factor ||
                     !interior_->solver.definite()))
      interior_ = nullptr;
  }

  const Flat_problem& problem() const { return P_; }

  // the first factor() kept the interior's block: solve_interior() works
  bool shares_interior() const { return shares_; }
  // position of v among the interior unknowns of solve_interior() (-1: border)
  int interior_index(int v) const { return shares_ && node_[v] >= 0 && node_[v] < n_interior_ ? node_[v] : -1; }
  int interior_size() const { return n_interior_; }

  // solves with the interior Laplacian (the border fixed), in interior_index() order
  bool solve_interior(const Eigen::VectorXcd& b, Eigen::VectorXcd& x) const
  {
    if(!shares_ || !factored_)
      return false;
    x = solver_.solve_leading(b);
    return x.size() == b.size() && x.allFinite();
  }

  // factored with the seam rotations at x (the matrix depends on x through them only)
  bool factored_at(const std::vector<double>& x) const
  {
    if(!factored_)
      return false;
    for(int v = 0; v < P_.n; ++v)
      if(P_.kind[v] == Transformed && !(rotation(v, x) == rho0_[v]))
        return false;
    return true;
  }

  // assembles A with the seam rotations at x and factors it (symbolic analysis once)
  bool factor(const std::vector<double>& x)
  {
    std::vector<Eigen::Triplet<Cd> > trip;
    trip.reserve(4 * P_.edges.size() + n_nodes_);
    std::vector<double> diag(n_nodes_, 0.0);
    for(std::size_t e = 0; e < P_.edges.size(); ++e) {
      const int a = P_.edges[e][0], b = P_.edges[e][1];
      const int na = node_of(a), nb = node_of(b);
      const double w = P_.edge_weight[e];
      const Cd ra = rotation(a, x), rb = rotation(b, x);
      if(na >= 0 && nb >= 0 && na == nb) {
        diag[na] += w * std::norm(ra - rb);
        continue;
      }
      if(na >= 0) diag[na] += w;
      if(nb >= 0) diag[nb] += w;
      if(na >= 0 && nb >= 0) {
        const Cd v = -w * std::conj(ra) * rb;
        trip.emplace_back(na, nb, v);
        trip.emplace_back(nb, na, std::conj(v));
      }
    }
    for(int i = 0; i < n_nodes_; ++i)
      trip.emplace_back(i, i, Cd(diag[i], 0.0));
    CMat A(n_nodes_, n_nodes_);
    A.setFromTriplets(trip.begin(), trip.end());
    std::vector<Eigen::Triplet<Cd> >().swap(trip); // (freed before the factorisation: 0.3 GB at a million vertices)
    if(!analyzed_) {
      analyzed_ = true;
      if(!solver_.analyze(A) && shares_) {
        shares_ = false; // (only the initialisation asks to share: it factors its own Laplacian instead)
        return factored_ = false;
      }
    }
    if(has_seams_ && !interior_ && !shares_ && !gauge_factored_) {
      gauge_factored_ = true;
      // the real Laplacian (no rotations) for the gauge
      Eigen::SparseMatrix<double> L = A.real();
      for(std::size_t e = 0; e < P_.edges.size(); ++e) {
        const int a = P_.edges[e][0], b = P_.edges[e][1];
        const int na = node_of(a), nb = node_of(b);
        if(na >= 0 && na == nb) L.coeffRef(na, na) -= P_.edge_weight[e] * std::norm(rotation(a, x) - rotation(b, x));
        else if(na >= 0 && nb >= 0) L.coeffRef(na, nb) = L.coeffRef(nb, na) = 0.0;
      }
      for(std::size_t e = 0; e < P_.edges.size(); ++e) {
        const int na = node_of(P_.edges[e][0]), nb = node_of(P_.edges[e][1]);
        if(na >= 0 && nb >= 0 && na != nb) { L.coeffRef(na, nb) -= P_.edge_weight[e]; L.coeffRef(nb, na) -= P_.edge_weight[e]; }
      }
      gauge_solver_.compute(L);
    }
    solver_.factorize(A);
    rho0_.assign(P_.n, Cd(1.0, 0.0));
    for(int v = 0; v < P_.n; ++v)
      if(P_.kind[v] == Transformed)
        rho0_[v] = rotation(v, x);
    factored_ = solver_.definite();
    if(factored_ && single_precision_)
      solver_.round_to_single_precision();
    return factored_;
  }

  // From now on (and after every new factorisation) the solves use the factor rounded to
  // single precision where it is CHOLMOD's (see Laplacian_factorization::round_to_single_precision)
  void solve_in_single_precision()
  {
    single_precision_ = true;
    if(factored_)
      solver_.round_to_single_precision();
  }
  bool solves_in_single_precision() const { return solver_.single_precision(); }

  // the metric scaling at x
  void set_scaling(const std::vector<double>& x)
  {
    scale_.resize(n_nodes_);
    Position_jet j;
    for(int i = 0; i < n_nodes_; ++i) {
      const int v = owner_[i];
      if(P_.kind[v] == Free) {
        const double r2 = x[P_.var[v]] * x[P_.var[v]] + x[P_.var[v] + 1] * x[P_.var[v] + 1];
        scale_[i] = Cd(2.0 / (1.0 - r2), 0.0);
      } else {
        position_jet(P_, x, v, j);
        const double lambda = 2.0 / (1.0 - norm(j.z));
        scale_[i] = Cd(lambda * j.dz[0].re, lambda * j.dz[0].im);
      }
    }
    // gauge: the seam rotations have turned by delta since the factorisation; spread the
    // turn smoothly over the mesh, so that psi jumps by delta across the seam
    gauge_.assign(n_nodes_, Cd(1.0, 0.0));
    if(!has_seams_) return;
    std::vector<double> delta(P_.n, 0.0);
    bool any = false;
    for(int v = 0; v < P_.n; ++v)
      if(P_.kind[v] == Transformed) {
        delta[v] = std::arg(rotation(v, x) / rho0_[v]);
        any = any || delta[v] != 0;
      }
    if(!any) return;
    if(interior_ || shares_) {
      // harmonic in the interior, +delta/2 on a seam vertex's side, -delta/2 on its twin's
      // side (the interior Laplacian with the border fixed: the leading block of this
      // factorisation, or the initialisation's)
      auto border_value = [&](int v) {
        if(P_.kind[v] == Transformed) return -delta[v] / 2;
        if(P_.kind[v] == Free && copy_[v] >= 0) return delta[copy_[v]] / 2;
        return 0.0;
      };
      auto index = [&](int v) { return shares_ ? interior_index(v) : interior_->index[v]; };
      Eigen::VectorXd rhs = Eigen::VectorXd::Zero(shares_ ? n_interior_ : interior_->size);
      for(std::size_t e = 0; e < P_.edges.size(); ++e) {
        const int a = P_.edges[e][0], b = P_.edges[e][1];
        const int ia = index(a), ib = index(b);
        if(ia >= 0 && ib < 0) rhs[ia] += P_.edge_weight[e] * border_value(b);
        else if(ib >= 0 && ia < 0) rhs[ib] += P_.edge_weight[e] * border_value(a);
      }
      Eigen::VectorXd psi;
      if(shares_) {
        Eigen::VectorXcd c;
        if(!solve_interior(rhs.cast<Cd>(), c))
          return; // (cannot happen once factored; no gauge is a valid, weaker, preconditioner)
        psi = c.real();
      } else {
        psi = interior_->solver.solve(rhs);
      }
      for(int i = 0; i < n_nodes_; ++i) {
        const int v = owner_[i], ii = index(v);
        gauge_[i] = std::polar(1.0, ii >= 0 ? psi[ii] : border_value(v));
      }
      return;
    }
    // least squares over the edges: L psi = div delta
    Eigen::VectorXd rhs = Eigen::VectorXd::Zero(n_nodes_);
    for(std::size_t e = 0; e < P_.edges.size(); ++e) {
      const int a = P_.edges[e][0], b = P_.edges[e][1];
      const int na = node_of(a), nb = node_of(b);
      if(na < 0 || nb < 0 || na == nb) continue;
      const double D = P_.edge_weight[e] * (delta[b] - delta[a]);
      rhs[nb] += D;
      rhs[na] -= D;
    }
    const Eigen::VectorXd psi = gauge_solver_.solve(rhs);
    for(int i = 0; i < n_nodes_; ++i)
      gauge_[i] = std::polar(1.0, psi[i]);
  }

  // z = S^-1 A^-1 S^-T r
  void apply(const Eigen::VectorXd& r, Eigen::VectorXd& z) const
  {
    Eigen::VectorXcd b(n_nodes_);
    for(int i = 0; i < n_nodes_; ++i) {
      const int v = owner_[i], k = P_.var[v];
      if(P_.kind[v] == Free)
        b[i] = Cd(r[k], r[k + 1]) / scale_[i].real();
      else
        b[i] = scale_[i] * (r[k] / std::norm(scale_[i]));
    }
    for(int i = 0; i < n_nodes_; ++i)
      b[i] *= gauge_[i];
    Eigen::VectorXcd xi = solver_.solve(b);
    for(int i = 0; i < n_nodes_; ++i)
      xi[i] *= std::conj(gauge_[i]);
    z.resize(r.size());
    for(int i = 0; i < n_nodes_; ++i) {
      const int v = owner_[i], k = P_.var[v];
      if(P_.kind[v] == Free) {
        z[k] = xi[i].real() / scale_[i].real();
        z[k + 1] = xi[i].imag() / scale_[i].real();
      } else {
        z[k] = std::real(std::conj(scale_[i]) * xi[i]) / std::norm(scale_[i]);
      }
    }
  }

private:
  int node_of(int v) const { return P_.kind[v] == Transformed ? node_[P_.twin[v]] : node_[v]; }

  // how a tangent vector of the owner turns on its way to this copy
  Cd rotation(int v, const std::vector<double>& x) const
  {
    if(P_.kind[v] != Transformed)
      return Cd(1.0, 0.0);
    Position_jet j;
    position_jet(P_, x, v, j);
    const double m = abs(j.dz[0]);
    return Cd(j.dz[0].re / m, j.dz[0].im / m);
  }

  const Flat_problem& P_;
  std::vector<int> node_, owner_;
  int n_nodes_ = 0, n_interior_ = 0;
  const Interior_laplacian* interior_;
  bool shares_ = false, factored_ = false, single_precision_ = false;
  std::vector<int> copy_;      // the seam twin of a vertex, -1 if none
  bool has_seams_ = false, gauge_factored_ = false;
  std::vector<Cd> scale_, gauge_, rho0_;
  Laplacian_factorization<double> gauge_solver_;
  Laplacian_factorization<Cd> solver_;
  bool analyzed_ = false;
};

// Places the border: cone copies at their corners, other border vertices along their
// tile side at the fraction of the 3D arc length between the side's corners (sphere:
// p-side vertices on the side's geodesic, their twins follow by the pairing; disk: the
// parameter t of the Klein segment). Interior vertices: Euclidean Tutte embedding in the
// Klein model with the same weights (paper, section 5), mapped back to Poincare.
template <class Point3, class Tile>
Error_code initialize_embedding(const Flat_problem& P, const Tile& tile, const std::vector<Point3>& base_points,
                                std::vector<double>& x, Interior_laplacian* keep = nullptr)
{
  Interior_laplacian local;
  Interior_laplacian& lap = keep ? *keep : local;
  typedef Complex<double> C;
  typedef Hyperbolic_isometry_2<double> Isometry;
  x.assign(P.n_vars, 0.0);
  const std::vector<int>& loop = P.border_loop;
  const int L = static_cast<int>(loop.size());
  auto dist3 = [&](int a, int b) {
    const Point3& p = base_points[P.base[a]];
    const Point3& q = base_points[P.base[b]];
    const double dx = CGAL::to_double(p.x()) - CGAL::to_double(q.x()), dy = CGAL::to_double(p.y()) - CGAL::to_double(q.y()),
                 dz = CGAL::to_double(p.z()) - CGAL::to_double(q.z());
    return std::sqrt(dx * dx + dy * dy + dz * dz);
  };
  // arc-length fraction along each side
  std::vector<double> frac(P.n, 0.0);
  {
    int i = 0;
    while(i < L) {
      int j = i + 1;
      while(j < L && P.corner[loop[j]] < 0)
        ++j;
      // corners at loop[i] and loop[j % L]
      std::vector<double> acc(1, 0.0);
      for(int q = i; q < j; ++q)
        acc.push_back(acc.back() + dist3(loop[q], loop[(q + 1) % L]));
      const double total = acc.back() > 0 ? acc.back() : 1.0;
      for(int q = i + 1; q < j; ++q)
        frac[loop[q]] = acc[q - i] / total;
      i = j;
    }
  }
  std::vector<C> z(P.n);
  std::vector<char> is_border(P.n, 0);
  for(int v : loop)
    is_border[v] = 1;
  for(int v : loop) {
    if(P.corner[v] >= 0) {
      z[v] = P.fixed[v];
    } else if(P.kind[v] == Free) { // sphere p-side: on the side's geodesic
      const int s = P.side[v];
      const auto& a = tile.corner(tile.side_source(s));
      const auto& b = tile.corner(tile.side_target(s));
      const C ca(CGAL::to_double(a.x()), CGAL::to_double(a.y())), cb(CGAL::to_double(b.x()), CGAL::to_double(b.y()));
      const Isometry to0 = Isometry::translation_to_origin(ca);
      const C b0 = to0.apply(cb);
      const double r = abs(b0);
      const double rr = std::tanh(frac[v] * std::atanh(r));
      z[v] = to0.inverse().apply(b0 * (rr / r));
      x[P.var[v]] = z[v].re;
      x[P.var[v] + 1] = z[v].im;
    } else if(P.kind[v] == On_line) {
      x[P.var[v]] = frac[v];
    }
  }
  for(int v : loop)
    if(P.kind[v] == Transformed || P.kind[v] == On_line)
      z[v] = position(P, x, v);

  // Tutte in Klein coordinates. The interior Laplacian is the leading block of the solver's
  // connection Laplacian (its rotations depend on the border's positions only, placed above):
  // where that block can be kept at little cost, the solver's factorisation is made here and
  // serves both (else the analysis alone was spent, a few percent of a factorisation).
  std::vector<int>& interior_index = lap.index;
  interior_index.assign(P.n, -1);
  lap.own_factor = false;
  lap.connection.reset();
  if(lap.share && P.n >= lap.share_from) {
    auto pre = std::make_shared<Connection_laplacian_preconditioner>(P, nullptr, true, lap.share_max_fill);
    if(pre->factor(x) && pre->shares_interior())
      lap.connection = pre;
  }
  int ni = 0;
  for(int v = 0; v < P.n; ++v)
    if(!is_border[v])
      interior_index[v] = lap.connection ? lap.connection->interior_index(v) : ni++;
  if(lap.connection)
    ni = lap.connection->interior_size();
  lap.size = ni;
  if(ni > 0) {
    typedef Eigen::SparseMatrix<double> SpMat;
    const bool own = !lap.connection; // a factorisation of its own
    std::vector<Eigen::Triplet<double> > trip;
    if(own)
      trip.reserve(4 * P.edges.size() + ni);
    Eigen::MatrixXd bxy = Eigen::MatrixXd::Zero(ni, 2); // both coordinates: one solve of two columns
    auto bx = bxy.col(0);
    auto by = bxy.col(1);
    std::vector<double> diag(own ? ni : 0, 0.0);
    auto klein = [](const C& p) { return p * (2.0 / (1.0 + norm(p))); };
    for(std::size_t e = 0; e < P.edges.size(); ++e) {
      const int a = P.edges[e][0], b = P.edges[e][1];
      const double w = P.edge_weight[e];
      const int ia = interior_index[a], ib = interior_index[b];
      if(ia >= 0 && own) diag[ia] += w;
      if(ib >= 0 && own) diag[ib] += w;
      if(ia >= 0 && ib >= 0) {
        if(!own)
          continue;
        trip.emplace_back(ia, ib, -w);
        trip.emplace_back(ib, ia, -w);
      } else if(ia >= 0) {
        const C kb = klein(z[b]);
        bx[ia] += w * kb.re;
        by[ia] += w * kb.im;
      } else if(ib >= 0) {
        const C ka = klein(z[a]);
        bx[ib] += w * ka.re;
        by[ib] += w * ka.im;
      }
    }
    Eigen::MatrixXd kxy;
    if(!own) { // both coordinates as one complex right-hand side
      Eigen::VectorXcd k;
      if(!lap.connection->solve_interior(bxy.col(0).cast<std::complex<double> >() +
                                           std::complex<double>(0.0, 1.0) * bxy.col(1).cast<std::complex<double> >(), k))
        return ERROR_CANNOT_SOLVE_LINEAR_SYSTEM;
      kxy.resize(ni, 2);
      kxy.col(0) = k.real();
      kxy.col(1) = k.imag();
    } else {
      for(int i = 0; i < ni; ++i)
        trip.emplace_back(i, i, diag[i]);
      SpMat Lm(ni, ni);
      Lm.setFromTriplets(trip.begin(), trip.end());
      std::vector<Eigen::Triplet<double> >().swap(trip); // (freed before the factorisation)
      auto& solver = lap.solver;
      solver.compute(Lm);
      lap.own_factor = true;
      if(!solver.definite())
        return ERROR_CANNOT_SOLVE_LINEAR_SYSTEM;
      kxy = solver.solve(bxy);
      if(solver.info() != Eigen::Success)
        return ERROR_CANNOT_SOLVE_LINEAR_SYSTEM;
    }
    const auto kx = kxy.col(0);
    const auto ky = kxy.col(1);
    for(int v = 0; v < P.n; ++v) {
      const int i = interior_index[v];
      if(i < 0)
        continue;
      const C k(kx[i], ky[i]);
      const double s = 1.0 - norm(k);
      if(!(s > 0) || !std::isfinite(k.re) || !std::isfinite(k.im))
        return ERROR_CANNOT_SOLVE_LINEAR_SYSTEM;
      const C p = k / (1.0 + std::sqrt(s));
      if(P.kind[v] == Free) {
        x[P.var[v]] = p.re;
        x[P.var[v] + 1] = p.im;
      }
    }
  }
  return OK;
}

// The energy is geodesically convex, its Hessian in the disk's coordinates is not: this
// subtracts the Christoffel terms of the metric (2/(1-|z|^2))^2 |dz|^2 at each free vertex,
// Hess_ij = d_ij E - (s_i g_j + s_j g_i - delta_ij s.g), s = grad log(2/(1-|z|^2)) =
// 2z/(1-|z|^2), g the gradient: the Riemannian Hessian, positive semi-definite, equal to the
// exact one where g = 0 (Newton stays quadratic); v^T Hess v is the second derivative of E
// along the geodesics of initial velocities v. (Seam copies follow their twin through an
// isometry, so the twin's terms cover them; border parameters keep the coordinate Hessian.)
inline void subtract_christoffel_terms(const Flat_problem& P, const std::vector<double>& x, const std::vector<double>& g,
                                       Eigen::SparseMatrix<double>& H)
{
  for(int v = 0; v < P.n; ++v) {
    if(P.kind[v] != Free)
      continue;
    const int i = P.var[v];
    const double q = 2 / (1 - (x[i] * x[i] + x[i + 1] * x[i + 1]));
    const double s0 = q * x[i], s1 = q * x[i + 1], g0 = g[i], g1 = g[i + 1];
    const double sg = s0 * g0 + s1 * g1;
    H.coeffRef(i, i) -= 2 * s0 * g0 - sg;
    H.coeffRef(i + 1, i + 1) -= 2 * s1 * g1 - sg;
    H.coeffRef(i, i + 1) -= s0 * g1 + s1 * g0;
    H.coeffRef(i + 1, i) -= s0 * g1 + s1 * g0;
  }
}

// Minimises the energy with a backtracking (Armijo) line search, in up to two phases:
//  1. (only with Solver_options::gradient_steps) Preconditioned gradient steps
//     p = -M^-1 g with the connection Laplacian M at the current scaling: no Hessian, one
//     triangular solve per step. M is so close to the Hessian that these steps converge
//     fast while the energy is far from its minimum.
//  2. Riemannian Newton: the exact Riemannian Hessian (subtract_christoffel_terms), steps
//     along geodesics, the systems solved by conjugate gradients preconditioned by M,
//     refactored when it no longer fits (truncated Newton, relative tolerance
//     min(1/2, sqrt(force imbalance)): inexact far from the solution, superlinear near it).
// Where the Hessian is not definite after all (border parameters, rounding; negative
// curvature met by CG), the Hessian projected edge by edge onto the positive semi-definite
// cone is used instead. Should the iterative solves stall, or the connection Laplacian not
// factor, the Hessian is factored directly (sparse LDL^T, symbolic analysis once): the
// former, slower, solver. The solver stops at the tolerance, or at the rounding floor (see
// Energy_evaluator::rounding_floor) when Newton stagnates above the tolerance.
inline Error_code minimize_energy(const Flat_problem& P, std::vector<double>& x, const Solver_options& opt,
                                  Solver_statistics& st, const Interior_laplacian* interior = nullptr)
{
  typedef Complex<double> C;
  typedef Eigen::SparseMatrix<double> SpMat;
  typedef std::chrono::steady_clock Clock;
  auto seconds = [](Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); };
  st = Solver_statistics();
  if(P.n_vars == 0) {
    st.converged = true;
    return OK;
  }
  const int nv = P.n_vars;
  std::vector<double> g, xn(nv), gn;
  SpMat H;
  Eigen::SimplicialLDLT<SpMat, Eigen::Lower, Eigen::AMDOrdering<int> > direct;
  bool direct_analyzed = false;
  // the initialisation's preconditioner where it made one for this problem (it is factored
  // again here only if the seam rotations have changed since), else one of our own
  std::unique_ptr<Connection_laplacian_preconditioner> own_pre;
  Connection_laplacian_preconditioner* pre_ptr = interior ? interior->connection.get() : nullptr;
  if(pre_ptr == nullptr || &pre_ptr->problem() != &P) {
    own_pre.reset(new Connection_laplacian_preconditioner(P, interior));
    pre_ptr = own_pre.get();
  }
  Connection_laplacian_preconditioner& pre = *pre_ptr;
  bool use_direct = opt.direct_solver;
  auto t0 = Clock::now();
  if(!use_direct && !pre.factored_at(x) && !pre.factor(x))
    use_direct = true;
  if(opt.single_precision_preconditioner)
    pre.solve_in_single_precision();
  st.time_factor += seconds(t0);
  // (the Hessian's pattern only now: a factor rounded to single precision has shrunk)
  Energy_evaluator ev(P);

  // per-variable weights of the hyperbolic norm of a gradient (or residual)
  Eigen::VectorXd hw(nv);
  auto set_norm_weights = [&]() {
    Position_jet j;
    for(int v = 0; v < P.n; ++v) {
      if(P.kind[v] == Free) {
        const int i = P.var[v];
        hw[i] = hw[i + 1] = (1 - (x[i] * x[i] + x[i + 1] * x[i + 1])) / 2;
      } else if(P.kind[v] == On_line) {
        position_jet(P, x, v, j);
        hw[P.var[v]] = (1 - norm(j.z)) / (2 * abs(j.dz[0]));
      }
    }
  };

  enum Phase { Model, Projected, Exact };
  Phase phase = use_direct ? Projected : (opt.polish || !opt.gradient_steps) ? Exact : Model;
  bool polishing = opt.polish;
  double tolerance = polishing ? 0.0 : opt.gradient_tolerance;
  int polish_start = 0;
  auto assemble = [&]() { // gradient, and the Hessian the phase needs
    auto t = Clock::now();
    const double e = ev.evaluate(x, g, phase == Model ? nullptr : &H, phase == Projected);
    if(phase == Exact && opt.riemannian_hessian)
      subtract_christoffel_terms(P, x, g, H);
    st.time_assemble += seconds(t);
    return e;
  };
  double E = assemble();
  st.initial_energy = E;
  st.initial_gradient = ev.hyperbolic_gradient_norm(x, g);
  const double g0 = st.initial_gradient > 0 ? st.initial_gradient : 1.0;
  double gnorm = st.initial_gradient;
  double grel = ev.hyperbolic_gradient_norm(x, g, true);
  int stalls = 0, last_cg = 0, slow_steps = 0, refactorings = 0;
  bool stagnated = false;
  double best_grel = grel;
  int since_best = 0;
  Eigen::VectorXd p(nv), r(nv), zv(nv), d(nv), Hd(nv);
  for(int it = 0; it < opt.max_iterations; ++it) {
    if(grel <= tolerance) {
      // converged as a whole; every vertex too? (a region squeezed to 1e-12 has forces too
      // small for the global imbalance to see): if not, Newton on, until it is or to the floor
      if(polishing || !(opt.vertex_imbalance > 0) || ev.unbalanced_vertices(x, g, opt.vertex_imbalance) == 0)
        break;
      polishing = true;
      tolerance = 0.0;
      polish_start = it;
      best_grel = grel;
      since_best = 0;
      if(phase != Exact) {
        phase = Exact;
        E = assemble();
      }
    } else if(polishing && opt.vertex_imbalance > 0 && ev.unbalanced_vertices(x, g, opt.vertex_imbalance) == 0) {
      break; // every vertex balanced, or at its rounding floor
    }
    // Near the solution Newton with the exact Hessian halves the imbalance at least every
    // few steps until rounding stops it: ten steps without that mean the floor of double
    // precision (three when polishing: Newton starts there next to the solution)
    if(grel < 0.5 * best_grel || phase != Exact || grel > 1e-6) {
      best_grel = std::min(best_grel, grel);
      since_best = 0;
    } else if(++since_best > (polishing ? 3 : 10) ||
              (since_best >= 3 && grel <= 10 * ev.rounding_floor(x))) { // (evaluates at x: g unchanged)
      stagnated = true;
      break;
    }
    auto t1 = Clock::now();
    Eigen::Map<const Eigen::VectorXd> gv(g.data(), nv);
    bool ok = false;
    if(phase == Model) {
      pre.set_scaling(x);
      r = -gv;
      pre.apply(r, p);
      ok = p.allFinite() && gv.dot(p) < 0;
    } else if(!use_direct) {
      if(phase == Projected) {
        // a tiny diagonal shift keeps the system definite where a projected block is singular
        double maxd = 0;
        for(int i = 0; i < nv; ++i)
          maxd = std::max(maxd, H.coeff(i, i));
        for(int i = 0; i < nv; ++i)
          H.coeffRef(i, i) += 1e-12 * maxd + 1e-300;
      }
      if(last_cg > opt.refactor_cg_iterations) { // the preconditioner has drifted away
        if(!pre.factor(x)) {
          use_direct = true;
          st.time_factor += seconds(t1);
          continue;
        }
        ++st.preconditioner_factorizations;
      }
      // preconditioned conjugate gradients on H p = -g, residual in the hyperbolic norm;
      // superlinear tolerance (sqrt), but no more accurate than the stopping test needs
      set_norm_weights();
      pre.set_scaling(x);
      const double eta = std::max(std::min(0.5, std::sqrt(grel)), std::min(0.5, 0.25 * tolerance / grel));
      const double target = eta * (gv.cwiseProduct(hw)).norm();
      p.setZero();
      r = -gv;
      pre.apply(r, zv);
      d = zv;
      double rz = r.dot(zv);
      bool negative_curvature = false, reached = false;
      int k = 0;
      for(; k < opt.max_cg_iterations; ++k) {
        Hd.noalias() = H * d;
        const double dHd = d.dot(Hd);
        if(!(dHd > 0)) {
          negative_curvature = true;
          break;
        }
        const double alpha = rz / dHd;
        p += alpha * d;
        r -= alpha * Hd;
        if(r.cwiseProduct(hw).norm() <= target) {
          reached = true;
          ++k;
          break;
        }
        pre.apply(r, zv);
        const double rz_new = r.dot(zv);
        d = zv + (rz_new / rz) * d;
        rz = rz_new;
      }
      st.cg_iterations += k;
      last_cg = k;
      if(negative_curvature && phase == Exact) { // back to the projected Hessian
        st.time_factor += seconds(t1);
        phase = Projected;
        last_cg = 0;
        E = assemble();
        continue;
      }
      if(k == 0) // negative curvature along the first direction: the preconditioned gradient
        p = zv;
      ok = p.allFinite() && gv.dot(p) < 0;
      if(!reached && !negative_curvature && ++st.cg_failures > 2)
        use_direct = true; // the preconditioner does not fit this problem
    }
    if(use_direct && phase != Model) {
      if(!direct_analyzed) {
        direct.analyzePattern(H);
        direct_analyzed = true;
      }
      direct.factorize(H);
      ok = direct.info() == Eigen::Success;
      if(ok && phase == Exact) // LDLT of an indefinite matrix "succeeds": check the pivots
        ok = (direct.vectorD().array() > 0).all();
      if(ok) {
        p = direct.solve(-gv);
        if(phase == Exact && direct.info() == Eigen::Success) {
          // one step of iterative refinement: the exact Hessian can be badly conditioned
          const Eigen::VectorXd res = -gv - H * p;
          p += direct.solve(res);
        }
        ok = direct.info() == Eigen::Success && p.allFinite() && gv.dot(p) < 0;
      }
    }
    st.time_factor += seconds(t1);
    if(!ok) {
      if(phase != Projected) { // to the projected Hessian
        phase = Projected;
        E = assemble();
        continue;
      }
      return ERROR_CANNOT_SOLVE_LINEAR_SYSTEM;
    }
    const double slope = gv.dot(p);
    auto t2 = Clock::now();
    double alpha = 1.0, En = 0;
    bool accepted = false;
    double gnorm_new = gnorm;
    for(int ls = 0; ls < 60; ++ls) {
      for(int i = 0; i < nv; ++i)
        xn[i] = x[i] + alpha * p[i];
      if(opt.geodesic_steps && phase != Projected) {
        // free vertices move along the geodesic of their step, by its hyperbolic length
        // (the exponential map): a long step near the circle then bends instead of leaving
        // the disk, and the line search need not shorten every vertex's step for it. Same
        // first-order step, so the Armijo test is unchanged; with the Riemannian Hessian
        // this is Riemannian Newton, whose steps stay long where straight ones must be cut
        // to 1/128 (stiff cotangent weights of 1e5 near the circle: 20 steps instead of 190).
        // Not for the projected Hessian: it models the energy along straight lines.
        for(int v = 0; v < P.n; ++v) {
          if(P.kind[v] != Free)
            continue;
          const int i = P.var[v];
          const C z(x[i], x[i + 1]), d(alpha * p[i], alpha * p[i + 1]);
          const double len = abs(d);
          if(!(len > 0))
            continue;
          const double L = 2 * len / (1 - norm(z));
          const C w = d * (std::tanh(L / 2) / len);
          const C y = (w + z) / (C(1.0) + conj(z) * w);
          xn[i] = y.re;
          xn[i + 1] = y.im;
        }
      }
      if(ev.feasible(xn)) {
        En = ev.energy(xn);
        if(En <= E + 1e-4 * alpha * slope) {
          accepted = true;
          break;
        }
        // At the precision of the energy (about 1e-16 |E|) Armijo cannot see progress any
        // more; then a step is accepted when it reduces the gradient.
        if(std::abs(En - E) <= 1e-12 * std::abs(E)) {
          ev.evaluate(xn, gn, nullptr);
          gnorm_new = ev.hyperbolic_gradient_norm(xn, gn);
          if(gnorm_new < gnorm) {
            accepted = true;
            break;
          }
        }
      }
      alpha *= 0.5;
    }
    st.time_line_search += seconds(t2);
    st.iterations = it + 1;
    if(!accepted) {
      if(++stalls > 2) {
        stagnated = true;
        break; // no progress possible at this precision: let the tolerance decide
      }
      phase = phase == Projected ? Exact : Projected;
      E = assemble();
      continue;
    }
    stalls = 0;
    x.swap(xn);
    const double grel_prev = grel;
    E = assemble();
    gnorm = ev.hyperbolic_gradient_norm(x, g);
    grel = ev.hyperbolic_gradient_norm(x, g, true);
    if(opt.verbose)
      std::cerr << "  step " << it + 1 << (phase == Model ? " (preconditioned gradient)" : phase == Exact ? " (Newton)" : " (projected Newton)")
                << ": E = " << E << "  |grad|/|grad0| = " << gnorm / g0 << "  force imbalance " << grel << "  step " << alpha
                << "  cg " << st.cg_iterations << std::endl;
    // a gradient step the line search had to shorten: the embedding has moved far from where
    // the preconditioner was factored (seam rotations, long edges): factor it anew, at most
    // a few times; when gradient steps keep being slow, Newton takes over
    if(phase == Model && alpha < 0.3 && refactorings < opt.max_model_refactorizations) {
      auto t4 = Clock::now();
      if(pre.factor(x)) {
        ++st.preconditioner_factorizations;
        ++refactorings;
      } else {
        use_direct = true;
        phase = Projected;
      }
      st.time_factor += seconds(t4);
    }
    if(phase == Model && (alpha < 1.0 || grel > 0.8 * grel_prev))
      ++slow_steps;
    // to Newton with the exact Hessian near the solution
    if(phase != Exact && grel > tolerance &&
       ((gnorm / g0 < opt.newton_threshold && alpha == 1.0) || (phase == Model && slow_steps >= 3))) {
      phase = Exact;
      E = assemble();
    }
  }
  if(polishing)
    st.polishing_iterations = st.iterations - polish_start;
  st.energy = E;
  st.gradient = gnorm;
  st.relative_gradient = grel;
  st.rounding_floor = ev.rounding_floor(x);
  // Converged: the imbalance is below the tolerance or, where rounding makes that
  // impossible (Newton stagnates), within ten times what rounding the coordinates causes
  st.at_rounding_floor = stagnated && grel > opt.gradient_tolerance && grel <= 10 * st.rounding_floor;
  st.converged = st.relative_gradient <= opt.gradient_tolerance || st.at_rounding_floor;
  return st.converged ? OK : ERROR_NOT_CONVERGED;
}

// Newton on a region only: the vertices whose variables' owner is marked in `region`
// move, their neighbours stay where they are. The region's energy, gradient and linear
// solves are then at the region's own scale, which the whole problem's cannot see: a
// squeezed part of the embedding (a long protrusion without landmarks, 1e-20 across and
// shrinking along it) has forces 1e-20 times the largest ones, below the rounding of any
// global quantity. Returns the region's solver status.
inline Error_code minimize_energy_on_region(const Flat_problem& P, std::vector<double>& x, const std::vector<char>& region,
                                            const Solver_options& opt, Solver_statistics& st)
{
  auto moving = [&](int v) { return P.kind[v] != Fixed && region[owner_vertex(P, v)]; };
  // the region's vertices and their neighbours, in a problem of their own
  std::vector<int> local(P.n, -1), global;
  auto add = [&](int v) {
    if(local[v] < 0) {
      local[v] = static_cast<int>(global.size());
      global.push_back(v);
    }
  };
  Flat_problem Q;
  for(std::size_t e = 0; e < P.edges.size(); ++e) {
    const int a = P.edges[e][0], b = P.edges[e][1];
    if(!moving(a) && !moving(b))
      continue;
    add(a);
    add(b);
    if(P.kind[a] == Transformed) add(P.twin[a]);
    if(P.kind[b] == Transformed) add(P.twin[b]);
    Q.edges.push_back({a, b});
    Q.edge_weight.push_back(P.edge_weight[e]);
  }
  if(global.empty())
    return OK;
  for(auto& e : Q.edges)
    e = {local[e[0]], local[e[1]]};
  Q.type = P.type;
  Q.k = P.k;
  Q.n = static_cast<int>(global.size());
  Q.kind.assign(Q.n, Fixed);
  Q.var.assign(Q.n, -1);
  Q.twin.assign(Q.n, -1);
  Q.transform.assign(Q.n, Flat_problem::Isometry());
  Q.fixed.assign(Q.n, Flat_problem::C());
  Q.line_k0.assign(Q.n, Flat_problem::C());
  Q.line_D.assign(Q.n, Flat_problem::C());
  std::vector<double> xq;
  for(int i = 0; i < Q.n; ++i) { // variables of the owners first (a twin's index is needed below)
    const int v = global[i];
    if(!moving(v) || P.kind[v] == Transformed) {
      if(!moving(v))
        Q.fixed[i] = position(P, x, v);
      continue;
    }
    Q.kind[i] = P.kind[v];
    Q.var[i] = static_cast<int>(xq.size());
    xq.push_back(x[P.var[v]]);
    if(P.kind[v] == Free)
      xq.push_back(x[P.var[v] + 1]);
    else {
      Q.line_k0[i] = P.line_k0[v];
      Q.line_D[i] = P.line_D[v];
    }
  }
  for(int i = 0; i < Q.n; ++i) {
    const int v = global[i];
    if(moving(v) && P.kind[v] == Transformed) {
      Q.kind[i] = Transformed;
      Q.twin[i] = local[P.twin[v]];
      Q.transform[i] = P.transform[v];
    }
  }
  Q.n_vars = static_cast<int>(xq.size());
  const Error_code ec = minimize_energy(Q, xq, opt, st);
  for(int i = 0; i < Q.n; ++i) {
    const int v = global[i];
    if(Q.kind[i] == Free) {
      x[P.var[v]] = xq[Q.var[i]];
      x[P.var[v] + 1] = xq[Q.var[i] + 1];
    } else if(Q.kind[i] == On_line) {
      x[P.var[v]] = xq[Q.var[i]];
    }
  }
  return ec;
}

// exact test: the hyperbolic triangle (a, b, c) of the Poincare disk is positively oriented
inline bool positive_triangle(const Complex<double>& a, const Complex<double>& b, const Complex<double>& c)
{
  typedef Poincare_disk_traits_2<> Traits;
  return Traits().hyperbolic_orientation_2_object()(Traits::Point_2(a.re, a.im), Traits::Point_2(b.re, b.im),
                                                    Traits::Point_2(c.re, c.im)) == POSITIVE;
}

// The faces around each vertex (a seam copy's faces listed at its twin, whose variables it
// uses) and the exact test of a face's orientation at x: what the one-ring repairs check.
class One_ring_faces
{
public:
  explicit One_ring_faces(const Flat_problem& P) : P_(P), faces_(P.n)
  {
    for(std::size_t f = 0; f < P.faces.size(); ++f)
      for(int i = 0; i < 3; ++i)
        faces_[owner(P.faces[f][i])].push_back(static_cast<int>(f));
  }
  int owner(int v) const { return owner_vertex(P_, v); }
  bool positive(int f, const std::vector<double>& x) const
  {
    return positive_triangle(position(P_, x, P_.faces[f][0]), position(P_, x, P_.faces[f][1]),
                             position(P_, x, P_.faces[f][2]));
  }
  bool all_positive(int v, const std::vector<double>& x) const
  {
    for(int f : faces_[v])
      if(!positive(f, x))
        return false;
    return true;
  }

private:
  const Flat_problem& P_;
  std::vector<std::vector<int> > faces_;
};

// The paper's post-processing (section 5): every free vertex that is not inside the
// hyperbolic convex hull of its neighbours (detected by a non-positive incident face, exact
// test) is moved by a Mobius map to the origin with its one-ring, put at the Euclidean
// weighted centroid of its neighbours there, and moved back; repeated until no face is
// flipped, or `max_sweeps` sweeps, or ten sweeps without fewer vertices to move (a region
// below what double resolves). Seam vertices see their neighbours across the seam
// through the side pairing. Returns the number of vertex moves.
inline int repair_one_rings(const Flat_problem& P, std::vector<double>& x, int max_sweeps = 100)
{
  typedef Complex<double> C;
  typedef Hyperbolic_isometry_2<double> Isometry;
  const One_ring_faces rings(P);
  // neighbours of each free vertex, with the map bringing them into its frame
  struct Nb { int u; int via; double w; };  // via: the vertex of the edge standing for v (v or a twin copy)
  std::vector<std::vector<Nb> > nb(P.n);
  auto owner = [&](int v) { return rings.owner(v); };
  for(std::size_t e = 0; e < P.edges.size(); ++e) {
    const int a = P.edges[e][0], b = P.edges[e][1];
    if(P.kind[owner(a)] == Free) nb[owner(a)].push_back(Nb{b, a, P.edge_weight[e]});
    if(P.kind[owner(b)] == Free) nb[owner(b)].push_back(Nb{a, b, P.edge_weight[e]});
  }
  int moves = 0, fewest = P.n + 1, idle = 0;
  for(int sweep = 0; sweep < max_sweeps; ++sweep) {
    int moved = 0;
    for(int v = 0; v < P.n; ++v) {
      if(P.kind[v] != Free)
        continue;
      if(rings.all_positive(v, x))
        continue;
      const C z(x[P.var[v]], x[P.var[v] + 1]);
      const Isometry to0 = Isometry::translation_to_origin(z);
      C sum;
      double wsum = 0;
      for(const Nb& q : nb[v]) {
        C zu = position(P, x, q.u);
        if(q.via != v) // the edge is at a seam copy: bring the neighbour back through the pairing
          zu = P.transform[q.via].inverse().apply(zu);
        sum += q.w * to0.apply(zu);
        wsum += q.w;
      }
      if(!(wsum > 0))
        continue;
      const C c = to0.inverse().apply(sum / wsum);
      x[P.var[v]] = c.re;
      x[P.var[v] + 1] = c.im;
      ++moved;
    }
    moves += moved;
    if(moved == 0)
      break;
    // hopeless (a region below what double resolves): ten sweeps without fewer vertices to move
    if(moved < fewest) {
      fewest = moved;
      idle = 0;
    } else if(++idle >= 10) {
      break;
    }
  }
  return moves;
}

// Last resort of the repair, at the resolution of double: a vertex of a non-positive face
// is searched for, around its computed position, a nearby point (1 to 2^20 units in the last
// place away, 16 directions) where all its faces are positive (exact predicate). The exact
// embedding is bijective; where its triangles are nearly flat and tiny (a squeezed region of
// a mesh with nearly flat triangles) the rounded solution may flip one, and a representable
// valid position exists close by. The certificate judges the result. Returns the moves.
// More than `max_vertices` such vertices: a whole region below what double resolves, which
// moving vertices one at a time cannot mend (and the exact tests would take seconds): none moved.
inline int snap_one_rings(const Flat_problem& P, std::vector<double>& x, int max_vertices = 100)
{
  const One_ring_faces rings(P);
  auto all_ok = [&](int v) { return rings.all_positive(v, x); };
  int to_move = 0;
  for(int v = 0; v < P.n && to_move <= max_vertices; ++v)
    to_move += (P.kind[v] == Free && !all_ok(v)) ? 1 : 0;
  if(to_move > max_vertices)
    return 0;
  int moves = 0;
  for(int v = 0; v < P.n; ++v) {
    if(P.kind[v] != Free || all_ok(v))
      continue;
    const int i = P.var[v];
    const double x0 = x[i], y0 = x[i + 1];
    const double ulp = std::numeric_limits<double>::epsilon() * (std::max)({std::abs(x0), std::abs(y0), 1e-3});
    bool found = false;
    for(double r = ulp; r < ulp * 2e6 && !found; r *= 2)
      for(int d = 0; d < 16 && !found; ++d) {
        x[i] = x0 + r * std::cos(d * CGAL_PI / 8);
        x[i + 1] = y0 + r * std::sin(d * CGAL_PI / 8);
        found = x[i] * x[i] + x[i + 1] * x[i + 1] < 1 && all_ok(v);
      }
    if(found)
      ++moves;
    else {
      x[i] = x0;
      x[i + 1] = y0;
    }
  }
  return moves;
}

} // namespace internal
} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_ORBIFOLD_SOLVER_H
