// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_EMBEDDING_LOCATOR_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_EMBEDDING_LOCATOR_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Hyperbolic_orbifold_Tutte/Chart_point.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/Hyperbolic_isometry_2.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/Orbifold_embedding.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/Orbifold_tile.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/Poincare_disk_traits_2.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/error_code.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/interpolation_model.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/core/disk_models.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/locator/lifted_triangulation.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/locator/locator_charts.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/locator/locator_build.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/locator/locator_search.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/locator/locator_walk.h>

#include <boost/graph/graph_traits.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <string>
#include <vector>

/// \file Embedding_locator.h

// Algorithm (Embedding_locator::locate):
//  1. z is reduced into the tile (Orbifold_tile::reduce_to_tile, exact side tests):
//     q = r(z).
//  2. A start triangle near q is read from a uniform grid over B's triangle centroids
//     (built in linear time); its Klein centroid p is strictly inside it (checked
//     exactly when the grid is built).
//  3. Straight walk from p to q in the lifted triangulation (B's triangles and their
//     images by the group, which tile the disk when Phi_B is bijective). The segment
//     [p, q] is fixed; the walk carries the group element h of the current copy. When it
//     crosses a cut edge (sphere type: the side pairing that glues the two sides, found
//     once per edge from the corner coordinates) or a border edge (disk type: the
//     reflection in the tile side holding it), h is composed with that element and only
//     the new triangle's third corner is computed as h(uv); the two corners of the
//     crossed edge are reused bit for bit, so consecutive triangles share their edge
//     exactly and no sliver opens between copies. All side tests use the exact
//     predicate Traits::Hyperbolic_orientation_2 on these doubles; a
//     vertex on the line (p, q) counts as left of it (a symbolic perturbation of the
//     line), so the walk is the straight walk of a segment that meets no vertex.
//     Termination: every new triangle is checked to be positively oriented, so the exit
//     point along [p, q] strictly advances at each step; no triangle is entered twice,
//     and only the finitely many lifted triangles meeting the segment are visited. The
//     walk ends in the (closed) triangle containing q.
//  4. Safety net, for inputs where a check of step 3 fails (a rounded third corner
//     flipping a needle triangle, an embedding that is not bijective, a step count
//     beyond 4 x (number of faces) + 1000): a best-first search over lifted triangles
//     (face, group element), ordered by hyperbolic distance from q to the triangle's
//     centroid, with a visited set. Before the triangle containing q is expanded only
//     triangles closer than the farthest one along some path from the start to it can
//     be expanded, a finite set (the group acts properly discontinuously), so it ends.
//     (Capped at 64 x (number of faces) + 100000 expansions for input that is not an
//     embedding; then the candidate with the largest smallest coordinate is returned,
//     with success only if that coordinate is above -1e-9.)
//
// The reported element is g = h^{-1} r (g(z) is in the face); the barycentric coordinates
// are those of g(z) = h^{-1}(q) w.r.t. the face's stored corners, in Klein coordinates of
// B's own frame (isometries are projective, not affine, maps of the Klein disk, so the
// coordinates w.r.t. the developed corners h(uv) would be different ones), or, on request,
// in the hyperboloid model, where they are invariant under the group (Interpolation_model).
// Points given exactly at a corner's coordinates are returned at that corner with the
// barycentric coordinates (1, 0, 0) (up to the corner's position), exactly.

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {

/*!
\ingroup PkgHyperbolicOrbifoldTutteMainClasses

exact point location in the embedding of a triangle mesh `B` into a hyperbolic orbifold,
given as the per-corner map written by `hyperbolic_orbifold_Tutte_embedding()` (for every
halfedge `h` of a face, the Poincar&eacute; point of corner `target(h)` in `face(h)`).

The embedding (one copy of the fundamental domain: the cut mesh) and its images under the
orbifold group tile the Poincar&eacute; disk. `locate(z)` returns, for any point `z` of the
disk, the face of `B` and the barycentric coordinates of the copy `g(z)` of `z` under the
group that lies in that face's triangle, and `g`. It reduces `z` into the tile, then walks
straight through `B`'s triangles and their images from a start triangle read from a grid,
with exact orientation tests; an exhaustive best-first search over the lifted triangles is
the safety net, so it never gives up on a bijective embedding. Points given exactly at a
corner's coordinates are returned at that corner, exactly.

Built once in linear time; `locate()` is then thread-safe (const, no shared state).

\tparam TriangleMesh a model of `FaceGraph` with triangular faces
\tparam HalfedgeUVMap a model of `ReadablePropertyMap` with
        `boost::graph_traits<TriangleMesh>::%halfedge_descriptor` as key type and a point type
        with `x()` and `y()` as value type
\tparam Traits a model of `HyperbolicOrbifoldTraits_2`, the traits of the tile;
        `Poincare_disk_traits_2<>` by default

\sa `map_vertices()`, `surface_point()`, `Orbifold_collection`
*/
template <class TriangleMesh, class HalfedgeUVMap, class Traits_ = Poincare_disk_traits_2<> >
class Embedding_locator
{
public:
  /// \name Types
  /// @{
  typedef boost::graph_traits<TriangleMesh> GT;                     ///< graph traits of the mesh
  typedef typename GT::vertex_descriptor vertex_descriptor;         ///< vertex of the mesh
  typedef typename GT::halfedge_descriptor halfedge_descriptor;     ///< halfedge of the mesh
  typedef typename GT::face_descriptor face_descriptor;             ///< face of the mesh
  typedef Traits_ Traits;                                           ///< traits of the tile
  typedef typename Traits::Point_2 Point_2;                         ///< point of the Poincar&eacute; disk
  typedef Orbifold_tile<Traits> Tile;                               ///< the orbifold's tile
  typedef Hyperbolic_isometry_2<double> Isometry;                   ///< element of the orbifold group
  /// @}

#ifndef DOXYGEN_RUNNING
  typedef std::complex<double> C;
#endif

  /// the face index of a location that was not found
  static constexpr std::size_t npos = static_cast<std::size_t>(-1);

  /// the answer of `locate()`
  struct Location
  {
    std::size_t face_index = npos;         ///< index of the face in `faces(B)` order
    face_descriptor face;                  ///< the face
    /// barycentric coordinates (see `Interpolation_model`) w.r.t. the corners of the face in
    /// the order of `halfedges_around_face(halfedge(face))`, clamped to be >= 0 and renormalised
    std::array<double, 3> barycentric{{0.0, 0.0, 0.0}};
    Isometry element;                      ///< g with g(z) in the face
    double min_raw_barycentric = 0;        ///< the smallest coordinate before clamping
    bool success = false;                  ///< whether the point was located
    std::size_t steps = 0;                 ///< triangles visited
    bool used_search = false;              ///< the walk failed a check; the fallback search answered
  };

  /// an invalid locator
  Embedding_locator() {}

  /// builds the locator of the embedding `uv` of `tm` into the orbifold of `tile`
  Embedding_locator(const TriangleMesh& tm, HalfedgeUVMap uv, const Tile& tile,
                    Interpolation_model model = Hyperboloid_linear)
  {
    lt_.model = model;
    build(tm, uv, tile);
  }

  /// builds the locator of the embedding `uv` of `tm` into the orbifold of the given type with `k` cones
  Embedding_locator(const TriangleMesh& tm, HalfedgeUVMap uv, Orbifold_type type, int k,
                    Interpolation_model model = Hyperboloid_linear)
    : Embedding_locator(tm, uv, regular_signature(type, k), model)
  {}

  /// builds the locator of the embedding `uv` of `tm` into the orbifold of `signature` (cones
  /// of any orders, `make_orbifold_tile()`)
  Embedding_locator(const TriangleMesh& tm, HalfedgeUVMap uv, const Orbifold_signature& signature,
                    Interpolation_model model = Hyperboloid_linear)
  {
    Tile tile;
    if(set_up_tile(signature, model, tile))
      build(tm, uv, tile);
  }

  /// builds the locator of an embedding written partly in charts around cone images
  /// (\ref HOT_Charts): `uv` as for the other constructors, `charts` the charts
  /// (`Embedding_statistics::charts`) and `chart_map` (a readable property map from halfedges to
  /// `Chart_point<Point_2>`) every corner's chart point. The faces written in a chart are
  /// located in its coordinates (the tile points of their corners are not used).
  template <class HalfedgeChartMap>
  Embedding_locator(const TriangleMesh& tm, HalfedgeUVMap uv, HalfedgeChartMap chart_map,
                    const std::vector<Isometry>& charts, Orbifold_type type, int k,
                    Interpolation_model model = Hyperboloid_linear)
    : Embedding_locator(tm, uv, chart_map, charts, regular_signature(type, k), model)
  {}

  /// the same for the orbifold of `signature` (cones of any orders, `make_orbifold_tile()`)
  template <class HalfedgeChartMap>
  Embedding_locator(const TriangleMesh& tm, HalfedgeUVMap uv, HalfedgeChartMap chart_map,
                    const std::vector<Isometry>& charts, const Orbifold_signature& signature,
                    Interpolation_model model = Hyperboloid_linear)
  {
    Tile tile;
    if(set_up_tile(signature, model, tile))
      build_with_charts(tm, uv, chart_map, charts, tile);
  }

  /// builds the locator of an embedding result: in its tile (`make_embedding_tile()` of its
  /// layout: the polygon of the cut graph for genus \f$ g \ge 1 \f$), with its charts when it
  /// is written partly in charts. A recentred embedding (written in a moved frame) is refused
  /// (`is_valid()` is `false`): maps are between embeddings in the tile itself.
  template <class HalfedgeChartMap>
  explicit Embedding_locator(const Orbifold_embedding<TriangleMesh, HalfedgeUVMap, HalfedgeChartMap>& embedding,
                             Interpolation_model model = Hyperboloid_linear)
  {
    lt_.model = model;
    Tile tile;
    if(!embedding.is_valid()) {
      lt_.fail("the embedding holds no coordinates (it was not computed)");
      return;
    }
    if(embedding.layout().recentred) {
      lt_.fail("the embedding is written in a moved frame (recentred): compute it without recentring to locate in it");
      return;
    }
    if(embedding.layout().genus > 0) { // (the polygon of the cut graph)
      if(embedding.tile(tile) != OK) {
        lt_.fail("the tile of the cut graph's polygon could not be built");
        return;
      }
    } else if(!set_up_tile(embedding.signature(), model, tile))
      return;
    if constexpr(Orbifold_embedding<TriangleMesh, HalfedgeUVMap, HalfedgeChartMap>::has_chart_map)
      build_with_charts(embedding.mesh(), embedding.uv_map(), embedding.chart_map(), embedding.layout().charts, tile);
    else
      build(embedding.mesh(), embedding.uv_map(), tile);
  }

  /// \name Access
  /// @{

  /// the charts of the embedding (empty if it is written in the tile only)
  const std::vector<Isometry>& charts() const { return ch_.charts; }
  /// the chart face `i` is written in, or -1 (the tile's coordinates)
  int face_chart(std::size_t i) const { return ch_.empty() ? -1 : ch_.face_chart[i]; }

  /// whether the locator was built (see `message()` otherwise)
  bool is_valid() const { return lt_.valid; }
  /// how barycentric coordinates are defined (see `Interpolation_model`)
  Interpolation_model interpolation_model() const { return lt_.model; }
  /// why the locator is not valid, or a warning (faces not positively oriented)
  const std::string& message() const { return lt_.message; }
  /// the orbifold's tile
  const Tile& tile() const { return lt_.tile; }
  /// the number of faces of the mesh
  std::size_t number_of_faces() const { return faces_.size(); }
  /// the number of vertices of the mesh
  std::size_t number_of_vertices() const { return vertices_.size(); }
  /// face `i` in `faces(B)` order
  face_descriptor face(std::size_t i) const { return faces_[i]; }
  /// vertex `i` in `vertices(B)` order
  vertex_descriptor vertex(std::size_t i) const { return vertices_[i]; }
  /// index (in `vertices(B)` order) of corner `j` of face `i`
  std::size_t corner_vertex_index(std::size_t i, int j) const { return static_cast<std::size_t>(lt_.faces[i].v[j]); }
  /// the stored Poincar&eacute; point of corner `j` of face `i`
  Point_2 corner_point(std::size_t i, int j) const { return Point_2(lt_.faces[i].z[j].real(), lt_.faces[i].z[j].imag()); }
  /// edges whose two sides carry different corner points (sphere type)
  std::size_t number_of_cut_edges() const { return lt_.n_cut_edges; }
  /// mesh border edges (disk type), glued to themselves by the reflection in a tile side
  std::size_t number_of_border_edges() const { return lt_.n_border_edges; }
  /// faces not positively oriented (exact test): zero for a bijective embedding
  std::size_t number_of_inverted_faces() const { return lt_.n_inverted; }
  /// @}

  /// the Poincar&eacute; point of face `i` with barycentric coordinates `b` (combination of its corners)
  Point_2 disk_point(std::size_t i, const std::array<double, 3>& b) const
  {
    const internal::Lifted_face& F = lt_.faces[i];
    for(int j = 0; j < 3; ++j)
      if(b[(j + 1) % 3] == 0.0 && b[(j + 2) % 3] == 0.0)
        return Point_2(F.z[j].real(), F.z[j].imag()); // a corner: its own point, bitwise
    C k;
    double s = 0;
    for(int j = 0; j < 3; ++j) {
      // Klein weights: the coordinates themselves, or lambda_j / w_j (hyperboloid)
      const double mu = (lt_.model == Klein_linear) ? b[j] : b[j] / internal::hyperboloid_weight(F.z[j]);
      k += mu * internal::poincare_to_klein(F.z[j]);
      s += mu;
    }
    const C z = internal::klein_to_poincare(k / s);
    return Point_2(z.real(), z.imag());
  }
  /// the Poincar&eacute; point of a location
  Point_2 disk_point(const Location& l) const { return disk_point(l.face_index, l.barycentric); }

  /// locates `z` (Poincar&eacute; coordinates, \f$|z| < 1\f$)
  Location locate(const Point_2& z) const
  {
    Location loc;
    if(!lt_.valid || lt_.faces.empty())
      return loc;
    const C z0(CGAL::to_double(z.x()), CGAL::to_double(z.y()));
    if(!(internal::squared_modulus(z0) < 1.0) || !std::isfinite(z0.real()) || !std::isfinite(z0.imag()))
      return loc;
    // a corner's point, bitwise (before reduction: a vertex of B outside the tile is found too),
    // not in a chart (where the tile points are rounded: the charts hold the embedding)
    if(lt_.corner_hit(z0, Isometry(), loc) && face_chart(loc.face_index) < 0)
      return with_face(loc);
    const typename Tile::Reduction r = lt_.tile.reduce_to_tile(Point_2(z0.real(), z0.imag()));
    const C q(CGAL::to_double(r.point.x()), CGAL::to_double(r.point.y()));
    if(lt_.corner_hit(q, r.element, loc) && face_chart(loc.face_index) < 0)
      return with_face(loc);
    loc = Location();
    // near a chart's origin: among its faces, in its coordinates (a cone's tile corner is its
    // chart's origin exactly: applying the chart to it would leave rounding noise, far larger
    // than the faces around the cone there)
    for(std::size_t c = 0; c < ch_.charts.size(); ++c) {
      const Point_2& corner = lt_.tile.corner(ch_.chart_corner[c]);
      const C w = (q == C(CGAL::to_double(corner.x()), CGAL::to_double(corner.y()))) ? C(0, 0) : ch_.charts[c].apply(q);
      if(2 * std::atanh((std::min)(std::abs(w), 1 - 1e-16)) <= ch_.reach[c] && locate_in_chart(static_cast<int>(c), w, loc)) {
        loc.element = loc.element * r.element;
        return with_face(loc);
      }
    }

    const int start = lt_.grid.start_face(q);
    Isometry h;
    if(internal::walk_to(lt_, q, start, loc, h)) {
      loc.element = h.inverse() * r.element;
      return with_face(loc);
    }
    // safety net
    const std::size_t steps = loc.steps;
    loc = Location();
    internal::search_lifted(lt_, q, start, loc, h);
    loc.steps += steps;
    loc.used_search = true;
    loc.element = h.inverse() * r.element;
    return with_face(loc);
  }

  /// locates `z` by a walk from `near`, the location of a point close to `z` (for example the
  /// same point before a small move): the face found is the one `locate(z)` finds (the element
  /// may differ by rounding), in fewer steps. Falls back to `locate(z)` when `near` is not a
  /// success, the embedding has charts, or the walk fails a check.
  Location locate_near(const Point_2& z, const Location& near) const
  {
    if(!near.success || near.face_index == npos || !ch_.charts.empty())
      return locate(z);
    const C z0(CGAL::to_double(z.x()), CGAL::to_double(z.y()));
    if(!(internal::squared_modulus(z0) < 1.0) || !std::isfinite(z0.real()) || !std::isfinite(z0.imag()))
      return locate(z);
    Location loc;
    Isometry h;
    if(internal::walk_to(lt_, near.element.apply(z0), static_cast<int>(near.face_index), loc, h)) {
      loc.element = h.inverse() * near.element;
      return with_face(loc);
    }
    return locate(z);
  }

  /// locates the point whose coordinates in the frame `chart` (an isometry applied to the tile's
  /// coordinates, such as a chart of another embedding of the same orbifold) are `w`: in this
  /// embedding's chart with the same isometry if it has one, else at `chart^-1(w)` (rounded to
  /// `double`). With charts centred at one cone's image in two embeddings, the points of a
  /// protrusion converging onto it are located at their own scale.
  Location locate(const Point_2& w, const Isometry& chart) const
  {
    Location loc;
    const C w0(CGAL::to_double(w.x()), CGAL::to_double(w.y()));
    if(!lt_.valid || lt_.faces.empty() || !(internal::squared_modulus(w0) < 1.0) || !std::isfinite(w0.real()) ||
       !std::isfinite(w0.imag()))
      return loc;
    const int c = ch_.chart_of(chart);
    if(c >= 0 && locate_in_chart(c, w0, loc))
      return with_face(loc);
    C z = chart.inverse().apply(w0);
    if(w0 == C(0, 0)) // a cone: its tile corner exactly (this embedding holds the cone there)
      for(const Point_2& corner : lt_.tile.corners()) {
        const C k(CGAL::to_double(corner.x()), CGAL::to_double(corner.y()));
        if(std::abs(k - z) < 1e-12)
          z = k;
      }
    return locate(Point_2(z.real(), z.imag()));
  }

  /// locates `z` with the fallback search only (for testing it; much slower than `locate()`)
  Location locate_by_search(const Point_2& z) const
  {
    Location loc;
    if(!lt_.valid || lt_.faces.empty())
      return loc;
    const typename Tile::Reduction r = lt_.tile.reduce_to_tile(z);
    const C q(CGAL::to_double(r.point.x()), CGAL::to_double(r.point.y()));
    Isometry h;
    internal::search_lifted(lt_, q, lt_.grid.start_face(q), loc, h);
    loc.used_search = true;
    loc.element = h.inverse() * r.element;
    return with_face(loc);
  }

private:
  // the faces in charts, then the tile's
  // the signature of `k` cones of angle pi (sphere type) or corners of angle pi/2 (disk type)
  static Orbifold_signature regular_signature(Orbifold_type type, int k)
  {
    return type == Sphere_type ? Orbifold_signature::sphere(k) : Orbifold_signature::disk(k);
  }

  // the interpolation model, and the tile of `signature`; false (the locator failed, saying
  // why) when it has none
  bool set_up_tile(const Orbifold_signature& signature, Interpolation_model model, Tile& tile)
  {
    lt_.model = model;
    if(make_orbifold_tile(signature, tile) == OK)
      return true;
    bool regular = signature.genus() == 0; // (genus g >= 1: the cut graph's tile, given as a tile)
    for(int i = 0; i < signature.number_of_cones(); ++i)
      regular = regular && signature.order(i) == 2;
    lt_.fail(regular ? "the orbifold with " + std::to_string(signature.number_of_cones()) + " cones is not hyperbolic"
                     : std::string("the orbifold of the signature has no tile (not hyperbolic, or not built)"));
    return false;
  }

  template <class HalfedgeChartMap>
  void build_with_charts(const TriangleMesh& tm, HalfedgeUVMap uv, HalfedgeChartMap chart_map,
                         const std::vector<Isometry>& charts, const Tile& tile)
  {
    if(charts.empty()) {
      build(tm, uv, tile);
      return;
    }
    // the faces in charts (faces(tm) order), with their corners in their charts
    ch_.charts = charts;
    for(const Isometry& m : charts) { // the tile corner at each chart's origin: the nearest one
      const C o = m.inverse().apply(C(0, 0));
      int best = 0;
      for(int i = 1; i < tile.number_of_corners(); ++i)
        if(internal::hyperbolic_proximity(o, lt_.to_c(tile.corner(i))) < internal::hyperbolic_proximity(o, lt_.to_c(tile.corner(best))))
          best = i;
      ch_.chart_corner.push_back(best);
    }
    for(face_descriptor f : faces(tm)) {
      const halfedge_descriptor h0 = halfedge(f, tm);
      const halfedge_descriptor hs[3] = {h0, next(h0, tm), next(next(h0, tm), tm)};
      int c = -1;
      for(int j = 0; j < 3; ++j) {
        const auto cp = get(chart_map, hs[j]);
        if(cp.chart < -1 || cp.chart >= static_cast<int>(charts.size())) {
          lt_.fail("a corner's chart is not one of the charts");
          return;
        }
        c = cp.chart >= 0 ? cp.chart : c;
      }
      std::array<C, 3> z;
      if(c >= 0)
        for(int j = 0; j < 3; ++j) {
          const auto p = chart_coordinates(charts, c, get(chart_map, hs[j]), get(uv, hs[j]));
          z[j] = C(CGAL::to_double(p.x()), CGAL::to_double(p.y()));
        }
      ch_.face_chart.push_back(c);
      ch_.z.push_back(z);
    }
    ch_.build(tile);
    // (the faces in charts stay in the tile's walk: their rounded corners there are far from
    // the points located in the tile, which the charts answer near their origins)
    build(tm, uv, tile);
    if(!lt_.valid)
      return;
    // inverted faces: those of the tile's coordinates, and those of the charts in theirs
    lt_.n_inverted = 0;
    for(std::size_t i = 0; i < faces_.size(); ++i) {
      const C* z = ch_.face_chart[i] >= 0 ? ch_.z[i].data() : lt_.faces[i].z;
      lt_.n_inverted += lt_.orient(z[0], z[1], z[2]) > 0 ? 0 : 1;
    }
    lt_.message = lt_.n_inverted == 0 ? std::string()
                                      : std::to_string(lt_.n_inverted) + " faces are not positively oriented: the embedding is not bijective";
  }


  void build(const TriangleMesh& tm, HalfedgeUVMap uv, const Tile& tile)
  {
    lt_.reset(tile, num_vertices(tm));
    internal::Face_halfedges<TriangleMesh> fhs(tm);
    if(internal::read_lifted_faces(tm, uv, lt_, fhs, faces_, vertices_) && internal::link_lifted_faces(tm, fhs, lt_))
      lt_.place_start_points();
  }

  // w among the faces of chart c, or across a side at its corner (an exact rotation into
  // another chart of the cone); loc.element maps the point into the face (tile coordinates)
  bool locate_in_chart(int c, const C& w, Location& loc) const
  {
    auto orient = [&](const C& a, const C& b, const C& p) { return lt_.orient(a, b, p); };
    int nearest = -1, nearest_chart = -1;
    double nearest_min = -std::numeric_limits<double>::infinity();
    Isometry nearest_rot;
    int f = -1, d = c;
    Isometry rot;
    for(std::size_t i = 0; f < 0 && i <= ch_.across[c].size(); ++i) {
      d = i == 0 ? c : ch_.across[c][i - 1].first;
      rot = i == 0 ? Isometry() : ch_.across[c][i - 1].second;
      const double before = nearest_min;
      f = ch_.find(d, rot.apply(w), orient, &nearest, &nearest_min);
      if(nearest_min > before) {
        nearest_chart = d;
        nearest_rot = rot;
      }
    }
    if(f < 0) { // just outside every face (rounding): the nearest one, if within rounding
      if(nearest < 0 || !(nearest_min > -1e-9))
        return false;
      f = nearest;
      d = nearest_chart;
      rot = nearest_rot;
    }
    loc = Location();
    loc.face_index = static_cast<std::size_t>(f);
    loc.barycentric = ch_.barycentric(f, rot.apply(w), lt_.model, loc.min_raw_barycentric);
    loc.element = ch_.charts[d].inverse() * rot * ch_.charts[c];
    loc.success = true;
    loc.steps = 1;
    return true;
  }

  // the internal code fills the face's index only
  Location& with_face(Location& loc) const
  {
    if(loc.face_index != npos)
      loc.face = faces_[loc.face_index];
    return loc;
  }

  internal::Lifted_triangulation<Traits> lt_;
  internal::Chart_faces ch_; // (empty: no charts)
  std::vector<face_descriptor> faces_;
  std::vector<vertex_descriptor> vertices_;
};

} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_EMBEDDING_LOCATOR_H
