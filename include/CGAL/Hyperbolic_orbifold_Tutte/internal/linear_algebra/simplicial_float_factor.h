// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_LINEAR_ALGEBRA_SIMPLICIAL_FLOAT_FACTOR_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_LINEAR_ALGEBRA_SIMPLICIAL_FLOAT_FACTOR_H

// Solves with Eigen's simplicial LDL^* factor of a complex Hermitian matrix (or a real
// symmetric one: Scalar double), P A P^T = L D L^*, its L rounded to single precision: the
// small meshes' counterpart of single_precision_factor.h (CHOLMOD's supernodal factors of 50K
// rows and more).
//
// The preconditioner's solves (20 to 90 per embedding, more with many landmarks; in the
// refinement's conjugate gradients, 5 to 20 per step) read the whole of L twice; its entries
// as float pairs and 32-bit row indices take 12 bytes instead of 20 (real: 8 instead of 12).
// The arithmetic is in double, D is kept in double: each solve is, to double rounding,
// exactly one with L~ D L~^*, L~ = fl32(L), a Hermitian positive definite matrix (D > 0)
// within a relative 6e-8 |L| D |L^*| of A, so conjugate gradients keep their guarantees. A
// fixed order of operations, no BLAS: the same bits on every machine and any number of
// threads.
//
// The solves run on two threads where the elimination tree allows (split_tree()): two
// disjoint sets of subtrees, each about 45% of L's entries, then the columns above them
// (the "top", about 10% on meshes of 14K to 26K vertices). In L~ y = b a subtree's columns
// update rows of their own subtree or of the top; those of the top are gathered per set and
// added after (set 1's, then set 2's: the same order on one thread); in L~^* x = y the top is
// solved first and each subtree reads only itself and the top.

#include <Eigen/Core>
#include <Eigen/SparseCholesky>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/parallel_invoke.h>
#endif

#include <algorithm>
#include <complex>
#include <queue>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {
namespace internal {

template <class Scalar>
class Simplicial_float_factor
{
public:
  typedef Scalar C;
  typedef Eigen::SparseMatrix<C> Matrix;
  // doubles per entry: 2 (complex: real and imaginary parts, interleaved) or 1
  static constexpr int K = std::is_same<Scalar, std::complex<double> >::value ? 2 : 1;
  static_assert(K == 2 || std::is_same<Scalar, double>::value, "complex<double> or double");

  // from a successful factorisation `f` (L strictly lower, column by column; D real)
  template <class Ordering>
  void assign(const Eigen::SimplicialLDLT<Matrix, Eigen::Lower, Ordering>& f)
  {
    const Matrix& L = f.matrixL().nestedExpression();
    n_ = static_cast<int>(L.cols());
    outer_.assign(L.outerIndexPtr(), L.outerIndexPtr() + n_ + 1);
    const int nnz = outer_[n_] - outer_[0];
    inner_.resize(nnz);
    re_im_.resize(K * static_cast<std::size_t>(nnz));
    // (Eigen's factor is compressed; were it not, each column ends at outer + innerNonZeros)
    for(int j = 0; j < n_; ++j) {
      const int b = L.outerIndexPtr()[j];
      const int e = L.isCompressed() ? L.outerIndexPtr()[j + 1] : b + L.innerNonZeroPtr()[j];
      outer_[j + 1] = outer_[j] + (e - b);
      for(int p = b, q = outer_[j]; p < e; ++p, ++q) {
        inner_[q] = L.innerIndexPtr()[p];
        re_im_[K * q] = static_cast<float>(std::real(L.valuePtr()[p]));
        if constexpr(K == 2)
          re_im_[2 * q + 1] = static_cast<float>(L.valuePtr()[p].imag());
      }
    }
    const Eigen::Matrix<C, Eigen::Dynamic, 1> D = f.vectorD(); // (a copy: Eigen returns it by value)
    inv_d_.resize(n_);
    for(int j = 0; j < n_; ++j)
      inv_d_[j] = 1.0 / std::real(D[j]);
    perm_ = f.permutationP().indices();
    split_tree();
  }

  bool empty() const { return n_ == 0 && perm_.size() == 0; }
  // the solves are split in two sets of subtrees and a top (see split_tree())
  bool split() const { return !columns_[1].empty(); }
  void clear()
  {
    n_ = 0;
    outer_.clear();
    inner_.clear();
    re_im_.clear();
    inv_d_.clear();
    perm_.resize(0);
    for(auto& c : columns_)
      c.clear();
  }

