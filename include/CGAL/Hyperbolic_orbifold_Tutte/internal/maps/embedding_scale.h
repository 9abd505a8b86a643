// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_MAPS_EMBEDDING_SCALE_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_MAPS_EMBEDDING_SCALE_H

// The scale of one embedding (its conformal factor, squeezed regions and rounding), measured
// by map_reliability() on both embeddings of a map.

#include <CGAL/disable_warnings.h>


#include <CGAL/Hyperbolic_orbifold_Tutte/Hyperbolic_isometry_2.h>
#include <CGAL/Kernel/global_functions.h>     // squared_area, squared_distance (3D)
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/core/dense_index.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstddef>
#include <limits>
#include <vector>

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {
namespace internal {

// the scale of one embedding: per vertex (vertices() order) the conformal factor rho (the
// hyperbolic length of its edges per unit of 3D length, root mean square over the edges of
// its faces) and the hyperbolic one-ring size (its longest edge); the squeezed regions
// (components of rho < squeeze_ratio x mean), and which of their vertices are cones (a
// corner at a corner of the tile); the logarithm of rho smoothed over the one-rings (NaN where
// rho is not resolved), and whether the one-ring is below `rounding_ulps` units in the last
// place of double at the vertex (as a hyperbolic length)
template <class TriangleMesh>
struct Embedding_scale
{
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename GT::vertex_descriptor vertex_descriptor;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  typedef typename GT::face_descriptor face_descriptor;

  std::vector<vertex_descriptor> verts;
  Dense_index<vertex_descriptor> index;
  std::vector<double> rho, size, log_rho;
  double total_area = 0; // the 3D area of the mesh
  std::vector<char> cone, unresolved;
  std::vector<std::size_t> region;    // region of each squeezed vertex (npos: not squeezed)
  std::vector<std::size_t> collapse;  // per region: the cone in it, else its vertex of least rho
  std::vector<std::size_t> region_size;
  static constexpr std::size_t npos = static_cast<std::size_t>(-1);

  template <class HalfedgeUVMap, class VertexPointMap, class Locator>
  Embedding_scale(const TriangleMesh& tm, HalfedgeUVMap uv, VertexPointMap vpm, const Locator& loc, double squeeze_ratio,
                  int smoothing_rounds = 0, double rounding_ulps = 0)
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
    std::vector<double> sh(n, 0.0), s3(n, 0.0), area(n, 0.0), ulp(n, 0.0);
    for(face_descriptor f : faces(tm)) {
      halfedge_descriptor h = halfedge(f, tm);
      Point_2 p = point(h);
      const halfedge_descriptor first = h;
      const double a3 = std::sqrt(CGAL::to_double(CGAL::squared_area(get(vpm, source(h, tm)), get(vpm, target(h, tm)),
                                                                       get(vpm, target(next(h, tm), tm)))));
      total_area += a3;
      do {
        const halfedge_descriptor g = next(h, tm);
        const Point_2 q = point(g);
        const std::size_t i = index(target(g, tm));
        const double dh = CGAL::to_double(distance(p, q));
        sh[i] += dh * dh;
        s3[i] += CGAL::to_double(CGAL::squared_distance(get(vpm, target(g, tm)), get(vpm, target(h, tm))));
        size[i] = (std::max)(size[i], dh);
        area[i] += a3;
        // the spacing of double at q, as a hyperbolic length (the metric 2 |dz| / (1 - |z|^2))
        const double x = CGAL::to_double(q.x()), y = CGAL::to_double(q.y()), r2 = x * x + y * y;
        const double spacing = std::numeric_limits<double>::epsilon() * (std::max)((std::max)(std::abs(x), std::abs(y)), 1e-300);
        ulp[i] = (std::max)(ulp[i], r2 < 1 ? 2 * spacing / (1 - r2) : std::numeric_limits<double>::infinity());
        h = g;
        p = q;
      } while(h != first);
    }
    unresolved.assign(n, 0);
    log_rho.assign(n, std::numeric_limits<double>::quiet_NaN());
    for(std::size_t i = 0; i < n; ++i) {
      unresolved[i] = rounding_ulps > 0 && !(size[i] >= rounding_ulps * ulp[i]);
      if(!unresolved[i] && s3[i] > 0 && sh[i] > 0 && std::isfinite(sh[i]))
        log_rho[i] = 0.5 * std::log(sh[i] / s3[i]);
    }
    for(int round = 0; round < smoothing_rounds; ++round) {
      std::vector<double> smoothed(n, std::numeric_limits<double>::quiet_NaN());
      for(std::size_t i = 0; i < n; ++i) {
        if(std::isnan(log_rho[i]))
          continue;
        double sum = area[i] * log_rho[i], weight = area[i];
        const halfedge_descriptor h0 = halfedge(verts[i], tm);
        if(h0 != GT::null_halfedge())
          for(vertex_descriptor w : vertices_around_target(h0, tm)) {
            const std::size_t k = index(w);
            if(!std::isnan(log_rho[k])) {
              sum += area[k] * log_rho[k];
              weight += area[k];
            }
          }
        smoothed[i] = weight > 0 ? sum / weight : log_rho[i];
      }
      log_rho.swap(smoothed);
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

  // descend(), memoized in `memo` (npos: not known yet) for every vertex of the walk
  std::size_t basin(const TriangleMesh& tm, std::size_t i, std::vector<std::size_t>& memo) const
  {
    if(memo[i] != npos)
      return memo[i];
    std::vector<std::size_t> path;
    std::size_t end = i;
    while(memo[end] == npos && !squeezed(end)) {
      path.push_back(end);
      const halfedge_descriptor h0 = halfedge(verts[end], tm);
      std::size_t best = end;
      if(h0 != GT::null_halfedge())
        for(vertex_descriptor w : vertices_around_target(h0, tm)) {
          const std::size_t k = index(w);
          if(rho[k] < rho[best])
            best = k;
        }
      if(best == end)
        break;
      end = best;
    }
    const std::size_t result = memo[end] != npos ? memo[end] : (squeezed(end) ? collapse[region[end]] : end);
    for(std::size_t j : path)
      memo[j] = result;
    memo[i] = result;
    return result;
  }
};

} // namespace internal

} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_MAPS_EMBEDDING_SCALE_H
