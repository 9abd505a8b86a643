// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_SOLVER_EDGE_WEIGHTS_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_SOLVER_EDGE_WEIGHTS_H

#include <CGAL/disable_warnings.h>

/// \file edge_weights.h
// The solver's edge weights (cotangent clamped, mean value, uniform) from the 3D geometry.

#include <CGAL/Hyperbolic_orbifold_Tutte/internal/solver/flat_problem.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/weight_type.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {
namespace internal {

// The edges of the cut mesh by vertex pair: per vertex, its edges (compressed rows;
// valences are small)
class Edges_by_vertex_pair
{
public:
  explicit Edges_by_vertex_pair(const Flat_problem& P)
    : first_(P.n + 1, 0), other_(2 * P.edges.size()), id_(2 * P.edges.size())
  {
    const std::size_t m = P.edges.size();
    for(const auto& e : P.edges) { ++first_[e[0] + 1]; ++first_[e[1] + 1]; }
    for(int v = 0; v < P.n; ++v) first_[v + 1] += first_[v];
    std::vector<int> fill(first_.begin(), first_.end() - 1);
    for(std::size_t e = 0; e < m; ++e) {
      const int a = P.edges[e][0], b = P.edges[e][1];
      other_[fill[a]] = b; id_[fill[a]++] = static_cast<int>(e);
      other_[fill[b]] = a; id_[fill[b]++] = static_cast<int>(e);
    }
  }
  // the edge (a, b), -1 if none
  int find(int a, int b) const
  {
    for(int k = first_[a]; k < first_[a + 1]; ++k)
      if(other_[k] == b) return id_[k];
    return -1;
  }

private:
  std::vector<int> first_, other_, id_;
};

// At corner i of a face (corners q), between the edges to corners i+1 and i+2: the
// cotangent dot / |cross|, and tan(angle / 2) = |cross| / (|u| |v| + dot) (no trigonometric
// function); len[i]: the length of the edge opposite corner i.
//
// (CGAL 5.5's CGAL::Weights::cotangent() computes the same cotangent with the same operations,
// but gives 0 where the cross product rounds to zero; its tangent_half_angle() rounds
// differently (|cross| / 2 times 2 / (|u| |v| + dot)); and the seam copies need the per-corner
// terms anyway: the weights stay ours, bit for bit as before.)
inline void corner_terms(const double q[3][3], double cot[3], double half_tan[3], double len[3])
{
  for(int i = 0; i < 3; ++i) {
    const double* o = q[i];
    const double* a = q[(i + 1) % 3];
    const double* b = q[(i + 2) % 3];
    const double u[3] = {a[0] - o[0], a[1] - o[1], a[2] - o[2]};
    const double v[3] = {b[0] - o[0], b[1] - o[1], b[2] - o[2]};
    const double dot = u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
    const double cx = u[1] * v[2] - u[2] * v[1], cy = u[2] * v[0] - u[0] * v[2], cz = u[0] * v[1] - u[1] * v[0];
    const double cr = std::sqrt(cx * cx + cy * cy + cz * cz);
    const double lu = std::sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
    const double lv = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    cot[i] = dot / cr; // +-infinity for a flat corner (exactly degenerate faces are refused before)
    half_tan[i] = cr / (lu * lv + dot);
    const double w[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    len[i] = std::sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
  }
}

// Every face's share of the weights of its three edges, added to P.edge_weight
template <class Point3>
void add_face_weights(Flat_problem& P, const std::vector<Point3>& base_points, Weight_type type)
{
  const Edges_by_vertex_pair edges(P);
  for(const auto& t : P.faces) {
    double q[3][3]; // the corners' coordinates
    for(int i = 0; i < 3; ++i) {
      const Point3& p = base_points[P.base[t[i]]];
      q[i][0] = CGAL::to_double(p.x());
      q[i][1] = CGAL::to_double(p.y());
      q[i][2] = CGAL::to_double(p.z());
    }
    double cot[3], half_tan[3], len[3];
    corner_terms(q, cot, half_tan, len);
    for(int i = 0; i < 3; ++i) {
      // edge opposite corner i: vertices i+1, i+2
      const int a = t[(i + 1) % 3], b = t[(i + 2) % 3];
      double w = 0;
      switch(type) {
        case Cotangent: w = 0.5 * cot[i]; break;
        case Uniform: w = 0.5; break;
        case Mean_value: w = 0.5 * (half_tan[(i + 1) % 3] + half_tan[(i + 2) % 3]) / len[i]; break;
      }
      const int e = edges.find(a, b);
      if(e >= 0)
        P.edge_weight[e] += w;
    }
  }
}

// Per base edge (its copies): the total over its copies. Uniform: 1 per base edge;
// cotangent sums below epsilon are clamped (degenerate geometry); a seam copy with a
// negative half shares the total with its twin copy.
inline void settle_base_edge(Flat_problem& P, const int* copy, std::size_t copies, Weight_type type, double epsilon)
{
  double sum = 0;
  for(std::size_t k = 0; k < copies; ++k)
    sum += P.edge_weight[copy[k]];
  bool rebalanced = false;
  for(std::size_t k = 0; k < copies; ++k) {
    double& w = P.edge_weight[copy[k]];
    if(type == Uniform) w = 1.0 / static_cast<double>(copies);
    else if(!(sum >= epsilon)) w = epsilon / static_cast<double>(copies);
    else if(!(w > 0)) { w = sum / static_cast<double>(copies); rebalanced = true; }
  }
  if(rebalanced) { // keep the total of the copies
    double total = 0;
    for(std::size_t k = 0; k < copies; ++k) total += P.edge_weight[copy[k]];
    for(std::size_t k = 0; k < copies; ++k) P.edge_weight[copy[k]] *= sum / total;
  }
}

// Edge weights from the 3D geometry, accumulated face by face on the cut mesh, so that
// the two copies of a seam edge together carry the base edge's weight (each base edge
// counts once in the energy). Cotangent sums are clamped below at epsilon per base edge.
template <class Point3>
void compute_edge_weights(Flat_problem& P, const std::vector<Point3>& base_points, Weight_type type, double epsilon)
{
  const std::size_t m = P.edges.size();
  P.edge_weight.assign(m, 0.0);
  // the copies of a base edge (two along a seam, one elsewhere): only an edge with both ends
  // on the border loop can have two; those are sorted by base pair
  std::vector<char> on_loop(P.n, 0);
  for(int v : P.border_loop)
    on_loop[v] = 1;
  auto key = [](int a, int b) { return (static_cast<long long>(std::min(a, b)) << 32) | static_cast<long long>(std::max(a, b)); };
  std::vector<std::pair<long long, int> > by_base;
  for(std::size_t e = 0; e < m; ++e)
    if(on_loop[P.edges[e][0]] && on_loop[P.edges[e][1]])
      by_base.emplace_back(key(P.base[P.edges[e][0]], P.base[P.edges[e][1]]), static_cast<int>(e));
  std::sort(by_base.begin(), by_base.end());

  add_face_weights(P, base_points, type);
  for(std::size_t e = 0; e < m; ++e)
    if(!(on_loop[P.edges[e][0]] && on_loop[P.edges[e][1]])) {
      const int c = static_cast<int>(e);
      settle_base_edge(P, &c, 1, type, epsilon);
    }
  std::vector<int> group;
  for(std::size_t i = 0; i < by_base.size();) {
    std::size_t j = i;
    group.clear();
    while(j < by_base.size() && by_base[j].first == by_base[i].first)
      group.push_back(by_base[j++].second);
    settle_base_edge(P, group.data(), group.size(), type, epsilon);
    i = j;
  }
}

} // namespace internal
} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_SOLVER_EDGE_WEIGHTS_H
