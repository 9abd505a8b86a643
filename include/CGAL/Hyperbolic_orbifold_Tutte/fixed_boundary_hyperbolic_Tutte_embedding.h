// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_FIXED_BOUNDARY_HYPERBOLIC_TUTTE_EMBEDDING_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_FIXED_BOUNDARY_HYPERBOLIC_TUTTE_EMBEDDING_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Hyperbolic_orbifold_Tutte/Embedding_statistics.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/check_input.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/error_code.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/parameters.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/weight_type.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/pipeline/certificate.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/pipeline/certify_and_repair.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/solver/convex_polygon_domain.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/solver/edge_weights.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/solver/flat_problem.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/solver/solver_doors.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/core/seam_mesh_storage.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/pipeline/statistics_parameter.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/solver/tutte_initialization.h>

#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/property_map.h>

#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <complex>
#include <sstream>
#include <string>
#include <vector>

/// \file fixed_boundary_hyperbolic_Tutte_embedding.h

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {
namespace internal {

// fixed_boundary_hyperbolic_Tutte_embedding()'s input: a disk, its corner vertices, a
// convex polygon, in the same order; whether the polygon and the corners go counterclockwise
template <class TriangleMesh, class VertexPointMap>
Status check_fixed_boundary_input(const TriangleMesh& tm, VertexPointMap vpm,
                                  const std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>& corner_vertices,
                                  const std::vector<std::complex<double> >& corners, bool& ccw_polygon, bool& ccw_corners)
{
  const std::size_t n = corner_vertices.size();
  Status r = Hyperbolic_orbifold_Tutte::check_mesh(tm, vpm, Disk_type);
  if(r && n < 3)
    r = Status::failure(ERROR_TOO_FEW_LANDMARKS, std::to_string(n) + " corner vertices are given; a polygon needs at least 3");
  if(r && corners.size() != n)
    r = Status::failure(ERROR_WRONG_PARAMETER, std::to_string(n) + " corner vertices are given for a polygon of " +
                                                 std::to_string(corners.size()) + " corners (one per corner is needed)");
  if(r) {
    r = Hyperbolic_orbifold_Tutte::check_landmark_vertices(tm, corner_vertices, Disk_type, 3);
    if(!r)
      r.message = "corner vertices: " + r.message;
  }
  if(r)
    r = internal::check_convex_polygon(corners, ccw_polygon);
  if(r)
    r = internal::check_boundary_order(tm, corner_vertices, ccw_corners);
  return r;
}

// fixed_boundary_hyperbolic_Tutte_embedding(): the message of an inner edge between two
// boundary vertices of one side (ERROR_BOUNDARY_CHORD), in the user's corner numbers
template <class VertexDescriptor>
std::string boundary_chord_message(const Flat_problem& P, const std::vector<VertexDescriptor>& base_vertex, std::size_t n,
                                   bool ccw_corners, Embedding_statistics& st)
{
  st.problem_vertices.assign(P.problem_vertices.begin(), P.problem_vertices.end());
  const VertexDescriptor a = base_vertex[st.problem_vertices[0]], b = base_vertex[st.problem_vertices[1]];
  std::size_t s = n; // the normalised side holding both ends
  for(int v = 0; v < P.n && s == n; ++v)
    if(base_vertex[P.base[v]] == a || base_vertex[P.base[v]] == b)
      s = P.side[v] >= 0 ? static_cast<std::size_t>(P.side[v]) : n;
  auto user = [&](std::size_t q) { return ccw_corners ? q % n : (n - q % n) % n; };
  return "the inner edge between mesh vertices " + std::to_string(st.problem_vertices[0]) + " and " +
         std::to_string(st.problem_vertices[1]) + " joins two boundary vertices of one side of the polygon" +
         (s < n ? " (between corners " + std::to_string((std::min)(user(s), user(s + 1))) + " and " +
                    std::to_string((std::max)(user(s), user(s + 1))) + ")" : std::string()) +
         ": its triangles would be flat; make a boundary vertex between its ends a corner, or split the edge";
}

// the user's edge weights (`wmap`) into P.edge_weight (no seam: one copy per edge); false
// (`msg` says which) when one is not a positive finite number
template <class TriangleMesh, class VertexDescriptor, class EdgeWeightMap>
bool user_edge_weights(Flat_problem& P, const TriangleMesh& tm, const std::vector<VertexDescriptor>& base_vertex,
                       const EdgeWeightMap& wmap, std::string& msg)
{
  P.edge_weight.resize(P.edges.size());
  for(std::size_t i = 0; i < P.edges.size(); ++i) {
    const int a = P.base[P.edges[i][0]], b = P.base[P.edges[i][1]];
    const double w = static_cast<double>(get(wmap, edge(base_vertex[a], base_vertex[b], tm).first));
    if(!(w > 0) || !std::isfinite(w)) {
      msg = "the user weight of the edge between mesh vertices " + std::to_string(a) + " and " + std::to_string(b) +
            " is not a positive finite number";
      return false;
    }
    P.edge_weight[i] = w;
  }
  return true;
}

// fixed_boundary_hyperbolic_Tutte_embedding(), both counterclockwise, corner 0 first: the
// corner vertices' order (`landmarks`) reversed if they go clockwise around the mesh (with the
// polygon's `corners`), the polygon mirrored if it then goes clockwise; whether it is mirrored
template <class VertexDescriptor>
bool make_counterclockwise(std::vector<VertexDescriptor>& landmarks, std::vector<std::complex<double> >& corners,
                           bool ccw_polygon, bool ccw_corners)
{
  if(!ccw_corners) {
    std::reverse(landmarks.begin() + 1, landmarks.end());
    std::reverse(corners.begin() + 1, corners.end());
  }
  const bool mirrored = ccw_polygon != ccw_corners;
  if(mirrored)
    for(std::complex<double>& z : corners)
      z = std::conj(z);
  return mirrored;
}

// fixed_boundary_hyperbolic_Tutte_embedding(): the edge weights, the user's
// (parameters::edge_weight_map(); false, `msg` saying which, when one is not usable) or
// computed from the `points` (parameters::weight_type(), parameters::weight_epsilon())
template <class TriangleMesh, class VertexDescriptor, class Point3, class NamedParameters>
bool fixed_boundary_edge_weights(Flat_problem& P, const TriangleMesh& tm, const std::vector<VertexDescriptor>& base_vertex,
                                 const std::vector<Point3>& points, const NamedParameters& np, std::string& msg)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  if constexpr(!CGAL::parameters::is_default_parameter<NamedParameters, internal_np::edge_weight_map_t>::value) {
    (void)points;
    return internal::user_edge_weights(P, tm, base_vertex, get_parameter(np, internal_np::edge_weight_map), msg);
  } else {
    (void)tm;
    (void)base_vertex;
    (void)msg;
    internal::compute_edge_weights(P, points, choose_parameter(get_parameter(np, internal_np::weight_type), Cotangent),
                                   choose_parameter(get_parameter(np, internal_np::weight_epsilon), 1e-6));
    return true;
  }
}

// the start of the fixed-boundary solve: the orbifold's Tutte initialisation (boundary
// vertices on their sides), then the boundary fixed at its place: the fraction of the side's
// hyperbolic length that is the vertex's fraction of its side's 3D arc length
template <class Domain, class Point3>
Error_code fixed_boundary_start(Flat_problem& P, const Domain& domain, const std::vector<std::complex<double> >& corners,
                                const std::vector<Point3>& points, std::vector<double>& x)
{
  typedef std::complex<double> C;
  const Error_code ec = internal::initialize_embedding(P, domain, points, x);
  if(ec != OK)
    return ec;
  std::vector<C> z(P.n);
  for(int v = 0; v < P.n; ++v)
    z[v] = internal::position(P, x, v);
  const std::vector<double> fraction = internal::side_arc_fractions(P, points);
  for(int v : P.border_loop)
    if(P.kind[v] == On_line) {
      const int s = P.side[v];
      P.kind[v] = Fixed;
      P.fixed[v] = internal::point_on_geodesic_segment(corners[domain.side_source(s)], corners[domain.side_target(s)], fraction[v]);
    }
  internal::number_variables(P);
  x.assign(P.n_vars, 0.0);
  for(int v = 0; v < P.n; ++v)
    if(P.kind[v] == Free) {
      x[P.var[v]] = z[v].real();
      x[P.var[v] + 1] = z[v].imag();
    }
  return OK;
}

// Newton to the floor of double when only flipped faces keep the certificate from passing,
// then the certificate again
template <class Domain>
void polish_and_certify(const Flat_problem& P, const Domain& domain, const Solver_options& opt, std::vector<double>& x,
                        std::vector<std::complex<double> >& uv, Embedding_statistics& st)
{
  Solver_options polish = opt;
  polish.polish = true;
  polish.vertex_imbalance = 0;
  Solver_statistics ps;
  internal::minimize_energy(P, x, polish, ps); // (only descent steps change x)
  st.polishing_iterations += ps.iterations;
  st.energy = ps.energy;
  st.relative_gradient_norm = ps.relative_gradient_norm;
  internal::certify(P, domain, x, uv, st);
}

} // namespace internal