  // x = P^T L~^-* D^-1 L~^-1 P b
  void solve(const Eigen::Matrix<C, Eigen::Dynamic, 1>& b, Eigen::Matrix<C, Eigen::Dynamic, 1>& x) const
  {
    const int n = n_;
    y_.resize(K * static_cast<std::size_t>(n));
    double* y = y_.data();
    for(int i = 0; i < n; ++i) // y = P b: (P b)[perm[i]] = b[i]
      store(b[i], y + K * (perm_.size() == n ? perm_[i] : i));
    if(columns_[1].empty()) { // (one set: every column in order)
      forward(0, n, nullptr, y, nullptr);
      scale(y);
      backward(0, n, nullptr, y);
    } else {
      // the subtrees' updates of the top: gathered per set, added in a fixed order
      for(auto& sum : top_sum_) {
        sum.resize(K * static_cast<std::size_t>(n));
        for(int r : columns_[0])
          for(int k = 0; k < K; ++k)
            sum[K * r + k] = 0;
      }
      in_parallel([&] { forward(0, static_cast<int>(columns_[1].size()), columns_[1].data(), y, top_sum_[0].data()); },
                  [&] { forward(0, static_cast<int>(columns_[2].size()), columns_[2].data(), y, top_sum_[1].data()); });
      for(int r : columns_[0])
        for(int k = 0; k < K; ++k)
          y[K * r + k] = (y[K * r + k] + top_sum_[0][K * r + k]) + top_sum_[1][K * r + k];
      forward(0, static_cast<int>(columns_[0].size()), columns_[0].data(), y, nullptr);
      scale(y);
      backward(0, static_cast<int>(columns_[0].size()), columns_[0].data(), y);
      in_parallel([&] { backward(0, static_cast<int>(columns_[1].size()), columns_[1].data(), y); },
                  [&] { backward(0, static_cast<int>(columns_[2].size()), columns_[2].data(), y); });
    }
    x.resize(n);
    for(int i = 0; i < n; ++i) // x = P^T y
      x[i] = load(y + K * (perm_.size() == n ? perm_[i] : i));
  }

private:
  static void store(const C& v, double* y)
  {
    y[0] = std::real(v);
    if constexpr(K == 2)
      y[1] = std::imag(v);
  }
  static C load(const double* y)
  {
    if constexpr(K == 2)
      return C(y[0], y[1]);
    else
      return y[0];
  }

  // L~ y = y (unit diagonal) over the columns cols[begin, end) (ascending; all columns when
  // cols is null), column by column: y_i -= l_ij y_j, rows of the top into `top` when given
  void forward(int begin, int end, const int* cols, double* y, double* top) const
  {
    const int* outer = outer_.data();
    const int* inner = inner_.data();
    const float* v = re_im_.data();
    for(int c = begin; c < end; ++c) {
      const int j = cols ? cols[c] : c;
      if constexpr(K == 2) {
        const double yr = y[2 * j], yi = y[2 * j + 1];
        for(int p = outer[j]; p < outer[j + 1]; ++p) {
          const double lr = v[2 * p], li = v[2 * p + 1];
          double* t = (top && in_top_[inner[p]] ? top : y) + 2 * inner[p];
          t[0] -= lr * yr - li * yi;
          t[1] -= lr * yi + li * yr;
        }
      } else {
        const double yj = y[j];
        for(int p = outer[j]; p < outer[j + 1]; ++p)
          (top && in_top_[inner[p]] ? top : y)[inner[p]] -= double(v[p]) * yj;
      }
    }
  }

  void scale(double* y) const
  {
    for(int j = 0; j < n_; ++j)
      for(int k = 0; k < K; ++k)
        y[K * j + k] *= inv_d_[j];
  }

  // L~^* y = y over the columns cols[begin, end) (all when cols is null), from the last:
  // y_j -= sum_i conj(l_ij) y_i
  void backward(int begin, int end, const int* cols, double* y) const
  {
    const int* outer = outer_.data();
    const int* inner = inner_.data();
    const float* v = re_im_.data();
    for(int c = end - 1; c >= begin; --c) {
      const int j = cols ? cols[c] : c;
      if constexpr(K == 2) {
        double sr = y[2 * j], si = y[2 * j + 1];
        for(int p = outer[j]; p < outer[j + 1]; ++p) {
          const double lr = v[2 * p], li = v[2 * p + 1];
          const double* t = y + 2 * inner[p];
          sr -= lr * t[0] + li * t[1];
          si -= lr * t[1] - li * t[0];
        }
        y[2 * j] = sr;
        y[2 * j + 1] = si;
      } else {
        double sj = y[j];
        for(int p = outer[j]; p < outer[j + 1]; ++p)
          sj -= double(v[p]) * y[inner[p]];
        y[j] = sj;
      }
    }
  }

  template <class F1, class F2>
  static void in_parallel(const F1& f1, const F2& f2)
  {
#ifdef CGAL_LINKED_WITH_TBB
    tbb::parallel_invoke(f1, f2);
#else
    f1();
    f2();
#endif
  }

