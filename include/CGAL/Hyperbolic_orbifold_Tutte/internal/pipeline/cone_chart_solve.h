// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_PIPELINE_CONE_CHART_SOLVE_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_PIPELINE_CONE_CHART_SOLVE_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Hyperbolic_orbifold_Tutte/Embedding_statistics.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/solver/cone_charts.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/solver/flat_problem.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/solver/newton_on_region.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/solver/orbifold_solver.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/pipeline/recentring.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <map>
#include <utility>
#include <vector>

// The region of the embedding that converges onto cone images, solved again in charts
// centred at them (cone_charts.h): Newton on the region alone, its neighbours held fixed,
// then Newton again on what is still unresolved there, each time at that part's own scale.

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {
namespace internal {

// the most rounds of Newton on the still unresolved part of the charted region
constexpr int max_chart_rounds = 24;

// the hyperbolic distance of two points of the Poincare disk
inline double hyperbolic_distance(const std::complex<double>& a, const std::complex<double>& b)
{
  return 2 * std::asinh(std::sqrt(hyperbolic_proximity(a, b)));
}

// Which cone images the unresolved faces `flag` (per face of P, at the tile positions `uv`)
// converge onto, and the charts of their tile corners: false when some of them are near no
// cone image (a protrusion without landmarks: charts cannot help).
template <class Tile>
bool choose_cone_charts(const Flat_problem& P, const Tile& tile, const std::vector<std::complex<double> >& uv,
                        const std::vector<char>& flag, double& radius, Cone_charts& ch)
{
  typedef std::complex<double> C;
  const int nc = tile.number_of_corners();
  std::vector<C> corner(nc);
  for(int i = 0; i < nc; ++i)
    corner[i] = C(CGAL::to_double(tile.corner(i).x()), CGAL::to_double(tile.corner(i).y()));
  double closest = std::numeric_limits<double>::infinity();
  for(int i = 0; i < nc; ++i)
    for(int j = i + 1; j < nc; ++j)
      closest = (std::min)(closest, hyperbolic_distance(corner[i], corner[j]));
  // a ball around each corner, far from the others: a quarter of the closest two
  radius = (std::min)(1.0, closest / 4);
  std::vector<char> cone(tile.number_of_cones(), 0);
  for(std::size_t f = 0; f < P.faces.size(); ++f) {
    if(!flag[f])
      continue;
    for(int v : P.faces[f]) {
      int near = -1;
      for(int i = 0; i < nc && near < 0; ++i)
        if(hyperbolic_distance(uv[v], corner[i]) < radius)
          near = i;
      if(near < 0)
        return false;
      cone[tile.corner_cone(near)] = 1;
    }
  }
  ch = Cone_charts();
  for(int i = 0; i < nc; ++i)
    if(cone[tile.corner_cone(i)]) {
      ch.chart.push_back(Cone_charts::Isometry::translation_to_origin(corner[i]));
      ch.chart_corner.push_back(i);
    }
  return !ch.empty();
}

// The vertices within `radius` of a chart's corner, each in that chart (cone copies in
// the chart of their own corner), and the seam twins of those: per vertex of P its chart
// or -1.
inline std::vector<int> assign_charts(const Flat_problem& P, const std::vector<std::complex<double> >& uv,
                                      const std::vector<std::complex<double> >& origin,
                                      const std::vector<int>& chart_corner, double radius)
{
  const int nch = static_cast<int>(origin.size());
  std::vector<int> chart_of(P.n, -1);
  auto nearest_chart = [&](int v, double limit) {
    int best = -1;
    double bd = limit;
    for(int c = 0; c < nch; ++c) {
      const double d = hyperbolic_distance(uv[v], origin[c]);
      if(d < bd) {
        bd = d;
        best = c;
      }
    }
    return best;
  };
  for(int v = 0; v < P.n; ++v)
    chart_of[v] = P.corner[v] >= 0 ? -1 : nearest_chart(v, radius);
  for(int v = 0; v < P.n; ++v) // cone copies: in the chart of their own corner
    for(int c = 0; c < nch; ++c)
      if(P.corner[v] == chart_corner[c])
        chart_of[v] = c;
  for(int v = 0; v < P.n; ++v) // a seam copy moves with its twin: both in the region or neither
    if(P.kind[v] == Transformed && (chart_of[v] < 0) != (chart_of[P.twin[v]] < 0)) {
      const int u = chart_of[v] < 0 ? v : P.twin[v];
      chart_of[u] = nearest_chart(u, std::numeric_limits<double>::infinity());
    }
  return chart_of;
}

// build_chart_problem(): the region's vertices in their charts (ch.Q's kinds, fixed points,
// lines, seam transforms): variables `xq` for the owners, then the seam copies
template <class Tile>
void chart_problem_variables(const Flat_problem& P, const Tile& tile, const std::vector<std::complex<double> >& uv,
                             const std::vector<int>& chart_of, Cone_charts& ch, std::vector<double>& xq)
{
  typedef std::complex<double> C;
  typedef Cone_charts::Isometry Isometry;
  Flat_problem& Q = ch.Q;
  xq.clear();
  for(int v = 0; v < P.n; ++v) {
    const int q = ch.region_q[v];
    if(q < 0)
      continue;
    const Isometry& m = ch.chart[chart_of[v]];
    switch(P.kind[v]) {
      case Fixed:
        // a cone copy at its chart's corner is the origin itself
        Q.fixed[q] = P.corner[v] == ch.chart_corner[chart_of[v]] ? C(0, 0) : m.apply(P.fixed[v]);
        break;
      case Free: {
        const C w = m.apply(uv[v]);
        Q.kind[q] = Free;
        Q.var[q] = static_cast<int>(xq.size());
        xq.push_back(w.real());
        xq.push_back(w.imag());
        break;
      }
      case On_line: {
        // the side in the chart: its end at the chart's corner is the origin
        const int s = P.side[v], corner = ch.chart_corner[chart_of[v]];
        C e0 = poincare_to_klein(m.apply(klein_to_poincare(P.line_k0[v])));
        C e1 = poincare_to_klein(m.apply(klein_to_poincare(P.line_k0[v] + P.line_D[v])));
        if(tile.side_target(s) == corner)
          std::swap(e0, e1);
        if(tile.side_source(s) == corner || tile.side_target(s) == corner)
          e0 = C(0, 0);
        Q.kind[q] = On_line;
        Q.line_k0[q] = e0;
        Q.line_D[q] = e1 - e0;
        const C d = poincare_to_klein(m.apply(uv[v])) - e0;
        Q.var[q] = static_cast<int>(xq.size());
        xq.push_back((d.real() * Q.line_D[q].real() + d.imag() * Q.line_D[q].imag()) / squared_modulus(Q.line_D[q]));
        break;
      }
      case Transformed:
        break;
    }
  }
  for(int v = 0; v < P.n; ++v) {
    const int q = ch.region_q[v];
    if(q < 0 || P.kind[v] != Transformed)
      continue;
    const int t = P.twin[v];
    Isometry m = ch.chart[chart_of[v]] * P.transform[v] * ch.chart[chart_of[t]].inverse();
    // between two corners of one cone the pairing fixes the origin: a rotation, kept exact
    if(std::abs(m.apply(C(0, 0))) < 1e-8)
      m = Isometry(m.a() / std::abs(m.a()), C(0, 0));
    Q.kind[q] = Transformed;
    Q.twin[q] = ch.region_q[t];
    Q.transform[q] = m;
  }
}

// The charted region's flat problem (Cone_charts::Q, positions in the charts) and its
// variables `xq`, from P's tile positions `uv`, for the charts `ch.chart` centred at the
// tile corners `ch.chart_corner` and the chart of each vertex `chart_of` (-1: none). False
// when a face or an edge would join two charts, or a seam copy is in a chart and its twin
// is not.
template <class Tile>
bool build_chart_problem(const Flat_problem& P, const Tile& tile, const std::vector<std::complex<double> >& uv,
                         const std::vector<int>& chart_of, Cone_charts& ch, std::vector<double>& xq)
{
  typedef std::complex<double> C;
  typedef Cone_charts::Isometry Isometry;
  for(int v = 0; v < P.n; ++v)
    if(P.kind[v] == Transformed && (chart_of[v] < 0) != (chart_of[P.twin[v]] < 0))
      return false;
  // Q's vertices: the region's (owners of variables first), then fixed copies of outside neighbours
  Flat_problem& Q = ch.Q;
  Q = Flat_problem();
  Q.type = P.type;
  Q.k = P.k;
  Q.n_base = P.n_base;
  ch.region_q.assign(P.n, -1);
  ch.q_source.clear();
  ch.q_chart.clear();
  ch.q_region.clear();
  auto add_vertex = [&](int v, int c, bool region) {
    ch.q_source.push_back(v);
    ch.q_chart.push_back(c);
    ch.q_region.push_back(region ? 1 : 0);
    Q.base.push_back(P.base[v]);
    Q.side.push_back(region ? P.side[v] : -1);
    Q.corner.push_back(region ? P.corner[v] : -1);
    Q.kind.push_back(Fixed);
    Q.var.push_back(-1);
    Q.twin.push_back(-1);
    Q.transform.push_back(Isometry());
    Q.fixed.push_back(C());
    Q.line_k0.push_back(C());
    Q.line_D.push_back(C());
    return Q.n++;
  };
  for(int v = 0; v < P.n; ++v)
    if(chart_of[v] >= 0)
      ch.region_q[v] = add_vertex(v, chart_of[v], true);
  std::map<std::pair<int, int>, int> outside; // (P vertex, chart) -> its fixed copy
  auto q_of = [&](int v, int c) {
    if(ch.region_q[v] >= 0)
      return ch.region_q[v];
    const auto it = outside.find(std::make_pair(v, c));
    if(it != outside.end())
      return it->second;
    const int q = add_vertex(v, c, false);
    Q.fixed[q] = ch.chart[c].apply(uv[v]);
    outside.emplace(std::make_pair(v, c), q);
    return q;
  };
  // faces and edges of the region, each in one chart
  ch.face_chart.assign(P.faces.size(), -1);
  ch.face_q.assign(P.faces.size(), -1);
  for(std::size_t f = 0; f < P.faces.size(); ++f) {
    int c = -1;
    for(int v : P.faces[f])
      if(chart_of[v] >= 0) {
        if(c >= 0 && chart_of[v] != c)
          return false;
        c = chart_of[v];
      }
    if(c < 0)
      continue;
    ch.face_chart[f] = c;
    ch.face_q[f] = static_cast<int>(Q.faces.size());
    Q.faces.push_back({q_of(P.faces[f][0], c), q_of(P.faces[f][1], c), q_of(P.faces[f][2], c)});
  }
  for(std::size_t e = 0; e < P.edges.size(); ++e) {
    const int a = P.edges[e][0], b = P.edges[e][1];
    if(chart_of[a] < 0 && chart_of[b] < 0)
      continue;
    if(chart_of[a] >= 0 && chart_of[b] >= 0 && chart_of[a] != chart_of[b])
      return false;
    const int c = chart_of[a] >= 0 ? chart_of[a] : chart_of[b];
    Q.edges.push_back({q_of(a, c), q_of(b, c)});
    Q.edge_weight.push_back(e < P.edge_weight.size() ? P.edge_weight[e] : 1.0); // (the certifier has no weights)
  }
  // the region's vertices in their charts: variables for the owners, then the seam copies
  chart_problem_variables(P, tile, uv, chart_of, ch, xq);
  Q.n_vars = static_cast<int>(xq.size());
  return true;
}

// the tile corners at the charts' origins
template <class Tile>
std::vector<std::complex<double> > chart_origins(const Tile& tile, const Cone_charts& ch)
{
  std::vector<std::complex<double> > origin;
  for(int i : ch.chart_corner)
    origin.emplace_back(CGAL::to_double(tile.corner(i).x()), CGAL::to_double(tile.corner(i).y()));
  return origin;
}

// The charts of a written embedding, for its certificate: the charts `charts`, each
// centred at the tile corner its origin comes from (the nearest one), the chart of each
// vertex of P `chart_of` and its position there `local`. False when they do not make a
// charted region (see build_chart_problem()).
template <class Tile>
bool charts_of_written_embedding(const Flat_problem& P, const Tile& tile, const std::vector<std::complex<double> >& uv,
                                 const std::vector<Cone_charts::Isometry>& charts, const std::vector<int>& chart_of,
                                 const std::vector<std::complex<double> >& local, Cone_charts& ch)
{
  typedef std::complex<double> C;
  ch = Cone_charts();
  ch.chart = charts;
  for(const auto& m : charts) {
    const C o = m.inverse().apply(C(0, 0));
    int best = 0;
    for(int i = 1; i < tile.number_of_corners(); ++i) {
      const C ci(CGAL::to_double(tile.corner(i).x()), CGAL::to_double(tile.corner(i).y()));
      const C cb(CGAL::to_double(tile.corner(best).x()), CGAL::to_double(tile.corner(best).y()));
      if(hyperbolic_distance(o, ci) < hyperbolic_distance(o, cb))
        best = i;
    }
    ch.chart_corner.push_back(best);
  }
  std::vector<double> xq;
  if(!build_chart_problem(P, tile, uv, chart_of, ch, xq))
    return false;
  ch.q_position.resize(ch.Q.n);
  for(int q = 0; q < ch.Q.n; ++q)
    ch.q_position[q] = ch.q_region[q] ? local[ch.q_source[q]] : ch.Q.fixed[q];
  return true;
}

// Solves the charted region again: Newton on all of it, then, where faces are still not
// positive or below what double resolves (deeper than the energy's double can see: it
// resolves 16 orders of magnitude of energy, 8 of length), sweeps from the shallowest of
// them down to the cone, Newton on one band of distances to the cone at a time (7 orders of
// magnitude, the next band 4 orders deeper), the rest held fixed: a band's upper part is
// then accurate whatever is below it (an error at the band's floor decays upwards as the
// square of the ratio of distances), and is the next band's ceiling. Returns the faces of Q
// left unresolved.
template <class Traits>
std::size_t solve_chart_problem(Cone_charts& ch, std::vector<double>& xq, const Traits& tr, const Solver_options& options,
                                Embedding_statistics& st)
{
  const Flat_problem& Q = ch.Q;
  Solver_options opt = options;
  opt.max_iterations = (std::min)(opt.max_iterations, 50);
  std::vector<char> region(Q.n, 0);
  for(int q = 0; q < Q.n; ++q)
    region[q] = ch.q_region[q];
  Unresolved_faces left;
  int rounds = 0;
  auto solve = [&](const char* what) {
    Solver_statistics rs;
    const Error_code rec = minimize_energy_on_region(Q, xq, region, opt, rs);
    st.polishing_iterations += rs.iterations;
    st.cg_iterations += rs.cg_iterations;
    ++rounds;
    if(options.verbose) {
      int moving = 0;
      for(char r : region)
        moving += r;
      std::cerr << "  cone charts, " << what << ": " << moving << " vertices, " << rs.iterations << " Newton steps, "
                << error_message(rec) << ", imbalance " << rs.relative_gradient_norm << std::endl;
    }
  };
  auto check = [&]() {
    ch.q_position.resize(Q.n);
    for(int q = 0; q < Q.n; ++q)
      ch.q_position[q] = position(Q, xq, q);
    left = unresolved_faces(Q, ch.q_position, tr, true);
    if(options.verbose)
      std::cerr << "  cone charts: " << left.count << " faces not positive or below what double resolves (smallest edge "
                << left.smallest << ")" << std::endl;
  };
  solve("the whole region");
  check();
  // the deepest moving vertex at the current positions
  auto lowest = [&]() {
    double r = std::numeric_limits<double>::infinity();
    for(int q = 0; q < Q.n; ++q)
      if(ch.q_region[q] && Q.kind[q] != Fixed && std::abs(ch.q_position[q]) > 0)
        r = (std::min)(r, std::abs(ch.q_position[q]));
    return r;
  };
  // bands from `top` down to the deepest vertex
  auto sweep_from = [&](double top) {
    for(; rounds < max_chart_rounds * 8; top *= 1e-4) {
      bool any = false;
      for(int q = 0; q < Q.n; ++q) {
        const double r = std::abs(ch.q_position[q]);
        region[q] = ch.q_region[q] && r <= top && r >= 1e-7 * top;
        any = any || (region[q] && Q.kind[q] != Fixed);
      }
      if(any)
        solve("a band");
      for(int q = 0; q < Q.n; ++q) // (the next band is chosen at the new positions)
        ch.q_position[q] = position(Q, xq, q);
      if(!(lowest() < 1e-7 * top))
        break; // the band reached the deepest vertex
    }
  };
  // the whole region's solve is accurate over 6 orders of magnitude or so below its
  // farthest vertex (positive faces deeper down are not yet harmonic): the rest in bands
  double farthest = 0;
  for(int q = 0; q < Q.n; ++q)
    if(ch.q_region[q] && Q.kind[q] != Fixed)
      farthest = (std::max)(farthest, std::abs(ch.q_position[q]));
  if(lowest() < 1e-6 * farthest) {
    sweep_from(1e-3 * farthest);
    check();
  }
  for(int sweep = 0; sweep < 3 && left.count > 0 && rounds < max_chart_rounds * 8; ++sweep) {
    double hi = 0;
    for(std::size_t f = 0; f < Q.faces.size(); ++f)
      if(left.flag[f])
        for(int q : Q.faces[f])
          hi = (std::max)(hi, std::abs(ch.q_position[q]));
    sweep_from(10 * hi);
    check();
  }
  if(options.verbose)
    std::cerr << "  cone charts: " << rounds << " solves, " << left.count << " faces left" << std::endl;
  return left.count;
}

// The faces of the tile's problem P that double cannot resolve and that converge onto cone
// images, solved again in charts at those images. On success (every face of the region
// resolved and positive) `ch` holds the charts and the region's positions, and `uv` the
// region's tile positions (rounded: the charts hold the embedding there); returns false and
// leaves `uv` as it was otherwise.
template <class Tile>
bool solve_in_cone_charts(const Flat_problem& P, const Tile& tile, std::vector<std::complex<double> >& uv,
                          const Solver_options& options, Cone_charts& ch, Embedding_statistics& st)
{
  const Unresolved_faces flagged = unresolved_faces(P, uv, tile.traits(), true);
  double radius = 0;
  std::vector<double> xq;
  if(flagged.count == 0 || !choose_cone_charts(P, tile, uv, flagged.flag, radius, ch) ||
     !build_chart_problem(P, tile, uv, assign_charts(P, uv, chart_origins(tile, ch), ch.chart_corner, radius), ch, xq)) {
    ch = Cone_charts();
    return false;
  }
  if(solve_chart_problem(ch, xq, tile.traits(), options, st) > 0) {
    ch = Cone_charts();
    return false;
  }
  for(int q = 0; q < ch.Q.n; ++q)
    if(ch.q_region[q])
      uv[ch.q_source[q]] = ch.chart[ch.q_chart[q]].inverse().apply(ch.q_position[q]);
  return true;
}

} // namespace internal
} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_PIPELINE_CONE_CHART_SOLVE_H
