// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_EMBEDDING_LAYOUT_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_EMBEDDING_LAYOUT_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Hyperbolic_orbifold_Tutte/Hyperbolic_isometry_2.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/Orbifold_type.h>

#include <cstddef>
#include <vector>

/// \file Embedding_layout.h
/// What is needed, besides the corner coordinates, to read an embedding: the orbifold, the
/// order of the landmarks, the frame, the charts and the cut (`Embedding_layout`). No times,
/// no counts: those are `Embedding_statistics`.

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {

/*!
\ingroup PkgHyperbolicOrbifoldTutteMainClasses
Everything needed, besides the corner coordinates, to read an embedding: the orbifold (type,
genus, cone orders, and for genus \f$ g \ge 1 \f$ the polygon of the cut graph), the order of
the landmarks, the frame of a recentred embedding, the charts around cone images and the
orientation. With the mesh and its corner coordinates it makes an `Orbifold_embedding`, which
the locator, the certificate, the maps and the writers take.

`Embedding_statistics` derives from it, so that code written against earlier versions, which
read these fields from the statistics, compiles unchanged; new code reads them from
`Orbifold_embedding::layout()`.
*/
struct Embedding_layout
{
  /// the orbifold's type (`Sphere_type` for a closed mesh of any genus)
  Orbifold_type type = Sphere_type;
  /// the genus of the mesh: 0 for the sphere and disk types; \f$ g \ge 1 \f$ for a closed
  /// mesh cut open along a graph (\ref HOT_Genus)
  int genus = 0;
  /// the order of every cone of the tile (cone angle \f$2\pi/p\f$), in the order of the cut
  /// (the landmarks as `landmark_order` lists them): 2 for all unless `cone_orders` was given
  std::vector<int> cone_orders;
  std::vector<std::size_t> landmark_order; ///< one-call function: indices of the landmarks in the order used
  bool landmark_order_reversed = false; ///< disk type: landmarks were given clockwise (fixed boundary: the corner vertices)
  /// `fixed_boundary_hyperbolic_Tutte_embedding()`: the corner vertices go around the mesh
  /// in the other direction than the polygon's corners around the polygon, so the map
  /// reverses orientation (every face is clockwise in the output)
  bool orientation_reversed = false;
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

  /// the signature of the orbifold: `Orbifold_signature(genus, cone_orders)` for genus
  /// \f$ g \ge 1 \f$, `Orbifold_signature(type, cone_orders)` otherwise
  Orbifold_signature signature() const
  {
    return genus > 0 ? Orbifold_signature(genus, cone_orders) : Orbifold_signature(type, cone_orders);
  }
};

} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_EMBEDDING_LAYOUT_H
