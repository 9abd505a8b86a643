// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_EMBEDDING_STATISTICS_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_EMBEDDING_STATISTICS_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Hyperbolic_orbifold_Tutte/Embedding_certificate.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/Embedding_layout.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/Hyperbolic_isometry_2.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/Orbifold_tile.h>

#include <cstddef>
#include <string>
#include <vector>

/// \file Embedding_statistics.h

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {

/*!
\ingroup PkgHyperbolicOrbifoldTutteMainClasses
What the nonlinear solver did (Riemannian Newton on the hyperbolic Dirichlet energy): its
steps, energies, force imbalance and timings (seconds). Part of `Embedding_statistics`.
*/
struct Solver_statistics
{
  int iterations = 0;                 ///< steps of the solver (preconditioned gradient steps, then Newton steps)
  int cg_iterations = 0;              ///< conjugate-gradient iterations of the Newton steps, in all
  int preconditioner_factorizations = 0; ///< factorisations of the connection-Laplacian preconditioner after the first
  double initial_energy = 0;          ///< Dirichlet energy of the Euclidean Tutte initialisation
  double energy = 0;                  ///< final Dirichlet energy \f$ \frac12\sum w_{ij} d_{ij}^2 \f$
  double gradient_norm = 0;           ///< final hyperbolic norm of the energy's gradient
  double relative_gradient_norm = 0;  ///< the same, relative to the norm of the sums of the absolute values of the edges' contributions (the forces' imbalance; its floor is the rounding error)
  /// the force imbalance that rounding the coordinates to `double` alone would cause (an
  /// estimate from each edge's length and how many digits its ends' coordinates give it):
  /// about \f$10^{-15}\f$ on ordinary meshes, far more where cotangent weights are huge
  /// (needle triangles) or vertices crowd towards the circle
  double rounding_floor = 0;
  /// `true` when the tolerance was out of reach of `double` and the solver stopped at the
  /// floor instead: Newton's steps no longer reduced the imbalance and it is within
  /// \f$10\times\f$ `rounding_floor` (the coordinates are then as accurate as `double` allows)
  bool converged_at_rounding_floor = false;
  /// `true` when the solver reached the gradient tolerance, or the rounding floor above it
  bool converged = false;
  /// Newton steps taken after the force imbalance reached the tolerance, because some vertex's
  /// own forces were still out of balance by more than \f$10^{-8}\f$ of their sizes (beyond
  /// what rounding explains), or because the certificate found a flipped face: the force
  /// imbalance is a global measure, blind to a region squeezed so small (a protrusion
  /// without landmarks, \f$10^{-12}\f$ across) that its forces are below the tolerance
  /// times the largest ones; such a region is solved to the precision of `double` (steps
  /// until rounding stops them), before the one-ring repair is tried
  int polishing_iterations = 0;
  /// \var time_assembly
  /// seconds spent assembling the Newton systems (part of `time_optimization`)
  /// \var time_factorization
  /// seconds spent factoring the Newton matrices (part of `time_optimization`)
  double time_assembly = 0, time_factorization = 0, time_line_search = 0; ///< parts of `time_optimization` (factorisation: the preconditioner's and the conjugate gradients)
  double initial_gradient_norm = 0;   ///< hyperbolic norm of the energy's gradient at the initialisation
  int cg_failures = 0;                ///< Newton steps whose conjugate gradients did not reach their tolerance
};

/*!
\ingroup PkgHyperbolicOrbifoldTutteMainClasses
What a parameterization did: the solver's statistics, the sizes, the other timings
(seconds) and the certificate.

It derives from `Embedding_layout` (what is needed to read the coordinates: the orbifold, the
landmark order, the frame, the charts, the cut) only so that code written against earlier
versions, which read those fields here, compiles unchanged: that part is deprecated here, and
new code reads it from the result, `Orbifold_embedding::layout()`.
*/
struct Embedding_statistics : public Solver_statistics, public Embedding_layout
{
  int number_of_vertices = 0;         ///< vertices of the cut (seam) mesh
  int number_of_variables = 0;        ///< unknowns after eliminating seam twins
  /// `true` when the initialisation solved its Tutte system with the leading block of the
  /// solver's factorisation, so that one factorisation served both (with CHOLMOD, from 50K
  /// vertices of the cut mesh on, where the order this needs fills the factor no more than
  /// CHOLMOD's own; otherwise each factors a matrix of its own)
  bool shared_factorization = false;
  int repaired_vertices = 0;          ///< vertices moved by the one-ring repair (paper, section 5)
  /// `true` when the embedding is the mean value weights' one: `hyperbolic_orbifold_Tutte_embedding()`
  /// without `weight_type` and `edge_weight_map` embeds with the cotangent weights, and again
  /// with the mean value weights when that embedding fails the certificate
  bool mean_value_fallback = false;
  std::string fallback_reason;        ///< then, why the cotangent weights' embedding was refused (its message)
  /// \var time_setup
  /// seconds spent checking the input, cutting the mesh and setting up the problem
  /// \var time_initialization
  /// seconds spent in the Euclidean Tutte initialisation (with `shared_factorization`, the
  /// solver's factorisation is made there and counted there)
  /// \var time_optimization
  /// seconds spent in Newton's method
  /// \var time_certificate
  /// seconds spent certifying the result (and repairing one-rings)
  double time_setup = 0, time_initialization = 0, time_optimization = 0, time_certificate = 0;
  /// the bijectivity certificate of the computed coordinates
  Embedding_certificate certificate;
  std::string message;                ///< one-line reason when the result is an error
  /// mesh vertices named by the error, as indices in the order of `vertices(tm)`
  /// (`ERROR_BOUNDARY_CHORD`: the ends of the offending edge)
  std::vector<std::size_t> problem_vertices;
};

/*!
\ingroup PkgHyperbolicOrbifoldTutteHelperFunctions
the tile in which an embedding with layout `layout` was computed, in the coordinates the
embedding was computed in (a recentred embedding's written coordinates are `layout.frame`
applied to them: see `Orbifold_tile::transformed()`): `make_cut_graph_tile()` of the cut
graph's polygon for genus \f$ g \ge 1 \f$, `make_orbifold_tile()` of the signature with
`layout.cone_orders` otherwise.
*/
template <class Traits>
Error_code make_embedding_tile(const Embedding_layout& layout, Orbifold_tile<Traits>& tile, const Traits& traits = Traits())
{
  if(layout.genus > 0)
    return make_cut_graph_tile(layout.signature(), layout.cut_corner_nodes, layout.cut_node_cones, layout.cut_paired_sides,
                               tile, traits);
  return make_orbifold_tile(layout.signature(), tile, traits);
}

/*!
\ingroup PkgHyperbolicOrbifoldTutteHelperFunctions
`make_embedding_tile()` of the layout `st` with the type `type` (for statistics filled by
code that does not set `Embedding_layout::type`).
*/
template <class Traits>
Error_code make_embedding_tile(Orbifold_type type, const Embedding_layout& st, Orbifold_tile<Traits>& tile,
                               const Traits& traits = Traits())
{
  if(st.genus > 0)
    return make_embedding_tile(st, tile, traits); // (the cut graph's polygon: no type)
  return make_orbifold_tile(Orbifold_signature(type, st.cone_orders), tile, traits);
}

} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_EMBEDDING_STATISTICS_H
