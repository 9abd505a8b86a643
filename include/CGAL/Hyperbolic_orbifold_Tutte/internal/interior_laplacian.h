// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_INTERIOR_LAPLACIAN_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_INTERIOR_LAPLACIAN_H

#include <CGAL/disable_warnings.h>

/// \file interior_laplacian.h
// The factored Laplacian of the cut mesh's interior, shared by the initialisation and the
// preconditioner's gauge.

#include <CGAL/Hyperbolic_orbifold_Tutte/internal/laplacian_factorization.h>

#include <memory>
#include <vector>

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {
namespace internal {

class Connection_laplacian_preconditioner; // (connection_preconditioner.h)

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

} // namespace internal
} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_INTERIOR_LAPLACIAN_H
