// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_PARAMETERS_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_PARAMETERS_H

#include <CGAL/Named_function_parameters.h>

/// \file parameters.h
/// The package's own named parameters. CGAL's list of chainable parameters is closed, so
/// ours combine by nesting: each takes an optional second argument, the parameters to
/// append to: `HOT::parameters::landmark_order(HOT::Tsp_order, HOT::parameters::weight_type(HOT::Mean_value))`.
/// CGAL's own parameters chain after ours as members:
/// `HOT::parameters::weight_type(HOT::Uniform).verbose(true).number_of_iterations(50)`.

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {

/*!
\ingroup PkgHyperbolicOrbifoldTutteEnums
How the landmarks are ordered before cutting a sphere-type mesh p1 -> p2 -> ... -> pk.
*/
enum Landmark_order
{
  Given_order, ///< as given
  Tsp_order    ///< the paper's section 7: shortest closed tour over geodesic distances, cut at its longest edge
};

namespace internal_np {
enum orbifold_type_t { orbifold_type };
enum weight_type_t { weight_type };
enum weight_epsilon_t { weight_epsilon };
enum mean_value_fallback_t { mean_value_fallback };
enum landmark_order_t { landmark_order };
enum gradient_tolerance_t { gradient_tolerance };
enum embedding_statistics_t { embedding_statistics };
enum edge_weight_map_t { edge_weight_map };
enum recentring_t { recentring };
enum frame_t { frame };
enum chart_map_t { chart_map };
enum charts_t { charts };
enum cone_orders_t { cone_orders };
enum cut_graph_t { cut_graph };
enum maximum_hole_length_t { maximum_hole_length };
enum keep_largest_component_t { keep_largest_component };
enum split_boundary_chords_t { split_boundary_chords };
enum input_landmarks_t { input_landmarks };
enum maximum_debris_fraction_t { maximum_debris_fraction };
enum target_genus_t { target_genus };
enum maximum_handle_length_t { maximum_handle_length };
enum multigrid_threshold_t { multigrid_threshold };
enum refine_t { refine };
enum progress_t { progress };
enum extremity_radius_t { extremity_radius };
enum tip_threshold_t { tip_threshold };
enum descriptor_tolerance_t { descriptor_tolerance };
enum match_along_map_t { match_along_map };
} // namespace internal_np

namespace parameters {

#define CGAL_HOT_NAMED_PARAMETER(NAME)                                                                   \
  template <class T>                                                                                     \
  Named_function_parameters<T, internal_np::NAME##_t> NAME(const T& t)                                   \
  {                                                                                                      \
    return Named_function_parameters<T, internal_np::NAME##_t>(t);                                       \
  }                                                                                                      \
  template <class T, class T2, class Tag2, class Base2>                                                  \
  Named_function_parameters<T, internal_np::NAME##_t, Named_function_parameters<T2, Tag2, Base2> >       \
  NAME(const T& t, const Named_function_parameters<T2, Tag2, Base2>& np)                                 \
  {                                                                                                      \
    return Named_function_parameters<T, internal_np::NAME##_t, Named_function_parameters<T2, Tag2, Base2> >(t, np); \
  }

/// `Orbifold_type`: `Sphere_type` or `Disk_type` (default: from the mesh's topology)
CGAL_HOT_NAMED_PARAMETER(orbifold_type)
/// `Weight_type` (default `Cotangent`)
CGAL_HOT_NAMED_PARAMETER(weight_type)
/// `double`: lower clamp of cotangent weights (default \f$10^{-6}\f$)
CGAL_HOT_NAMED_PARAMETER(weight_epsilon)
/// `bool`: whether an embedding that fails the certificate is computed again with the mean
/// value weights (default: `true` when neither `weight_type` nor `edge_weight_map` is given,
/// else `false`; see `hyperbolic_orbifold_Tutte_embedding()`)
CGAL_HOT_NAMED_PARAMETER(mean_value_fallback)
/// `Landmark_order` (default `Given_order`)
CGAL_HOT_NAMED_PARAMETER(landmark_order)
/// `double`: force imbalance (relative hyperbolic gradient norm) at which the solver stops (default \f$10^{-10}\f$)
CGAL_HOT_NAMED_PARAMETER(gradient_tolerance)
/// `Embedding_statistics*`: receives statistics, timings and the certificate
CGAL_HOT_NAMED_PARAMETER(embedding_statistics)
/// `std::size_t`: the size (vertices of the cut mesh) from which the solver's linear systems
/// are solved by conjugate gradients preconditioned by algebraic multigrid instead of sparse
/// factorisations (default 400000; see
/// `Hyperbolic_orbifold_Tutte_parameterizer_3::set_multigrid_threshold()`)
CGAL_HOT_NAMED_PARAMETER(multigrid_threshold)

/// a readable property map from the mesh's edges to positive `double` weights, used
/// instead of `weight_type`
CGAL_HOT_NAMED_PARAMETER(edge_weight_map)

/// `bool`: allows the result to be written in a frame that moves a region too squeezed for
/// `double` to the origin (default `false`; see
/// `Hyperbolic_orbifold_Tutte_parameterizer_3::set_recentring()`)
CGAL_HOT_NAMED_PARAMETER(recentring)

/// `Hyperbolic_isometry_2<double>`: for `certify_hyperbolic_orbifold_embedding()`, the frame
/// of a recentred embedding (`Embedding_statistics::frame`; default the identity)
CGAL_HOT_NAMED_PARAMETER(frame)

/// a read-write property map from halfedges to `Chart_point`: allows a part of the
/// embedding that converges onto cone images to be written in charts around them, and
/// receives every corner's chart point (\ref HOT_Charts); for
/// `certify_hyperbolic_orbifold_embedding()`, `Embedding_locator` and the surface maps,
/// the chart points of an embedding written so (default: none; such a part is refused)
CGAL_HOT_NAMED_PARAMETER(chart_map)
/// `std::vector<Hyperbolic_isometry_2<double> >`: the charts of an embedding
/// (`Embedding_statistics::charts`), with `chart_map` (default: none)
CGAL_HOT_NAMED_PARAMETER(charts)
/// `std::vector<int>`: the order \f$p\f$ of every landmark's cone (cone angle \f$2\pi/p\f$), in
/// the order of the landmarks as given; sphere type only (default: 2 for every cone, angle
/// \f$\pi\f$). The orbifold must be hyperbolic, \f$\sum_i (1 - 1/p_i) > 2\f$: three cones such
/// as (2,3,7), (3,3,4) or (2,4,5), four such as (2,2,2,3), five or more of any orders
CGAL_HOT_NAMED_PARAMETER(cone_orders)
/// `std::vector<std::vector<vertex_descriptor> >`: a closed mesh of genus \f$ g \ge 1 \f$ is cut
/// along this graph, given as vertex paths (consecutive vertices joined by an edge; see
/// `check_cut_graph()`), which must cut it into a disk and hold every landmark; the tile's corner
/// 0 is set by the first path's first edge, so two meshes cut along corresponding graphs are
/// embedded in the same tile and can be mapped (default: `compute_cut_graph()`, \ref HOT_Genus)
CGAL_HOT_NAMED_PARAMETER(cut_graph)

/// `double`: for `prepare_polygon_soup_for_embedding()`, the longest boundary loop that is
/// filled as a hole, as a fraction of the diagonal of the mesh's bounding box (default 0.5)
CGAL_HOT_NAMED_PARAMETER(maximum_hole_length)
/// `bool`: for `prepare_polygon_soup_for_embedding()`, keeps the largest connected component
/// (in faces) of a mesh with several, instead of failing (default `false`)
CGAL_HOT_NAMED_PARAMETER(keep_largest_component)
/// `bool`: for `prepare_polygon_soup_for_embedding()`, splits every inner edge of a disk-type
/// mesh that joins two boundary vertices (default `true`)
CGAL_HOT_NAMED_PARAMETER(split_boundary_chords)
/// `std::vector<std::size_t>`: for `prepare_polygon_soup_for_embedding()`, the landmarks as
/// input vertex indices; the preparation then aims at the orbifold they ask for: it keeps the
/// component that holds them and, unless they all lie on one boundary loop (a disk), closes
/// every boundary loop whatever its length (default: none)
CGAL_HOT_NAMED_PARAMETER(input_landmarks)
/// `double`: for `prepare_polygon_soup_for_embedding()`, a connected component without
/// landmark and with fewer faces than this fraction of the mesh's is debris, dropped
/// (default 0.01)
CGAL_HOT_NAMED_PARAMETER(maximum_debris_fraction)
/// `int`: for `prepare_polygon_soup_for_embedding()`, the genus the prepared closed mesh must
/// have at most: handles are cut along short non-separating loops, both sides closed, until it
/// has it (default: the genus is kept)
CGAL_HOT_NAMED_PARAMETER(target_genus)
/// `double`: for `prepare_polygon_soup_for_embedding()` with `target_genus`, the longest loop
/// cut, as a fraction of the diagonal of the bounding box; a handle whose shortest loop found
/// is longer is an error (default 0.2)
CGAL_HOT_NAMED_PARAMETER(maximum_handle_length)
/// `int`: for `refine_orbifold_map()`, the largest number of refinement iterations (default 100)
CGAL_HOT_NAMED_PARAMETER(refine)
/// a callable `void(const char* phase, double fraction)` (stored as a `std::function`): for
/// `hyperbolic_orbifold_Tutte_embedding()`, told the progress of the phases "input", "cut",
/// "initialization", "optimization" and "certificate", in this order, from the calling thread
/// (see `Hyperbolic_orbifold_Tutte_parameterizer_3::set_progress()`); for `refine_orbifold_map()`,
/// the phase "refinement", after every iteration (default: none)
CGAL_HOT_NAMED_PARAMETER(progress)
/// `double`: for `match_extremities()`, the radius of an extremity's geodesic ball as a fraction
/// of the largest geodesic distance to the landmarks (default 0.25)
CGAL_HOT_NAMED_PARAMETER(extremity_radius)
/// `double`: for `match_extremities()`, the largest area of an extremity's geodesic ball of
/// radius r, over pi r^2 (default 0.65: sharper than a cone of half-angle 40 degrees)
CGAL_HOT_NAMED_PARAMETER(tip_threshold)
/// `double`: for `match_extremities()`, the largest relative difference of the descriptors of
/// a matched pair (default 0.1)
CGAL_HOT_NAMED_PARAMETER(descriptor_tolerance)
/// `bool`: for `match_extremities()`, whether the tips that the descriptors leave unmatched are
/// matched along the orbifold map computed with the landmarks and the pairs found (default `true`)
CGAL_HOT_NAMED_PARAMETER(match_along_map)

#undef CGAL_HOT_NAMED_PARAMETER

} // namespace parameters
} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_PARAMETERS_H