/*!
\ingroup PkgHyperbolicOrbifoldTutteHelperFunctions

computes the hyperbolic Tutte embedding of a disk mesh with its boundary fixed on a convex
polygon of the hyperbolic plane (the paper's Theorem 1 and Figure 8): corner vertex `i`
goes to polygon corner `i`, the boundary vertices between two consecutive corner vertices go
onto the geodesic side between their corners, spaced in hyperbolic length as they are
spaced in 3D arc length along the boundary, and every interior vertex goes to the minimiser
of the hyperbolic Dirichlet energy \f$\frac12\sum_{ij} w_{ij}\, d(\Phi_i,\Phi_j)^2\f$ with the
boundary fixed: the weighted hyperbolic centre of mass of its neighbours. With positive
weights and a convex polygon this critical point is a bijection onto the polygon (Theorem 1:
in the Klein model every interior vertex is a strict convex combination of its neighbours,
and Tutte's and Floater's theorem applies). The result is checked with the package's exact
certificate (`Embedding_certificate`, in `Embedding_statistics::certificate`): every triangle
positively oriented (exact predicate), the angle sums (\f$2\pi\f$ inside, \f$\pi\f$ on the
sides, the polygon's angle at the corners), the total area (the polygon's,
\f$(n-2)\pi - \sum_i \alpha_i\f$), corners on their corners and boundary vertices on their
sides; `OK` is returned only for a certified embedding.

Unlike the disk-type orbifold of `hyperbolic_orbifold_Tutte_embedding()`, where the boundary
vertices slide along the sides to lower the energy, here they stay where they are put; the
orbifold's energy is therefore the lower one (the paper's Figure 8), and this embedding is
the one to use when the boundary's image is prescribed: a given polygon, any number of
corners from 3 on, any convex angles.

Orientation: corner vertex order and polygon orientation are both free. When the corner
vertices go around the mesh (counterclockwise: the interior on their left, as the faces are
oriented) in the same direction as the corners around the polygon, the map keeps the
orientation. Otherwise the only bijection with this correspondence reverses it: the embedding
is computed onto the mirror image of the polygon and mirrored back, every face is clockwise
in the output, and `Embedding_statistics::orientation_reversed` is `true` (the certificate is
that of the mirror image, an isometric copy).

\tparam TriangleMesh a model of `FaceListGraph` (e.g. `Surface_mesh`, `Polyhedron_3`)
\tparam PointRange a range of points with `x()` and `y()` (e.g. `std::vector<K::Point_2>`),
        Poincar&eacute;-disk coordinates, rounded to `double`
\tparam VertexUVMap a model of `WritablePropertyMap` with
        `boost::graph_traits<TriangleMesh>::%vertex_descriptor` as key type and a point type
        constructible from two `double` as value type
\tparam NamedParameters a sequence of named parameters
\param tm a triangulated disk (one boundary loop, no handle)
\param corner_vertices at least 3 distinct boundary vertices, in boundary order (either
       direction): the ones that go to the polygon's corners; the first one starts the boundary
\param polygon the polygon's corners, as many as `corner_vertices`, in order (either
       orientation): a strictly convex polygon strictly inside the unit disk
\param uvmap receives the Poincar&eacute; coordinates of every vertex; unchanged unless `OK` is
       returned
\param np an optional sequence of named parameters among the ones listed below

\cgalNamedParamsBegin
  \cgalParamNBegin{vertex_point_map} \cgalParamDescription{the 3D points}
    \cgalParamDefault{`get(CGAL::vertex_point, tm)`} \cgalParamNEnd
  \cgalParamNBegin{weight_type} \cgalParamDescription{`Cotangent`, `Mean_value` or `Uniform`}
    \cgalParamDefault{`Cotangent`} \cgalParamNEnd
  \cgalParamNBegin{edge_weight_map} \cgalParamDescription{a readable property map from `edge_descriptor`
    to positive `double` weights, used instead of `weight_type`} \cgalParamDefault{unused} \cgalParamNEnd
  \cgalParamNBegin{weight_epsilon} \cgalParamDescription{lower clamp of cotangent weights}
    \cgalParamDefault{`1e-6`} \cgalParamNEnd
  \cgalParamNBegin{gradient_tolerance} \cgalParamDescription{relative gradient norm to reach}
    \cgalParamDefault{`1e-10`} \cgalParamNEnd
  \cgalParamNBegin{number_of_iterations} \cgalParamDescription{maximum number of Newton iterations}
    \cgalParamDefault{`200`} \cgalParamNEnd
  \cgalParamNBegin{verbose} \cgalParamDescription{prints the solver's progress on `std::cerr`}
    \cgalParamDefault{`false`} \cgalParamNEnd
  \cgalParamNBegin{embedding_statistics} \cgalParamDescription{an `Embedding_statistics*` filled on return}
    \cgalParamDefault{none} \cgalParamNEnd
\cgalNamedParamsEnd

\return `OK`, or the reason of the failure, in this order of checks: the mesh's own
        (`check_mesh()` for the disk type: `ERROR_WRONG_TOPOLOGY` when it is not a disk);
        `ERROR_TOO_FEW_LANDMARKS` (fewer than 3 corners); `ERROR_WRONG_PARAMETER` (not as many
        polygon corners as corner vertices); `ERROR_LANDMARK_OUT_OF_RANGE`,
        `ERROR_DUPLICATE_LANDMARK`, `ERROR_LANDMARK_NOT_ON_BORDER` (a corner vertex not a
        vertex of `tm`, given twice, or not on the boundary); `ERROR_POLYGON_NOT_CONVEX`;
        `ERROR_CORNERS_NOT_IN_BOUNDARY_ORDER`; `ERROR_BOUNDARY_CHORD` (an inner edge joins two
        boundary vertices of one side, ends included: its triangles would be flat;
        `Embedding_statistics::problem_vertices` names it); `ERROR_WRONG_PARAMETER` (a user
        weight not positive and finite); `ERROR_CANNOT_SOLVE_LINEAR_SYSTEM` or
        `ERROR_NOT_CONVERGED` (the solver); `ERROR_NO_1_TO_1_MAPPING` (the certificate).
        Details in `Embedding_statistics::message`.
*/
template <class TriangleMesh, class PointRange, class VertexUVMap,
          class NamedParameters = CGAL::parameters::Default_named_parameters>
