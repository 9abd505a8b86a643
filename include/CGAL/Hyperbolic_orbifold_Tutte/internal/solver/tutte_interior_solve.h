// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_SOLVER_TUTTE_INTERIOR_SOLVE_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_SOLVER_TUTTE_INTERIOR_SOLVE_H

#include <CGAL/disable_warnings.h>

/// \file tutte_interior_solve.h
// The initialisation's solve (the definition of solve_interior_tutte(), declared in
// solver_doors.h): the interior's Tutte embedding in the Klein model, by a factorisation
// (shared with the solver's connection Laplacian where CHOLMOD keeps its leading block, or
// concurrent with the factorisation of that Laplacian) or by multigrid.

#include <CGAL/Hyperbolic_orbifold_Tutte/Hyperbolic_isometry_2.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/error_code.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/solver/connection_preconditioner.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/solver/flat_problem.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/linear_algebra/interior_laplacian.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/solver/solver_doors.h>

#include <Eigen/Dense>
#include <Eigen/Sparse>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/task_group.h>
#endif

#include <cmath>
#include <complex>
#include <memory>
#include <vector>

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {
namespace internal {

// Numbers the interior vertices (lap.index, lap.size). The interior Laplacian is the leading
// block of the solver's connection Laplacian (its rotations depend on the border's positions
// only, placed before): where that block can be kept at little cost, the solver's
// factorisation is made here and serves both (lap.connection; else the analysis alone was
// spent, a few percent of a factorisation).
inline void number_interior(const Flat_problem& P, const std::vector<double>& x, Interior_laplacian& lap)
{
  std::vector<char> is_border(P.n, 0);
  for(int v : P.border_loop)
    is_border[v] = 1;
  std::vector<int>& interior_index = lap.index;
  interior_index.assign(P.n, -1);
  lap.own_factor = false;
  lap.connection.reset();
  lap.prefactored.reset();
  lap.multigrid.reset();
  if(lap.share && P.n >= lap.share_from && P.n < lap.multigrid_from) {
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
}

// the relative residual of the Tutte embedding's solves by multigrid (a factorisation's are
// about 1e-15): Newton starts from it, and the embedding lies inside the disk
constexpr double klein_tutte_tolerance = 1e-9;

// The Tutte embedding of the interior in Klein coordinates (kxy: one column per coordinate),
// the border at z: with the connection's leading block, with a factorisation of its own, or
// (from lap.multigrid_from vertices) by conjugate gradients preconditioned by multigrid
inline Error_code solve_klein_tutte(const Flat_problem& P, const std::vector<std::complex<double> >& z, Interior_laplacian& lap,
                                    Eigen::MatrixXd& kxy)
{
  typedef std::complex<double> C;
  typedef Eigen::SparseMatrix<double> SpMat;
  const std::vector<int>& interior_index = lap.index;
  const int ni = lap.size;
  const bool own = !lap.connection; // a factorisation of its own
  std::vector<Eigen::Triplet<double> > trip;
  if(own)
    trip.reserve(4 * P.edges.size() + ni);
  Eigen::MatrixXd bxy = Eigen::MatrixXd::Zero(ni, 2); // both coordinates: one solve of two columns
  auto bx = bxy.col(0);
  auto by = bxy.col(1);
  std::vector<double> diag(own ? ni : 0, 0.0);
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
      const C kb = poincare_to_klein(z[b]);
      bx[ia] += w * kb.real();
      by[ia] += w * kb.imag();
    } else if(ib >= 0) {
      const C ka = poincare_to_klein(z[a]);
      bx[ib] += w * ka.real();
      by[ib] += w * ka.imag();
    }
  }
  if(!own) { // both coordinates as one complex right-hand side
    Eigen::VectorXcd k;
    if(!lap.connection->solve_interior(bxy.col(0).cast<std::complex<double> >() +
                                         std::complex<double>(0.0, 1.0) * bxy.col(1).cast<std::complex<double> >(), k))
      return ERROR_CANNOT_SOLVE_LINEAR_SYSTEM;
    kxy.resize(ni, 2);
    kxy.col(0) = k.real();
    kxy.col(1) = k.imag();
    return OK;
  }
  for(int i = 0; i < ni; ++i)
    trip.emplace_back(i, i, diag[i]);
  if(P.n >= lap.multigrid_from) { // conjugate gradients, preconditioned by multigrid
    typedef Interior_laplacian::Multigrid Multigrid;
    typename Multigrid::Matrix Lr(ni, ni);
    Lr.setFromTriplets(trip.begin(), trip.end());
    std::vector<Eigen::Triplet<double> >().swap(trip);
    lap.multigrid = std::make_shared<Multigrid>();
    if(!lap.multigrid->compute(std::move(Lr))) {
      lap.multigrid.reset();
      return ERROR_CANNOT_SOLVE_LINEAR_SYSTEM;
    }
    Eigen::VectorXcd k; // (from 0; both coordinates at once)
    if(!lap.solve_by_multigrid(bxy.col(0).cast<C>() + C(0.0, 1.0) * bxy.col(1).cast<C>(), k, klein_tutte_tolerance))
      return ERROR_CANNOT_SOLVE_LINEAR_SYSTEM;
    kxy.resize(ni, 2);
    kxy.col(0) = k.real();
    kxy.col(1) = k.imag();
    return OK;
  }
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
  return OK;
}

// The initialisation's solve, once the border is placed (x, and z at every vertex on the
// border): the interior's Tutte embedding in the Klein model, written into x in Poincare
// coordinates; lap numbers the interior and keeps what the solver reuses. (The door declared
// in solver_doors.h.)
template <int>
Error_code solve_interior_tutte(const Flat_problem& P, const std::vector<std::complex<double> >& z, std::vector<double>& x,
                                Interior_laplacian& lap)
{
  typedef std::complex<double> C;
  number_interior(P, x, lap);
  if(lap.size == 0)
    return OK;
  Eigen::MatrixXd kxy;
  Error_code solved = OK;
#ifdef CGAL_LINKED_WITH_TBB
  // the solver's connection Laplacian factored meanwhile, where both factorisations are
  // Eigen's (sequential): see Interior_laplacian::prefactored
  bool both_sequential = !lap.connection && P.n < lap.multigrid_from;
#ifdef CGAL_HOT_USE_CHOLMOD
  both_sequential = both_sequential && P.n < Laplacian_factorization<double>::cholmod_threshold;
#endif
  if(lap.prefactor && both_sequential) {
    auto pre = std::make_shared<Connection_laplacian_preconditioner>(P);
    pre->expect_interior();
    bool factored = false;
    tbb::task_group tasks;
    tasks.run([&] { factored = pre->factor(x); }); // (reads the border's positions only, placed)
    try {
      solved = solve_klein_tutte(P, z, lap, kxy);
    } catch(...) {
      tasks.wait();
      throw;
    }
    tasks.wait();
    if(factored && pre->attach_interior(&lap))
      lap.prefactored = pre;
  } else
#endif
  {
    solved = solve_klein_tutte(P, z, lap, kxy);
  }
  if(solved != OK)
    return solved;
  const auto kx = kxy.col(0);
  const auto ky = kxy.col(1);
  for(int v = 0; v < P.n; ++v) {
    const int i = lap.index[v];
    if(i < 0)
      continue;
    const C k(kx[i], ky[i]);
    const double s = 1.0 - squared_modulus(k);
    if(!(s > 0) || !std::isfinite(k.real()) || !std::isfinite(k.imag()))
      return ERROR_CANNOT_SOLVE_LINEAR_SYSTEM;
    const C p = klein_to_poincare(k); // s > 0: the same s, unclamped
    if(P.kind[v] == Free) {
      x[P.var[v]] = p.real();
      x[P.var[v] + 1] = p.imag();
    }
  }
  return OK;
}

} // namespace internal
} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_SOLVER_TUTTE_INTERIOR_SOLVE_H
