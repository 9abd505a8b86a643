// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_SOLVER_ORBIFOLD_SOLVER_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_SOLVER_ORBIFOLD_SOLVER_H

/// \file orbifold_solver.h
// The solver of the flat problem, one concern per header (all in namespace internal):
//  - edge_weights.h:              compute_edge_weights (cotangent clamped, mean value, uniform)
//  - laplacian_factorization.h:   Laplacian_factorization (Eigen or CHOLMOD, single precision)
//  - interior_laplacian.h:        Interior_laplacian (the interior's factored Laplacian, shared)
//  - dirichlet_energy.h:          Energy_evaluator (energy, gradient, Hessian, force imbalance)
//  - connection_preconditioner.h: Connection_laplacian_preconditioner
//  - tutte_initialization.h:      initialize_embedding (the border placed, then solve_interior_tutte)
//  - solver_doors.h:              Solver_options; minimize_energy and solve_interior_tutte declared
//                                 (compiled once in the project's own builds: compiled_once.h)
//  - newton.h:                    minimize_energy (filling the public Solver_statistics; the steps of
//                                 Newton_minimizer), subtract_christoffel_terms
//  - tutte_interior_solve.h:      solve_interior_tutte
//  - newton_on_region.h:          minimize_energy_on_region
//  - one_ring_repair.h:           positive_triangle, One_ring_faces, repair_one_rings, snap_one_rings

#include <CGAL/Hyperbolic_orbifold_Tutte/internal/solver/edge_weights.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/linear_algebra/laplacian_factorization.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/linear_algebra/interior_laplacian.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/solver/solver_doors.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/solver/tutte_initialization.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/solver/newton_on_region.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/solver/one_ring_repair.h>
// (newton.h, dirichlet_energy.h, connection_preconditioner.h and tutte_interior_solve.h come
// through solver_doors.h in header-only use; the project's own units do not parse them)

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_SOLVER_ORBIFOLD_SOLVER_H
