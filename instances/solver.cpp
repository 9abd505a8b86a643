// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

// The solver's doors, instantiated once for the project's own programs
// (internal/core/compiled_once.h): Newton on the hyperbolic Dirichlet energy, and the Tutte
// initialisation's solve.

#include <CGAL/Hyperbolic_orbifold_Tutte/internal/solver/newton.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/solver/tutte_interior_solve.h>

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {
namespace internal {

CGAL_HOT_INSTANCE(, CGAL_HOT_MINIMIZE_ENERGY_DOOR)
CGAL_HOT_INSTANCE(, CGAL_HOT_SOLVE_INTERIOR_TUTTE_DOOR)

} // namespace internal
} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL
