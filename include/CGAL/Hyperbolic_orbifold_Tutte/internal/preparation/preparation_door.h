// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_PREPARATION_PREPARATION_DOOR_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_PREPARATION_PREPARATION_DOOR_H

// The mesh preparation's door (compiled_once.h), declared: prepare_loaded_soup() takes a
// loaded soup (soup_loading.h) to the prepared triangles (PMP's orientation, repair and hole
// filling; defined in mesh_preparation_steps.h), with its options, and write_prepared_mesh()
// builds the user's mesh from them. prepare_mesh_for_embedding.h includes this header only:
// in header-only use it brings the definition in; in the project's own builds
// (CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_EXTERN_INSTANCES) the door is extern and the unit does not
// parse the steps (instances/preparation.cpp does).

#include <CGAL/Hyperbolic_orbifold_Tutte/Mesh_preparation.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/error_code.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/core/compiled_once.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/preparation/soup_loading.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>

#include <array>
#include <cstddef>
#include <optional>
#include <vector>

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {
namespace internal {
namespace preparation {

// the options of the steps (prepare_polygon_soup_for_embedding()'s named parameters)
struct Preparation_options
{
  bool keep_largest = false;
  double max_hole = 0.5;
  std::optional<Orbifold_type> required;
  bool split_chords = true;
  bool max_hole_given = false; // (with landmarks, the loops are closed whatever their length unless a maximum is given)
  std::vector<std::size_t> landmarks; // input vertex indices (input_landmarks); empty: none
  double debris_fraction = 0.01;
  long long target_genus = -1; // (-1: keep the genus)
  double max_handle = 0.2;     // the longest loop cut, in bounding box diagonals
};

// The steps after the soup is loaded, up to the prepared soup: points, and triangles as
// indices into them, input vertices first in input order (mesh_preparation_steps.h).
template <int = 0>
Status prepare_loaded_soup(Soup& soup, const Preparation_options& o, Mesh_preparation& prep, std::vector<Point>& points,
                           std::vector<std::array<std::size_t, 3> >& triangles);

#define CGAL_HOT_PREPARE_LOADED_SOUP_DOOR                                                                 \
  Status prepare_loaded_soup<0>(Soup&, const Preparation_options&, Mesh_preparation&, std::vector<Point>&, \
                                std::vector<std::array<std::size_t, 3> >&)
#ifdef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_EXTERN_INSTANCES
CGAL_HOT_INSTANCE(extern, CGAL_HOT_PREPARE_LOADED_SOUP_DOOR)
#endif

// Writes the prepared soup (prepare_loaded_soup()) into `out` as a mesh.
template <class TriangleMesh>
void write_prepared_mesh(const std::vector<Point>& points, const std::vector<std::array<std::size_t, 3> >& triangles,
                         TriangleMesh& out)
{
  CGAL::clear(out);
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, triangles, out);
}

} // namespace preparation
} // namespace internal
} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_EXTERN_INSTANCES
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/preparation/mesh_preparation_steps.h>
#endif

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_PREPARATION_PREPARATION_DOOR_H
