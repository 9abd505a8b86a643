// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_LINEAR_ALGEBRA_INTERIOR_LAPLACIAN_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_LINEAR_ALGEBRA_INTERIOR_LAPLACIAN_H

#include <CGAL/disable_warnings.h>

/// \file interior_laplacian.h
// The factored Laplacian of the cut mesh's interior, shared by the initialisation and the
// preconditioner's gauge.

#include <CGAL/Hyperbolic_orbifold_Tutte/internal/linear_algebra/laplacian_factorization.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/linear_algebra/smoothed_aggregation.h>

#include <complex>
#include <memory>
#include <vector>

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {
namespace internal {

class Connection_laplacian_preconditioner; // (connection_preconditioner.h)

// The size (cut-mesh vertices) from which the Laplacians are solved by multigrid-preconditioned
// conjugate gradients instead of factored: a sparse factorisation's work grows like n^1.5 on a
// surface (22x from 250K to 2M vertices), multigrid's linearly.
constexpr Eigen::Index default_multigrid_from = 400000;

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
  // Where the interior Laplacian is factored on its own by Eigen (below `share_from` cut-mesh
  // vertices, or where sharing failed below that size), the solver's connection Laplacian is
  // factored at the same time on a second thread (both factorisations are sequential; the
  // connection's depends on the border's positions only): `prefactored`, which the solver
  // takes over. (With TBB only; `prefactor` false: the solver factors it itself.)
  bool prefactor = true;
  std::shared_ptr<Connection_laplacian_preconditioner> prefactored;
  // From this many cut-mesh vertices on, no factorisation: the initialisation solves with
  // conjugate gradients preconditioned by algebraic multigrid (`multigrid`, kept for the
  // gauge), and so does the solver (Solver_options::multigrid_from, the same default)
  Eigen::Index multigrid_from = default_multigrid_from;
  typedef Smoothed_aggregation<double, std::complex<double> > Multigrid; // (two real right-hand sides at once)
  std::shared_ptr<Multigrid> multigrid;
  // solves with the interior Laplacian's hierarchy (relative residual `tolerance`), from x
  // if it has b's size (else from 0): the real and imaginary parts are two real systems.
  // (A template so that only the units that call it, those of the solver, compile the
  // multigrid's solve: compiled_once.h.)
  template <int = 0>
  bool solve_by_multigrid(const Eigen::VectorXcd& b, Eigen::VectorXcd& x, double tolerance) const
  {
    return multigrid && multigrid->solve(b, x, tolerance, multigrid_max_iterations) >= 0 && x.allFinite();
  }
  static constexpr int multigrid_max_iterations = 500;
};

} // namespace internal
} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_LINEAR_ALGEBRA_INTERIOR_LAPLACIAN_H
