// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_HYPERBOLIC_ORBIFOLD_TUTTE_EMBEDDING_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_HYPERBOLIC_ORBIFOLD_TUTTE_EMBEDDING_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Hyperbolic_orbifold_Tutte/genus.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/landmark_checks.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/Hyperbolic_orbifold_Tutte_parameterizer_3.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/Orbifold_embedding.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/check_input.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/cut_graph.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/cut_through_landmarks.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/landmark_tour.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/input/input_stage.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/core/seam_mesh_storage.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/pipeline/statistics_parameter.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/parameters.h>

#include <CGAL/boost/graph/Seam_mesh.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/property_map.h>

#include <boost/property_map/property_map.hpp>

#include <chrono>
#include <functional>
#include <optional>
#include <vector>

/// \file hyperbolic_orbifold_Tutte_embedding.h

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {
namespace internal {

// the one-call function's named parameters for the solver, given to its parameterizer
template <class Parameterizer, class NamedParameters>
void set_solver_parameters(Parameterizer& parameterizer, const NamedParameters& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  parameterizer.set_gradient_tolerance(choose_parameter(get_parameter(np, internal_np::gradient_tolerance), 1e-10));
  parameterizer.set_maximum_number_of_iterations(choose_parameter(get_parameter(np, CGAL::internal_np::number_of_iterations), 200));
  parameterizer.set_verbose(choose_parameter(get_parameter(np, CGAL::internal_np::verbose), false));
  parameterizer.set_multigrid_threshold(choose_parameter(get_parameter(np, internal_np::multigrid_threshold),
                                                         static_cast<std::size_t>(internal::default_multigrid_from)));
  parameterizer.set_recentring(choose_parameter(get_parameter(np, internal_np::recentring), false));
}

// hyperbolic_orbifold_Tutte_embedding(): the cones' given `orders` in the order of the cut
// (`landmark_order`); a failure when there is not one per landmark (here their number; the
// orders themselves: the parameterizer's tile)
inline Status cone_orders_in_cut_order(const std::vector<int>& orders, std::size_t number_of_landmarks,
                                       const std::vector<std::size_t>& landmark_order, std::vector<int>& ordered_orders)
{
  Cone_order_check check;
  if(check_cone_orders(orders, number_of_landmarks, &check) != OK && check.problem == Wrong_number_of_cone_orders)
    return Status::failure(ERROR_WRONG_PARAMETER, check.message);
  for(std::size_t i : landmark_order)
    ordered_orders.push_back(orders[i]);
  return Status();
}

// hyperbolic_orbifold_Tutte_embedding(), genus g >= 1: the cut graph's paths, in vertex indices,
// into Embedding_statistics::cut_graph
template <class TriangleMesh>
void record_cut_graph(const TriangleMesh& tm,
                      const std::vector<std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor> >& cut_paths,
                      Embedding_statistics& st)
{
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  const internal::Dense_index<vertex_descriptor> vindex(vertices(tm));
  for(const auto& path : cut_paths) {
    st.cut_graph.emplace_back();
    for(vertex_descriptor v : path)
      st.cut_graph.back().push_back(vindex(v));
  }
}

// Runs `solve(weights)` (an embedding with those weights, its statistics in `st`). Tutte's
// theorem holds for any positive weights: with `fallback` (the default weights), an embedding
// that fails the certificate is computed again with the mean value weights (positive, bounded
// away from 0 on any triangle, unlike the clamped cotangent weights) and kept if certified,
// `st` saying so; if that one fails too, the first failure is returned with both reasons.
template <class Solve>
Error_code solve_with_mean_value_fallback(const Solve& solve, Weight_type weights, bool fallback, Embedding_statistics& st)
{
  const Embedding_statistics before_solve = st;
  Error_code ec = solve(weights);
  if(!fallback || ec != ERROR_NO_1_TO_1_MAPPING)
    return ec;
  const Embedding_statistics failed = st;
  st = before_solve;
  if(solve(Mean_value) == OK) {
    st.mean_value_fallback = true;
    st.fallback_reason = failed.message;
    return OK;
  }
  const std::string mean_value_failure = st.message;
  st = failed;
  st.message += " (with the mean value weights too: " + mean_value_failure + ")";
  return ERROR_NO_1_TO_1_MAPPING;
}

} // namespace internal

/*!
\ingroup PkgHyperbolicOrbifoldTutteHelperFunctions

computes, in one call, the hyperbolic orbifold Tutte embedding of a triangle mesh with
landmarks: checks the input, orders the landmarks, cuts a closed mesh open through
them (genus 0: shortest paths that are pairwise disjoint except at shared landmarks; genus
\f$ g \ge 1 \f$: a cut graph of \f$2g\f$ handle loops and paths to the landmarks, \ref HOT_Genus),
builds the `Seam_mesh`, embeds with `Hyperbolic_orbifold_Tutte_parameterizer_3` and certifies
the result.

The output is a halfedge map of `tm`: for every halfedge `h` of a face, the Poincar&eacute;
coordinates of the corner `target(h)` in `face(h)`. A vertex on the cut has a different
point in the faces on each side of the cut; the two are related by a side pairing of the
orbifold tile (`Orbifold_tile::side_pairing()`).

\tparam TriangleMesh a model of `FaceGraph` (e.g. `Surface_mesh`, `Polyhedron_3`)
\tparam HalfedgeUVMap a model of `WritablePropertyMap` with
        `boost::graph_traits<TriangleMesh>::%halfedge_descriptor` as key and `Point_2` of the
        traits as value type
\tparam NamedParameters a sequence of named parameters
\param tm a closed triangle mesh (sphere type, any genus) or a triangulated disk (disk type)
\param landmarks distinct vertices: on a closed genus-0 mesh at least 5 (3 with cone orders above
       2); of genus 1 at least 1; of genus 2 or more any number, also none; for the disk type at
       least 5, on the boundary, in boundary order (either orientation)
\param uvmap receives the coordinates; unchanged unless `OK` is returned
\param np an optional sequence of named parameters among the ones listed below

\cgalNamedParamsBegin
  \cgalParamNBegin{vertex_point_map} \cgalParamDescription{the 3D points}
    \cgalParamDefault{`get(CGAL::vertex_point, tm)`} \cgalParamNEnd
  \cgalParamNBegin{orbifold_type} \cgalParamDescription{`Sphere_type` or `Disk_type`}
    \cgalParamDefault{`Sphere_type` for a closed mesh, `Disk_type` for a mesh with one boundary loop} \cgalParamNEnd
  \cgalParamNBegin{weight_type} \cgalParamDescription{`Cotangent`, `Mean_value` or `Uniform`}
    \cgalParamDefault{`Cotangent`; when neither this nor `edge_weight_map` is given and the cotangent
    weights' embedding fails the certificate, the mean value weights' one if it passes
    (`Embedding_statistics::mean_value_fallback`, `fallback_reason`)} \cgalParamNEnd
  \cgalParamNBegin{mean_value_fallback} \cgalParamDescription{a `bool`: whether an embedding that fails
    the certificate is computed again with the mean value weights, kept if it passes (for a
    `weight_type` given explicitly, e.g. a program passing on its user's choice, which may be
    the default's); never with `edge_weight_map`}
    \cgalParamDefault{`true` when neither `weight_type` nor `edge_weight_map` is given, else `false`} \cgalParamNEnd
  \cgalParamNBegin{edge_weight_map} \cgalParamDescription{a readable property map from `edge_descriptor`
    to positive `double` weights, used instead of `weight_type`} \cgalParamDefault{unused} \cgalParamNEnd
  \cgalParamNBegin{weight_epsilon} \cgalParamDescription{lower clamp of cotangent weights}
    \cgalParamDefault{`1e-6`} \cgalParamNEnd
  \cgalParamNBegin{landmark_order} \cgalParamDescription{`Given_order` or `Tsp_order` (sphere type)}
    \cgalParamDefault{`Given_order`} \cgalParamNEnd
  \cgalParamNBegin{cone_orders} \cgalParamDescription{`std::vector<int>`: the order \f$p\f$ of every
    landmark's cone (angle \f$2\pi/p\f$), in the order of `landmarks`; sphere type; the orbifold must be
    hyperbolic, \f$\sum (1 - 1/p) > 2\f$ (`ERROR_NOT_HYPERBOLIC` otherwise). `Embedding_statistics::cone_orders`
    receives them in the order of the cut}
    \cgalParamDefault{2 for every cone (angle \f$\pi\f$)} \cgalParamNEnd
  \cgalParamNBegin{cut_graph} \cgalParamDescription{`std::vector<std::vector<vertex_descriptor> >`: a closed
    mesh of genus \f$ g \ge 1 \f$ is cut along this graph, given as vertex paths (`check_cut_graph()`); its
    first edge sets the tile's corner 0, so two meshes cut along corresponding graphs are embedded in one
    tile and can be mapped. `Embedding_statistics::cut_graph` receives the graph used}
    \cgalParamDefault{`compute_cut_graph()`} \cgalParamNEnd
  \cgalParamNBegin{gradient_tolerance} \cgalParamDescription{relative gradient norm to reach}
    \cgalParamDefault{`1e-10`} \cgalParamNEnd
  \cgalParamNBegin{number_of_iterations} \cgalParamDescription{maximum number of Newton iterations}
    \cgalParamDefault{`200`} \cgalParamNEnd
  \cgalParamNBegin{recentring} \cgalParamDescription{allows the result to be written in a moved frame
    when a region of the embedding is too squeezed for `double` in the tile (a long protrusion
    without landmarks): then `Embedding_statistics::recentred` is `true` and the corner
    coordinates are `Embedding_statistics::frame` applied to the positions in the tile; see
    `Hyperbolic_orbifold_Tutte_parameterizer_3::set_recentring()`}
    \cgalParamDefault{`false`} \cgalParamNEnd
  \cgalParamNBegin{chart_map} \cgalParamDescription{a read-write property map from halfedges to
    `Chart_point<Point_2>`: allows a part of the embedding that converges onto cone images (a long
    protrusion ending at a landmark), too small for `double` in the tile, to be written in charts
    centred at them, and receives each corner's chart point (\ref HOT_Charts);
    `Embedding_statistics::charts` receives the charts}
    \cgalParamDefault{none: such an embedding is refused (`ERROR_NO_1_TO_1_MAPPING`)} \cgalParamNEnd
  \cgalParamNBegin{multigrid_threshold} \cgalParamDescription{`std::size_t`: from this many vertices of the
    cut mesh on, the linear systems are solved by conjugate gradients preconditioned by algebraic multigrid
    instead of sparse factorisations (`Hyperbolic_orbifold_Tutte_parameterizer_3::set_multigrid_threshold()`)}
    \cgalParamDefault{`400000`} \cgalParamNEnd
  \cgalParamNBegin{verbose} \cgalParamDescription{prints the solver's progress on `std::cerr`}
    \cgalParamDefault{`false`} \cgalParamNEnd
  \cgalParamNBegin{embedding_statistics} \cgalParamDescription{an `Embedding_statistics*` filled on return}
    \cgalParamDefault{none} \cgalParamNEnd
  \cgalParamNBegin{progress} \cgalParamDescription{a callable `void(const char* phase, double fraction)`
    (stored as a `std::function`), called from the calling thread with the progress of the phases
    `"input"` (the checks and the landmark order), `"cut"` (the cut through the landmarks and the seam mesh),
    `"initialization"`, `"optimization"` and `"certificate"` (`Hyperbolic_orbifold_Tutte_parameterizer_3::set_progress()`),
    in this order: each phase is told 0 when it starts and 1 when it ends, `"optimization"` also after every
    accepted Newton step (the gradient norm's progress towards the tolerance on a log scale); the fractions
    of a phase never decrease. A failure ends the reports (its phase is not told 1). Same result, to the
    bit, with or without it}
    \cgalParamDefault{none} \cgalParamNEnd
\cgalNamedParamsEnd

\return `OK`, or the specific reason of the failure (see `Error_code`); details in
        `Embedding_statistics::message`.
*/
template <class TriangleMesh, class HalfedgeUVMap, class NamedParameters = CGAL::parameters::Default_named_parameters>
Error_code hyperbolic_orbifold_Tutte_embedding(
  const TriangleMesh& tm,
  const std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>& landmarks,
  HalfedgeUVMap uvmap,
  const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  using CGAL::parameters::is_default_parameter;
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename GT::vertex_descriptor vertex_descriptor;
  typedef typename GT::edge_descriptor edge_descriptor;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  typedef typename GT::face_descriptor face_descriptor;
  typedef typename GetVertexPointMap<TriangleMesh, NamedParameters>::const_type VPM;

  Embedding_statistics local;
  Embedding_statistics& st = internal::statistics_parameter(np, local);
  auto fail = [&](Error_code ec, const std::string& msg) { return internal::record_failure(st, ec, msg); };
  typedef std::chrono::steady_clock Clock;
  const auto t0 = Clock::now();

  const VPM vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point), get_const_property_map(vertex_point, tm));
  std::function<void(const char*, double)> progress; // (empty: no report)
  if constexpr(!is_default_parameter<NamedParameters, internal_np::progress_t>::value)
    progress = get_parameter(np, internal_np::progress);
  auto tell = [&progress](const char* phase, double fraction) {
    if(progress)
      progress(phase, fraction);
  };
  tell("input", 0.0);

  // 1. prepare: the orbifold type and the mesh's checks; the landmarks and their order
  const std::vector<int> orders = choose_parameter(get_parameter(np, internal_np::cone_orders), std::vector<int>());
  Orbifold_type type = Sphere_type;
  Status r = internal::prepare_mesh(tm, vpm, np, type);
  const long long genus = (r && type == Sphere_type) ? closed_mesh_genus(tm) : 0;
  if(r)
    r = check_landmark_vertices(tm, landmarks, type, minimum_number_of_landmarks_for(type, genus, !orders.empty()));
  std::vector<vertex_descriptor> ordered;
  if(r) // (genus g >= 1: the cut graph joins the landmarks to the handle loops in any order)
    r = internal::order_landmarks(tm, vpm, landmarks, type,
                                  genus > 0 ? Given_order
                                            : choose_parameter(get_parameter(np, internal_np::landmark_order), Given_order),
                                  ordered, st.landmark_order);
  std::vector<int> ordered_orders; // (in the order of the cut)
  if(r && !orders.empty())
    r = internal::cone_orders_in_cut_order(orders, landmarks.size(), st.landmark_order, ordered_orders);
  if(r) {
    tell("input", 1.0);
    tell("cut", 0.0);
  }
  // 2. cut: the seam mesh (genus g >= 1: along the given cut graph, or one computed here)
  std::vector<std::vector<vertex_descriptor> > cut_paths =
    choose_parameter(get_parameter(np, internal_np::cut_graph), std::vector<std::vector<vertex_descriptor> >());
  internal::Seam_mesh_storage<TriangleMesh> seams(tm);
  typedef typename internal::Seam_mesh_storage<TriangleMesh>::Mesh Mesh;
  Mesh& mesh = seams.mesh;
  typename boost::graph_traits<Mesh>::halfedge_descriptor bhd;
  if(r)
    r = internal::cut_open(tm, vpm, ordered, type, seams, bhd, genus, &cut_paths);
  if(!r)
    return fail(r.code, r.message);
  const double time_cut = std::chrono::duration<double>(Clock::now() - t0).count();
  tell("cut", 1.0);

  // 3. solve, certify and mend (the parameterizer runs the pipeline's solve stage)
  typedef Hyperbolic_orbifold_Tutte_parameterizer_3<Mesh> Parameterizer;
  typedef typename Parameterizer::Point_2 Point_2;
  internal::Seam_vertex_points<Mesh, Point_2> canonical(tm);
  constexpr bool with_charts = !is_default_parameter<NamedParameters, internal_np::chart_map_t>::value;
  std::optional<internal::Seam_vertex_points<Mesh, Chart_point<Point_2> > > chart_points;
  if constexpr(with_charts)
    chart_points.emplace(tm);
  const std::vector<std::size_t> order_used = st.landmark_order;
  const auto solve = [&](Weight_type weights) {
    Parameterizer parameterizer(type, weights, choose_parameter(get_parameter(np, internal_np::weight_epsilon), 1e-6));
    internal::set_solver_parameters(parameterizer, np);
    parameterizer.set_cone_orders(ordered_orders);
    parameterizer.set_progress(progress);
    if(genus > 0) // the tile's corner 0: where the border runs along the cut graph's first edge
      parameterizer.set_cut_graph_start(cut_paths[0][0], cut_paths[0][1]);
    if constexpr(!is_default_parameter<NamedParameters, internal_np::edge_weight_map_t>::value) {
      const auto wmap = get_parameter(np, internal_np::edge_weight_map);
      parameterizer.set_edge_weights([wmap](const edge_descriptor& e) { return static_cast<double>(get(wmap, e)); });
    }
    if constexpr(with_charts)
      return parameterizer.parameterize(mesh, bhd, ordered, canonical.map(), chart_points->map(), &st);
    else
      return parameterizer.parameterize(mesh, bhd, ordered, canonical.map(), &st);
  };
  constexpr bool default_weights = is_default_parameter<NamedParameters, internal_np::weight_type_t>::value &&
                                   is_default_parameter<NamedParameters, internal_np::edge_weight_map_t>::value;
  // (never with weights of one's own: the fallback replaces a weight type)
  const bool fallback = is_default_parameter<NamedParameters, internal_np::edge_weight_map_t>::value &&
                        choose_parameter(get_parameter(np, internal_np::mean_value_fallback), default_weights);
  Error_code ec = internal::solve_with_mean_value_fallback(solve, choose_parameter(get_parameter(np, internal_np::weight_type), Cotangent),
                                                           fallback, st);
  st.landmark_order = order_used;
  st.time_setup += time_cut;
  if(genus > 0)
    internal::record_cut_graph(tm, cut_paths, st);
  if(ec != OK)
    return ec;

  // 4. corner coordinates
  for(face_descriptor f : faces(tm))
    for(halfedge_descriptor h : halfedges_around_face(halfedge(f, tm), tm)) {
      const typename boost::graph_traits<Mesh>::halfedge_descriptor sh(h, false);
      const auto vd = target(sh, mesh);
      put(uvmap, h, canonical.at(vd));
      if constexpr(with_charts)
        put(get_parameter(np, internal_np::chart_map), h, chart_points->at(vd));
    }
  return OK;
}

