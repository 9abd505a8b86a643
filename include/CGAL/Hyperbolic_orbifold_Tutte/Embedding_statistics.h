// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_EMBEDDING_STATISTICS_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_EMBEDDING_STATISTICS_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Hyperbolic_orbifold_Tutte/Embedding_certificate.h>
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
*/
struct Embedding_statistics : public Solver_statistics
{
  int number_of_vertices = 0;         ///< vertices of the cut (seam) mesh
  int number_of_variables = 0;        ///< unknowns after eliminating seam twins
  /// `true` when the initialisation solved its Tutte system with the leading block of the
  /// solver's factorisation, so that one factorisation served both (with CHOLMOD, from 50K
  /// vertices of the cut mesh on, where the order this needs fills the factor no more than
  /// CHOLMOD's own; otherwise each factors a matrix of its own)
  bool shared_factorization = false;
  int repaired_vertices = 0;          ///< vertices moved by the one-ring repair (paper, section 5)
  /// `true` when the coordinates were written in a moved frame (recentring allowed, and the
  /// embedding in the canonical tile had triangles below what `double` resolves): the
  /// written point of a vertex is `frame(z)`, where `z` is its position in the tile of
  /// `make_orbifold_tile()`, and the embedding fills `tile.transformed(frame)`
  bool recentred = false;
  /// the isometry of the frame (the identity unless `recentred`): the translation that
  /// moves the most squeezed region of the embedding to the origin
  Hyperbolic_isometry_2<double> frame;
  /// faces written in charts centred at cone images (0 unless a part of the mesh converges
  /// onto a cone's image below what `double` resolves in the tile: a long protrusion ending
  /// at a landmark); see `Chart_point`
  std::size_t charted_faces = 0;
  /// the charts (\ref HOT_Charts): chart `i` maps the tile's coordinates to its own, moving
  /// the tile corner `chart_corners[i]` to the origin; empty when `charted_faces` is 0
  std::vector<Hyperbolic_isometry_2<double> > charts;
  /// the tile corner at the origin of each chart
  std::vector<int> chart_corners;
  bool landmark_order_reversed = false; ///< disk type: landmarks were given clockwise (fixed boundary: the corner vertices)
  /// `fixed_boundary_hyperbolic_Tutte_embedding()`: the corner vertices go around the mesh
  /// in the other direction than the polygon's corners around the polygon, so the map
  /// reverses orientation (every face is clockwise in the output)
  bool orientation_reversed = false;
  std::vector<std::size_t> landmark_order; ///< one-call function: indices of the landmarks in the order used
  /// the order of every cone of the tile (cone angle \f$2\pi/p\f$), in the order of the cut
  /// (the landmarks as `landmark_order` lists them): 2 for all unless `cone_orders` was given
  std::vector<int> cone_orders;
  /// the genus of the mesh: 0 for the sphere and disk types; \f$ g \ge 1 \f$ for a closed
  /// mesh cut open along a graph (\ref HOT_Genus)
  int genus = 0;
  /// \name Genus g >= 1: the polygon of the cut graph
  /// The tile is `make_cut_graph_tile()` of `Orbifold_signature(genus, cone_orders)` and of these
  /// (empty for genus 0): corner `i` of the tile is a copy of node `cut_corner_nodes[i]`, whose
  /// mesh vertex is `cut_node_vertices[n]` (its index in `vertices(tm)`) and whose cone (in the
  /// order of the cut) is `cut_node_cones[n]` or -1; side `i` is glued to side `cut_paired_sides[i]`.
  /// @{
  std::vector<int> cut_corner_nodes;  ///< the node of which each corner of the tile is a copy
  std::vector<int> cut_node_vertices; ///< the mesh vertex of each node (its index in `vertices(tm)`)
  std::vector<int> cut_node_cones;    ///< the cone of each node (in the order of the cut), or -1
  std::vector<int> cut_paired_sides;  ///< the side glued to each side of the tile
  /// the one-call function: the cut graph as vertex paths (vertex positions in `vertices(tm)`),
  /// the given one or the computed one (`compute_cut_graph()`)
  std::vector<std::vector<std::size_t> > cut_graph;
  /// @}
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
the tile in which an embedding of type `type` with statistics `st` was computed, in the
coordinates the embedding was computed in (a recentred embedding's written coordinates are
`st.frame` applied to them: see `Orbifold_tile::transformed()`): `make_cut_graph_tile()` of the cut
graph's polygon for genus \f$ g \ge 1 \f$, `make_orbifold_tile()` of the signature with
`st.cone_orders` otherwise.
*/
template <class Traits>
Error_code make_embedding_tile(Orbifold_type type, const Embedding_statistics& st, Orbifold_tile<Traits>& tile,
                               const Traits& traits = Traits())
{
  if(st.genus > 0)
    return make_cut_graph_tile(Orbifold_signature(st.genus, st.cone_orders), st.cut_corner_nodes, st.cut_node_cones,
                               st.cut_paired_sides, tile, traits);
  return make_orbifold_tile(Orbifold_signature(type, st.cone_orders), tile, traits);
}

} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_EMBEDDING_STATISTICS_H
