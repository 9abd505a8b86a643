// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_INPUT_CHECKS_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_INPUT_CHECKS_H

// transitional: for the tools until they use the public names.
// The input checks are public now, in <CGAL/Hyperbolic_orbifold_Tutte/check_input.h>, which
// also holds the internal aliases (internal::check_mesh, internal::Check_result, ...) that
// io.h and fuzz/fuzz_mesh_reader.cpp still use. Remove this file once they include it.

#include <CGAL/Hyperbolic_orbifold_Tutte/check_input.h>

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_INPUT_CHECKS_H
