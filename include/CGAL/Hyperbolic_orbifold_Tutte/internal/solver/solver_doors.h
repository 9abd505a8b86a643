// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_SOLVER_SOLVER_DOORS_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_SOLVER_SOLVER_DOORS_H

#include <CGAL/disable_warnings.h>

/// \file solver_doors.h
// The solver's two doors (compiled_once.h), declared: minimize_energy() (Riemannian Newton on
// the hyperbolic Dirichlet energy; defined in newton.h) with its options, and
// solve_interior_tutte() (the initialisation's solve; defined in tutte_interior_solve.h).
// The pipeline includes this header only: in header-only use it brings both definitions in;
// in the project's own builds (CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_EXTERN_INSTANCES) it declares
// them extern, and a unit that does not include the definitions does not parse the energy,
// the preconditioner, the multigrid or Newton at all (instances/solver.cpp does).

#include <CGAL/Hyperbolic_orbifold_Tutte/Embedding_statistics.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/error_code.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/core/compiled_once.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/solver/flat_problem.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/linear_algebra/interior_laplacian.h>

#include <complex>
#include <functional>
#include <vector>

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {
namespace internal {

// (The fields that nothing set are constants of Newton_minimizer now: the conjugate gradients'
// iterations, when the preconditioner is refactored, when Newton takes over from gradient
// steps; always on: geodesic steps, the Riemannian Hessian, the single-precision preconditioner.)
struct Solver_options
{
  double gradient_tolerance = 1e-10; // force imbalance (relative hyperbolic gradient norm)
  int max_iterations = 200;
  // Preconditioned gradient steps before Newton (phase 1 of minimize_energy). Off: Newton
  // from the start is as fast with 7 landmarks and up to 1.8x faster with 50, where the
  // gradient steps' long moves need the preconditioner factored again two or three times.
  bool gradient_steps = false;
  bool direct_solver = false;        // factor every Newton system instead of conjugate gradients
  // Newton steps from the start, until rounding stops them (the tolerance is ignored): for a
  // converged embedding whose small regions need the last digits (see the parameterizer)
  bool polish = false;
  // converged also means: no vertex's own forces are out of balance by more than this
  // fraction of their sizes, unless rounding explains it (else Newton goes on to the floor)
  double vertex_imbalance = 1e-8;
  // the preconditioner's solves with its factor rounded to single precision where that factor
  // is Eigen's (below 50K rows; CHOLMOD's, from 50K, always are): off for the solves of a
  // squeezed region (newton_on_region.h), where it was seen to spoil the recentring at the
  // limit of double's range (a tube of length 350)
  bool single_precision_small_preconditioner = true;
  // from this many cut-mesh vertices on, the preconditioner is a V-cycle of algebraic
  // multigrid instead of a factorisation, where minimize_energy() is given no initialisation's
  // interior Laplacian (with one, the preconditioner follows the initialisation: multigrid
  // where it solved by multigrid, see Interior_laplacian::multigrid_from)
  Eigen::Index multigrid_from = default_multigrid_from;
  bool verbose = false;
  // told after every accepted Newton step the progress of the solve in [0, 1], non-decreasing:
  // the relative gradient norm's way from the start towards the tolerance on a log scale
  // (none while polishing); only reads the solver's state
  std::function<void(double)> progress;
};

// Minimises the energy (see Newton_minimizer, newton.h), from x, in place. `interior`: the
// initialisation's interior Laplacian, for the preconditioner's gauge, and its connection
// Laplacian where it factored one for this problem.
template <int = 0>
Error_code minimize_energy(const Flat_problem& P, std::vector<double>& x, const Solver_options& opt,
                           Solver_statistics& st, const Interior_laplacian* interior = nullptr);

// The initialisation's solve, once the border is placed (x, and z at every vertex on the
// border): the interior's Tutte embedding in the Klein model, written into x in Poincare
// coordinates; lap numbers the interior and keeps what the solver reuses
// (tutte_interior_solve.h).
template <int = 0>
Error_code solve_interior_tutte(const Flat_problem& P, const std::vector<std::complex<double> >& z, std::vector<double>& x,
                                Interior_laplacian& lap);

#define CGAL_HOT_MINIMIZE_ENERGY_DOOR                                                                     \
  Error_code minimize_energy<0>(const Flat_problem&, std::vector<double>&, const Solver_options&,       \
                                Solver_statistics&, const Interior_laplacian*)
#define CGAL_HOT_SOLVE_INTERIOR_TUTTE_DOOR                                                                \
  Error_code solve_interior_tutte<0>(const Flat_problem&, const std::vector<std::complex<double> >&,     \
                                     std::vector<double>&, Interior_laplacian&)
#ifdef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_EXTERN_INSTANCES
CGAL_HOT_INSTANCE(extern, CGAL_HOT_MINIMIZE_ENERGY_DOOR)
CGAL_HOT_INSTANCE(extern, CGAL_HOT_SOLVE_INTERIOR_TUTTE_DOOR)
#endif

} // namespace internal
} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_EXTERN_INSTANCES
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/solver/newton.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/solver/tutte_interior_solve.h>
#endif

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_SOLVER_SOLVER_DOORS_H
