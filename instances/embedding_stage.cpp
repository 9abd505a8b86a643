// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

// The solve stage of the pipeline (flat problem, weights, initialisation, Newton, certificate
// and mends) instantiated once for the project's own programs, for the seam mesh of a
// CGAL::Surface_mesh over Epick's points and the default tile (internal/core/compiled_once.h).

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/pipeline/embedding_pipeline.h>

#ifndef CGAL_HOT_RUN_EMBEDDING_STAGE_DOOR
#error "the door of the solve stage is not declared"
#endif

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {
namespace internal {

CGAL_HOT_INSTANCE(, CGAL_HOT_RUN_EMBEDDING_STAGE_DOOR)

} // namespace internal
} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL
