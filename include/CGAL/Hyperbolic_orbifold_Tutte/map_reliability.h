// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_MAP_RELIABILITY_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_MAP_RELIABILITY_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Hyperbolic_orbifold_Tutte/Embedding_locator.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/Hyperbolic_isometry_2.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/surface_maps.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/dense_index.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstddef>
#include <limits>
#include <vector>

/// \file map_reliability.h
/// Which vertices of a surface map cannot be trusted: the squeezed regions (protrusions
/// without a landmark) that the two embeddings collapse below their own disagreement.

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {

/*!
\ingroup PkgHyperbolicOrbifoldTutteMainClasses

the thresholds of `map_reliability()`.
*/
struct Map_reliability_options
{
  /// a vertex is squeezed when the hyperbolic length of its edges per unit of 3D length is
  /// below this fraction of the mesh's average (the square root of the sum of the squared
  /// hyperbolic edge lengths over the sum of the squared 3D edge lengths)
  double squeeze_ratio = 1e-2;
  /// a squeezed region is unresolved when the distance between the point it collapses to
  /// in the source's embedding, carried to the target, and the point the target's region
  /// collapses to exceeds this many times the larger hyperbolic one-ring size of the two
  /// collapse vertices (below it the two differ by about a triangle: an ordinary offset)
  double noise_factor = 4;
  /// in an unresolved region, a vertex is unreliable when its uncertainty (how far its
  /// image on the target moves when the two collapse points are made to correspond)
  /// exceeds this fraction of the target's bounding-box diagonal
  double error_fraction = 0.01;
};

/*!
\ingroup PkgHyperbolicOrbifoldTutteMainClasses

a squeezed region of the source mesh and what `map_reliability()` found out about it. Vertex
numbers are positions in `vertices(A)` and `vertices(B)` order.
*/
struct Squeezed_region
{
  std::size_t number_of_vertices = 0; ///< the squeezed vertices of the region in `A`
  std::size_t source_vertex = 0;      ///< the vertex of `A` it collapses to (a landmark if it holds one, else the most squeezed)
  std::size_t target_vertex = 0;      ///< the same for the region of `B` where the map sends it (not for a region at a landmark)
  bool at_landmark = false;           ///< the region of `A` holds a landmark: both embeddings collapse onto its cone (not flagged)
  double discrepancy = 0;             ///< hyperbolic distance between the image of `source_vertex` and `target_vertex` in `B`'s embedding
  double source_size = 0;             ///< hyperbolic one-ring size of `source_vertex` in `A`'s embedding
  double target_size = 0;             ///< hyperbolic one-ring size of `target_vertex` in `B`'s embedding
  bool unresolved = false;            ///< `discrepancy` exceeds `noise_factor` times the larger size
  std::size_t unreliable_vertices = 0; ///< the vertices flagged in this region
};

/*!
\ingroup PkgHyperbolicOrbifoldTutteMainClasses

the answer of `map_reliability()`.
*/
struct Map_reliability
{
  /// the vertices of `A` whose image cannot be trusted, as positions in `vertices(A)` order, increasing
  std::vector<std::size_t> unreliable_vertices;
  /// the squeezed regions of `A` (connected sets of squeezed vertices)
  std::vector<Squeezed_region> regions;
  /// per vertex of `A`, in `vertices(A)` order, its uncertainty (a length on `B`, see
  /// `map_reliability()`) if it was checked: the flagged vertices and their neighbours; zero
  /// for the others
  std::vector<double> uncertainty;
};

namespace internal {

// the scale of one embedding: per vertex (vertices() order) the conformal factor rho (the
// hyperbolic length of its edges per unit of 3D length, root mean square over the edges of
// its faces) and the hyperbolic one-ring size (its longest edge); the squeezed regions
// (components of rho < squeeze_ratio x mean), and which of their vertices are cones (a
// corner at a corner of the tile)
template <class TriangleMesh>
struct Embedding_scale
{
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename GT::vertex_descriptor vertex_descriptor;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  typedef typename GT::face_descriptor face_descriptor;

  std::vector<vertex_descriptor> verts;
  Dense_index<vertex_descriptor> index;
  std::vector<double> rho, size;
  std::vector<char> cone;
  std::vector<std::size_t> region;    // region of each squeezed vertex (npos: not squeezed)
  std::vector<std::size_t> collapse;  // per region: the cone in it, else its vertex of least rho
  std::vector<std::size_t> region_size;
  static constexpr std::size_t npos = static_cast<std::size_t>(-1);

  template <class HalfedgeUVMap, class VertexPointMap, class Locator>
  Embedding_scale(const TriangleMesh& tm, HalfedgeUVMap uv, VertexPointMap vpm, const Locator& loc, double squeeze_ratio)
    : index(vertices(tm))
  {
    typedef typename Locator::Point_2 Point_2;
    const auto distance = typename Locator::Traits().compute_hyperbolic_distance_2_object();
    auto point = [&](halfedge_descriptor h) {
      const auto p = get(uv, h);
      return Point_2(CGAL::to_double(p.x()), CGAL::to_double(p.y()));
    };
    for(vertex_descriptor v : vertices(tm))
      verts.push_back(v);
    const std::size_t n = verts.size();
    rho.assign(n, std::numeric_limits<double>::infinity());
    size.assign(n, 0.0);
    cone.assign(n, 0);
    // per vertex and face, the edge from the previous corner (each edge of a vertex once)
    std::vector<double> sh(n, 0.0), s3(n, 0.0);
    for(face_descriptor f : faces(tm)) {
      halfedge_descriptor h = halfedge(f, tm);
      Point_2 p = point(h);
      const halfedge_descriptor first = h;
      do {
        const halfedge_descriptor g = next(h, tm);
        const Point_2 q = point(g);
        const std::size_t i = index(target(g, tm));
        const double dh = CGAL::to_double(distance(p, q));
        sh[i] += dh * dh;
        s3[i] += CGAL::to_double(CGAL::squared_distance(get(vpm, target(g, tm)), get(vpm, target(h, tm))));
        size[i] = (std::max)(size[i], dh);
        h = g;
        p = q;
      } while(h != first);
    }
    double total_h = 0, total_3 = 0;
    for(std::size_t i = 0; i < n; ++i)
      if(s3[i] > 0 && std::isfinite(sh[i])) {
        rho[i] = std::sqrt(sh[i] / s3[i]);
        total_h += sh[i];
        total_3 += s3[i];
      }
    const double threshold = squeeze_ratio * (total_3 > 0 ? std::sqrt(total_h / total_3) : 0.0);
    region.assign(n, npos);
    std::vector<std::size_t> stack;
    for(std::size_t i = 0; i < n; ++i) {
      if(region[i] != npos || !(rho[i] < threshold))
        continue;
      const std::size_t r = collapse.size();
      collapse.push_back(i);
      region_size.push_back(0);
      region[i] = r;
      stack.assign(1, i);
      while(!stack.empty()) {
        const std::size_t j = stack.back();
        stack.pop_back();
        ++region_size[r];
        // a cone: a corner at a corner of the tile (landmarks are placed there exactly)
        for(halfedge_descriptor h : halfedges_around_target(halfedge(verts[j], tm), tm))
          if(!is_border(h, tm))
            for(int c = 0; c < loc.tile().number_of_corners(); ++c)
              if(point(h) == loc.tile().corner(c))
                cone[j] = 1;
        std::size_t& c = collapse[r];
        if(!cone[c] && (cone[j] || rho[j] < rho[c]))
          c = j;
        for(vertex_descriptor w : vertices_around_target(halfedge(verts[j], tm), tm)) {
          const std::size_t k = index(w);
          if(region[k] == npos && rho[k] < threshold) {
            region[k] = r;
            stack.push_back(k);
          }
        }
      }
    }
  }

  bool squeezed(std::size_t i) const { return region[i] != npos; }

  // from vertex i downhill in rho (to the neighbour of least rho) until a squeezed vertex or
  // a local minimum; returns the collapse vertex of that squeezed region, or the minimum
  std::size_t descend(const TriangleMesh& tm, std::size_t i) const
  {
    while(!squeezed(i)) {
      const halfedge_descriptor h0 = halfedge(verts[i], tm);
      if(h0 == GT::null_halfedge())
        return i;
      std::size_t best = i;
      for(vertex_descriptor w : vertices_around_target(h0, tm)) {
        const std::size_t k = index(w);
        if(rho[k] < rho[best])
          best = k;
      }
      if(best == i)
        return i;
      i = best;
    }
    return collapse[region[i]];
  }
};

} // namespace internal

/*!
\ingroup PkgHyperbolicOrbifoldTutteHelperFunctions

finds the vertices of `A` whose image under the vertex map `locations` (computed by
`map_vertices(A, uvA, locB)`) cannot be trusted, from the two embeddings alone.

A protrusion without a landmark is squeezed by the embedding exponentially with its length
(a tube of radius 1 by a factor e per unit of length) onto a point of the disk. The two
embeddings squeeze corresponding protrusions onto slightly different points; where the
images of `A`'s vertices are closer to their collapse point than the two collapse points
are to each other, the map cannot resolve them: it sends them all to about one place of
`B` (for a tube, one ring near its base). The criterion:

1. In each embedding, the conformal factor of a vertex is the hyperbolic length of its
   edges per unit of their 3D length (root mean square over the edges of its faces); a
   vertex is squeezed when that is below `options.squeeze_ratio` times the mesh's average.
   The squeezed regions are the connected sets of squeezed vertices. A region collapses
   onto a landmark's cone if it holds a landmark (a vertex with a corner at a corner of
   the tile), otherwise onto its vertex of least conformal factor.
2. For each squeezed region of `A` that holds no landmark (both embeddings collapse a region
   with a landmark onto the same cone, exactly, and it is not checked further): the image in
   `B`'s embedding of its collapse vertex, the squeezed region of `B` that image lies in (if
   it is in none, the first squeezed region, or local minimum, reached by walking down `B`'s
   conformal factor from it), and that region's collapse vertex. The discrepancy
   \f$\delta\f$ is the hyperbolic distance between the two points. The region is unresolved
   when \f$\delta\f$ exceeds `options.noise_factor` times the larger hyperbolic one-ring
   size of the two collapse vertices (otherwise the embeddings agree there up to about a
   triangle).
3. In an unresolved region, the uncertainty of a vertex is how far (in 3D, on `B`) its
   image moves when the isometry of the disk that takes the image of `A`'s collapse point
   onto `B`'s (a translation by \f$\delta\f$, no rotation there) is applied to it before
   it is located: the map that makes the two collapse points correspond against the one
   computed. For a vertex far from the collapse point that is \f$\delta\f$ over its
   conformal factor; the vertices closer to it than \f$\delta\f$ are sent near `B`'s collapse
   point instead of a ring near the base. The vertices whose uncertainty exceeds
   `options.error_fraction` times `B`'s bounding-box diagonal are flagged, found from the
   collapse vertex outwards along the edges (the neighbours of a flagged vertex are checked).

On a capsule mapped onto a bent copy of itself without a landmark at its tip, the
uncertainty of the flagged vertices is within a few percent of their actual error (vertex
`i` corresponds to vertex `i`); see the manual for the measurements. Limits: a protrusion
with a landmark part way along it and none at its tip counts as collapsing onto that
landmark's cone and is not flagged; protrusions joined through a squeezed part form one
region, and only its deepest point is checked; where the collapse vertex of `B` lies on the
cut, the discrepancy is measured to the nearest of its corners; the uncertainty assumes that
the two collapse points correspond (the tips of two protrusions of different lengths do, but
a protrusion that has no counterpart on `B` is judged against whatever region its tip is
sent to); errors of the map that have other causes (a large deformation between `A` and
`B`) are not estimated.

\tparam TriangleMeshA a model of `FaceGraph` and `VertexListGraph`
\tparam HalfedgeUVMapA a model of `ReadablePropertyMap` from the halfedges of `A` to a point type with `x()` and `y()`
\tparam TriangleMeshB a model of `FaceGraph` and `VertexListGraph`
\tparam HalfedgeUVMapB the same for `B`
\tparam Locator the `Embedding_locator` of `B` built from `uvB`
\tparam NamedParametersA a sequence of named parameters for `A`
\tparam NamedParametersB a sequence of named parameters for `B`

\param A the source mesh
\param uvA its embedding (per-corner map written by `hyperbolic_orbifold_Tutte_embedding()`)
\param B the target mesh
\param uvB its embedding, into the same orbifold with corresponding landmarks
\param locB the locator of `uvB`
\param locations the vertex map, `map_vertices(A, uvA, locB)`
\param options the thresholds
\param npA named parameters for `A`: `vertex_point_map` (default `get(CGAL::vertex_point, A)`)
\param npB named parameters for `B`: `vertex_point_map` (default `get(CGAL::vertex_point, B)`)

\pre `locations` has one location per vertex of `A` and `locB` is a valid locator of `uvB`
     (otherwise the result is empty)

\return the unreliable vertices, the squeezed regions and the uncertainties. Linear in the
        sizes of `A` and `B`, plus a point location per vertex checked; vertices that were not
        located are not flagged (their location says so).
*/
template <class TriangleMeshA, class HalfedgeUVMapA, class TriangleMeshB, class HalfedgeUVMapB, class Locator,
          class NamedParametersA = CGAL::parameters::Default_named_parameters,
          class NamedParametersB = CGAL::parameters::Default_named_parameters>
Map_reliability map_reliability(const TriangleMeshA& A, HalfedgeUVMapA uvA, const TriangleMeshB& B, HalfedgeUVMapB uvB,
                                const Locator& locB, const std::vector<typename Locator::Location>& locations,
                                const Map_reliability_options& options = Map_reliability_options(),
                                const NamedParametersA& npA = CGAL::parameters::default_values(),
                                const NamedParametersB& npB = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef typename boost::graph_traits<TriangleMeshA>::vertex_descriptor vertex_descriptor_A;
  typedef typename boost::graph_traits<TriangleMeshB>::halfedge_descriptor halfedge_descriptor_B;
  typedef typename Locator::Point_2 Point_2;
  typedef Hyperbolic_isometry_2<double> Isometry;
  typedef std::complex<double> C;

  Map_reliability result;
  const auto vpmA = choose_parameter(get_parameter(npA, CGAL::internal_np::vertex_point), get_const_property_map(vertex_point, A));
  const auto vpmB = choose_parameter(get_parameter(npB, CGAL::internal_np::vertex_point), get_const_property_map(vertex_point, B));
  const internal::Embedding_scale<TriangleMeshA> a(A, uvA, vpmA, locB, options.squeeze_ratio);
  const internal::Embedding_scale<TriangleMeshB> b(B, uvB, vpmB, locB, options.squeeze_ratio);
  result.uncertainty.assign(a.verts.size(), 0.0);
  if(locations.size() != a.verts.size() || !locB.is_valid())
    return result;

  CGAL::Bbox_3 box;
  for(typename boost::graph_traits<TriangleMeshB>::vertex_descriptor v : vertices(B))
    box += get(vpmB, v).bbox();
  const double diagonal = std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin()) +
                                    CGAL::square(box.zmax() - box.zmin()));
  const double max_uncertainty = options.error_fraction * diagonal;
  const auto distance = typename Locator::Traits().compute_hyperbolic_distance_2_object();

  std::vector<char> flagged(a.verts.size(), 0), visited(a.verts.size(), 0);
  std::vector<std::size_t> stack, seen;
  for(std::size_t r = 0; r < a.collapse.size(); ++r) {
    Squeezed_region region;
    region.number_of_vertices = a.region_size[r];
    region.source_vertex = a.collapse[r];
    region.source_size = a.size[region.source_vertex];
    region.at_landmark = a.cone[region.source_vertex] != 0;
    const typename Locator::Location& l = locations[region.source_vertex];
    if(region.at_landmark || !l.success) {
      result.regions.push_back(region);
      continue;
    }
    // the region of B the collapse vertex's image lies in, and where that region collapses
    std::size_t landing = 0;
    for(int j = 1; j < 3; ++j)
      if(l.barycentric[j] > l.barycentric[landing])
        landing = static_cast<std::size_t>(j);
    region.target_vertex = b.descend(B, locB.corner_vertex_index(l.face_index, static_cast<int>(landing)));
    region.target_size = b.size[region.target_vertex];
    const Point_2 image = locB.disk_point(l);
    region.discrepancy = std::numeric_limits<double>::infinity();
    C target;
    for(halfedge_descriptor_B h : halfedges_around_target(halfedge(b.verts[region.target_vertex], B), B))
      if(!is_border(h, B)) {
        const auto p = get(uvB, h);
        const C q(CGAL::to_double(p.x()), CGAL::to_double(p.y()));
        const double d = CGAL::to_double(distance(image, Point_2(q.real(), q.imag())));
        if(d < region.discrepancy) {
          region.discrepancy = d;
          target = q;
        }
      }
    region.unresolved = region.discrepancy > options.noise_factor * (std::max)(region.source_size, region.target_size);
    if(region.unresolved) {
      // the isometry that moves the image of A's collapse point onto B's, applied to the
      // image of each vertex: how far on B its image moves (from the collapse vertex
      // outwards, through the vertices that move too far)
      const C from(CGAL::to_double(image.x()), CGAL::to_double(image.y()));
      const Isometry to_origin = Isometry::translation_to_origin(from), to_target = Isometry::translation_from_origin(target);
      auto uncertainty = [&](std::size_t i) {
        if(!locations[i].success)
          return 0.0;
        const Point_2 z = locB.disk_point(locations[i]);
        const C w = to_target.apply(to_origin.apply(C(CGAL::to_double(z.x()), CGAL::to_double(z.y()))));
        const typename Locator::Location moved = locB.locate(Point_2(w.real(), w.imag()));
        if(!moved.success)
          return std::numeric_limits<double>::infinity();
        return std::sqrt(CGAL::to_double(CGAL::squared_distance(surface_point(locations[i], locB, vpmB), surface_point(moved, locB, vpmB))));
      };
      stack.clear();
      seen.clear();
      auto visit = [&](std::size_t i) {
        visited[i] = 1;
        seen.push_back(i);
        result.uncertainty[i] = (std::max)(result.uncertainty[i], uncertainty(i));
        if(result.uncertainty[i] > max_uncertainty) {
          if(!flagged[i])
            ++region.unreliable_vertices;
          flagged[i] = 1;
          stack.push_back(i);
        }
      };
      visit(region.source_vertex);
      while(!stack.empty()) {
        const std::size_t i = stack.back();
        stack.pop_back();
        for(vertex_descriptor_A w : vertices_around_target(halfedge(a.verts[i], A), A))
          if(!visited[a.index(w)])
            visit(a.index(w));
      }
      for(std::size_t i : seen)
        visited[i] = 0;
    }
    result.regions.push_back(region);
  }
  for(std::size_t i = 0; i < flagged.size(); ++i)
    if(flagged[i])
      result.unreliable_vertices.push_back(i);
  return result;
}

} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_MAP_RELIABILITY_H
