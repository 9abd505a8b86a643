// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_MAP_REFINEMENT_STATISTICS_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_MAP_REFINEMENT_STATISTICS_H

#include <cstddef>
#include <string>

/// \file Map_refinement_statistics.h
/// What `refine_orbifold_map()` reports (a vocabulary header: no algorithm).

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {

/*!
\ingroup PkgHyperbolicOrbifoldTutteEnums
why `refine_orbifold_map()` stopped
*/
enum Refinement_stop
{
  Refinement_not_run,     ///< no iteration was asked for
  Refinement_iterations,  ///< the asked number of iterations ran
  Refinement_converged,   ///< five iterations in a row lowered the energy by less than a relative 1e-6 (kept), or no step along an iteration's moves lowered it
  Refinement_certificate, ///< no step along an iteration's moves that lowered the energy passed the exact certificate: the last certified iterate is kept
  Refinement_solver       ///< the global step's linear system could not be solved: the last iterate is kept
};

/*!
\ingroup PkgHyperbolicOrbifoldTutteMainClasses
what `refine_orbifold_map()` did
*/
struct Map_refinement_statistics
{
  int iterations = 0;                ///< accepted iterations (each one certified)
  double energy_before = 0;          ///< the symmetric Dirichlet energy of the map before (see `refine_orbifold_map()`; 4 for an isometry up to scale)
  double energy_after = 0;           ///< and after
  double tempered_energy_before = 0; ///< the energy the iterations lower: as `energy_before`, with the density above 100 (faces squeezed about 10 times or more) counted as \f$100 (1 + \log(d / 100))\f$ (see `refine_orbifold_map()`)
  double tempered_energy_after = 0;  ///< and after (below `tempered_energy_before` when an iteration was accepted)
  std::size_t free_vertices = 0;     ///< vertices that may move (not landmarks, not on a border)
  std::size_t undone_moves = 0;      ///< in the last accepted iteration: moves undone so that no face turns over
  double seconds = 0;                ///< the time of the refinement
  double seconds_certificate = 0;    ///< of which the certificates of the iterates
  Refinement_stop stop = Refinement_not_run; ///< why it stopped
  std::string message;               ///< one line: the stop, in words
};

} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_MAP_REFINEMENT_STATISTICS_H
