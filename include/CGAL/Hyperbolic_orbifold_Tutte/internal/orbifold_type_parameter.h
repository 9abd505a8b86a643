// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_ORBIFOLD_TYPE_PARAMETER_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_ORBIFOLD_TYPE_PARAMETER_H

#include <CGAL/Hyperbolic_orbifold_Tutte/check_input.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/parameters.h>

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {
namespace internal {

// The orbifold type of the named parameter `orbifold_type`, or, when it is not given,
// the one of the mesh's topology (closed: sphere type; one boundary loop: disk type).
// Returns false when it is not given and the mesh is neither.
template <class TriangleMesh, class NamedParameters>
bool orbifold_type_parameter(const TriangleMesh& tm, const NamedParameters& np, Orbifold_type& type)
{
  if(CGAL::parameters::is_default_parameter<NamedParameters, internal_np::orbifold_type_t>::value)
    return CGAL::Hyperbolic_orbifold_Tutte::detect_orbifold_type(tm, type);
  type = CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np, internal_np::orbifold_type), Sphere_type);
  return true;
}

} // namespace internal
} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_ORBIFOLD_TYPE_PARAMETER_H
