// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_CERTIFY_CORNER_EMBEDDING_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_CERTIFY_CORNER_EMBEDDING_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Hyperbolic_orbifold_Tutte/Corner_embedding.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/Corner_embedding_certificate.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/Hyperbolic_isometry_2.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/Orbifold_tile.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/landmark_checks.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/Poincare_disk_traits_2.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/error_code.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/certifier/corner_embedding_checks.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/certifier/corner_embedding_genus.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/certifier/corner_embedding_topology.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/parameters.h>

#include <CGAL/Named_function_parameters.h>

#include <boost/graph/graph_traits.hpp>

#include <limits>
#include <optional>
#include <string>
#include <vector>

/// \file certify_corner_embedding.h

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {

namespace internal {
namespace corner_certificate {

// certify_corner_embedding(): the cones' orders as given (`orders`, empty: all 2) for `k`
// cones on a surface of genus `genus` (check_cone_orders(), in the certifier's words), and
// whether they are `mixed` (one is not 2)
inline Status check_orders_of_cones(const std::vector<int>& orders, int k, int genus, bool& mixed)
{
  Cone_order_check check;
  if(!orders.empty() && check_cone_orders(orders, static_cast<std::size_t>(k), &check) != OK)
    return Status::failure(ERROR_WRONG_PARAMETER,
                           check.problem == Wrong_number_of_cone_orders
                             ? std::to_string(orders.size()) + " cone orders are given for " + std::to_string(k) +
                                 " cones (one per cone is needed)"
                             : "cone " + std::to_string(check.index) + " is given the order " + std::to_string(orders[check.index]) +
                                 ": orders are integers of at least 2 (cone angle 2 pi / order)");
  mixed = false;
  for(int p : orders)
    mixed = mixed || p != 2;
  if(genus > 0 && check_cone_orders(Orbifold_signature(genus, orders.empty() ? std::vector<int>(k, 2) : orders),
                                    static_cast<std::size_t>(k)) == ERROR_NOT_HYPERBOLIC)
    return Status::failure(ERROR_NOT_HYPERBOLIC, "a closed surface of genus 1 needs at least one cone to be hyperbolic, " +
                                                 std::to_string(k) + " given");
  if(k < 5 && !mixed && genus == 0)
    return Status::failure(ERROR_TOO_FEW_LANDMARKS, "the orbifold needs at least 5 cones, " + std::to_string(k) + " given");
  return Status();
}

// certify_corner_embedding(): the cones' vertices (dense indices), which vertices are cones
// and which are on the border; a cone given twice, or off the boundary of a disk, refused
template <class TriangleMesh>
Status index_cones(const Indexed_mesh<TriangleMesh>& M,
                   const std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>& cones,
                   Orbifold_type type, std::vector<std::size_t>& cone_index, std::vector<char>& is_cone,
                   std::vector<char>& on_border)
{
  const int k = static_cast<int>(cones.size());
  is_cone.assign(M.number_of_vertices(), 0);
  on_border.assign(M.number_of_vertices(), 0);
  for(std::size_t v : M.border_loop)
    on_border[v] = 1;
  for(int i = 0; i < k; ++i) {
    const std::size_t v = M.index(cones[i]);
    if(is_cone[v])
      return Status::failure(ERROR_DUPLICATE_LANDMARK, "vertex " + std::to_string(v) + " is given twice as a cone");
    if(type == Disk_type && !on_border[v])
      return Status::failure(ERROR_LANDMARK_NOT_ON_BORDER, "cone " + std::to_string(i) + " (vertex " + std::to_string(v) +
                                                             ") is not on the boundary: a disk's cones are corners of its boundary");
    is_cone[v] = 1;
    cone_index.push_back(v);
  }
  return Status();
}

// certify_corner_embedding(): the embedding's arrays (every face's points exist) and its
// charts' arrays (as many as the charts and the points, every point's chart exists)
inline Status check_embedding_arrays(const Corner_embedding& embedding)
{
  if(embedding.face_points.size() != embedding.face_vertices.size())
    return Status::failure(ERROR_WRONG_PARAMETER, "the embedding has " + std::to_string(embedding.face_vertices.size()) +
                                                        " faces but points for " + std::to_string(embedding.face_points.size()));
  for(std::size_t e = 0; e < embedding.number_of_faces(); ++e)
    for(int c = 0; c < 3; ++c)
      if(embedding.face_points[e][c] >= embedding.points.size())
        return Status::failure(ERROR_WRONG_PARAMETER, "corner " + std::to_string(c) + " of face " + std::to_string(e) +
                                                            " refers to point " + std::to_string(embedding.face_points[e][c]) +
                                                            ", but the embedding has " + std::to_string(embedding.points.size()));

  // the charts' arrays
  if(embedding.has_charts() || !embedding.point_charts.empty()) {
    if(!embedding.has_charts())
      return Status::failure(ERROR_WRONG_PARAMETER, "the embedding has points in charts but no chart");
    if(embedding.chart_corners.size() != embedding.charts.size())
      return Status::failure(ERROR_WRONG_PARAMETER, "the embedding has " + std::to_string(embedding.charts.size()) +
                                                          " charts but corners for " + std::to_string(embedding.chart_corners.size()));
    if(embedding.point_charts.size() != embedding.points.size() || embedding.chart_points.size() != embedding.points.size())
      return Status::failure(ERROR_WRONG_PARAMETER, "the embedding has " + std::to_string(embedding.points.size()) +
                                                          " points but charts for " + std::to_string(embedding.point_charts.size()) +
                                                          " and chart points for " + std::to_string(embedding.chart_points.size()));
    for(std::size_t p = 0; p < embedding.points.size(); ++p)
      if(embedding.point_charts[p] < -1 || embedding.point_charts[p] >= static_cast<int>(embedding.charts.size()))
        return Status::failure(ERROR_WRONG_PARAMETER, "point " + std::to_string(p) + " is in chart " +
                                                            std::to_string(embedding.point_charts[p]) + ", but the embedding has " +
                                                            std::to_string(embedding.charts.size()) + " charts");
  }

  return Status();
}

// certify_corner_embedding(): the certificate's sizes and tolerances, before its checks
template <class TriangleMesh>
void start_certificate(const Indexed_mesh<TriangleMesh>& M, const Corner_embedding& embedding, Orbifold_type type, int k,
                       double expected_area, Corner_embedding_certificate& certificate)
{
  certificate.type = type;
  certificate.number_of_cones = k;
  certificate.number_of_faces = embedding.number_of_faces();
  certificate.number_of_vertices = M.number_of_vertices();
  certificate.number_of_points = embedding.points.size();
  certificate.number_of_border_vertices = M.border_loop.size();
  certificate.expected_area = expected_area;
  certificate.absolute_tolerance = absolute_tolerance;
  certificate.relative_tolerance = relative_tolerance;
  certificate.cone_order.assign(k, -1);
  certificate.cone_orders.assign(k, 0);
  certificate.measured_cone_orders.assign(k, std::numeric_limits<double>::quiet_NaN());
}

// certify_corner_embedding(): the checks of a map whose faces match the mesh's (match_faces(),
// `rotation` per face), in the order of `Corner_embedding_check`. With `mixed` orders, `tile`
// (which S refers to) is built again for the cones' sequence read from the map, and moved by
// `frame` when `framed`; the one failure: no tile for that sequence.
template <class TriangleMesh>
Status check_matched_map(Certification<TriangleMesh>& S, const Indexed_mesh<TriangleMesh>& M,
                         const Corner_embedding& embedding, const std::vector<int>& rotation, Orbifold_type type,
                         const std::vector<std::size_t>& cone_index, const std::vector<int>& orders, bool mixed,
                         bool framed, const Hyperbolic_isometry_2<double>& frame,
                         Orbifold_tile<Poincare_disk_traits_2<> >& tile, Corner_embedding_certificate& certificate)
{
  S.pid.resize(M.number_of_faces());
  for(std::size_t f = 0; f < M.number_of_faces(); ++f)
    for(int c = 0; c < 3; ++c)
      S.pid[f][c] = embedding.face_points[S.efface[f]][(c + rotation[f]) % 3];
  S.charted = embedding.has_charts();
  corner_certificate::check_points(S);
  const std::vector<std::vector<std::size_t> > points_of = corner_certificate::points_of_vertices(S);
  const Hyperbolic_isometry_2<double> to_tile = frame.inverse();
  if(mixed) {
    // the tile of the given orders in the sequence of the cones along its boundary, read from
    // their points (cone_sequence()); S refers to `tile`
    const std::vector<int> sequence = corner_certificate::cone_sequence(S, cone_index, points_of, to_tile);
    std::vector<int> sequence_orders;
    for(int i : sequence)
      sequence_orders.push_back(orders[i]);
    if(make_orbifold_tile(Orbifold_signature(type, sequence_orders), tile) != OK)
      return Status::failure(ERROR_NOT_HYPERBOLIC, "no tile for the cone orders given"); // (built above in another sequence)
    if(framed)
      tile = tile.transformed(frame);
    certificate.expected_area = tile.area();
  }
  certificate.measured_cone_orders = corner_certificate::measure_cone_orders(S, cone_index, points_of, to_tile);
  corner_certificate::check_charts(S);
  corner_certificate::compute_tolerances(S);
  const bool order_known = corner_certificate::check_cones(S, cone_index, points_of);
  if(type == Sphere_type)
    certificate.checks[Border_check].run = true; // nothing to check: no boundary
  else if(order_known)
    corner_certificate::check_border(S, cone_index, points_of);
  corner_certificate::check_faces(S);
  corner_certificate::check_angle_sums_and_area(S, cone_index);
  corner_certificate::check_seams(S);
  return Status();
}

} // namespace corner_certificate
} // namespace internal

/*!
\ingroup PkgHyperbolicOrbifoldTutteHelperFunctions

certifies that a map of a mesh into the Poincar&eacute; disk, given per face corner
(`Corner_embedding`: an OBJ file's `vt` points and `f v/vt` faces), is a bijection of the mesh
onto the hyperbolic orbifold whose cones are `cones`, of orders `cone_orders` (2 by default),
deciding it from the map alone. It
shares no code with the solver beyond the traits (`Poincare_disk_traits_2`), the isometries
(`Hyperbolic_isometry_2`) and the tile (`make_orbifold_tile()`): not the cut, nor the seam
mesh, nor the solver's certificate. The checks, in the order of `Corner_embedding_check` (the
first failure is the one reported):

- *repeated_face*, *mesh_faces*: the embedding's faces are the mesh's faces, with their
  orientation, each one once (in any order, each from any of its corners);
- *finite*, *inside_disk*: every point is finite and strictly inside the unit disk (exact);
- *cones*: every point of every cone is at a corner of the tile (`make_orbifold_tile()` for
  the orbifold type and the cones' orders, see below), and all of a cone's points at corners
  of the same tile cone, each tile cone taken once: this gives the cone order
  (`Corner_embedding_certificate::cone_order`), found rather than assumed; the tile cone's order
  (its corners' angles add up to \f$2\pi/p\f$) is the cone's given order
  (`Corner_embedding_certificate::cone_orders`); on a disk, the cones that follow each other
  counterclockwise along the boundary are at consecutive corners;
- *border* (disk type): every other boundary vertex is on the segment of the tile side between
  the corners of the cones before and after it (not only on the side's geodesic line);
- *degenerate_face*, *orientation*: every face is positively oriented, decided exactly;
- *angle_sum*: per mesh vertex, the hyperbolic angles of all its corners (in every face, across
  seams) add up to \f$2\pi\f$, to \f$2\pi/p\f$ at a sphere-type cone of order \f$p\f$
  (\f$\pi\f$ for order 2), to \f$\pi\f$ along a disk's boundary, and to \f$\pi/2\f$ at a
  disk's corner;
- *seams*: every edge whose two faces give different points to one of its ends is a seam; the
  orientation-preserving isometry relating its two sides is computed from the copies, and must
  be one of the tile's side pairings (a disk-type map has no seams: its tile's pairings are
  reflections);
- *area*: the total hyperbolic area of the faces is the orbifold's (Gauss-Bonnet):
  \f$2\pi(\sum_i (1 - 1/p_i) - 2)\f$ on a sphere, \f$(k-4)\pi\f$ for \f$k\f$ cones of
  order 2, \f$(k-4)\pi/2\f$ for a disk's \f$k\f$ right-angled corners.

Cones of orders other than 2 (sphere type). The tile of orders \f$(p_1, \dots, p_k)\f$
(`make_orbifold_tile(Orbifold_signature)`, the solver's for a cut through the cones in that
sequence) depends on the sequence, not only on the orders: its corners \f$c_1, \dots, c_k\f$
are the cones in that sequence, and \f$\bar c_2, \dots, \bar c_{k-1}\f$ the second copies
of the inner ones. The checker does not take the sequence from the solver (it does not read
the cut): it reads it from the map. In the tile's own frame (the frame's inverse applied), \f$c_1\f$ is on
the positive real axis, \f$c_k\f$ on the negative one and \f$c_2, \dots, c_{k-1}\f$ in the
upper half-disk at strictly increasing arguments (the \f$k\f$-gon is convex and the origin is
the midpoint of its side \f$c_k c_1\f$), their conjugates below them; so the cones are put in
the order of the arguments of their highest points (the imaginary part clamped at 0, so that a
point of the real axis rounded below it stays at argument 0 or \f$\pi\f$), and the tile is
built for the given orders in that sequence. Whenever the cones' points are at the corners of
the tile of some sequence (within the tolerance, far below the distances between corners),
this is that sequence (the tolerance is at most \f$10^{-6}\f$ of the edges at the cone, in
any frame). The sequence is only a choice of the tile: the checks decide, exactly as for
order 2, whether every cone is at a corner of it, of its given order, and whether the
map is a bijection onto it; a tile the map does not fit makes the *cones* check fail, never a
wrong map pass. The orders measured on the cones' points alone
(`Corner_embedding_certificate::measured_cone_orders`: the angles of the polygon they form,
which is the tile when the map is right) are reported, and the message of a cone at no
corner names the cones whose measured order is not the given one (orders given to the wrong
cones, or wrong orders). Three cones suffice when the orders make the orbifold hyperbolic,
\f$\sum_i (1 - 1/p_i) > 2\f$ (e.g. (2,3,7)), four for e.g. (2,2,2,3); with orders 2 only,
everything is as it always was (the paper's tiles, at least 5 cones).

With charts around cone images (`Corner_embedding::charts`: a protrusion ending at a
landmark, converging onto its cone's image below what `double` resolves in the tile), the map
is certified in the charts' coordinates, and one more check runs after *inside_disk*:

- *charts*: every chart a normalized orientation-preserving isometry of the disk whose origin
  is its tile corner within \f$64u\f$ (\f$u = 2^{-53}\f$: the chart's rounding), every chart point
  finite, strictly inside the disk and whose tile point is its point's within the rounding of
  computing it, every face's charted corners in one chart.

A chart stands for the isometry that moves its corner exactly to the origin: a cone written in
a chart must be exactly at its origin (*cones*); a face is decided in its chart, exactly when
its corners are all chart points, else for every position of its other corners (brought into
the chart from their tile points) within their certified error bound; a seam between two
charts of one cone must match by the rotation about the origin that the side pairing is
between them, within its rounding relative to the points' distance to the origin. The bounds
and their derivations: the user manual, "Charts" in \ref HOT_IndependentCertificate.

Together (paper, section 4 and Appendix B): the map to the orbifold is continuous across
seams, a local homeomorphism at every point, hence a covering, and of degree one by the area:
a bijection.

Closed surfaces of genus \f$g \ge 1\f$ (`Corner_embedding_certificate::genus`; the map of
the polygon of a cut graph, `embed` of such a mesh), with \f$k \ge 0\f$ cones of the given
orders (2 by default; at least one cone on a torus). There is no tile to compare with: the
checker does not rebuild the library's cut or polygon, it reads the gluings off the map. The
checks, with the same names:

- *repeated_face*, *mesh_faces*, *finite*, *inside_disk*, *degenerate_face*, *orientation* as
  above (orientation exact, with the package's filtered `Hyperbolic_orientation_2`); *charts*,
  *cones* and *border* have nothing to check (charts are refused; a cone's order is decided by
  its angle sum; there is no boundary);
- *angle_sum*: per mesh vertex, the angles of all its corners (each face in the frame it is
  written in) add up to \f$2\pi\f$, to \f$2\pi/p\f$ at a cone of order \f$p\f$, the certified
  enclosure within `Corner_embedding_certificate::angle_sum_tolerance` (\f$10^{-6}\f$) of it;
  an extra cone claimed (its sum is \f$2\pi\f$, not \f$2\pi/p\f$) or a wrong order fails here;
- *seams*: every edge whose two faces give different points to one of its ends is a seam; the
  orientation-preserving isometry \f$h\f$ taking the first face's copy of one end, and the
  direction of the edge there, to the second face's is computed, and must take the other end's
  copy to its twin (the two copies have the same hyperbolic length) within the positions'
  tolerance of the edge; and at every vertex copy on the cut that is not a cone, the seam
  edges with the same two copies of it (consecutive edges of one side of the cut) share the
  isometry: the first one's takes another's copy of its other end to its twin, within that
  edge's tolerance (`Corner_embedding_certificate::number_of_seam_isometries` counts the
  classes of seam edges so linked);
- *area*: the total hyperbolic area is \f$2\pi(2g - 2 + \sum_i (1 - 1/p_i))\f$ (Gauss-Bonnet,
  \f$g\f$ from \f$V - E + F = 2 - 2g\f$), within half of it.

Why this certifies the map. The corner points give every face a positively oriented geodesic
triangle, and the seams glue the two copies of every edge by an isometry: a hyperbolic metric
on the mesh, with cone points where the angle sums are not \f$2\pi\f$. Developing the faces
around a vertex across its seams closes up by the rotation about its copy by the angle sum
(the holonomy of its fan), so with the sums \f$2\pi\f$ (\f$2\pi/p\f$) the metric is smooth
away from the cones and has a cone of angle \f$2\pi/p\f$ at each: the developing map is a
local isometry, the map onto \f$\mathbb{H}^2/\Gamma\f$ (\f$\Gamma\f$ generated by the seam
isometries) a covering of the closed orbifold, of degree one since the area is the
orbifold's, hence a bijection; the faces in the disk form a fundamental domain of
\f$\Gamma\f$ (the polygon of the cut), whatever the cut was. The consistency of the seams is
implied by the angle sums (two isometries taking a copy of a vertex to the same copy differ by
a rotation about it, the fan's holonomy, by the sum minus \f$2\pi\f$) and is checked directly
to name the broken seam; at a cone the cut may pass from one side of the polygon to another,
glued by isometries that differ by the rotation of \f$2\pi/p\f$: not compared there. The angle
sums cannot be decided by rounding to the group here (no tile gives the group in advance):
they are accepted within \f$10^{-6}\f$ (the package's embeddings: below \f$10^{-11}\f$), a
numerical bound, as the positions' tolerances are.

Exactness and tolerances. Orientation and the unit disk are decided exactly on the given
coordinates. Angles are computed with certified error bounds (interval arithmetic); with every
face positive and the seams glued by the group, an angle sum can only be its expected value
plus a multiple of \f$\pi\f$ (at a cone of order \f$p\f$, a multiple of \f$2\pi/p\f$: the
fan closes up to a rotation of the group about the cone's image), and the area only a multiple
of the orbifold's: the checks accept a certified enclosure within \f$\pi/2\f$ (within
\f$\pi/p\f$ at a cone of order \f$p\f$, the same for order 2), and within half the orbifold's
area, of the expected value, which decides them (`Corner_embedding_certificate::max_angle_sum_deviation`
reports the actual deviations, \f$10^{-15}\f$ to \f$3\cdot10^{-7}\f$ for the package's
embeddings). Positions (cones at corners, boundary points on sides, a seam copy against its
twin's image by the side pairing) are compared with a tolerance of \f$10^{-9}\f$ in disk
coordinates, or \f$10^{-6}\f$ of the shortest edge at the vertex (of the seam edge) when that
is smaller: far above the rounding of coordinates in `double` (\f$10^{-16}\f$; the package's
embeddings are within \f$6\cdot10^{-13}\f$), far below the size of the triangles a
misplacement has to be compared with.

\tparam TriangleMesh a model of `FaceListGraph`, `VertexListGraph` and `HalfedgeListGraph`
\tparam NamedParameters a sequence of named parameters

\param tm the mesh: a triangulated closed surface (of any genus) or disk (checked)
\param cones the vertices at the orbifold's cones (sphere type) or corners (disk type), in any
       order: distinct, on the boundary for a disk; at least 5 of order 2, or as many as make
       the orbifold of the given orders hyperbolic (3 for (2,3,7)); on a closed surface of
       genus \f$g \ge 1\f$ any number (at least one for \f$g = 1\f$)
\param embedding the map; its vertex indices are those of `vertices(tm)` in order
\param certificate receives the verdict, every count and the first failure of each check
\param message if not null, receives one line: the error, or `certificate.summary()`
\param np optional named parameters: `orbifold_type` (default: from the mesh's boundary),
       `frame` (a `Hyperbolic_isometry_2<double>`, default the identity: the map fills the tile
       moved by it, as a recentred embedding does; `Embedding_statistics::frame`; without
       effect on a closed surface of genus \f$g \ge 1\f$, which has no tile) and
       `cone_orders` (a `std::vector<int>`, the order of each of `cones`, in their order, as
       `hyperbolic_orbifold_Tutte_embedding()` takes them; default or empty: 2 for every cone;
       orders other than 2 for sphere type only)

\pre `cones` are vertices of `tm`
\return `OK` when the map was checked (read `certificate.is_certified()`); otherwise the input
error: the mesh is not a triangulated closed surface or disk (`ERROR_NON_TRIANGULAR_MESH`,
`ERROR_NON_MANIFOLD`, `ERROR_SEVERAL_COMPONENTS`, `ERROR_WRONG_TOPOLOGY`, `ERROR_EMPTY_MESH`),
the cones are too few (`ERROR_TOO_FEW_LANDMARKS`), repeated or off a disk's boundary, the
orders are not one per cone, below 2 or other than 2 on a disk (`ERROR_WRONG_PARAMETER`) or do
not make the orbifold hyperbolic (`ERROR_NOT_HYPERBOLIC`; a torus without cone), the frame
reverses orientation, `embedding` refers to points it does not have, or has charts on a
closed surface of genus \f$g \ge 1\f$ (`ERROR_WRONG_PARAMETER`).
*/
template <class TriangleMesh, class NamedParameters = CGAL::parameters::Default_named_parameters>
Error_code certify_corner_embedding(const TriangleMesh& tm,
                                    const std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>& cones,
                                    const Corner_embedding& embedding,
                                    Corner_embedding_certificate& certificate,
                                    std::string* message = nullptr,
                                    const NamedParameters& np = CGAL::parameters::default_values())
{
  namespace cc = internal::corner_certificate;
  typedef Orbifold_tile<Poincare_disk_traits_2<> > Tile;
  certificate = Corner_embedding_certificate();
  std::string local;
  std::string& msg = message ? *message : local;
  auto fail = [&](const Status& s) {
    msg = s.message;
    return s.code;
  };

  // the mesh and the orbifold
  std::optional<Orbifold_type> required;
  if constexpr(!CGAL::parameters::is_default_parameter<NamedParameters, internal_np::orbifold_type_t>::value)
    required = CGAL::parameters::get_parameter(np, internal_np::orbifold_type);
  cc::Indexed_mesh<TriangleMesh> M(tm);
  Orbifold_type type = Sphere_type;
  int genus = 0;
  const Status topology = cc::index_and_check_mesh(M, required, type, &genus);
  if(!topology)
    return fail(topology);
  const int k = static_cast<int>(cones.size());
  // the cones' orders, as given (per cone of `cones`); `mixed` when one is not 2
  const std::vector<int> orders = CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np, internal_np::cone_orders),
                                                                     std::vector<int>());
  bool mixed = false;
  const Status orders_checked = cc::check_orders_of_cones(orders, k, genus, mixed);
  if(!orders_checked)
    return fail(orders_checked);
  std::vector<std::size_t> cone_index;
  std::vector<char> is_cone, on_border;
  const Status cone_vertices = cc::index_cones(M, cones, type, cone_index, is_cone, on_border);
  if(!cone_vertices)
    return fail(cone_vertices);
  Tile tile;
  if(genus > 0) {
    // no tile: the checks do without one (certify_closed_genus())
  } else if(!mixed) {
    if(make_orbifold_tile(type, k, tile) != OK)
      return fail(Status::failure(ERROR_NOT_HYPERBOLIC, "no tile for " + std::to_string(k) + " cones"));
  } else {
    // for now the orders in the given sequence (the area and the refusals do not depend on the
    // sequence); the tile is built again for the cones' sequence found on the map, below
    const Status s = internal::tile_of_cone_orders(type, orders, k, tile, Poincare_disk_traits_2<>());
    if(!s)
      return fail(s);
  }
  Hyperbolic_isometry_2<double> frame; // the identity by default
  constexpr bool framed = !CGAL::parameters::is_default_parameter<NamedParameters, internal_np::frame_t>::value;
  if constexpr(framed) {
    frame = CGAL::parameters::get_parameter(np, internal_np::frame);
    if(!frame.is_orientation_preserving())
      return fail(Status::failure(ERROR_WRONG_PARAMETER, "the frame must be an orientation-preserving isometry"));
    if(genus == 0)
      tile = tile.transformed(frame);
  }

  // the embedding's arrays, and its charts' arrays
  const Status arrays = cc::check_embedding_arrays(embedding);
  if(!arrays)
    return fail(arrays);

  if(genus > 0) {
    if(embedding.has_charts())
      return fail(Status::failure(ERROR_WRONG_PARAMETER, "the embedding has charts around cone images, which are for genus 0 only"));
    cc::certify_closed_genus(M, genus, cone_index, orders, is_cone, embedding, certificate);
    msg = certificate.summary();
    return OK;
  }

  cc::start_certificate(M, embedding, type, k, tile.area(), certificate);

  cc::Certification<TriangleMesh> S(M, embedding, tile, certificate);
  S.is_cone = is_cone;
  S.on_border = on_border;
  if(mixed)
    S.orders = orders;
  std::vector<int> rotation;
  if(cc::match_faces(M, embedding, certificate, S.efface, rotation)) {
    const Status checked = cc::check_matched_map(S, M, embedding, rotation, type, cone_index, orders, mixed, framed, frame,
                                                 tile, certificate);
    if(!checked)
      return fail(checked);
  }
  msg = certificate.summary();
  return OK;
}

} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_CERTIFY_CORNER_EMBEDDING_H
