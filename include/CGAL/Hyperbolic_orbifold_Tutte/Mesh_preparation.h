// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_MESH_PREPARATION_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_MESH_PREPARATION_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Hyperbolic_orbifold_Tutte/Orbifold_type.h>

#include <cstddef>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

/// \file Mesh_preparation.h
/// What `prepare_polygon_soup_for_embedding()` did to a mesh, and how the prepared mesh's
/// vertices are addressed by the input's.

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {

/*!
\ingroup PkgHyperbolicOrbifoldTutteMainClasses
a hole filled by `prepare_polygon_soup_for_embedding()`.
*/
struct Filled_hole
{
  std::size_t boundary_vertices = 0; ///< the number of vertices on its boundary loop
  double boundary_length = 0;        ///< the length of its boundary loop, in the mesh's units
  std::size_t faces_added = 0;       ///< the triangles that fill it
  std::size_t vertices_added = 0;    ///< the vertices added inside it
  std::size_t vertex = 0;            ///< a vertex of its boundary (an output index, see `Mesh_preparation`)
  bool faired = false;               ///< `true` if the filling was faired (smooth), `false` if only refined
};

/*!
\ingroup PkgHyperbolicOrbifoldTutteMainClasses
a handle cut by `prepare_polygon_soup_for_embedding()` (`target_genus`): the mesh was cut along
a short non-separating loop and both sides of the cut were closed (two `Filled_hole`s).
*/
struct Cut_handle
{
  double length = 0;                 ///< the length of the loop, in the mesh's units
  /// the loop's vertices, in order (output indices, see `Mesh_preparation`: the vertex on the
  /// right side of the cut; its copy on the left side is an added vertex)
  std::vector<std::size_t> vertices;
};

/*!
\ingroup PkgHyperbolicOrbifoldTutteMainClasses
the record of `prepare_polygon_soup_for_embedding()`: every change it made, counted, and the
addressing of the prepared mesh by the input.

<b>Addressing.</b> The vertices of the prepared mesh are the input vertices that lie on a
kept face, in input order, followed by the vertices the preparation added (copies of split
non-manifold vertices, vertices inside filled holes, midpoints of split chords), in the order
they were added. Files written for the prepared mesh use <em>output indices</em>: input vertex
`i` keeps index `i` (also the ones that lie on no kept face, which are written but used by no
face), and the `j`-th added vertex gets `number_of_input_vertices + j`. So landmark files
and vertex numbers keep referring to the input file.
*/
struct Mesh_preparation
{
  /// no vertex
  static constexpr std::size_t npos = std::size_t(-1);

  std::size_t number_of_input_vertices = 0; ///< the input's points
  std::size_t number_of_input_faces = 0;     ///< the input's polygons

  /// per input vertex, the prepared mesh's vertex (its position in `vertices()`) it became:
  /// itself, the vertex it was merged into (duplicates, collapsed degenerate faces: the
  /// nearest remaining vertex), or `npos` if it lies on no face or only on removed components
  /// (a split non-manifold vertex whose original lies on a removed component and a copy on
  /// the kept one is that copy)
  std::vector<std::size_t> prepared_vertex;
  /// per vertex of the prepared mesh, its output index (see above): increasing
  std::vector<std::size_t> output_index;

  std::size_t merged_duplicate_vertices = 0;  ///< border vertices merged into an earlier one at the same position
  std::size_t isolated_vertices = 0;          ///< input vertices on no face (dropped)
  std::size_t invalid_faces_removed = 0;      ///< polygons with fewer than 3 distinct vertices, a repeated one, or (in a soup that is not a manifold mesh) two corners at one position
  std::size_t duplicate_faces_removed = 0;    ///< polygons on the same vertices as another (either orientation)
  std::size_t reoriented_faces = 0;           ///< polygons reversed to orient the surface consistently
  std::size_t non_manifold_vertices_split = 0; ///< vertex copies added to make the surface manifold
  std::size_t polygons_triangulated = 0;      ///< polygons with more than 3 vertices
  std::size_t triangles_from_polygons = 0;    ///< the triangles they became
  std::size_t degenerate_faces_removed = 0;   ///< degenerate (zero-area) faces removed (by edge collapses or flips)
  std::size_t components_removed = 0;         ///< connected components dropped (all but the kept one: the landmarks', or the largest)
  std::size_t component_faces_removed = 0;    ///< their faces
  /// of `components_removed`, those dropped as debris: without a landmark and with fewer faces
  /// than `maximum_debris_fraction` of the mesh's (the others were dropped because
  /// `keep_largest_component` was asked for)
  std::size_t debris_components_removed = 0;
  std::vector<Filled_hole> filled_holes;      ///< the holes filled, in the order they were filled
  /// the faces of the prepared mesh that fill holes (their positions in `faces()` order),
  /// increasing: a point on them is not a point of the input's surface
  std::vector<std::size_t> filled_faces;
  /// the handles cut to reach `target_genus` (topological noise: fused fingers, an arm
  /// touching the body), in the order they were cut
  std::vector<Cut_handle> cut_handles;
  /// `true` if the landmarks (`input_landmarks`) decided which component is kept and which
  /// boundary loops are holes (see `prepare_polygon_soup_for_embedding()`)
  bool landmarks_decided = false;
  /// the inner edges of a disk-type mesh joining two boundary vertices, split at their
  /// midpoint (output indices of their endpoints)
  std::vector<std::pair<std::size_t, std::size_t> > split_chords;
  Orbifold_type type = Sphere_type;           ///< the prepared mesh's orbifold type

  /// the number of vertices the preparation added
  std::size_t number_of_added_vertices() const
  {
    std::size_t input_derived = 0;
    for(std::size_t o : output_index)
      if(o < number_of_input_vertices) ++input_derived;
    return output_index.size() - input_derived;
  }

  /// the number of faces added by hole filling
  std::size_t faces_added_by_hole_filling() const
  {
    std::size_t n = 0;
    for(const Filled_hole& h : filled_holes) n += h.faces_added;
    return n;
  }

  /// `true` if the prepared mesh differs from the input in any way
  bool changed() const
  {
    return merged_duplicate_vertices + isolated_vertices + invalid_faces_removed + duplicate_faces_removed +
           reoriented_faces + non_manifold_vertices_split + polygons_triangulated + degenerate_faces_removed +
           components_removed + filled_holes.size() + split_chords.size() + cut_handles.size() != 0;
  }

  /// one line listing every change, e.g. "filled 2 holes (118 faces added), split 3 boundary
  /// chords"; "no change" if there is none
  std::string summary() const
  {
    std::ostringstream os;
    const char* sep = "";
    auto item = [&](std::size_t n, const char* what) {
      if(n == 0) return;
      os << sep << what << " " << n;
      sep = ", ";
    };
    item(merged_duplicate_vertices, "merged duplicated vertices:");
    item(isolated_vertices, "dropped isolated vertices:");
    item(invalid_faces_removed, "removed invalid faces:");
    item(duplicate_faces_removed, "removed duplicated faces:");
    item(reoriented_faces, "reoriented faces:");
    item(non_manifold_vertices_split, "split non-manifold vertices (copies added):");
    if(polygons_triangulated != 0) {
      os << sep << "triangulated polygons: " << polygons_triangulated << " (into " << triangles_from_polygons << " triangles)";
      sep = ", ";
    }
    item(degenerate_faces_removed, "removed degenerate faces:");
    if(components_removed != 0) {
      os << sep << "dropped components: " << components_removed << " (" << component_faces_removed << " faces";
      if(debris_components_removed != 0)
        os << "; " << debris_components_removed << " of them small debris without landmark";
      os << ")";
      sep = ", ";
    }
    if(!filled_holes.empty()) {
      std::size_t v = 0;
      for(const Filled_hole& h : filled_holes) v += h.vertices_added;
      os << sep << "filled holes: " << filled_holes.size() << " (" << faces_added_by_hole_filling() << " faces and "
         << v << " vertices added)";
      sep = ", ";
    }
    item(split_chords.size(), "split boundary chords:");
    if(!cut_handles.empty()) {
      os << sep << "cut handles: " << cut_handles.size() << " (loops of";
      for(std::size_t i = 0; i < cut_handles.size() && i < 6; ++i)
        os << (i ? ", " : " ") << cut_handles[i].vertices.size();
      os << (cut_handles.size() > 6 ? ", ..." : "") << " vertices, both sides closed)";
      sep = ", ";
    }
    return changed() ? os.str() : std::string("no change");
  }
};

} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_MESH_PREPARATION_H
