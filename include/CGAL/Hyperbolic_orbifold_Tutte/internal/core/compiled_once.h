// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_CORE_COMPILED_ONCE_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_CORE_COMPILED_ONCE_H

// Stages compiled once, for the project's own builds.
//
// The package is header-only, and stays so for its users: every function is compiled in the
// translation unit that calls it. Some internal stages cost most of a unit's compile time
// (Newton with its energy, preconditioner and multigrid; the Tutte initialisation's solve;
// the mesh preparation with PMP's hole filling) while depending on no type of the user's:
// each of them is entered through one "door", a function template with one defaulted
// parameter (`template <int = 0>`), called like a plain function.
//
// - Header-only use (nothing defined): a door is instantiated where it is called, like an
//   inline function. Nothing changes for users.
// - The project's own programs (tests, examples, benchmarks, the command-line program and the
//   Python module) link the library `Hyperbolic_orbifold_Tutte_instances` (folder `instances/`),
//   whose CMake target defines CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_EXTERN_INSTANCES: each door is then
//   declared `extern template` right after its definition (CGAL_HOT_INSTANCE(extern, ...)), so
//   that no unit instantiates it, nor what only it calls; the library instantiates each door
//   once (CGAL_HOT_INSTANCE(, ...)), with the same flags.
//
// A door's signature is written once, in a macro next to its definition, and used for both.

#define CGAL_HOT_INSTANCE(KEYWORD, SIGNATURE_MACRO) KEYWORD template SIGNATURE_MACRO;

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_CORE_COMPILED_ONCE_H
