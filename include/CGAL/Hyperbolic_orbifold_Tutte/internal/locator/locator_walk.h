// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_LOCATOR_LOCATOR_WALK_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_LOCATOR_LOCATOR_WALK_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Hyperbolic_orbifold_Tutte/internal/locator/lifted_triangulation.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>

// The point locator's straight walk through the lifted triangulation, and the barycentric
// coordinates of the point found (Embedding_locator.h describes the algorithm).

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {
namespace internal {

// The barycentric coordinates of q in the triangle h(f) (developed corners D), in the Klein
// model of B's own frame: those of h^{-1}(q) w.r.t. the stored corners. (An isometry is a
// projective, not an affine, map of the Klein disk: the coordinates w.r.t. the developed
// corners would differ.) In the hyperboloid model on request (lt.model).
template <class Traits, class Location>
void finish_location(const Lifted_triangulation<Traits>& lt, const std::complex<double>& q, int f, const std::complex<double>* D,
                     bool identity, const Hyperbolic_isometry_2<double>& h, Location& loc)
{
  typedef std::complex<double> C;
  std::array<double, 3> l;
  if(identity) {
    l = klein_barycentric(D[0], D[1], D[2], q);
  } else {
    const Hyperbolic_isometry_2<long double> hi(h.inverse());
    const std::complex<long double> w = hi.apply(std::complex<long double>(q.real(), q.imag()));
    const Lifted_face& F = lt.faces[f];
    l = klein_barycentric(F.z[0], F.z[1], F.z[2], C(static_cast<double>(w.real()), static_cast<double>(w.imag())));
  }
  loc.face_index = static_cast<std::size_t>(f);
  if(!std::isfinite(l[0]) || !std::isfinite(l[1]) || !std::isfinite(l[2])) {
    // a needle too thin for double Klein coordinates: the nearest corner
    int best = 0;
    for(int j = 1; j < 3; ++j)
      if(squared_modulus(D[j] - q) < squared_modulus(D[best] - q))
        best = j;
    l = {{0.0, 0.0, 0.0}};
    l[best] = 1.0;
  }
  if(lt.model == Hyperboloid_linear) {
    const Lifted_face& F = lt.faces[f];
    double t = 0;
    for(int j = 0; j < 3; ++j) {
      l[j] *= hyperboloid_weight(F.z[j]);
      t += l[j];
    }
    for(int j = 0; j < 3; ++j)
      l[j] /= t;
  }
  loc.min_raw_barycentric = (std::min)(l[0], (std::min)(l[1], l[2]));
  double s = 0;
  for(int j = 0; j < 3; ++j) {
    loc.barycentric[j] = l[j] > 0 ? l[j] : 0.0;
    s += loc.barycentric[j];
  }
  for(int j = 0; j < 3; ++j)
    loc.barycentric[j] /= s;
}

// The straight walk from the centroid of `start` to q (see Embedding_locator.h).
// Returns false when a check fails (then the search answers); h: the copy's element.
template <class Traits, class Location>
bool walk_to(const Lifted_triangulation<Traits>& lt, const std::complex<double>& q, int start, Location& loc,
             Hyperbolic_isometry_2<double>& h)
{
  typedef std::complex<double> C;
  h = Hyperbolic_isometry_2<double>();
  bool identity = true;
  int f = start;
  C D[3] = {lt.faces[f].z[0], lt.faces[f].z[1], lt.faces[f].z[2]}; // developed corners, face corner order
  const C p = lt.centroids[f];
  std::size_t steps = 1;
  loc.steps = steps;
  // the start triangle is positively oriented in face corner order, p strictly inside
  int o[3];
  for(int j = 0; j < 3; ++j)
    o[j] = lt.orient(D[j], D[(j + 1) % 3], q);
  if(o[0] >= 0 && o[1] >= 0 && o[2] >= 0) {
    finish_location(lt, q, f, D, true, h, loc);
    loc.success = true;
    return true;
  }
  bool left[3];
  for(int j = 0; j < 3; ++j)
    left[j] = lt.orient(p, q, D[j]) >= 0;
  // exit edge (u, v), counterclockwise, u right of the line p->q and v left of it
  int u = -1, v = -1;
  for(int j = 0; j < 3; ++j)
    if(!left[j] && left[(j + 1) % 3]) {
      u = j;
      v = (j + 1) % 3;
    }
  if(u < 0 || o[u] >= 0) // (edge u is the edge (u, u+1) = (u, v))
    return false;
  const std::size_t max_steps = 4 * lt.faces.size() + 1000;
  for(;;) {
    if(++steps > max_steps)
      return false;
    loc.steps = steps;
    // cross the edge (u, v) of face f
    const Lifted_face& F = lt.faces[f];
    const int j = Lifted_triangulation<Traits>::edge_index(u, v);
    const int t = F.tr[j];
    if(t < 0)
      return false;
    const int nf = F.nf[j], nj = F.ne[j];
    // corner c of f on edge j -> corner of nf
    auto map_corner = [&](int c) { return F.mirror[j] ? c : (c == j ? (nj + 1) % 3 : nj); };
    const int u2 = map_corner(u), v2 = map_corner(v), s2 = 3 - u2 - v2;
    C E[3];
    E[u2] = D[u];
    E[v2] = D[v];
    if(t != 0) {
      h = h * lt.transitions[t];
      identity = false;
    }
    E[s2] = identity ? lt.faces[nf].z[s2] : h.apply(lt.faces[nf].z[s2]);
    // the new triangle (v, u, s) must be positively oriented
    if(lt.orient(E[v2], E[u2], E[s2]) <= 0)
      return false;
    f = nf;
    D[0] = E[0];
    D[1] = E[1];
    D[2] = E[2];
    u = u2;
    v = v2;
    const int s = s2;
    // q is strictly beyond the entry edge (u, v): orient(v, u, q) > 0 by construction
    const int ous = lt.orient(D[u], D[s], q), osv = lt.orient(D[s], D[v], q);
    if(ous >= 0 && osv >= 0) {
      finish_location(lt, q, f, D, identity, h, loc);
      loc.success = true;
      return true;
    }
    if(lt.orient(p, q, D[s]) >= 0) { // s left: exit through (u, s)
      if(ous >= 0)
        return false;
      v = s;
    } else { // s right: exit through (s, v)
      if(osv >= 0)
        return false;
      u = s;
    }
  }
}

} // namespace internal
} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_LOCATOR_LOCATOR_WALK_H
