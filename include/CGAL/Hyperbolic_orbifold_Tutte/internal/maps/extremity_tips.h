// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_MAPS_EXTREMITY_TIPS_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_MAPS_EXTREMITY_TIPS_H

// The thin tips of one mesh that match_extremities() matches: the distance to the landmarks,
// its distinct maxima, the tips' balls and descriptors, and the thin maximum nearest to a vertex
// (for the matching along the map). Edge path distances over the mesh's graph only.

#include <CGAL/disable_warnings.h>

#include <CGAL/Hyperbolic_orbifold_Tutte/internal/core/mesh_graph.h>

#include <CGAL/number_type_config.h> // CGAL_PI
#include <CGAL/boost/graph/iterator.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {
namespace internal {
namespace extremities {

// a ratio test: the best candidate's descriptor difference is at most 1/kRatio of the second's,
// and the second's is at least kRatio * kIndistinct (descriptors within 1% of each other cannot
// tell two tips apart: edge path distances are off by more than that)
constexpr double kRatio = 1.5;
constexpr double kIndistinct = 0.01;
// an extremity is at least this fraction of the largest distance to the landmarks away from them
constexpr double kFarthest = 0.2;

// one mesh's thin tips (dense vertex indices, farthest from the landmarks first), their
// tipness and their descriptors (geodesic distances to the landmarks over sqrt(area)); after
// the `tips` tips, the rivals: the mesh's other distinct maxima (see distinct_maxima()), with
// their descriptors (tipness 0), which a tip of the other mesh must not be nearer to
struct Tips
{
  std::size_t tips = 0;
  std::vector<int> vertex;
  std::vector<double> tipness;
  std::vector<std::vector<double> > descriptor;
};

// The distinct maxima of `f` (a vertex function; `candidate[v]`: v is a local maximum worth
// looking at) and, for every vertex, the distinct maximum whose feature holds it. Superlevel
// sets {f >= t} are swept down (union-find over the vertices in decreasing f): where two
// components meet, the one with the lower top dies, and its top's persistence is how far f
// dropped from it, f(top) - t. A maximum whose persistence is below `noise` is not a feature
// of its own: its feature is the one it merged into. The highest maximum never dies.
template <class Graph>
std::vector<int> distinct_maxima(const Graph& g, const std::vector<double>& f, const std::vector<char>& candidate,
                                 double noise, std::vector<int>& feature)
{
  const std::size_t n = g.size();
  std::vector<int> order(n);
  for(std::size_t i = 0; i < n; ++i) order[i] = static_cast<int>(i);
  const auto higher = [&](int a, int b) { return f[a] > f[b] || (f[a] == f[b] && a < b); };
  std::sort(order.begin(), order.end(), higher);
  // (owner: the top of the component that a vertex joined when it was swept, or that a maximum
  // merged into when it died with a persistence below `noise`; -1 for the distinct maxima)
  std::vector<int> parent(n, -1), top(n, -1), owner(n, -1);
  const auto find = [&](int x) {
    while(parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  for(int u : order) {
    parent[u] = top[u] = u;
    for(std::size_t e = g.offsets[u]; e < g.offsets[u + 1]; ++e) {
      const int v = g.nbrs[e];
      if(parent[v] < 0) continue; // (not swept yet)
      const int a = find(u), b = find(v);
      if(a == b) continue;
      const bool a_higher = higher(top[a], top[b]);
      const int survivor = a_higher ? top[a] : top[b], dead = a_higher ? top[b] : top[a];
      if(f[dead] - f[u] < noise) owner[dead] = survivor;
      parent[a_higher ? b : a] = a_higher ? a : b;
    }
  }
  feature.assign(n, -1);
  std::vector<int> distinct;
  for(int u : order) { // (an owner is higher: settled before)
    if(owner[u] >= 0)
      feature[u] = feature[owner[u]];
    else {
      feature[u] = u;
      if(candidate[u]) distinct.push_back(u);
    }
  }
  return distinct;
}

// whether vertex u is a far local maximum of the distance `dist` (largest value dmax): at least
// kFarthest dmax, no neighbour farther (thin_tips()'s candidates, the maxima of the matching along
// the map)
template <class Graph>
bool is_far_maximum(const Graph& g, const std::vector<double>& dist, double dmax, std::size_t u)
{
  if(dist[u] < kFarthest * dmax)
    return false;
  for(std::size_t e = g.offsets[u]; e < g.offsets[u + 1]; ++e)
    if(dist[g.nbrs[e]] > dist[u])
      return false;
  return true;
}

template <class Graph, class TriangleMesh>
std::vector<double> vertex_areas(const Graph& g, const TriangleMesh& tm, double& total)
{
  std::vector<double> area(g.size(), 0.);
  total = 0;
  for(auto f : faces(tm)) {
    int c[3], n = 0;
    for(auto v : vertices_around_face(halfedge(f, tm), tm))
      if(n < 3) c[n++] = static_cast<int>(g.index(v));
    if(n < 3) continue;
    const double* p = &g.xyz[3 * c[0]];
    const double* q = &g.xyz[3 * c[1]];
    const double* r = &g.xyz[3 * c[2]];
    const double u[3] = {q[0] - p[0], q[1] - p[1], q[2] - p[2]}, w[3] = {r[0] - p[0], r[1] - p[1], r[2] - p[2]};
    const double x = u[1] * w[2] - u[2] * w[1], y = u[2] * w[0] - u[0] * w[2], z = u[0] * w[1] - u[1] * w[0];
    const double a = 0.5 * std::sqrt(x * x + y * y + z * z);
    total += a;
    for(int i = 0; i < 3; ++i) area[c[i]] += a / 3;
  }
  return area;
}

// the vertices within geodesic (edge path) distance `r` of `s`
template <class Graph>
std::vector<int> geodesic_ball(const Graph& g, Dijkstra_workspace& ws, int s, double r)
{
  std::vector<int> ball;
  bool beyond = false;
  ws.begin_run();
  dijkstra(g, ws, s, [&](int u) { if(ws.distance(u) <= r) ball.push_back(u); else beyond = true; },
           [&]() { return beyond; });
  return ball;
}

// The thin tips of a mesh: the local maxima of the geodesic distance to the landmarks (at least
// kFarthest of its largest value), each the largest within its geodesic ball of radius
// `radius` times that largest value, whose ball has an area under `threshold` times the flat
// disk's pi r^2 (a cone of half-angle alpha gives sin(alpha); a flat or convex region about 1).
// what thin_tips() computed on one mesh, kept for the matching along the map: the vertex areas,
// the distance to the nearest landmark, its largest value, the ball radius r and the
// descriptors' scale
struct Distance_field
{
  std::vector<double> area, dist;
  double dmax = 0, r = 0, scale = 1;
};

template <class Graph, class TriangleMesh>
Tips thin_tips(const Graph& g, const TriangleMesh& tm, const std::vector<int>& landmarks, double radius, double threshold,
               Distance_field& field)
{
  Tips tips;
  const std::size_t n = g.size();
  double total_area = 0;
  field.area = vertex_areas(g, tm, total_area);
  const std::vector<double>& area = field.area;
  Dijkstra_distances nearest(n); // to the nearest landmark
  for(int l : landmarks)
    dijkstra(g, nearest, l, [](int) {}, []() { return false; });
  double dmax = 0;
  for(double d : nearest.dist) dmax = (std::max)(dmax, d);
  std::vector<std::pair<double, int> > candidates; // (-distance, vertex)
  std::vector<char> is_candidate(n, 0);
  for(std::size_t i = 0; i < n; ++i) {
    const bool top = is_far_maximum(g, nearest.dist, dmax, i);
    if(top) candidates.emplace_back(-nearest.dist[i], static_cast<int>(i));
    is_candidate[i] = top;
  }
  // the distinct maxima: edge path distances place a maximum only to about an edge, so a drop
  // of less than the mean edge length between two maxima does not make them two features
  double mean_edge = 0;
  for(double l : g.lengths) mean_edge += l / g.lengths.size();
  std::vector<int> feature;
  const std::vector<int> distinct = distinct_maxima(g, nearest.dist, is_candidate, mean_edge, feature);
  std::sort(candidates.begin(), candidates.end());
  Dijkstra_workspace ws;
  ws.init(n);
  std::vector<char> covered(n, 0);
  const double r = radius * dmax;
  for(const std::pair<double, int>& c : candidates) {
    if(covered[c.second]) continue;
    double a = 0;
    for(int u : geodesic_ball(g, ws, c.second, r)) {
      covered[u] = 1;
      a += area[u];
    }
    const double tipness = a / (CGAL_PI * r * r);
    if(tipness < threshold) {
      tips.vertex.push_back(c.second);
      tips.tipness.push_back(tipness);
    }
  }
  // the rivals: the distinct maxima that are no tip's feature
  tips.tips = tips.vertex.size();
  std::vector<char> is_tip(n, 0);
  for(int t : tips.vertex) is_tip[feature[t]] = 1;
  for(int m : distinct)
    if(!is_tip[m]) {
      tips.vertex.push_back(m);
      tips.tipness.push_back(0.);
    }
  // the descriptors: one search per landmark, stopped once every tip and rival is settled
  tips.descriptor.assign(tips.vertex.size(), std::vector<double>(landmarks.size()));
  std::fill(is_tip.begin(), is_tip.end(), 0);
  for(int t : tips.vertex) is_tip[t] = 1;
  const double scale = 1 / std::sqrt(total_area);
  for(std::size_t j = 0; j < landmarks.size() && !tips.vertex.empty(); ++j) {
    std::size_t settled = 0;
    ws.begin_run();
    dijkstra(g, ws, landmarks[j], [&](int u) { settled += is_tip[u]; }, [&]() { return settled == tips.vertex.size(); });
    for(std::size_t t = 0; t < tips.vertex.size(); ++t)
      tips.descriptor[t][j] = ws.distance(tips.vertex[t]) * scale;
  }
  field.dist = std::move(nearest.dist);
  field.dmax = dmax;
  field.r = r;
  field.scale = scale;
  return tips;
}

// the area of the geodesic ball of radius field.r about `v` over pi r^2
template <class Graph>
double tipness_at(const Graph& g, Dijkstra_workspace& ws, const Distance_field& field, int v)
{
  double a = 0;
  for(int u : geodesic_ball(g, ws, v, field.r)) a += field.area[u];
  return a / (CGAL_PI * field.r * field.r);
}

// the descriptor of `v`: its distances to the landmarks over sqrt(area), one search stopped
// once every landmark is settled
template <class Graph>
std::vector<double> descriptor_at(const Graph& g, Dijkstra_workspace& ws, const Distance_field& field, const std::vector<int>& landmarks, int v)
{
  std::vector<char> is_landmark(g.size(), 0);
  for(int l : landmarks) is_landmark[l] = 1;
  std::size_t settled = 0;
  ws.begin_run();
  dijkstra(g, ws, v, [&](int u) { settled += is_landmark[u]; }, [&]() { return settled >= landmarks.size(); });
  std::vector<double> x(landmarks.size());
  for(std::size_t j = 0; j < landmarks.size(); ++j) x[j] = ws.distance(landmarks[j]) * field.scale;
  return x;
}

// the thin local maximum of the distance nearest to `v` (at least kFarthest of the largest
// distance, all its neighbours at most as far, its ball's area below `threshold`) within
// geodesic distance field.r of `v`, -1 if none; `tipness` receives its tipness
template <class Graph>
int nearest_thin_maximum(const Graph& g, const Distance_field& field, int v, double threshold, double& tipness)
{
  Dijkstra_workspace ws, ball;
  ws.init(g.size());
  ball.init(g.size());
  int found = -1;
  bool beyond = false;
  ws.begin_run();
  dijkstra(g, ws, v, [&](int u) {
    if(ws.distance(u) > field.r) { beyond = true; return; }
    if(!is_far_maximum(g, field.dist, field.dmax, u)) return;
    const double t = tipness_at(g, ball, field, u);
    if(t < threshold) { found = u; tipness = t; }
  }, [&]() { return beyond || found >= 0; });
  return found;
}

// whether the distance has a thin local maximum anywhere (as nearest_thin_maximum() finds near
// a vertex): a thin tip is one; else every maximum's ball is measured, until a thin one
template <class Graph>
bool has_thin_maximum(const Graph& g, const Distance_field& field, const Tips& tips, double threshold)
{
  if(tips.tips > 0)
    return true;
  Dijkstra_workspace ball;
  ball.init(g.size());
  for(std::size_t u = 0; u < g.size(); ++u)
    if(is_far_maximum(g, field.dist, field.dmax, u) && tipness_at(g, ball, field, static_cast<int>(u)) < threshold)
      return true;
  return false;
}

// the relative difference of two descriptors, sqrt(2 |x - y|^2 / (|x|^2 + |y|^2))
inline double descriptor_difference(const std::vector<double>& x, const std::vector<double>& y)
{
  double num = 0, den = 0;
  for(std::size_t j = 0; j < x.size(); ++j) {
    num += (x[j] - y[j]) * (x[j] - y[j]);
    den += x[j] * x[j] + y[j] * y[j];
  }
  return den > 0 ? std::sqrt(2 * num / den) : 0.;
}

// the tip of `to` whose descriptor is the nearest to `x`: its position, and the differences of
// the nearest and the second nearest
inline std::size_t nearest_tip(const Tips& to, const std::vector<double>& x, double& first, double& second)
{
  std::size_t best = 0;
  first = second = std::numeric_limits<double>::infinity();
  for(std::size_t t = 0; t < to.vertex.size(); ++t) {
    const double d = descriptor_difference(to.descriptor[t], x);
    if(d < first) { second = first; first = d; best = t; }
    else if(d < second) second = d;
  }
  return best;
}

} // namespace extremities
} // namespace internal
} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_MAPS_EXTREMITY_TIPS_H
