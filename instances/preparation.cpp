// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

// The mesh preparation's door, instantiated once for the project's own programs
// (internal/core/compiled_once.h): from a loaded polygon soup to the prepared triangles (PMP's
// orientation, repair and hole filling).

#include <CGAL/Hyperbolic_orbifold_Tutte/internal/preparation/mesh_preparation_steps.h>

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {
namespace internal {
namespace preparation {

CGAL_HOT_INSTANCE(, CGAL_HOT_PREPARE_LOADED_SOUP_DOOR)

} // namespace preparation
} // namespace internal
} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL
