// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_CORE_ORBIFOLD_ENUMS_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_CORE_ORBIFOLD_ENUMS_H

// CGAL's <CGAL/Surface_mesh_parameterization/orbifold_enums.h> (5.5) defines the function
// get_orbifold_type() without `inline`: a program with two translation units that include it
// fails to link (multiple definition). Declared inline before the header defines it, the
// function is inline (C++17 [dcl.inline]), and any number of translation units may include our
// headers. (When the header was included first, the definition is already there: nothing can
// be done here, and such a program has the problem without us.)
#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_ORBIFOLD_ENUMS_H
namespace CGAL {
namespace Surface_mesh_parameterization {
inline const char* get_orbifold_type(int orb_type);
} // namespace Surface_mesh_parameterization
} // namespace CGAL
#endif

#include <CGAL/Surface_mesh_parameterization/orbifold_enums.h>

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_CORE_ORBIFOLD_ENUMS_H