/*!
\ingroup PkgHyperbolicOrbifoldTutteHelperFunctions

`hyperbolic_orbifold_Tutte_embedding()` into a result object: the coordinates go to
`embedding.uv_map()` (and `embedding.chart_map()`, which allows charts, if it has one), and
`embedding.layout()` receives what is needed to read them (the orbifold, the landmark order,
the frame, the charts, the cut graph), `embedding.landmarks()` the landmarks. The statistics
(times, counts, the message) still go to the named parameter `embedding_statistics` if given.

\param tm the mesh: `embedding.mesh()` must be `tm` (`ERROR_WRONG_PARAMETER` otherwise)
\param landmarks as for the other overload
\param embedding built from `tm` and its maps; on success `is_valid()`, unchanged on failure
\param np the named parameters of the other overload (`chart_map` is the embedding's)
*/
template <class TriangleMesh, class HalfedgeUVMap, class HalfedgeChartMap,
          class NamedParameters = CGAL::parameters::Default_named_parameters>
Error_code hyperbolic_orbifold_Tutte_embedding(
  const TriangleMesh& tm,
  const std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>& landmarks,
  Orbifold_embedding<TriangleMesh, HalfedgeUVMap, HalfedgeChartMap>& embedding,
  const NamedParameters& np = CGAL::parameters::default_values())
{
  Embedding_statistics local;
  Embedding_statistics& st = internal::statistics_parameter(np, local);
  if(!embedding.has_mesh())
    return internal::record_failure(st, ERROR_WRONG_PARAMETER, "the embedding object has no mesh (build it from the mesh and its maps)");
  if(&embedding.mesh() != &tm)
    return internal::record_failure(st, ERROR_WRONG_PARAMETER, "the embedding object's maps belong to another mesh");
  Error_code ec;
  if constexpr(Orbifold_embedding<TriangleMesh, HalfedgeUVMap, HalfedgeChartMap>::has_chart_map)
    ec = hyperbolic_orbifold_Tutte_embedding(
      tm, landmarks, embedding.uv_map(),
      parameters::embedding_statistics(&st, parameters::chart_map(embedding.chart_map(), np)));
  else
    ec = hyperbolic_orbifold_Tutte_embedding(tm, landmarks, embedding.uv_map(), parameters::embedding_statistics(&st, np));
  if(ec != OK)
    return ec;
  embedding.layout() = st; // (the layout part of the statistics)
  embedding.set_landmarks(landmarks);
  embedding.set_valid();
  return OK;
}

} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_HYPERBOLIC_ORBIFOLD_TUTTE_EMBEDDING_H
