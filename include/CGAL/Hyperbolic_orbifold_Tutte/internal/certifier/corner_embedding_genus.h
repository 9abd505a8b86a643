// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_CERTIFIER_CORNER_EMBEDDING_GENUS_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_CERTIFIER_CORNER_EMBEDDING_GENUS_H

// certify_corner_embedding() on a closed mesh of genus g >= 1, without a tile: the checks of
// genus 0 that do not need one (faces, points, orientation, angle sums with a tight
// tolerance, area), and the seams' own: each seam edge's isometry computed from its two
// copies (equal hyperbolic lengths), and the isometries of seam edges that meet at a vertex
// copy on the cut equal (the cut's sides glued by one isometry each). Written for the
// certificate alone: it reads neither the solver's cut nor its tile.

#include <CGAL/Hyperbolic_orbifold_Tutte/Corner_embedding.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/Corner_embedding_certificate.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/Hyperbolic_isometry_2.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/Orbifold_tile.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/certifier/corner_embedding_checks.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/certifier/corner_embedding_geometry.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/certifier/corner_embedding_state.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/certifier/corner_embedding_topology.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {
namespace internal {
namespace corner_certificate {

// the largest accepted deviation of an angle sum from its cone angle on a closed surface of
// genus g >= 1 (radians, the certified enclosure within it)
constexpr double closed_genus_angle_tolerance = 1e-6;

// seams of a closed surface of genus g >= 1: every edge whose two faces give different points
// to an end is a seam; its orientation-preserving isometry h (taking the first face's copy to
// the second's) is computed from the copies' ends a (isometry_from_copies(): a1 to a2, the
// direction towards b1 to that towards b2), and must take b1 to b2 within the edge's tolerance
// (the copies have the same hyperbolic length). At each end x whose two copies differ and
// that is not a cone, the seam edges with the same pair of copies of x (the consecutive edges
// of one side of the cut) must share the isometry: the first one's, applied to another's copy
// of its other end, must land on the twin copy within that edge's tolerance. (With the angle
// sums this is implied: two isometries taking the same copy of x to the same copy differ by a
// rotation about it, which is the fan's holonomy, by the angle sum minus 2 pi; checked
// directly, it names the seam. At a cone of order p the cut may turn from one side of the
// polygon to another, glued by another isometry: they differ by the rotation of 2 pi / p.)
template <class TM>
void check_closed_genus_seams(Certification<TM>& S)
{
  typedef Corner_embedding_certificate Cert;
  typedef Hyperbolic_isometry_2<long double> Iso;
  Cert::Check_result& R = S.cert.checks[Seam_check];
  R.run = true;
  auto same = [&](std::size_t p, std::size_t q) { return same_point(S, p, q); };
  struct Seam
  {
    std::size_t u, w, f, g;
    std::size_t pu1, pw1, pu2, pw2; // the points of u and w in f (1) and in g (2)
    Iso h;                          // takes the copies in f to those in g
    double tol;
  };
  std::vector<Seam> seams;
  for_each_seam_edge(S, [&](const Seam_edge& e) {
    const std::size_t u = e.u, w = e.w, f = e.f, g = e.g;
    if(!(S.valid[e.pa1] && S.valid[e.pb1] && S.valid[e.pa2] && S.valid[e.pb2]))
      return;
    ++R.checked;
    const C a1 = S.point(e.pa1), b1 = S.point(e.pb1), a2 = S.point(e.pa2), b2 = S.point(e.pb2);
    const double length = (std::min)(std::abs(a1 - b1), std::abs(a2 - b2));
    const double tol = (std::min)(absolute_tolerance, relative_tolerance * length);
    const Iso h = isometry_from_copies(a1, b1, a2, b2);
    const double m = image_distance(h, b1, b2);
    S.cert.max_seam_mismatch = (std::max)(S.cert.max_seam_mismatch, m);
    S.cert.max_seam_length_mismatch = (std::max)(S.cert.max_seam_length_mismatch, m);
    S.cert.max_relative_seam_mismatch = (std::max)(S.cert.max_relative_seam_mismatch, m / length);
    if(!(m <= tol)) {
      std::ostringstream os;
      os.precision(6);
      os << "edge (" << u << ", " << w << ") between faces " << S.efface[f] << " and " << S.efface[g]
         << ": its two copies have different hyperbolic lengths (the isometry taking one copy of vertex " << u
         << " and its direction to the other's misplaces vertex " << w << " by " << m << ", tolerance " << tol << ")";
      record(S.cert, Seam_check, Cert::Edge, u, w, os.str());
      return;
    }
    seams.push_back(Seam{u, w, f, g, e.pa1, e.pb1, e.pa2, e.pb2, h, tol});
  });

  // the seam edges by (vertex, lower point, higher point) of an end whose two copies differ,
  // each with its isometry oriented from the lower point's side to the higher's
  struct End
  {
    std::size_t v, p_low, p_high, seam;
    bool reversed; // the seam's isometry takes the higher point's side to the lower's
  };
  std::vector<End> ends;
  for(std::size_t i = 0; i < seams.size(); ++i) {
    const Seam& s = seams[i];
    if(!same(s.pu1, s.pu2) && !S.is_cone[s.u])
      ends.push_back(End{s.u, (std::min)(s.pu1, s.pu2), (std::max)(s.pu1, s.pu2), i, s.pu1 > s.pu2});
    if(!same(s.pw1, s.pw2) && !S.is_cone[s.w])
      ends.push_back(End{s.w, (std::min)(s.pw1, s.pw2), (std::max)(s.pw1, s.pw2), i, s.pw1 > s.pw2});
  }
  std::sort(ends.begin(), ends.end(), [](const End& a, const End& b) {
    return std::tie(a.v, a.p_low, a.p_high, a.seam) < std::tie(b.v, b.p_low, b.p_high, b.seam);
  });
  std::vector<std::size_t> parent(seams.size());
  std::iota(parent.begin(), parent.end(), std::size_t(0));
  auto find = [&](std::size_t x) {
    while(parent[x] != x)
      x = parent[x] = parent[parent[x]];
    return x;
  };
  std::size_t classes = seams.size();
  for(std::size_t begin = 0; begin < ends.size();) {
    std::size_t end = begin + 1;
    while(end < ends.size() && ends[end].v == ends[begin].v && ends[end].p_low == ends[begin].p_low &&
          ends[end].p_high == ends[begin].p_high)
      ++end;
    const End& r = ends[begin];
    const Iso ref = r.reversed ? seams[r.seam].h.inverse() : seams[r.seam].h; // lower side to higher side
    for(std::size_t j = begin + 1; j < end; ++j) {
      const End& e = ends[j];
      const Seam& s = seams[e.seam];
      ++S.cert.number_of_seam_consistency_checks;
      // the other end of seam e, its copy on the lower point's side and on the higher's
      const bool at_u = e.v == s.u;
      const std::size_t q1 = at_u ? s.pw1 : s.pu1, q2 = at_u ? s.pw2 : s.pu2;
      const C low = S.point(e.reversed ? q2 : q1), high = S.point(e.reversed ? q1 : q2);
      const double m = image_distance(ref, low, high);
      S.cert.max_seam_consistency_mismatch = (std::max)(S.cert.max_seam_consistency_mismatch, m);
      S.cert.max_seam_mismatch = (std::max)(S.cert.max_seam_mismatch, m);
      if(!(m <= s.tol)) {
        std::ostringstream os;
        os.precision(6);
        os << "edge (" << s.u << ", " << s.w << ") between faces " << S.efface[s.f] << " and " << S.efface[s.g]
           << ": its two sides are not glued by the isometry of the adjacent seam edge (" << seams[r.seam].u << ", "
           << seams[r.seam].w << ") at the same copies of vertex " << e.v << " (it misplaces the copy of vertex "
           << (at_u ? s.w : s.u) << " by " << m << ", tolerance " << s.tol << ")";
        record(S.cert, Seam_check, Cert::Edge, s.u, s.w, os.str());
        continue;
      }
      const std::size_t a = find(r.seam), b = find(e.seam);
      if(a != b) {
        parent[a] = b;
        --classes;
      }
    }
    begin = end;
  }
  S.cert.number_of_seam_isometries = classes;
}

// The certification of a closed mesh of genus g >= 1 with cones `cones` (vertex indices) of
// orders `orders` (one per cone, or empty: 2), after the mesh and the embedding's arrays were
// checked (see certify_corner_embedding()).
template <class TM>
void certify_closed_genus(const Indexed_mesh<TM>& M, int genus, const std::vector<std::size_t>& cones,
                          const std::vector<int>& orders, const std::vector<char>& is_cone, const Corner_embedding& embedding,
                          Corner_embedding_certificate& certificate)
{
  typedef Orbifold_tile<Poincare_disk_traits_2<> > Tile;
  const std::size_t k = cones.size();
  const std::vector<int> given = orders.empty() ? std::vector<int>(k, 2) : orders;
  const Tile no_tile; // (its traits' predicates only)
  certificate.type = Sphere_type;
  certificate.genus = genus;
  certificate.number_of_cones = static_cast<int>(k);
  certificate.number_of_faces = embedding.number_of_faces();
  certificate.number_of_vertices = M.number_of_vertices();
  certificate.number_of_points = embedding.points.size();
  certificate.expected_area = Orbifold_signature(genus, given).area();
  certificate.absolute_tolerance = absolute_tolerance;
  certificate.relative_tolerance = relative_tolerance;
  certificate.angle_sum_tolerance = closed_genus_angle_tolerance;
  certificate.cone_order.assign(k, -1);
  certificate.cone_orders.assign(k, 0);
  certificate.measured_cone_orders.assign(k, std::numeric_limits<double>::quiet_NaN());

  Certification<TM> S(M, embedding, no_tile, certificate);
  S.is_cone = is_cone;
  S.on_border.assign(M.number_of_vertices(), 0);
  S.orders = given;
  S.angle_tolerance = closed_genus_angle_tolerance;
  std::vector<int> rotation;
  if(!match_faces(M, embedding, certificate, S.efface, rotation))
    return;
  S.pid.resize(M.number_of_faces());
  for(std::size_t f = 0; f < M.number_of_faces(); ++f)
    for(int c = 0; c < 3; ++c)
      S.pid[f][c] = embedding.face_points[S.efface[f]][(c + rotation[f]) % 3];
  check_points(S);
  certificate.checks[Chart_check].run = true;  // no chart (refused before)
  certificate.checks[Border_check].run = true; // no boundary
  // cones: no tile corner to be at; each cone's order is decided by its angle sum (angle_sum)
  certificate.checks[Cone_check].run = true;
  certificate.checks[Cone_check].checked = k;
  compute_tolerances(S);
  check_faces(S);
  check_angle_sums_and_area(S, cones);
  for(std::size_t i = 0; i < k; ++i) {
    const double sum = S.angle_sum.empty() ? std::numeric_limits<double>::quiet_NaN() : S.angle_sum[cones[i]];
    if(sum > 0) {
      certificate.measured_cone_orders[i] = 2 * CGAL_PI / sum;
      if(std::abs(sum - 2 * CGAL_PI / given[i]) <= closed_genus_angle_tolerance)
        certificate.cone_orders[i] = given[i];
    }
  }
  check_closed_genus_seams(S);
}

} // namespace corner_certificate
} // namespace internal
} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_CERTIFIER_CORNER_EMBEDDING_GENUS_H
