// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_LOCATOR_LOCATOR_CHARTS_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_LOCATOR_LOCATOR_CHARTS_H

#include <CGAL/Hyperbolic_orbifold_Tutte/Hyperbolic_isometry_2.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/interpolation_model.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/core/disk_models.h>

#include <array>
#include <cmath>
#include <complex>
#include <map>
#include <utility>
#include <vector>

// Point location among the faces of an embedding that are written in charts around cone
// images (Chart_point.h): per chart, its faces indexed by the binary logarithm of their
// corners' distances to the origin (a protrusion's faces are spread over hundreds of
// orders of magnitude there, a ring of them per order or so), each candidate tested with
// the exact orientation predicate in the chart's coordinates. A point just across a tile
// side near a cone is tried again in the chart across (the side pairing between two charts
// of one cone is an exact rotation about the origin).

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {
namespace internal {

struct Chart_faces
{
  typedef std::complex<double> C;
  typedef Hyperbolic_isometry_2<double> Isometry;

  std::vector<Isometry> charts;
  std::vector<int> chart_corner;               // per chart: the tile corner at its origin
  std::vector<int> face_chart;                 // per face: its chart, or -1
  std::vector<std::array<C, 3> > z;            // per face: its corners in its chart
  std::vector<double> reach;                   // per chart: the farthest corner (hyperbolic distance to the origin)
  std::vector<double> rmax;                    // per face: its farthest corner's modulus
  std::vector<std::map<int, std::vector<int> > > buckets; // per chart: faces by floor(log2 |w|)
  std::vector<std::vector<int> > near_origin;  // per chart: faces at or around the origin
  std::vector<std::vector<std::pair<int, Isometry> > > across; // per chart: (chart, rotation) across its sides

  bool empty() const { return charts.empty(); }

  int chart_of(const Isometry& m) const
  {
    for(std::size_t c = 0; c < charts.size(); ++c)
      if(charts[c].a() == m.a() && charts[c].b() == m.b() && charts[c].is_orientation_preserving() == m.is_orientation_preserving())
        return static_cast<int>(c);
    return -1;
  }

  // the index, after face_chart and z are filled; `tile` gives the side pairings
  template <class Tile>
  void build(const Tile& tile)
  {
    const int nch = static_cast<int>(charts.size());
    reach.assign(nch, 0.0);
    buckets.assign(nch, std::map<int, std::vector<int> >());
    near_origin.assign(nch, std::vector<int>());
    rmax.assign(face_chart.size(), 0.0);
    for(std::size_t f = 0; f < face_chart.size(); ++f) {
      const int c = face_chart[f];
      if(c < 0)
        continue;
      double rmin = 1, diam = 0;
      for(int j = 0; j < 3; ++j) {
        const double r = std::abs(z[f][j]);
        rmin = (std::min)(rmin, r);
        rmax[f] = (std::max)(rmax[f], r);
        diam = (std::max)(diam, std::abs(z[f][j] - z[f][(j + 1) % 3]));
        reach[c] = (std::max)(reach[c], 2 * std::atanh((std::min)(r, 1 - 1e-16)));
      }
      // the farthest point of a geodesic triangle from the origin is a corner; the nearest one
      // is no nearer than the nearest corner less the triangle's (Euclidean) diameter, unless the
      // triangle is about as large as its distance to the origin
      const double low = rmin - 2 * diam;
      if(!(low > 0)) {
        near_origin[c].push_back(static_cast<int>(f));
        continue;
      }
      for(int b = std::ilogb(low); b <= std::ilogb(rmax[f]); ++b)
        buckets[c][b].push_back(static_cast<int>(f));
    }
    // around each chart's cone: its rotations about the origin (2 pi j / p for a cone of
    // order p: the embedding's faces around the cone need not fill the tile's corner, only
    // the cone's angle with the other corners of the cone), and the side pairings into the
    // charts of its other corners, after them
    across.assign(nch, std::vector<std::pair<int, Isometry> >());
    for(int c = 0; c < nch; ++c) {
      const int corner = chart_corner.empty() ? -1 : chart_corner[c];
      const int p = corner < 0 ? 1 : tile.signature().order(tile.corner_cone(corner));
      std::vector<Isometry> turns;
      for(int j = 0; j < p; ++j)
        turns.push_back(Isometry(std::polar(1.0, CGAL_PI * j / p), C(0, 0)));
      for(int j = 1; j < p; ++j)
        across[c].emplace_back(c, turns[j]);
      for(int s = 0; s < tile.number_of_sides(); ++s)
        for(const Isometry& g : {tile.side_pairing(s), tile.side_pairing(s).inverse()})
          for(int d = 0; d < nch; ++d) {
            if(d == c)
              continue;
            Isometry m = charts[d] * g * charts[c].inverse();
            if(!(std::abs(m.apply(C(0, 0))) < 1e-8))
              continue; // g does not take c's corner to d's
            m = Isometry(m.a() / std::abs(m.a()), C(0, 0)); // exact rotation (as the solver's seam twins)
            for(const Isometry& t : turns)
              across[c].emplace_back(d, m * t);
          }
    }
  }

  // the face of chart c containing w (exact test in the chart's coordinates), or -1; `orient`
  // is the exact orientation of three points (positive: 1). `nearest`: the candidate whose
  // smallest barycentric coordinate of w is the largest, and that coordinate (for a point
  // just outside every face, by rounding)
  template <class Orient>
  int find(int c, const C& w, const Orient& orient, int* nearest = nullptr, double* nearest_min = nullptr) const
  {
    // (a geodesic triangle's points are no farther from the origin than its farthest corner:
    // the faces nearer the origin than w are not tested)
    const double r = std::abs(w) * (1 - 1e-12);
    auto inside = [&](int f) {
      const auto& t = z[f];
      if(r > rmax[f])
        return false;
      if(nearest) {
        const std::array<double, 3> l = klein_barycentric(t[0], t[1], t[2], w);
        const double m = (std::min)(l[0], (std::min)(l[1], l[2]));
        if(m == m && m > *nearest_min) {
          *nearest_min = m;
          *nearest = f;
        }
      }
      return orient(t[0], t[1], w) >= 0 && orient(t[1], t[2], w) >= 0 && orient(t[2], t[0], w) >= 0;
    };
    if(!(w == C(0, 0))) {
      const auto it = buckets[c].find(std::ilogb(std::abs(w)));
      if(it != buckets[c].end())
        for(int f : it->second)
          if(inside(f))
            return f;
    }
    for(int f : near_origin[c])
      if(inside(f))
        return f;
    return -1;
  }

  // barycentric coordinates of w in face f (its chart's coordinates), clamped and normalised,
  // and the smallest one before clamping
  std::array<double, 3> barycentric(int f, const C& w, Interpolation_model model, double& min_raw) const
  {
    std::array<double, 3> l = klein_barycentric(z[f][0], z[f][1], z[f][2], w);
    for(int j = 0; j < 3; ++j)
      if(w == z[f][j]) {
        l = {{0.0, 0.0, 0.0}};
        l[j] = 1.0;
      }
    if(model == Hyperboloid_linear) {
      double t = 0;
      for(int j = 0; j < 3; ++j) {
        l[j] *= hyperboloid_weight(z[f][j]);
        t += l[j];
      }
      for(int j = 0; j < 3; ++j)
        l[j] /= t;
    }
    if(!(l[0] == l[0] && l[1] == l[1] && l[2] == l[2])) { // (a needle too thin for double: its nearest corner)
      int best = 0;
      for(int j = 1; j < 3; ++j)
        if(std::abs(z[f][j] - w) < std::abs(z[f][best] - w))
          best = j;
      l = {{0.0, 0.0, 0.0}};
      l[best] = 1.0;
    }
    min_raw = (std::min)(l[0], (std::min)(l[1], l[2]));
    double s = 0;
    for(int j = 0; j < 3; ++j) {
      l[j] = l[j] > 0 ? l[j] : 0.0;
      s += l[j];
    }
    for(int j = 0; j < 3; ++j)
      l[j] /= s;
    return l;
  }
};

} // namespace internal
} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_LOCATOR_LOCATOR_CHARTS_H