  // The two sets of subtrees and the top (columns_[1], columns_[2], columns_[0]) where that
  // shortens the solve by a quarter or more, else none (columns_[1] empty). The elimination
  // tree's parent of column j is its first row below the diagonal. From the roots down, the
  // heaviest subtree (entries of L) of the frontier is moved to the top and its children
  // join the frontier; at each step the frontier is dealt largest first to the lighter set,
  // and the split whose longer path (top + heavier set) is shortest is kept. Depends on L's
  // pattern only.
  void split_tree()
  {
    for(auto& c : columns_)
      c.clear();
    if(n_ < min_split_columns)
      return;
    std::vector<int> parent(n_, -1);
    std::vector<double> work(n_), subtree(n_);
    double total = 0;
    for(int j = 0; j < n_; ++j) {
      for(int p = outer_[j]; p < outer_[j + 1]; ++p)
        parent[j] = parent[j] < 0 ? inner_[p] : (std::min)(parent[j], inner_[p]);
      work[j] = 1.0 + (outer_[j + 1] - outer_[j]);
      total += work[j];
    }
    subtree = work;
    for(int j = 0; j < n_; ++j)
      if(parent[j] >= 0)
        subtree[parent[j]] += subtree[j];
    std::vector<int> child_first(n_ + 1, 0), children(n_);
    for(int j = 0; j < n_; ++j)
      if(parent[j] >= 0)
        ++child_first[parent[j] + 1];
    for(int j = 0; j < n_; ++j)
      child_first[j + 1] += child_first[j];
    {
      std::vector<int> fill(child_first.begin(), child_first.end() - 1);
      for(int j = 0; j < n_; ++j)
        if(parent[j] >= 0)
          children[fill[parent[j]]++] = j;
    }
    // (ties broken by column: the same split everywhere)
    auto lighter = [&](int a, int b) { return subtree[a] < subtree[b] || (subtree[a] == subtree[b] && a > b); };
    std::priority_queue<int, std::vector<int>, decltype(lighter)> frontier(lighter);
    for(int j = 0; j < n_; ++j)
      if(parent[j] < 0)
        frontier.push(j);
    std::vector<int> moved; // to the top, in order
    double top = 0, best = total;
    std::size_t best_moves = 0;
    std::vector<int> dealt;
    // (a longer path than top + (total - top) / 2 cannot be shortened by moving more)
    for(int step = 0; step < max_split_steps && !frontier.empty() && top + (total - top) / 2 < best; ++step) {
      auto q = frontier;
      double bins[2] = {0, 0};
      while(!q.empty()) {
        bins[bins[0] <= bins[1] ? 0 : 1] += subtree[q.top()];
        q.pop();
      }
      const double span = top + (std::max)(bins[0], bins[1]);
      if(span < best) {
        best = span;
        best_moves = moved.size();
      }
      const int j = frontier.top();
      frontier.pop();
      moved.push_back(j);
      top += work[j];
      for(int k = child_first[j]; k < child_first[j + 1]; ++k)
        frontier.push(children[k]);
    }
    if(!(best <= 0.75 * total))
      return;
    // the best split again: its top, and its frontier dealt to the two sets
    in_top_.assign(n_, 0);
    for(std::size_t k = 0; k < best_moves; ++k)
      in_top_[moved[k]] = 1;
    std::vector<int> roots;
    for(int j = 0; j < n_; ++j)
      if(!in_top_[j] && (parent[j] < 0 || in_top_[parent[j]]))
        roots.push_back(j);
    std::sort(roots.begin(), roots.end(), [&](int a, int b) { return lighter(b, a); });
    std::vector<char> set(n_, 0);
    double bins[2] = {0, 0};
    for(int r : roots) {
      const int b = bins[0] <= bins[1] ? 0 : 1;
      bins[b] += subtree[r];
      set[r] = static_cast<char>(b + 1);
    }
    for(int j = n_ - 1; j >= 0; --j) // (a parent's column is after its children's)
      if(!in_top_[j] && set[j] == 0)
        set[j] = set[parent[j]];
    for(int j = 0; j < n_; ++j)
      columns_[in_top_[j] ? 0 : set[j]].push_back(j);
  }

  static constexpr int min_split_columns = 4096;
  static constexpr int max_split_steps = 4000;

  std::vector<int> columns_[3];      // the top's columns, the first set's, the second's (ascending)
  std::vector<char> in_top_;
  mutable std::vector<double> top_sum_[2];
  int n_ = 0;
  std::vector<int> outer_, inner_;
  std::vector<float> re_im_; // L's entries (complex: interleaved real and imaginary parts)
  std::vector<double> inv_d_;
  Eigen::VectorXi perm_;
  mutable std::vector<double> y_;
};

} // namespace internal
} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_LINEAR_ALGEBRA_SIMPLICIAL_FLOAT_FACTOR_H
