// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_PIPELINE_CERTIFICATE_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_PIPELINE_CERTIFICATE_H

#include <CGAL/Hyperbolic_orbifold_Tutte/Embedding_certificate.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/solver/cone_charts.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/solver/flat_problem.h>

#include <cmath>
#include <vector>

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {
namespace internal {

// the twin, cone and border checks of certify_flat() for the charted region's vertex q
template <class Distance>
void check_charted_vertex(const Cone_charts& ch, int q, double tolerance, const Distance& hdist, Embedding_certificate& cert)
{
  typedef std::complex<double> C;
  const Flat_problem& Q = ch.Q;
  const C z = ch.q_position[q];
  if(Q.kind[q] == Transformed) {
    const double d = hdist(Q.transform[q].apply(ch.q_position[Q.twin[q]]), z);
    cert.max_twin_error = (std::max)(cert.max_twin_error, d);
    if(!(d <= tolerance))
      ++cert.twin_failures;
  }
  if(Q.corner[q] >= 0 && Q.kind[q] == Fixed) { // a cone copy: at its chart's origin
    const double d = hdist(Q.fixed[q], z);
    cert.max_cone_error = (std::max)(cert.max_cone_error, d);
    if(!(d <= tolerance) || Q.fixed[q] != C(0, 0))
      ++cert.cone_failures;
  }
  if(Q.kind[q] == On_line) { // on its side's segment in the chart (a Klein segment)
    const C k = poincare_to_klein(z) - Q.line_k0[q], D = Q.line_D[q];
    const double off = std::abs(D.real() * k.imag() - D.imag() * k.real()) / std::abs(D);
    cert.max_border_error = (std::max)(cert.max_border_error, off);
    if(!(off <= tolerance))
      ++cert.border_failures;
  }
}

// Checks an embedding of the cut mesh given by one Poincare point per cut-mesh vertex.
//
// Tolerances. The orientation of every face is decided exactly. When every face is
// positive, the angle sum at a vertex can only be its expected value plus a multiple of
// 2 pi (its star winds an integer number of times), and the total area only a multiple
// of the tile's area (the degree of the covering): the angle-sum and area checks must
// tell these values apart, not measure them. So they accept an error up to 0.5 radian
// and a quarter of the tile's area, far above the rounding of the angles computed in
// double precision (which reaches 1e-4 on nearly flat triangles) and far below the
// smallest wrong value. Twins, cones and border points are measured with `tolerance`.
//
// With `charts`, the faces of the charted region are checked in their charts' coordinates
// (orientation, angles and areas do not depend on the frame: isometries), and so are the
// twins, cones and border points of the region's vertices.
template <class Tile>
Embedding_certificate certify_flat(const Flat_problem& P, const Tile& tile, const std::vector<std::complex<double> >& uv,
                                   double tolerance = 1e-6, const Cone_charts* charts = nullptr)
{
  typedef std::complex<double> C;
  typedef typename Tile::Traits Traits;
  typedef typename Traits::Point_2 Point_2;
  Embedding_certificate cert;
  Traits tr = tile.traits();
  auto orient = tr.hyperbolic_orientation_2_object();
  auto angle = tr.compute_hyperbolic_angle_2_object();
  cert.number_of_faces = P.faces.size();
  cert.expected_area = tile.area();

  for(int v = 0; v < P.n; ++v)
    if(!(squared_modulus(uv[v]) < 1.0) || !std::isfinite(uv[v].real()) || !std::isfinite(uv[v].imag()))
      ++cert.points_outside_disk;
  const bool charted = charts != nullptr && !charts->empty();
  if(charted)
    for(const C& z : charts->q_position)
      if(!(squared_modulus(z) < 1.0) || !std::isfinite(z.real()) || !std::isfinite(z.imag()))
        ++cert.points_outside_disk;

  std::vector<double> angle_sum(P.n_base, 0.0);
  auto pt = [&](int v) { return Point_2(uv[v].real(), uv[v].imag()); };
  auto point = [](const C& z) { return Point_2(z.real(), z.imag()); };
  if(cert.points_outside_disk == 0) {
    for(std::size_t f = 0; f < P.faces.size(); ++f) {
      const auto& t = P.faces[f];
      const Point_2 a = charted ? point(charts->face_point(P, uv, f, 0)) : pt(t[0]);
      const Point_2 b = charted ? point(charts->face_point(P, uv, f, 1)) : pt(t[1]);
      const Point_2 c = charted ? point(charts->face_point(P, uv, f, 2)) : pt(t[2]);
      const Orientation o = orient(a, b, c);
      if(o == NEGATIVE)
        ++cert.flipped_faces;
      else if(o == ZERO)
        ++cert.degenerate_faces;
      const double A = CGAL::to_double(angle(a, b, c)), B = CGAL::to_double(angle(b, c, a)),
                   Cc = CGAL::to_double(angle(c, a, b));
      angle_sum[P.base[t[0]]] += A;
      angle_sum[P.base[t[1]]] += B;
      angle_sum[P.base[t[2]]] += Cc;
      const double area = CGAL_PI - (A + B + Cc);
      cert.total_area += (o == NEGATIVE) ? -area : area;
    }
    // expected angle sums per base vertex
    std::vector<double> expected(P.n_base, 2 * CGAL_PI);
    for(int v = 0; v < P.n; ++v) {
      if(P.corner[v] >= 0 && tile.corner_cone(P.corner[v]) >= 0) { // (a corner that is no cone: 2 pi)
        const int c = tile.corner_cone(P.corner[v]);
        expected[P.base[v]] = tile.signature().cone_angle(c);
      } else if(tile.type() == Disk_type && P.side[v] >= 0) {
        expected[P.base[v]] = CGAL_PI;
      }
    }
    std::vector<char> seen(P.n_base, 0);
    for(int v = 0; v < P.n; ++v) {
      const int b = P.base[v];
      if(seen[b])
        continue;
      seen[b] = 1;
      const double err = std::abs(angle_sum[b] - expected[b]);
      cert.max_angle_sum_error = std::max(cert.max_angle_sum_error, err);
      if(!(err <= 0.5))
        ++cert.angle_sum_failures;
    }
    cert.area_error = std::abs(cert.total_area - cert.expected_area);
    // seam twins and cones
    auto hdist = [&](const C& p, const C& q) {
      return CGAL::to_double(tr.compute_hyperbolic_distance_2_object()(Point_2(p.real(), p.imag()), Point_2(q.real(), q.imag())));
    };
    for(int v = 0; v < P.n; ++v) {
      const int q = charted ? charts->region_q[v] : -1;
      if(q >= 0) { // in its chart
        check_charted_vertex(*charts, q, tolerance, hdist, cert);
        if(P.corner[v] >= 0) { // and the chart is centred at the cone's tile corner
          const auto& c = tile.corner(P.corner[v]);
          const double d = hdist(charts->chart[charts->q_chart[q]].apply(C(CGAL::to_double(c.x()), CGAL::to_double(c.y()))), C(0, 0));
          cert.max_cone_error = std::max(cert.max_cone_error, d);
          if(!(d <= tolerance))
            ++cert.cone_failures;
        }
        continue;
      }
      if(P.kind[v] == Transformed) {
        const double d = hdist(P.transform[v].apply(uv[P.twin[v]]), uv[v]);
        cert.max_twin_error = std::max(cert.max_twin_error, d);
        if(!(d <= tolerance))
          ++cert.twin_failures;
      }
      if(P.corner[v] >= 0 && tile.corner_cone(P.corner[v]) >= 0) {
        const auto& c = tile.corner(P.corner[v]);
        const double d = hdist(C(CGAL::to_double(c.x()), CGAL::to_double(c.y())), uv[v]);
        cert.max_cone_error = std::max(cert.max_cone_error, d);
        if(!(d <= tolerance))
          ++cert.cone_failures;
      }
      if(tile.type() == Disk_type && P.side[v] >= 0) {
        // on its side: distance to the side's line in the Klein model
        const int s = P.side[v];
        const auto Kp = tr.construct_Klein_point_2_object()(pt(v));
        const auto K0 = tr.construct_Klein_point_2_object()(tile.corner(tile.side_source(s)));
        const auto K1 = tr.construct_Klein_point_2_object()(tile.corner(tile.side_target(s)));
        const double ux = K1.x() - K0.x(), uy = K1.y() - K0.y();
        const double off = std::abs(ux * (Kp.y() - K0.y()) - uy * (Kp.x() - K0.x())) / std::sqrt(ux * ux + uy * uy);
        cert.max_border_error = std::max(cert.max_border_error, off);
        if(!(off <= tolerance))
          ++cert.border_failures;
      }
    }
  }
  cert.area_ok = cert.points_outside_disk == 0 && cert.area_error <= 0.25 * cert.expected_area;
  return cert;
}

} // namespace internal
} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_PIPELINE_CERTIFICATE_H
