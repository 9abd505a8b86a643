// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_LINEAR_ALGEBRA_SINGLE_PRECISION_FACTOR_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_LINEAR_ALGEBRA_SINGLE_PRECISION_FACTOR_H

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
// The loops are ours, in a fixed order of operations on two threads (two halves of the
// elimination tree, see Supernodal_float_factor), so the result is the same whatever the
// number of threads; a version compiled for AVX2 (no FMA: no contraction, the same
// roundings) is taken where the processor has it, giving the same bits.

#ifdef CGAL_HOT_USE_CHOLMOD

#include <cholmod.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/parallel_invoke.h>
#endif

#include <algorithm>
#include <complex>
#include <cstddef>
#include <cstring>
#include <vector>

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {
namespace internal {

// The parts of a supernodal factor the solves read (CHOLMOD's layout: supernode q holds
// the columns super[q] .. super[q+1]-1 as a dense column-major block of pi[q+1]-pi[q] rows,
// their row indices s[pi[q]] ..., values from px[q]; the diagonal block on top), and the
// schedule of the solves on two threads: two groups of whole subtrees of the supernodal
// elimination tree and the top, the supernodes above them. In the forward solve a group
// adds what it sends to the top's rows into a buffer of its own; the two buffers are added
// to the top in group order, then the top is solved. In the backward solve the top is solved
// first, then each group reads only its own and the top's rows. The same operations in the
// same order whether the two groups run at once or one after the other.
struct Supernodal_float_factor
{
  int n = 0, nsuper = 0;
  const int *super = nullptr, *pi = nullptr, *px = nullptr, *s = nullptr, *perm = nullptr;
  const float* x = nullptr; // interleaved real and imaginary parts
  std::vector<int> group[2], top; // supernodes, in increasing order (children before parents)
  std::vector<int> top_slot;      // per column: its place among the top's columns (-1: not in the top)
  std::vector<int> top_column;    // the top's columns
};

namespace supernodal_detail {

// the two groups and the top (see Supernodal_float_factor): from the roots down, the
// largest subtree is split into its children (its root joins the top), up to 64 times and
// while the top holds less than a quarter of the work; of these frontiers, the one whose
// subtrees, dealt to the lighter group largest first, give the least heavier group's work
// plus the top's
inline void make_schedule(Supernodal_float_factor& F)
{
  const int ns = F.nsuper;
  std::vector<int> node_of(F.n), parent(ns, -1);
  std::vector<double> work(ns), below(ns, 0.0);
  for(int q = 0; q < ns; ++q)
    for(int k = F.super[q]; k < F.super[q + 1]; ++k)
      node_of[k] = q;
  double total = 0;
  for(int q = 0; q < ns; ++q) {
    const int nc = F.super[q + 1] - F.super[q], nr = F.pi[q + 1] - F.pi[q];
    if(nr > nc)
      parent[q] = node_of[F.s[F.pi[q] + nc]];
    work[q] = double(nr) * nc;
    total += work[q];
  }
  std::vector<std::vector<int> > children(ns);
  std::vector<int> frontier;
  for(int q = 0; q < ns; ++q) { // (a parent comes after its children)
    below[q] += work[q];
    if(parent[q] >= 0) {
      below[parent[q]] += below[q];
      children[parent[q]].push_back(q);
    } else {
      frontier.push_back(q);
    }
  }
  // deals the frontier's subtrees to the lighter group, largest first; the time of a solve
  // goes as the heavier group's work plus the top's
  auto deal = [&](std::vector<int>& order, double load[2]) {
    order = frontier;
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return below[a] > below[b]; });
    load[0] = load[1] = 0;
    for(int f : order)
      load[load[1] < load[0] ? 1 : 0] += below[f];
  };
  std::vector<int> order, best_frontier = frontier;
  double load[2], top_work = 0;
  deal(order, load);
  double best = std::max(load[0], load[1]);
  for(int step = 0; step < 64; ++step) { // splits the largest subtree while that pays
    int largest = -1;
    for(int f : frontier)
      if(!children[f].empty() && (largest < 0 || below[f] > below[largest]))
        largest = f;
    if(largest < 0)
      break;
    top_work += work[largest];
    if(top_work > 0.25 * total)
      break;
    frontier.erase(std::find(frontier.begin(), frontier.end(), largest));
    frontier.insert(frontier.end(), children[largest].begin(), children[largest].end());
    deal(order, load);
    const double cost = std::max(load[0], load[1]) + top_work;
    if(cost < best) {
      best = cost;
      best_frontier = frontier;
    }
  }
  // the best split found: its frontier's subtrees in the groups, everything above in the top
  std::vector<int> label(ns, 2); // 0, 1: group; 2: top
  frontier = best_frontier;
  deal(order, load);
  std::vector<int> in_group(ns, -1);
  {
    double l[2] = {0, 0};
    for(int f : order) {
      const int g = l[1] < l[0] ? 1 : 0;
      in_group[f] = g;
      l[g] += below[f];
    }
  }
  for(int q = ns - 1; q >= 0; --q) // (parents first)
    label[q] = in_group[q] >= 0 ? in_group[q] : (parent[q] >= 0 && label[parent[q]] != 2 ? label[parent[q]] : 2);
  F.group[0].clear();
  F.group[1].clear();
  F.top.clear();
  F.top_column.clear();
  F.top_slot.assign(F.n, -1);
  for(int q = 0; q < ns; ++q) {
    if(label[q] == 2) {
      F.top.push_back(q);
      for(int k = F.super[q]; k < F.super[q + 1]; ++k) {
        F.top_slot[k] = static_cast<int>(F.top_column.size());
        F.top_column.push_back(k);
      }
    } else {
      F.group[label[q]].push_back(q);
    }
  }
}

// the forward solve of supernode q: y := L_q^-1 y on its columns, and what they send to
// the rows below, through send(row, re, im) (W: workspace of 2 nr)
template <class Send>
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
inline void forward_node(const Supernodal_float_factor& F, int q, double* Y, double* W, const Send& send)
{
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
  for(int i = nc; i < nr; ++i)
    send(rows[i], W[2 * i], W[2 * i + 1]);
}

// the backward solve of supernode q: y := L_q^-* y on its columns (the rows below final)
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
inline void backward_node(const Supernodal_float_factor& F, int q, double* Y, double* W)
{
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

// the forward solve of some supernodes, in increasing order (what they send to the top's
// rows into B; B null: everything straight into y), or their backward solve, decreasing
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
inline void nodes_pass(const Supernodal_float_factor& F, const std::vector<int>& nodes, bool forward, double* Y,
                       double* W, double* B)
{
  if(forward) {
    auto send = [&](int r, double re, double im) {
      const int t = B ? F.top_slot[r] : -1;
      double* dst = t >= 0 ? B + 2 * static_cast<std::size_t>(t) : Y + 2 * static_cast<std::size_t>(r);
      dst[0] += re;
      dst[1] += im;
    };
    for(int q : nodes)
      forward_node(F, q, Y, W, send);
  } else {
    for(auto it = nodes.rbegin(); it != nodes.rend(); ++it)
      backward_node(F, *it, Y, W);
  }
}
inline void nodes_pass_generic(const Supernodal_float_factor& F, const std::vector<int>& nodes, bool forward, double* Y,
                               double* W, double* B)
{
  nodes_pass(F, nodes, forward, Y, W, B);
}
#if defined(__GNUC__) && (defined(__x86_64__) || defined(__i386__))
#define CGAL_HOT_SUPERNODAL_AVX2 1
__attribute__((target("avx2"))) inline void nodes_pass_avx2(const Supernodal_float_factor& F, const std::vector<int>& nodes,
                                                             bool forward, double* Y, double* W, double* B)
{
  nodes_pass(F, nodes, forward, Y, W, B);
}
inline bool has_avx2()
{
  static const bool yes = __builtin_cpu_supports("avx2");
  return yes;
}
#endif

} // namespace supernodal_detail

// Rounds the values of a complex, double, supernodal factor to float in place: afterwards
// the first half of F->x holds interleaved floats (CHOLMOD must not solve with F any more;
// a new numeric factorisation overwrites the values, it does not read them). Makes the
// schedule of the solves.
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
  supernodal_detail::make_schedule(out);
  return true;
}

