// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_PREPARE_MESH_FOR_EMBEDDING_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_PREPARE_MESH_FOR_EMBEDDING_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Hyperbolic_orbifold_Tutte/Mesh_preparation.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/check_input.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/error_code.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/parameters.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/core/dense_index.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/preparation/preparation_door.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/Named_function_parameters.h>

#include <exception>
#include <iterator>
#include <optional>
#include <string>
#include <vector>

/// \file prepare_mesh_for_embedding.h

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {

namespace internal {

template <class PointRange, class PolygonRange, class TriangleMesh, class NamedParameters>
Status run_preparation(const PointRange& points, const PolygonRange& polygons, TriangleMesh& out,
                       Mesh_preparation& prep, const NamedParameters& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  using CGAL::parameters::get_parameter_reference;
  namespace P = preparation;
  P::Preparation_options o;
  o.max_hole = choose_parameter(get_parameter(np, internal_np::maximum_hole_length), 0.5);
  o.keep_largest = choose_parameter(get_parameter(np, internal_np::keep_largest_component), false);
  o.split_chords = choose_parameter(get_parameter(np, internal_np::split_boundary_chords), true);
  if(!CGAL::parameters::is_default_parameter<NamedParameters, internal_np::orbifold_type_t>::value)
    o.required = choose_parameter(get_parameter(np, internal_np::orbifold_type), Sphere_type);
  o.max_hole_given = !CGAL::parameters::is_default_parameter<NamedParameters, internal_np::maximum_hole_length_t>::value;
  o.debris_fraction = choose_parameter(get_parameter(np, internal_np::maximum_debris_fraction), 0.01);
  o.target_genus = choose_parameter(get_parameter(np, internal_np::target_genus), -1);
  o.max_handle = choose_parameter(get_parameter(np, internal_np::maximum_handle_length), 0.2);
  if(!(o.max_handle >= 0) || !std::isfinite(o.max_handle))
    return Status::failure(ERROR_WRONG_PARAMETER, "maximum_handle_length must be a finite number >= 0");
  if(!(o.max_hole >= 0)) // (+infinity: no limit)
    return Status::failure(ERROR_WRONG_PARAMETER, "maximum_hole_length must be a number >= 0 or infinity");
  if(!(o.debris_fraction >= 0) || !(o.debris_fraction <= 1))
    return Status::failure(ERROR_WRONG_PARAMETER, "maximum_debris_fraction must be a number in [0, 1]");
  if constexpr(!CGAL::parameters::is_default_parameter<NamedParameters, internal_np::input_landmarks_t>::value) {
    const long long n = static_cast<long long>(std::distance(std::begin(points), std::end(points)));
    for(const auto j : get_parameter_reference(np, internal_np::input_landmarks)) {
      const long long i = static_cast<long long>(j);
      if(i < 0 || i >= n)
        return Status::failure(ERROR_LANDMARK_OUT_OF_RANGE, "landmark " + std::to_string(o.landmarks.size()) + " (vertex " +
                                                                std::to_string(i) + ") is not a vertex of the input");
      o.landmarks.push_back(static_cast<std::size_t>(i));
    }
  }

  P::Soup soup;
  Status r = P::load_points(points, soup, prep);
  if(r) r = P::load_polygons(polygons, soup, prep);
  std::vector<P::Point> prepared_points;
  std::vector<std::array<std::size_t, 3> > prepared_triangles;
  if(r) r = P::prepare_loaded_soup(soup, o, prep, prepared_points, prepared_triangles);
  if(!r) return r;
  P::write_prepared_mesh(prepared_points, prepared_triangles, out);
  return check_mesh(out, prep.type);
}

} // namespace internal

/*!
\ingroup PkgHyperbolicOrbifoldTutteHelperFunctions

prepares a polygon soup, as read from a file, so that it can be embedded into a hyperbolic
orbifold: on success `out` is a triangle mesh that passes `check_mesh()` for the orbifold type
`prep.type`, and `prep` counts every change and gives the addressing of `out`'s vertices by the
input's (see `Mesh_preparation`: landmark files keep referring to the input's vertex numbers).

In this order, each step doing nothing on a mesh that does not need it:
 -# a coordinate that is not finite is an error (`ERROR_NON_FINITE_COORDINATES`); repeated
    consecutive corners are dropped; polygons left with fewer than three corners or with a
    repeated corner are removed;
 -# points on the border of the soup (on an edge of only one polygon) at equal positions
    (exact comparison) are merged into the first one, which glues unwelded seams and
    triangle soups (STL); distinct inner vertices at one position are kept apart;
 -# if the polygons do not form an oriented manifold surface
    (`CGAL::Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh()`), duplicated polygons
    are removed (`merge_duplicate_polygons_in_polygon_soup()`, after the polygons with two
    corners at one position), and the soup is oriented
    (`orient_polygon_soup()`), which duplicates the vertices where the surface is not a
    manifold;
 -# points on no polygon (isolated vertices) are dropped;
 -# polygons with more than three corners are triangulated (`triangulate_faces()`);
 -# of a mesh with several connected components, one is kept: the one that holds the
    landmarks (`input_landmarks`), else the largest (in faces). The others are dropped when
    they hold no landmark and have fewer faces than `maximum_debris_fraction` of the mesh's
    (debris, e.g. a stray triangle of a scan), or all of them if `keep_largest_component`
    is `true`; otherwise the mesh fails (`ERROR_SEVERAL_COMPONENTS`, with their sizes).
    Landmarks on different components fail (`ERROR_SEVERAL_COMPONENTS`, naming them);
 -# degenerate faces (collinear or coincident corners) are removed (`remove_degenerate_faces()`);
 -# holes are filled (`triangulate_refine_and_fair_hole()`). Without landmarks: every boundary
    loop no longer than `maximum_hole_length` times the diagonal of the bounding box, except,
    when the disk type is required, the longest loop. With landmarks, the orbifold they ask
    for: a loop that holds every landmark is the disk's boundary (unless the sphere type is
    required) and every other loop is filled; landmarks not all on one loop ask for the sphere
    type, and every loop is filled whatever its length (a scan with an open sole or a missing
    scalp becomes a sphere), unless `maximum_hole_length` is given. The loops that remain
    decide the type: none, sphere type; one, disk type; more, an error
    (`ERROR_WRONG_TOPOLOGY`) that gives their sizes and lengths. The faces that fill holes are
    listed (`Mesh_preparation::filled_faces`): a point on them is not on the input's surface;
 -# with `target_genus`, a mesh of a higher genus has its handles cut (topological
    noise of scans: two fused fingers, an arm touching the body): the shortest non-separating
    loop found (a tree-cotree system of shortest loops from several roots) is cut and both
    sides are closed as holes, until the genus is the target; each cut is recorded
    (`Mesh_preparation::cut_handles`); a loop longer than `maximum_handle_length` diagonals is
    an error (`ERROR_WRONG_TOPOLOGY`) that says which handle. A disk's handles are cut
    without `target_genus` too (target 0: a disk-type orbifold has genus 0). A disk's boundary is capped
    while its loops are sought (the loops avoid its vertices; one that cannot is refused);
 -# disk type: every inner edge joining two boundary vertices (a chord, e.g. the inner edge of
    a boundary ear) is split at its midpoint and the midpoint joined to the two opposite
    corners (Euler operations), so no triangle gets flat on a side of the disk orbifold's tile;
 -# `check_mesh()` on the result, whose failure (e.g. a disk of genus 1 kept by `target_genus` 1, for which there is no
    orbifold) is returned with its own code; a closed mesh keeps its genus (\ref HOT_Genus).

The input's geometry is kept: no input vertex is moved. Faces are added only by the
triangulation of polygons, the filling of holes and the splitting of chords.

\tparam PointRange a range of points of a CGAL kernel, or of `std::array<double, 3>`
\tparam PolygonRange a range of ranges of vertex indices (integers)
\tparam TriangleMesh a model of `MutableFaceGraph` with an internal vertex point map
        (`Surface_mesh`, `Polyhedron_3`)
\param points the input vertices
\param polygons the input faces, as indices into `points`
\param out receives the prepared mesh (cleared first; left empty on failure); its `i`-th
       vertex is the one of output index `prep.output_index[i]`
\param prep receives the record of what was done (also on failure, as far as it got)
\param np optional named parameters (namespace `CGAL::Hyperbolic_orbifold_Tutte::parameters`):
  - `orbifold_type`: the type the result must have (default: the one the remaining loops give);
  - `input_landmarks` (`std::vector<std::size_t>`, default none): the landmarks, as input
    vertex indices (the ones a landmark file holds); a landmark out of range is an error
    (`ERROR_LANDMARK_OUT_OF_RANGE`); one on no face is left for the landmark check to report;
  - `maximum_hole_length` (`double`, default 0.5, or no limit with landmarks): the longest
    boundary loop filled, in bounding box diagonals (`std::numeric_limits<double>::infinity()`:
    no limit, every loop but a disk's boundary is filled);
  - `maximum_debris_fraction` (`double` in [0, 1], default 0.01): components without landmark
    and with fewer faces than this fraction of the mesh's are dropped;
  - `target_genus` (`int`, default: keep the genus of a closed mesh, 0 for a disk) and `maximum_handle_length` (`double`,
    default 0.2 bounding box diagonals): see above;
  - `keep_largest_component` (`bool`, default `false`): drops every component but the kept one
    (the landmarks', else the largest), whatever its size;
  - `split_boundary_chords` (`bool`, default `true`).
\return `OK`, or the reason why the mesh cannot be prepared
*/
template <class PointRange, class PolygonRange, class TriangleMesh,
          class NamedParameters = CGAL::parameters::Default_named_parameters>
Status prepare_polygon_soup_for_embedding(const PointRange& points, const PolygonRange& polygons, TriangleMesh& out,
                                          Mesh_preparation& prep,
                                          const NamedParameters& np = CGAL::parameters::default_values())
{
  prep = Mesh_preparation();
  CGAL::clear(out);
  Status r;
  try {
    r = internal::run_preparation(points, polygons, out, prep, np);
  } catch(const std::exception& e) { // CGAL's failure exceptions, bad_alloc
    std::string what = e.what(); // CGAL's messages have several lines
    for(char& c : what)
      if(c == '\n' || c == '\r') c = ' ';
    r = Status::failure(ERROR_NON_MANIFOLD, "CGAL could not repair the mesh: " + what);
  }
  if(!r)
    CGAL::clear(out);
  return r;
}

/*!
\ingroup PkgHyperbolicOrbifoldTutteHelperFunctions

same as `prepare_polygon_soup_for_embedding()` for a polygon mesh: input vertex `i` is the
`i`-th vertex of `vertices(in)`, input face `j` the `j`-th face of `faces(in)`.
\tparam PolygonMesh a model of `FaceListGraph` with an internal vertex point map
*/
template <class PolygonMesh, class TriangleMesh, class NamedParameters = CGAL::parameters::Default_named_parameters>
Status prepare_mesh_for_embedding(const PolygonMesh& in, TriangleMesh& out, Mesh_preparation& prep,
                                  const NamedParameters& np = CGAL::parameters::default_values())
{
  typedef typename boost::graph_traits<PolygonMesh>::vertex_descriptor vertex_descriptor;
  typedef typename boost::property_traits<typename boost::property_map<PolygonMesh, CGAL::vertex_point_t>::const_type>::value_type Point;
  const internal::Dense_index<vertex_descriptor> index(vertices(in));
  std::vector<Point> points;
  for(vertex_descriptor v : vertices(in))
    points.push_back(get(CGAL::vertex_point, in, v));
  std::vector<std::vector<std::size_t> > polygons;
  for(auto f : faces(in)) {
    polygons.emplace_back();
    for(vertex_descriptor v : vertices_around_face(halfedge(f, in), in))
      polygons.back().push_back(index(v));
  }
  return prepare_polygon_soup_for_embedding(points, polygons, out, prep, np);
}

} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_PREPARE_MESH_FOR_EMBEDDING_H
