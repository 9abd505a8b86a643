// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_SOLVER_HESSIAN_PATTERN_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_SOLVER_HESSIAN_PATTERN_H

#include <CGAL/disable_warnings.h>

// The parts of the Dirichlet energy's Hessian (dirichlet_energy.h) that do not depend on the
// point: the owners of variables as groups and their neighbouring groups (from which the
// sparsity pattern is built), and the projection of an edge's block onto the positive
// semi-definite cone.

#include <CGAL/Hyperbolic_orbifold_Tutte/internal/solver/flat_problem.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {
namespace internal {

// The owners of variables as groups of consecutive variables, numbered in vertex order,
// and per group its neighbouring groups (itself included), sorted by first variable.
struct Variable_groups
{
  std::vector<int> group_of;   // group of each variable
  std::vector<int> start, dim; // first variable and number of variables of each group
  std::vector<int> first, nb;  // neighbours of group g: nb[first[g]], ..., nb[first[g + 1] - 1]
  std::vector<int> row_offset; // per neighbour: its first row in the column
  std::vector<int> rows;       // rows per column of each group (rows[g + 1]: group g's)

  // first row of group h in the columns of group g
  int offset_in_column(int g, int h) const
  {
    const auto it = std::lower_bound(nb.begin() + first[g], nb.begin() + first[g + 1], h,
                                     [&](int p, int q) { return start[p] < start[q]; });
    return row_offset[it - nb.begin()];
  }
};

// owners as groups of consecutive variables: group of each variable, its start and size
inline void group_variables(const Flat_problem& P, Variable_groups& G)
{
  G.group_of.assign(P.n_vars, -1);
  for(int v = 0; v < P.n; ++v)
    if(P.kind[v] == Free || P.kind[v] == On_line) {
      const int d = P.kind[v] == Free ? 2 : 1;
      for(int i = 0; i < d; ++i)
        G.group_of[P.var[v] + i] = static_cast<int>(G.start.size());
      G.start.push_back(P.var[v]);
      G.dim.push_back(d);
    }
}

// neighbouring groups (compressed rows, itself first, unsorted, with duplicates)
inline void find_neighbour_groups(const Flat_problem& P, Variable_groups& G)
{
  const std::size_t m = P.edges.size();
  const int ng = static_cast<int>(G.start.size());
  auto group_of_end = [&](std::size_t e, int s) {
    const int v = P.edges[e][s];
    return P.kind[v] == Fixed ? -1 : G.group_of[variable_owner(P, v)];
  };
  std::vector<int>& first = G.first;
  first.assign(ng + 1, 0);
  for(std::size_t e = 0; e < m; ++e) {
    const int ga = group_of_end(e, 0), gb = group_of_end(e, 1);
    if(ga >= 0 && gb >= 0 && ga != gb) { ++first[ga + 1]; ++first[gb + 1]; }
  }
  for(int g = 0; g < ng; ++g)
    first[g + 1] += first[g] + 1; // + itself
  G.nb.resize(first[ng]);
  std::vector<int> fill(first.begin(), first.end() - 1);
  for(int g = 0; g < ng; ++g)
    G.nb[fill[g]++] = g;
  for(std::size_t e = 0; e < m; ++e) {
    const int ga = group_of_end(e, 0), gb = group_of_end(e, 1);
    if(ga >= 0 && gb >= 0 && ga != gb) { G.nb[fill[ga]++] = gb; G.nb[fill[gb]++] = ga; }
  }
}

// (groups are numbered in vertex order, their variables need not be: sort by variable,
// remove the duplicates, and place each neighbour's rows in the column)
inline void sort_neighbour_groups(Variable_groups& G)
{
  const int ng = static_cast<int>(G.start.size());
  std::vector<int>& first = G.first;
  std::vector<int>& nb = G.nb;
  G.rows.assign(ng + 1, 0);
  G.row_offset.resize(nb.size());
  std::size_t w = 0;
  for(int g = 0; g < ng; ++g) {
    const std::size_t b = w;
    std::sort(nb.begin() + first[g], nb.begin() + first[g + 1], [&](int p, int q) { return G.start[p] < G.start[q]; });
    for(int k = first[g]; k < first[g + 1]; ++k)
      if(w == b || nb[w - 1] != nb[k]) nb[w++] = nb[k];
    first[g] = static_cast<int>(b);
    int off = 0;
    for(std::size_t k = b; k < w; ++k) {
      G.row_offset[k] = off;
      off += G.dim[nb[k]];
    }
    G.rows[g + 1] = off; // rows per column of this group
  }
  first[ng] = static_cast<int>(w);
  nb.resize(w);
  G.row_offset.resize(w);
}

// the leading N x N block of M with its negative eigenvalues set to 0
template <int N>
void clamp_eigenvalues(Eigen::Matrix4d& M)
{
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, N, N> > es(M.template topLeftCorner<N, N>());
  if(es.eigenvalues().minCoeff() >= 0) return;
  Eigen::Matrix<double, N, 1> l = es.eigenvalues().cwiseMax(0.0);
  M.template topLeftCorner<N, N>() = es.eigenvectors() * l.asDiagonal() * es.eigenvectors().transpose();
}

// an edge's n x n Hessian block (the leading block of M) projected onto the positive
// semi-definite cone
inline void project_psd(Eigen::Matrix4d& M, int n)
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
  if(n == 2)
    clamp_eigenvalues<2>(M);
  else if(n == 3)
    clamp_eigenvalues<3>(M);
  else
    clamp_eigenvalues<4>(M);
}

} // namespace internal
} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_SOLVER_HESSIAN_PATTERN_H
