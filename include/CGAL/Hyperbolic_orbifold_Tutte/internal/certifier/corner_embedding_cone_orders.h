// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_CERTIFIER_CORNER_EMBEDDING_CONE_ORDERS_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_CERTIFIER_CORNER_EMBEDDING_CONE_ORDERS_H

#include <CGAL/disable_warnings.h>

// The cone orders read by certify_corner_embedding() from where the cones' points are: the
// sequence of the cones along the boundary of a tile of mixed orders, the orders measured
// on the points (informative), and the cones whose measured order is not the given one (the
// checks themselves are in corner_embedding_checks.h).

#include <CGAL/Hyperbolic_orbifold_Tutte/Corner_embedding.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/Corner_embedding_certificate.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/Hyperbolic_isometry_2.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/Orbifold_tile.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/Poincare_disk_traits_2.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/certifier/corner_embedding_chart_checks.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/certifier/corner_embedding_geometry.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/certifier/corner_embedding_state.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/certifier/corner_embedding_topology.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {
namespace internal {
namespace corner_certificate {

// The sequence of the cones along the boundary of a sphere tile of mixed orders, read from
// where their points are (the tile of make_orbifold_tile(Orbifold_signature) depends on it:
// its corners p_1 .. p_k are the cones in the sequence of the signature's orders). In the
// tile's own frame (`to_tile`, the inverse of the frame), p_1 is on the positive real axis,
// p_k on the negative one, p_2 .. p_(k-1) in the upper half-disk at strictly increasing
// arguments between them (the k-gon is convex and the origin is the midpoint of its side
// p_k p_1), and the other corners are q_j = conj(p_j). So each cone is placed by the argument
// of its highest point, its imaginary part clamped at 0 (a point of the real axis rounded just
// below it stays at argument 0 or pi), ties in the given order. Returns the given cones'
// indices in that sequence; in the given order when a cone has no valid point. A choice of
// tile only: the checks decide whether the cones are at its corners.
template <class TM>
std::vector<int> cone_sequence(const Certification<TM>& S, const std::vector<std::size_t>& cones,
                               const std::vector<std::vector<std::size_t> >& points_of, const Hyperbolic_isometry_2<double>& to_tile)
{
  const int k = static_cast<int>(cones.size());
  std::vector<int> sequence(k);
  std::vector<double> key(k, 0);
  for(int i = 0; i < k; ++i) {
    sequence[i] = i;
    double best = -std::numeric_limits<double>::infinity();
    for(std::size_t p : points_of[cones[i]]) {
      if(!S.valid[p])
        return sequence;
      const C w = to_tile.apply(S.point(p));
      if(w.imag() > best) {
        best = w.imag();
        key[i] = std::atan2((std::max)(w.imag(), 0.0), w.real());
      }
    }
    if(points_of[cones[i]].empty())
      return sequence;
  }
  std::stable_sort(sequence.begin(), sequence.end(), [&](int a, int b) { return key[a] < key[b]; });
  return sequence;
}

// The cones' orders measured on their points alone (Corner_embedding_certificate::
// measured_cone_orders; informative): the points of the cones, moved into the tile's own frame
// (`to_tile`) and ordered by their arguments about its origin (inside the tile), are the
// tile's corners in order when the map is right; the hyperbolic angle of that polygon at a
// point z between its neighbours a (before) and b (after) is the angle from T(b) to T(a),
// T(w) = (w - z) / (1 - conj(z) w) (an isometry, taking z to the origin); a cone's order is
// 2 pi (pi at a disk's corner) over the sum of the angles at its points. NaN when a cone's
// point is not valid or the points are not as many as the tile's corners.
template <class TM>
std::vector<double> measure_cone_orders(const Certification<TM>& S, const std::vector<std::size_t>& cones,
                                        const std::vector<std::vector<std::size_t> >& points_of, const Hyperbolic_isometry_2<double>& to_tile)
{
  const int k = static_cast<int>(cones.size());
  std::vector<double> r(k, std::numeric_limits<double>::quiet_NaN());
  std::vector<std::pair<double, std::pair<int, C> > > polygon; // (argument, (cone, point))
  for(int i = 0; i < k; ++i)
    for(std::size_t p : points_of[cones[i]]) {
      if(!S.valid[p])
        return r;
      const C w = to_tile.apply(S.point(p));
      polygon.push_back({std::atan2(w.imag(), w.real()), {i, w}});
    }
  if(static_cast<int>(polygon.size()) != S.tile.number_of_corners())
    return r;
  std::sort(polygon.begin(), polygon.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
  const std::size_t n = polygon.size();
  std::vector<double> sum(k, 0);
  for(std::size_t j = 0; j < n; ++j) {
    const C z = polygon[j].second.second, a = polygon[(j + n - 1) % n].second.second, b = polygon[(j + 1) % n].second.second;
    auto T = [&](const C& w) { return (w - z) / (1.0 - std::conj(z) * w); };
    double angle = std::arg(T(a) / T(b));
    if(angle <= 0)
      angle += 2 * CGAL_PI;
    sum[polygon[j].second.first] += angle;
  }
  const double full = S.tile.type() == Sphere_type ? 2 * CGAL_PI : CGAL_PI;
  for(int i = 0; i < k; ++i)
    r[i] = full / sum[i];
  return r;
}

// the cones whose measured order (measure_cone_orders()) is not the one given, as a clause to
// end the message of a cone at no corner with; empty when the orders are all 2 or all match
template <class TM>
std::string order_mismatches(const Certification<TM>& S, const std::vector<std::size_t>& cones)
{
  if(S.orders.empty())
    return std::string();
  std::ostringstream os;
  os.precision(4);
  os << std::fixed;
  int n = 0;
  for(std::size_t i = 0; i < cones.size(); ++i) {
    const double m = i < S.cert.measured_cone_orders.size() ? S.cert.measured_cone_orders[i] : 0.0;
    if(!(m > 0 && m < 1e9) || std::lround(m) == S.orders[i]) // (NaN: not measured)
      continue;
    os << (n++ ? ", " : "; the cones' points give other orders than those given (measured on the polygon they form, whose angles at a cone's points add up to 2 pi / its order): ")
       << "cone " << i << " (vertex " << cones[i] << ") has order " << m << ", not " << S.orders[i];
  }
  return os.str();
}

} // namespace corner_certificate
} // namespace internal
} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_CERTIFIER_CORNER_EMBEDDING_CONE_ORDERS_H