Error_code fixed_boundary_hyperbolic_Tutte_embedding(
  const TriangleMesh& tm,
  const std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>& corner_vertices,
  const PointRange& polygon,
  VertexUVMap uvmap,
  const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  using CGAL::parameters::is_default_parameter;
  typedef std::complex<double> C;
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename GT::vertex_descriptor vertex_descriptor;
  typedef typename GetVertexPointMap<TriangleMesh, NamedParameters>::const_type VPM;
  typedef internal::Seam_mesh_storage<TriangleMesh> Storage;
  typedef typename Storage::Mesh Mesh;
  typedef internal::Convex_polygon_domain<> Domain;
  typedef std::chrono::steady_clock Clock;
  auto seconds_since = [](Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); };

  Embedding_statistics local;
  Embedding_statistics& st = internal::statistics_parameter(np, local);
  auto fail = [&](Error_code ec, const std::string& msg) { return internal::record_failure(st, ec, msg); };
  const auto t0 = Clock::now();
  const VPM vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point), get_const_property_map(vertex_point, tm));

  // 1. the input: a disk, its corner vertices, a convex polygon, in the same order
  std::vector<C> corners;
  for(const auto& p : polygon)
    corners.push_back(C(CGAL::to_double(p.x()), CGAL::to_double(p.y())));
  const std::size_t n = corner_vertices.size();
  bool ccw_polygon = true, ccw_corners = true;
  const Status r = internal::check_fixed_boundary_input(tm, vpm, corner_vertices, corners, ccw_polygon, ccw_corners);
  if(!r)
    return fail(r.code, r.message);

  // 2. both counterclockwise, corner 0 first: the corner vertices' order reversed if they go
  // clockwise around the mesh (with the polygon's), the polygon mirrored if it then goes clockwise
  std::vector<vertex_descriptor> landmarks = corner_vertices;
  const bool mirrored = internal::make_counterclockwise(landmarks, corners, ccw_polygon, ccw_corners);
  st.landmark_order_reversed = !ccw_corners;
  st.orientation_reversed = mirrored;
  const Domain domain(corners);

  // 3. the flat problem (the uncut disk; its boundary vertices on the sides) and its weights
  Storage seams(tm);
  typename boost::graph_traits<Mesh>::halfedge_descriptor bhd;
  seams.border_halfedge(bhd);
  internal::Flat_problem P;
  std::vector<vertex_descriptor> base_vertex;
  std::vector<typename boost::graph_traits<Mesh>::vertex_descriptor> cut_vertices;
  std::string msg;
  Error_code ec = internal::build_flat_topology(seams.mesh, bhd, landmarks, domain, P, base_vertex, cut_vertices, msg);
  if(ec == ERROR_BOUNDARY_CHORD && P.problem_vertices.size() == 2) // (said in the user's corner numbers)
    msg = internal::boundary_chord_message(P, base_vertex, n, ccw_corners, st);
  if(ec != OK)
    return fail(ec, msg);
  CGAL_assertion(!P.landmark_order_reversed); // (normalised above)
  std::vector<typename boost::property_traits<VPM>::value_type> points;
  for(vertex_descriptor v : base_vertex)
    points.push_back(get(vpm, v));
  if(!internal::fixed_boundary_edge_weights(P, tm, base_vertex, points, np, msg))
    return fail(ERROR_WRONG_PARAMETER, msg);
  st.time_setup = seconds_since(t0);

  // 4. the start: the orbifold's Tutte initialisation (boundary vertices on their sides), then
  // the boundary fixed at its place: the fraction of the side's hyperbolic length that is
  // the vertex's fraction of its side's 3D arc length
  const auto t1 = Clock::now();
  std::vector<double> x;
  ec = internal::fixed_boundary_start(P, domain, corners, points, x);
  if(ec != OK)
    return fail(ec, "the Euclidean Tutte initialisation failed");
  st.number_of_vertices = P.n;
  st.number_of_variables = P.n_vars;
  st.time_initialization = seconds_since(t1);

  // 5. Newton, the certificate, and its mends (Newton to the floor of double, the one-ring repairs)
  const auto t2 = Clock::now();
  internal::Solver_options opt;
  opt.gradient_tolerance = choose_parameter(get_parameter(np, internal_np::gradient_tolerance), 1e-10);
  opt.max_iterations = choose_parameter(get_parameter(np, CGAL::internal_np::number_of_iterations), 200);
  opt.verbose = choose_parameter(get_parameter(np, CGAL::internal_np::verbose), false);
  ec = internal::minimize_energy(P, x, opt, st);
  st.time_optimization = seconds_since(t2);
  const auto t3 = Clock::now();
  std::vector<C> uv(P.n);
  internal::certify(P, domain, x, uv, st);
  if(ec == OK && internal::flipped_only(st))
    internal::polish_and_certify(P, domain, opt, x, uv, st);
  if(ec == OK)
    internal::repair(P, domain, x, uv, st); // (nothing unless faces are flipped or flat)
  st.time_certificate = seconds_since(t3);
  if(ec != OK) {
    std::ostringstream os;
    os << "the solver stopped at relative gradient norm " << st.relative_gradient_norm << " after " << st.iterations
       << " iterations (tolerance " << opt.gradient_tolerance << ", rounding floor " << st.rounding_floor << ")";
    return fail(ec, os.str());
  }
  if(!st.certificate.is_bijective()) {
    std::ostringstream os;
    os << "the embedding failed the certificate: " << st.certificate;
    return fail(ERROR_NO_1_TO_1_MAPPING, os.str());
  }

  // 6. the coordinates (mirrored back)
  typedef typename boost::property_traits<VertexUVMap>::value_type UV_point;
  for(int v = 0; v < P.n; ++v)
    put(uvmap, base_vertex[P.base[v]], UV_point(uv[v].real(), mirrored ? -uv[v].imag() : uv[v].imag()));
  return OK;
}

} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_FIXED_BOUNDARY_HYPERBOLIC_TUTTE_EMBEDDING_H
