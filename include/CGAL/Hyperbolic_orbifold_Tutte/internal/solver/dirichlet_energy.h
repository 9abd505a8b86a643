// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_SOLVER_DIRICHLET_ENERGY_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_SOLVER_DIRICHLET_ENERGY_H

#include <CGAL/disable_warnings.h>

/// \file dirichlet_energy.h
// The Dirichlet energy of the flat problem (sum over the edges of w d^2 / 2, d hyperbolic),
// its gradient and (projected) Hessian, and the measures of force imbalance.
// The per-edge terms (squared hyperbolic distance and its derivatives, position jets) are
// in hyperbolic_energy.h, below Flat_problem (flat_problem.h includes it); this header sums
// them over a Flat_problem's edges, so the two stay apart.

#include <CGAL/Hyperbolic_orbifold_Tutte/internal/solver/flat_problem.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/solver/hessian_pattern.h>

#include <Eigen/Dense>
#include <Eigen/Sparse>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#endif

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {
namespace internal {

// Dirichlet energy (1/2) sum w d^2; gradient and projected Hessian if requested.
class Energy_evaluator
{
public:
  typedef std::complex<double> C;
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
      const double A = 1 - squared_modulus(a), B = 1 - squared_modulus(b);
      if(!(A > 0 && B > 0)) {
        edge_energy_[e] = std::numeric_limits<double>::infinity();
        return;
      }
      const double dx = a.real() - b.real(), dy = a.imag() - b.imag();
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
        if(!(squared_modulus(k) < 1.0))
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
    if(!H)
      for_each_edge([&](std::size_t e) { edge_terms(x, e, false, project); });
    else
      assemble_hessian(x, *H, project);
    terms_x_ = x;
    noise_.clear();
    // ...then summed in edge order: the same result bit for bit whatever the number of threads
    return sum_edge_terms(g);
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
        const double speed = std::abs(j.dz[0]) * 2 / (1 - squared_modulus(j.z));
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
      const double ra = (1 - squared_modulus(a)) / 2, rb = (1 - squared_modulus(b)) / 2;
      const double d = std::sqrt(2 * edge_energy_[e] / P_.edge_weight[e]);
      const double err = 8 * u * (std::abs(a) / ra + std::abs(b) / rb);
      const double rel = d > err ? err / d : 1.0;
      const int n = local_variables(e, gi);
      for(int i = 0; i < n; ++i)
        noise[gi[i]] += std::abs(edge_gradient_[4 * e + i]) * rel;
    }
    noise_ = noise;
  }

private:
  // every edge's terms with its Hessian block, the blocks added into H (given the pattern
  // first where it has not got it)
  void assemble_hessian(const std::vector<double>& x, Eigen::SparseMatrix<double>& H, bool project) const
  {
    const std::size_t m = P_.edges.size();
    if(H.nonZeros() != pattern_nnz_ || H.rows() != P_.n_vars || H.cols() != P_.n_vars) {
      if(pattern_given_) // rare (tests): build the pattern again
        build_pattern();
      // (swapped, not assigned: Eigen 3.4's SparseMatrix has no move assignment, so
      // `H = std::move(pattern_)` would copy it and keep both: 336 MB at a million vertices)
      H.swap(pattern_);
      Eigen::SparseMatrix<double>().swap(pattern_); // H's former storage freed
      pattern_given_ = true;
    }
    double* hv = H.valuePtr();
    std::fill(hv, hv + H.nonZeros(), 0.0);
    // the Hessian blocks a chunk of edges at a time (a small buffer, not 16 doubles per
    // edge: 0.4 GB at a million vertices), each chunk's blocks added to the columns of the
    // groups it touches, in parallel over those groups (disjoint columns); each entry gets its
    // terms in edge order, as a sequential sum over the edges would: the same bits on any
    // number of threads
    std::vector<int> next(incidence_first_.begin(), incidence_first_.end() - 1); // per group, its next incidence
    for(std::size_t c = 0, ci = 0; c < m; c += hessian_chunk, ++ci) {
      const std::size_t c_end = (std::min)(m, c + hessian_chunk);
      hessian_offset_ = static_cast<std::size_t>(slot_begin_[c]);
      edge_hessian_.resize(static_cast<std::size_t>(slot_begin_[c_end]) - hessian_offset_);
      for_each_edge(c, c_end, [&](std::size_t e) { edge_terms(x, e, true, project); });
      for_each_index(chunk_groups_first_[ci], chunk_groups_first_[ci + 1], [&](std::size_t q) {
        const int g = chunk_groups_[q];
        int gi[4];
        for(int& k = next[g]; k < incidence_first_[g + 1] && static_cast<std::size_t>(incidence_[k] >> 2) < c_end; ++k) {
          const std::size_t e = static_cast<std::size_t>(incidence_[k] >> 2);
          const int ends = incidence_[k] & 3;
          const int n = local_variables(e, gi), na = end_dimension(P_.edges[e][0]);
          const std::size_t b = static_cast<std::size_t>(slot_begin_[e]);
          for(int i = 0; i < n; ++i)
            for(int j = 0; j < n; ++j)
              if(ends & (j < na ? 1 : 2))
                hv[slots_[b + i * n + j]] += edge_hessian_[b - hessian_offset_ + i * n + j];
        }
      });
    }
    hessian_offset_ = 0;
  }

  // the energy, and the gradient g (and the forces' sizes g_abs_): the edges' terms in edge order
  double sum_edge_terms(std::vector<double>& g) const
  {
    g.assign(P_.n_vars, 0.0);
    g_abs_.assign(P_.n_vars, 0.0);
    double E = 0;
    for(std::size_t e = 0; e < P_.edges.size(); ++e)
      E += edge_energy_[e];
    // (per group of variables, its edges in edge order: in parallel, the same sums)
    for_each_index(0, incidence_first_.size() - 1, [&](std::size_t group) {
      int gi[4];
      for(int k = incidence_first_[group]; k < incidence_first_[group + 1]; ++k) {
        const std::size_t e = static_cast<std::size_t>(incidence_[k] >> 2);
        const int ends = incidence_[k] & 3;
        const int n = local_variables(e, gi), na = end_dimension(P_.edges[e][0]);
        for(int i = 0; i < n; ++i)
          if(ends & (i < na ? 1 : 2)) {
            g[gi[i]] += edge_gradient_[4 * e + i];
            g_abs_[gi[i]] += std::abs(edge_gradient_[4 * e + i]);
          }
      }
    });
    return E;
  }

  template <class F>
  void for_each_edge(const F& f) const
  {
    for_each_edge(0, P_.edges.size(), f);
  }

  // edges [begin, end); in parallel on meshes of more than 20000 edges
  template <class F>
  void for_each_edge(std::size_t begin, std::size_t end, const F& f) const
  {
    for_each_index(begin, end, f, 4096);
  }

  // f(i) for i in [begin, end) (edges, groups of variables, or a chunk's groups), in
  // parallel, in blocks of `grain`, on meshes of more than 20000 edges
  template <class F>
  void for_each_index(std::size_t begin, std::size_t end, const F& f, std::size_t grain = 1024) const
  {
#ifdef CGAL_LINKED_WITH_TBB
    if(P_.edges.size() > 20000) {
      tbb::parallel_for(tbb::blocked_range<std::size_t>(begin, end, grain), [&](const tbb::blocked_range<std::size_t>& r) {
        for(std::size_t i = r.begin(); i != r.end(); ++i)
          f(i);
      });
      return;
    }
#else
    (void)grain;
#endif
    for(std::size_t i = begin; i < end; ++i)
      f(i);
  }

  // energy, gradient and (projected) Hessian block of edge e, into the per-edge buffers
  void edge_terms(const std::vector<double>& x, std::size_t e, bool want_hessian, bool project) const
  {
    const int a = P_.edges[e][0], b = P_.edges[e][1];
    if(P_.kind[a] == Free && P_.kind[b] == Free) {
      free_edge_terms(x, e, a, b, want_hessian, project);
      return;
    }
    Position_jet ja, jb;
    Squared_distance_derivatives sd;
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
      J[i][0] = ja.dz[i].real(); J[i][1] = ja.dz[i].imag(); off[i] = 0;
    }
    for(int i = 0; i < jb.dim; ++i) {
      J[ja.dim + i][0] = jb.dz[i].real(); J[ja.dim + i][1] = jb.dz[i].imag(); off[ja.dim + i] = 2;
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
          h += sd.g[off[i]] * jj.ddz[ii][kk].real() + sd.g[off[i] + 1] * jj.ddz[ii][kk].imag();
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

  // edge_terms() of an edge between two free vertices (most edges): the variables are the
  // positions themselves (identity Jacobian, no second derivatives), so the terms are those
  // of the squared distance, scaled; the same values as the general case's (its products
  // with 1 and 0 change no bit)
  void free_edge_terms(const std::vector<double>& x, std::size_t e, int a, int b, bool want_hessian, bool project) const
  {
    Squared_distance_derivatives sd;
    const C za(x[P_.var[a]], x[P_.var[a] + 1]), zb(x[P_.var[b]], x[P_.var[b] + 1]);
    const double hw = 0.5 * P_.edge_weight[e];
    squared_hyperbolic_distance(za, zb, sd, want_hessian);
    edge_energy_[e] = hw * sd.f;
    for(int i = 0; i < 4; ++i)
      edge_gradient_[4 * e + i] = hw * sd.g[i];
    if(!want_hessian)
      return;
    double* out = &edge_hessian_[slot_begin_[e] - hessian_offset_];
    if(project) {
      Eigen::Matrix4d M;
      for(int i = 0; i < 4; ++i)
        for(int j = 0; j < 4; ++j)
          M(i, j) = hw * sd.H[i][j];
      project_psd(M, 4);
      for(int i = 0; i < 4; ++i)
        for(int j = 0; j < 4; ++j)
          out[i * 4 + j] = M(i, j);
      return;
    }
    for(int i = 0; i < 4; ++i)
      for(int j = 0; j < 4; ++j)
        out[i * 4 + j] = hw * sd.H[i][j];
  }

  // number of variables of a vertex's position
  int end_dimension(int v) const { return P_.kind[v] == Fixed ? 0 : (P_.kind[v] == On_line ? 1 : 2); }

  // local variables of edge e: those of its first end, then those of its second
  int local_variables(std::size_t e, int* gi) const
  {
    int n = 0;
    for(int s = 0; s < 2; ++s) {
      const int v = P_.edges[e][s];
      const int o = variable_owner(P_, v);
      const int dim = end_dimension(v);
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
    Variable_groups G;
    group_variables(P_, G);
    find_neighbour_groups(P_, G);
    sort_neighbour_groups(G);
    std::vector<int> outer;
    build_columns(G, outer);
    build_slots(G, outer);
    build_incidences(G);
  }

  // per group of variables, its edges in edge order (incidence_: 4 e + the ends of e in the
  // group, bit 1 the first, bit 2 the second), and per chunk of `hessian_chunk` edges the
  // groups its edges touch
  void build_incidences(const Variable_groups& G) const
  {
    const std::size_t m = P_.edges.size();
    const int ng = static_cast<int>(G.start.size());
    auto ends_groups = [&](std::size_t e, int& ga, int& gb) {
      const int a = P_.edges[e][0], b = P_.edges[e][1];
      ga = P_.kind[a] == Fixed ? -1 : G.group_of[variable_owner(P_, a)];
      gb = P_.kind[b] == Fixed ? -1 : G.group_of[variable_owner(P_, b)];
    };
    incidence_first_.assign(ng + 1, 0);
    int ga, gb;
    for(std::size_t e = 0; e < m; ++e) {
      ends_groups(e, ga, gb);
      if(ga >= 0) ++incidence_first_[ga + 1];
      if(gb >= 0 && gb != ga) ++incidence_first_[gb + 1];
    }
    for(int g = 0; g < ng; ++g)
      incidence_first_[g + 1] += incidence_first_[g];
    incidence_.resize(incidence_first_[ng]);
    std::vector<int> fill(incidence_first_.begin(), incidence_first_.end() - 1);
    std::vector<int> last_chunk(ng, -1);
    chunk_groups_first_.assign(1, 0);
    chunk_groups_.clear();
    for(std::size_t e = 0; e < m; ++e) {
      const int ci = static_cast<int>(e / hessian_chunk);
      if(e % hessian_chunk == 0 && e > 0)
        chunk_groups_first_.push_back(static_cast<int>(chunk_groups_.size()));
      ends_groups(e, ga, gb);
      const int code = 4 * static_cast<int>(e);
      if(ga >= 0 && ga == gb) {
        incidence_[fill[ga]++] = code | 3;
      } else {
        if(ga >= 0) incidence_[fill[ga]++] = code | 1;
        if(gb >= 0) incidence_[fill[gb]++] = code | 2;
      }
      for(int g : {ga, gb})
        if(g >= 0 && last_chunk[g] != ci) {
          last_chunk[g] = ci;
          chunk_groups_.push_back(g);
        }
    }
    chunk_groups_first_.push_back(static_cast<int>(chunk_groups_.size()));
  }

  // the pattern's compressed columns (`outer`: each column's first entry)
  void build_columns(const Variable_groups& G, std::vector<int>& outer) const
  {
    const int nv = P_.n_vars;
    pattern_.resize(nv, nv);
    outer.assign(nv + 1, 0);
    for(int c = 0; c < nv; ++c)
      outer[c + 1] = outer[c] + G.rows[G.group_of[c] + 1];
    pattern_.resizeNonZeros(outer[nv]);
    std::copy(outer.begin(), outer.end(), pattern_.outerIndexPtr());
    int* inner = pattern_.innerIndexPtr();
    for(int c = 0; c < nv; ++c) {
      const int g = G.group_of[c];
      int k = outer[c];
      for(int q = G.first[g]; q < G.first[g + 1]; ++q)
        for(int i = 0; i < G.dim[G.nb[q]]; ++i)
          inner[k++] = G.start[G.nb[q]] + i;
    }
    std::fill(pattern_.valuePtr(), pattern_.valuePtr() + pattern_.nonZeros(), 0.0);
    pattern_nnz_ = pattern_.nonZeros();
  }

  // per edge, the position of each entry of its block
  void build_slots(const Variable_groups& G, const std::vector<int>& outer) const
  {
    const std::size_t m = P_.edges.size();
    slot_begin_.assign(m + 1, 0);
    int gi[4];
    for(std::size_t e = 0; e < m; ++e) {
      const int n = local_variables(e, gi);
      slot_begin_[e + 1] = slot_begin_[e] + n * n;
    }
    slots_.resize(slot_begin_.back());
    for(std::size_t e = 0; e < m; ++e) {
      const int n = local_variables(e, gi);
      if(n == 0)
        continue;
      const int g0 = G.group_of[gi[0]], g1 = G.group_of[gi[n - 1]];
      const int off[2][2] = {{G.offset_in_column(g0, g0), G.offset_in_column(g0, g1)},
                             {G.offset_in_column(g1, g0), G.offset_in_column(g1, g1)}};
      for(int j = 0; j < n; ++j) {
        const int col = gi[j], gc = G.group_of[col];
        for(int i = 0; i < n; ++i) {
          const int gr = G.group_of[gi[i]];
          slots_[slot_begin_[e] + i * n + j] = outer[col] + off[gc == g1][gr == g1] + (gi[i] - G.start[gr]);
        }
      }
    }
  }

  const Flat_problem& P_;
  mutable std::vector<double> g_abs_;
  mutable Eigen::SparseMatrix<double> pattern_;
  mutable Eigen::Index pattern_nnz_ = 0;
  mutable bool pattern_given_ = false;
  mutable std::vector<int> slot_begin_, slots_;
  static constexpr std::size_t hessian_chunk = 65536; // edges whose Hessian blocks are buffered at a time
  mutable std::vector<int> incidence_first_, incidence_, chunk_groups_first_, chunk_groups_; // (build_incidences)
  mutable std::vector<double> edge_energy_, edge_gradient_, edge_hessian_;
  mutable std::size_t hessian_offset_ = 0; // slot of the first edge of the chunk in edge_hessian_
  mutable std::vector<double> terms_x_;     // the point of the last evaluate(): the per-edge terms are its
  mutable std::vector<double> noise_;       // rounding_noise() there, once computed
};

} // namespace internal
} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_SOLVER_DIRICHLET_ENERGY_H
