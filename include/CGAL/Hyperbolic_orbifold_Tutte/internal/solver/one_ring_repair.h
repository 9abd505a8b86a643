// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_SOLVER_ONE_RING_REPAIR_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_SOLVER_ONE_RING_REPAIR_H

#include <CGAL/disable_warnings.h>

/// \file one_ring_repair.h
// The post-processing of the embedding: one-rings with a flipped face repaired (paper,
// section 5), and snapped at the resolution of double as a last resort.

#include <CGAL/Hyperbolic_orbifold_Tutte/Hyperbolic_isometry_2.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/core/disk_models.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/solver/flat_problem.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {
namespace internal {

// exact test: the hyperbolic triangle (a, b, c) of the Poincare disk is positively oriented
// (Traits: a model of HyperbolicOrbifoldTraits_2, the tile's traits)
template <class Traits>
bool positive_triangle(const Traits& tr, const std::complex<double>& a, const std::complex<double>& b, const std::complex<double>& c)
{
  typedef typename Traits::Point_2 Point_2;
  return tr.hyperbolic_orientation_2_object()(Point_2(a.real(), a.imag()), Point_2(b.real(), b.imag()), Point_2(c.real(), c.imag())) ==
         POSITIVE;
}

// The faces around each vertex (a seam copy's faces listed at its twin, whose variables it
// uses) and the exact test of a face's orientation at x: what the one-ring repairs check.
template <class Traits>
class One_ring_faces
{
public:
  One_ring_faces(const Flat_problem& P, const Traits& tr) : P_(P), tr_(tr), faces_(P.n)
  {
    for(std::size_t f = 0; f < P.faces.size(); ++f)
      for(int i = 0; i < 3; ++i)
        faces_[owner(P.faces[f][i])].push_back(static_cast<int>(f));
  }
  int owner(int v) const { return owner_vertex(P_, v); }
  bool positive(int f, const std::vector<double>& x) const
  {
    return positive_triangle(tr_, position(P_, x, P_.faces[f][0]), position(P_, x, P_.faces[f][1]),
                             position(P_, x, P_.faces[f][2]));
  }
  bool all_positive(int v, const std::vector<double>& x) const
  {
    for(int f : faces_[v])
      if(!positive(f, x))
        return false;
    return true;
  }

private:
  const Flat_problem& P_;
  Traits tr_;
  std::vector<std::vector<int> > faces_;
};

// The paper's post-processing (section 5): every free vertex that is not inside the
// hyperbolic convex hull of its neighbours (detected by a non-positive incident face, exact
// test) is moved by a Mobius map to the origin with its one-ring, put at the Euclidean
// weighted centroid of its neighbours there, and moved back; repeated until no face is
// flipped, or `max_sweeps` sweeps, or ten sweeps without fewer vertices to move (a region
// below what double resolves). Seam vertices see their neighbours across the seam
// through the side pairing. Returns the number of vertex moves. Traits: the tile's traits.
template <class Traits>
int repair_one_rings(const Flat_problem& P, std::vector<double>& x, const Traits& tr, int max_sweeps = 100)
{
  typedef std::complex<double> C;
  typedef Hyperbolic_isometry_2<double> Isometry;
  const One_ring_faces<Traits> rings(P, tr);
  // neighbours of each free vertex, with the map bringing them into its frame
  struct Nb { int u; int via; double w; };  // via: the vertex of the edge standing for v (v or a twin copy)
  std::vector<std::vector<Nb> > nb(P.n);
  auto owner = [&](int v) { return rings.owner(v); };
  for(std::size_t e = 0; e < P.edges.size(); ++e) {
    const int a = P.edges[e][0], b = P.edges[e][1];
    if(P.kind[owner(a)] == Free) nb[owner(a)].push_back(Nb{b, a, P.edge_weight[e]});
    if(P.kind[owner(b)] == Free) nb[owner(b)].push_back(Nb{a, b, P.edge_weight[e]});
  }
  int moves = 0, fewest = P.n + 1, idle = 0;
  for(int sweep = 0; sweep < max_sweeps; ++sweep) {
    int moved = 0;
    for(int v = 0; v < P.n; ++v) {
      if(P.kind[v] != Free)
        continue;
      if(rings.all_positive(v, x))
        continue;
      const C z(x[P.var[v]], x[P.var[v] + 1]);
      const Isometry to0 = Isometry::translation_to_origin(z);
      C sum;
      double wsum = 0;
      for(const Nb& q : nb[v]) {
        C zu = position(P, x, q.u);
        if(q.via != v) // the edge is at a seam copy: bring the neighbour back through the pairing
          zu = P.transform[q.via].inverse().apply(zu);
        sum += q.w * to0.apply(zu);
        wsum += q.w;
      }
      if(!(wsum > 0))
        continue;
      const C c = to0.inverse().apply(sum / wsum);
      x[P.var[v]] = c.real();
      x[P.var[v] + 1] = c.imag();
      ++moved;
    }
    moves += moved;
    if(moved == 0)
      break;
    // hopeless (a region below what double resolves): ten sweeps without fewer vertices to move
    if(moved < fewest) {
      fewest = moved;
      idle = 0;
    } else if(++idle >= 10) {
      break;
    }
  }
  return moves;
}

// Last resort of the repair, at the resolution of double: a vertex of a non-positive face
// is searched for, around its computed position, a nearby point (1 to 2^20 units in the last
// place away, 16 directions) where all its faces are positive (exact predicate). The exact
// embedding is bijective; where its triangles are nearly flat and tiny (a squeezed region of
// a mesh with nearly flat triangles) the rounded solution may flip one, and a representable
// valid position exists close by. The certificate judges the result. Returns the moves.
// More than `max_vertices` such vertices: a whole region below what double resolves, which
// moving vertices one at a time cannot mend (and the exact tests would take seconds): none moved.
template <class Traits>
int snap_one_rings(const Flat_problem& P, std::vector<double>& x, const Traits& tr, int max_vertices = 100)
{
  const One_ring_faces<Traits> rings(P, tr);
  auto all_ok = [&](int v) { return rings.all_positive(v, x); };
  int to_move = 0;
  for(int v = 0; v < P.n && to_move <= max_vertices; ++v)
    to_move += (P.kind[v] == Free && !all_ok(v)) ? 1 : 0;
  if(to_move > max_vertices)
    return 0;
  int moves = 0;
  for(int v = 0; v < P.n; ++v) {
    if(P.kind[v] != Free || all_ok(v))
      continue;
    const int i = P.var[v];
    const double x0 = x[i], y0 = x[i + 1];
    const double ulp = std::numeric_limits<double>::epsilon() * (std::max)({std::abs(x0), std::abs(y0), 1e-3});
    bool found = false;
    for(double r = ulp; r < ulp * 2e6 && !found; r *= 2)
      for(int d = 0; d < 16 && !found; ++d) {
        x[i] = x0 + r * std::cos(d * CGAL_PI / 8);
        x[i + 1] = y0 + r * std::sin(d * CGAL_PI / 8);
        found = x[i] * x[i] + x[i + 1] * x[i + 1] < 1 && all_ok(v);
      }
    if(found)
      ++moves;
    else {
      x[i] = x0;
      x[i + 1] = y0;
    }
  }
  return moves;
}

} // namespace internal
} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_SOLVER_ONE_RING_REPAIR_H