// x = P^T L~^-* L~^-1 P b (x and b of size n); with `lead` >= 0: b and x of size lead, the
// solve with the leading lead x lead block (P keeps those rows first: L~^-1, the entries from
// `lead` on set to 0, then L~^-*). `work`: workspace. `avx2`: false forces the portable
// loops, `parallel`: false one group after the other (tests: the same bits either way).
template <class Vector>
void solve_with_float_factor(const Supernodal_float_factor& F, const Vector& b, Vector& x, int lead,
                             std::vector<double>& work, bool avx2 = true, bool parallel = true)
{
  using namespace supernodal_detail;
  const std::size_t n = static_cast<std::size_t>(F.n), nt = F.top_column.size();
  work.assign(2 * n + 2 * n + 2 * n + 2 * nt + 2 * nt, 0.0); // y, two W, two B
  double *Y = work.data(), *W0 = Y + 2 * n, *W1 = W0 + 2 * n, *B0 = W1 + 2 * n, *B1 = B0 + 2 * nt;
  const int m = lead >= 0 ? lead : F.n;
  for(int k = 0; k < m; ++k) {
    const std::complex<double> v = b[F.perm[k]];
    Y[2 * k] = v.real();
    Y[2 * k + 1] = v.imag();
  }
  // the groups with their own workspace and buffer; the top (B null) with group 0's workspace
  auto pass = [&](const std::vector<int>& nodes, bool forward, double* W, double* B) {
#ifdef CGAL_HOT_SUPERNODAL_AVX2
    if(avx2 && has_avx2())
      nodes_pass_avx2(F, nodes, forward, Y, W, B);
    else
#endif
      nodes_pass_generic(F, nodes, forward, Y, W, B);
  };
  auto both = [&](bool forward) {
#ifdef CGAL_LINKED_WITH_TBB
    if(parallel && !F.group[0].empty() && !F.group[1].empty()) {
      tbb::parallel_invoke([&]() { pass(F.group[0], forward, W0, B0); }, [&]() { pass(F.group[1], forward, W1, B1); });
      return;
    }
#endif
    pass(F.group[0], forward, W0, B0);
    pass(F.group[1], forward, W1, B1);
  };
  // forward: the groups, their sends to the top (group 0's, then group 1's), the top
  both(true);
  for(std::size_t t = 0; t < nt; ++t) {
    const std::size_t r = 2 * static_cast<std::size_t>(F.top_column[t]);
    Y[r] += B0[2 * t];
    Y[r + 1] += B0[2 * t + 1];
    Y[r] += B1[2 * t];
    Y[r + 1] += B1[2 * t + 1];
  }
  pass(F.top, true, W0, nullptr);
  if(lead >= 0)
    std::memset(Y + 2 * static_cast<std::size_t>(lead), 0, 2 * sizeof(double) * (n - static_cast<std::size_t>(lead)));
  // backward: the top, then the groups
  pass(F.top, false, W0, nullptr);
  both(false);
  (void)avx2;
  (void)parallel;
  x.resize(m);
  for(int k = 0; k < m; ++k)
    x[F.perm[k]] = std::complex<double>(Y[2 * k], Y[2 * k + 1]);
}

} // namespace internal
} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#endif // CGAL_HOT_USE_CHOLMOD

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_LINEAR_ALGEBRA_SINGLE_PRECISION_FACTOR_H
