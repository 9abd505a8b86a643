// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_CERTIFIER_CORNER_EMBEDDING_CHECKS_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_CERTIFIER_CORNER_EMBEDDING_CHECKS_H

// The checks of certify_corner_embedding(), one function each, on the corner points of the
// mesh's faces: points (finite, in the disk), cones at tile corners (the cone order), disk
// boundary vertices on their sides' segments, faces (exact orientation), angle sums and area
// (certified enclosures), seams (side pairings); the charts' checks are in
// corner_embedding_chart_checks.h, the state in corner_embedding_state.h. Written for the certificate alone: it shares
// the traits, the isometries and the tile with the solver, nothing else.

#include <CGAL/Hyperbolic_orbifold_Tutte/Corner_embedding.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/Corner_embedding_certificate.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/Hyperbolic_isometry_2.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/Orbifold_tile.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/Poincare_disk_traits_2.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/certifier/corner_embedding_chart_checks.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/certifier/corner_embedding_geometry.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/certifier/corner_embedding_cone_orders.h>
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

// finite and inside_disk, per point used by a face
template <class TM>
void check_points(Certification<TM>& S)
{
  typedef Corner_embedding_certificate Cert;
  const std::size_t F = S.M.number_of_faces();
  S.valid.assign(S.E.points.size(), 0);
  std::vector<char> seen(S.E.points.size(), 0);
  S.cert.checks[Finite_coordinates_check].run = S.cert.checks[Inside_disk_check].run = true;
  // in the embedding's face order, so that the first failure is the first in the file
  std::vector<std::size_t> mesh_face_of(S.E.number_of_faces());
  for(std::size_t f = 0; f < F; ++f)
    mesh_face_of[S.efface[f]] = f;
  for(std::size_t e = 0; e < S.E.number_of_faces(); ++e) {
    const std::size_t f = mesh_face_of[e];
    for(int c = 0; c < 3; ++c) {
      const std::size_t p = S.pid[f][c];
      if(seen[p])
        continue;
      seen[p] = 1;
      const C z = S.point(p);
      const std::size_t v = S.M.face_vertices[f][c];
      ++S.cert.checks[Finite_coordinates_check].checked;
      if(!std::isfinite(z.real()) || !std::isfinite(z.imag())) {
        record(S.cert, Finite_coordinates_check, Cert::Vertex, v, 0, "vertex " + std::to_string(v) + " (in face " +
               std::to_string(e) + ") is at " + point_string(z) + ": not a finite point");
        continue;
      }
      ++S.cert.checks[Inside_disk_check].checked;
      if(!strictly_inside_unit_disk(z.real(), z.imag())) {
        record(S.cert, Inside_disk_check, Cert::Vertex, v, 0, "vertex " + std::to_string(v) + " (in face " +
               std::to_string(e) + ") is at " + point_string(z) + ", not strictly inside the unit disk");
        continue;
      }
      S.valid[p] = 1;
    }
  }
}

// the tolerance of each vertex's positions: absolute, or relative to its shortest incident
// edge (in any of its faces' points) when that is smaller
template <class TM>
void compute_tolerances(Certification<TM>& S)
{
  const std::size_t V = S.M.number_of_vertices();
  std::vector<double> shortest(V, std::numeric_limits<double>::infinity());
  for(std::size_t f = 0; f < S.M.number_of_faces(); ++f) {
    if(!S.face_points_valid(f))
      continue;
    for(int c = 0; c < 3; ++c) {
      const double l = std::abs(S.corner(f, c) - S.corner(f, (c + 1) % 3));
      for(int d : {c, (c + 1) % 3}) {
        double& s = shortest[S.M.face_vertices[f][d]];
        s = (std::min)(s, l);
      }
    }
  }
  S.tolerance.assign(V, absolute_tolerance);
  for(std::size_t v = 0; v < V; ++v)
    S.tolerance[v] = (std::min)(absolute_tolerance, relative_tolerance * shortest[v]);
}

// the distinct points of a vertex's corners (a short list: one per side of a cut)
template <class TM>
std::vector<std::vector<std::size_t> > points_of_vertices(const Certification<TM>& S)
{
  std::vector<std::vector<std::size_t> > r(S.M.number_of_vertices());
  for(std::size_t f = 0; f < S.M.number_of_faces(); ++f)
    for(int c = 0; c < 3; ++c) {
      std::vector<std::size_t>& l = r[S.M.face_vertices[f][c]];
      const std::size_t p = S.pid[f][c];
      bool found = false;
      for(std::size_t q : l)
        if(same_point(S, p, q)) { found = true; break; }
      if(!found)
        l.push_back(p);
    }
  return r;
}

// a cone's points are all at corners of one tile cone: `c` is the tile cone of its next point,
// `cone` that of its points so far (-1: none); false, the failure recorded, when they differ
template <class TM>
bool at_one_tile_cone(Certification<TM>& S, std::size_t v, const std::string& who, int& cone, int c)
{
  if(cone >= 0 && c != cone) {
    record(S.cert, Cone_check, Corner_embedding_certificate::Vertex, v, 0, who + " has copies at corners of two tile cones, " +
           std::to_string(cone) + " and " + std::to_string(c));
    return false;
  }
  cone = c;
  return true;
}

// cones: each at a corner of the tile, all its points at corners of one tile cone, each tile
// cone once (which gives the cone order), of the tile cone's order the given one; on a disk,
// consecutive along the boundary loop (counterclockwise) at consecutive tile corners. Returns
// true when the cone order is known.
template <class TM>
bool check_cones(Certification<TM>& S, const std::vector<std::size_t>& cones,
                 const std::vector<std::vector<std::size_t> >& points_of)
{
  typedef Corner_embedding_certificate Cert;
  const int k = static_cast<int>(cones.size());
  Cert::Check_result& R = S.cert.checks[Cone_check];
  R.run = true;
  S.cert.cone_order.assign(k, -1);
  S.cert.cone_orders.assign(k, 0);
  std::vector<int> owner(k, -1);
  for(int i = 0; i < k; ++i) {
    const std::size_t v = cones[i];
    ++R.checked;
    const std::string who = "cone " + std::to_string(i) + " (vertex " + std::to_string(v) + ")";
    int cone = -1;
    bool ok = true;
    for(std::size_t p : points_of[v]) {
      if(!S.valid[p]) { ok = false; break; }
      const int k = S.point_chart(p);
      if(k >= 0) {
        // written in a chart: exactly at its origin, the chart's tile corner (check_charts())
        const C w = S.chart_point(p);
        if(!(w == C(0, 0))) {
          record(S.cert, Cone_check, Cert::Vertex, v, 0, who + " is at " + point_string(w) + " in chart " + std::to_string(k) +
                 ", not at its origin (a cone written in a chart is at its origin, exactly 0; its tile corner " +
                 std::to_string(S.charts[k].corner) + ")");
          ok = false;
          break;
        }
        if(!at_one_tile_cone(S, v, who, cone, S.tile.corner_cone(S.charts[k].corner))) {
          ok = false;
          break;
        }
        continue;
      }
      const C z = S.point(p);
      int best = 0;
      double best_d = std::numeric_limits<double>::infinity();
      for(int t = 0; t < S.tile.number_of_corners(); ++t) {
        const double d = std::abs(z - S.tile_corner(t));
        if(d < best_d) { best_d = d; best = t; }
      }
      if(!(best_d <= S.tolerance[v])) {
        record(S.cert, Cone_check, Cert::Vertex, v, 0, who + " is at " + point_string(z) +
               ", at no corner of the tile (the nearest, a corner of tile cone " + std::to_string(S.tile.corner_cone(best)) +
               ", is " + number_string(best_d) + " away; tolerance " + number_string(S.tolerance[v]) + ")" +
               order_mismatches(S, cones));
        ok = false;
        break;
      }
      S.cert.max_cone_distance = (std::max)(S.cert.max_cone_distance, best_d);
      if(!at_one_tile_cone(S, v, who, cone, S.tile.corner_cone(best))) {
        ok = false;
        break;
      }
    }
    if(!ok || cone < 0)
      continue;
    if(owner[cone] >= 0) {
      record(S.cert, Cone_check, Cert::Vertex, v, 0, who + " is at a corner of tile cone " + std::to_string(cone) +
             ", like cone " + std::to_string(owner[cone]) + " (vertex " + std::to_string(cones[owner[cone]]) + ")");
      continue;
    }
    owner[cone] = i;
    S.cert.cone_order[i] = cone;
    S.cert.cone_orders[i] = S.tile.signature().order(cone);
    if(!S.orders.empty() && S.cert.cone_orders[i] != S.orders[i])
      record(S.cert, Cone_check, Cert::Vertex, v, 0, who + " is at a corner of tile cone " + std::to_string(cone) + ", of order " +
             std::to_string(S.cert.cone_orders[i]) + " (cone angle 2 pi / " + std::to_string(S.cert.cone_orders[i]) +
             "), but its given order is " + std::to_string(S.orders[i]));
  }
  if(R.failures > 0)
    return false;
  if(S.tile.type() == Disk_type) {
    // counterclockwise along the boundary, the corners must follow the tile's corners
    const std::vector<std::size_t>& loop = S.M.border_loop;
    std::vector<int> cone_at(S.M.number_of_vertices(), -1);
    for(int i = 0; i < k; ++i)
      cone_at[cones[i]] = i;
    std::vector<int> along; // the cones in counterclockwise order along the boundary
    for(std::size_t v : loop)
      if(cone_at[v] >= 0)
        along.push_back(cone_at[v]);
    // (the step from the last back to the first then follows: the tile cones are a permutation)
    for(std::size_t j = 1; j < along.size(); ++j) {
      const int i = along[j], previous = along[j - 1];
      if(S.cert.cone_order[i] != (S.cert.cone_order[previous] + 1) % k) {
        record(S.cert, Cone_check, Cert::Vertex, cones[i], 0, "cone " + std::to_string(i) + " (vertex " +
               std::to_string(cones[i]) + ") follows cone " + std::to_string(previous) + " counterclockwise along the boundary, but is at tile corner " +
               std::to_string(S.cert.cone_order[i]) + ", not " + std::to_string((S.cert.cone_order[previous] + 1) % k));
        return false;
      }
    }
  }
  return R.failures == 0;
}

// disk type: every boundary vertex that is not a corner on the segment of its side (the side
// from the corner before it to the corner after it, counterclockwise)
template <class TM>
void check_border(Certification<TM>& S, const std::vector<std::size_t>& cones,
                  const std::vector<std::vector<std::size_t> >& points_of)
{
  typedef Corner_embedding_certificate Cert;
  Cert::Check_result& R = S.cert.checks[Border_check];
  R.run = true;
  const std::vector<std::size_t>& loop = S.M.border_loop;
  std::vector<int> cone_at(S.M.number_of_vertices(), -1);
  for(std::size_t i = 0; i < cones.size(); ++i)
    cone_at[cones[i]] = static_cast<int>(i);
  std::size_t start = 0;
  while(cone_at[loop[start]] < 0)
    ++start;
  int side = -1;
  for(std::size_t j = 0; j < loop.size(); ++j) {
    const std::size_t v = loop[(start + j) % loop.size()];
    if(cone_at[v] >= 0) {
      side = S.cert.cone_order[cone_at[v]]; // side i runs from tile corner i to corner i + 1
      continue;
    }
    const C t0 = S.tile_corner(S.tile.side_source(side)), t1 = S.tile_corner(S.tile.side_target(side));
    for(std::size_t p : points_of[v]) {
      if(!S.valid[p])
        continue;
      ++R.checked;
      C c0 = t0, c1 = t1, z = S.point(p);
      const int k = S.point_chart(p);
      if(k >= 0) { // in its chart: the side's ends moved there (the chart's own corner to its origin)
        double e0 = 0;
        z = S.chart_point(p);
        c0 = S.tile.side_source(side) == S.charts[k].corner ? C(0, 0) : chart_coordinates(S.charts[k], t0, e0);
        c1 = S.tile.side_target(side) == S.charts[k].corner ? C(0, 0) : chart_coordinates(S.charts[k], t1, e0);
      }
      const double off = distance_to_geodesic(z, c0, c1), beyond = distance_beyond_segment(z, c0, c1);
      S.cert.max_border_distance = (std::max)(S.cert.max_border_distance, (std::max)(off, beyond));
      const std::string who = "boundary vertex " + std::to_string(v) + " at " + point_string(z);
      if(!(off <= S.tolerance[v]))
        record(S.cert, Border_check, Cert::Vertex, v, 0, who + " is off its tile side " + std::to_string(side) + " by " +
               number_string(off) + " (tolerance " + number_string(S.tolerance[v]) + ")");
      else if(!(beyond <= S.tolerance[v]))
        record(S.cert, Border_check, Cert::Vertex, v, 0, who + " is on the line of its tile side " + std::to_string(side) +
               " but beyond the side's segment, by " + number_string(beyond) + " (tolerance " + number_string(S.tolerance[v]) + ")");
    }
  }
}

// degenerate_face and orientation, exact
template <class TM>
void check_faces(Certification<TM>& S)
{
  typedef Corner_embedding_certificate Cert;
  const std::size_t F = S.M.number_of_faces();
  S.face_ok.assign(F, 0);
  S.cert.checks[Degenerate_face_check].run = S.cert.checks[Orientation_check].run = true;
  const auto orient = S.tile.traits().hyperbolic_orientation_2_object();
  typedef typename Poincare_disk_traits_2<>::Point_2 Point_2;
  std::vector<std::size_t> mesh_face_of(S.E.number_of_faces());
  for(std::size_t f = 0; f < F; ++f)
    mesh_face_of[S.efface[f]] = f;
  for(std::size_t e = 0; e < S.E.number_of_faces(); ++e) {
    const std::size_t f = mesh_face_of[e];
    if(!S.face_points_valid(f))
      continue;
    ++S.cert.checks[Degenerate_face_check].checked;
    ++S.cert.checks[Orientation_check].checked;
    const C a = S.corner(f, 0), b = S.corner(f, 1), c = S.corner(f, 2);
    const bool mixed = S.mixed(f);
    const Orientation o = mixed ? robust_orientation({{a, b, c}}, S.ferr[f])
                                : orient(Point_2(a.real(), a.imag()), Point_2(b.real(), b.imag()), Point_2(c.real(), c.imag()));
    if(o == POSITIVE) {
      S.face_ok[f] = 1;
      continue;
    }
    const std::string t = "face " + std::to_string(e) + " " + triangle_string(S.M.face_vertices[f]) +
                          (S.charted && S.face_chart[f] >= 0 ? " (in chart " + std::to_string(S.face_chart[f]) + ")" : std::string());
    if(o == ZERO && mixed)
      record(S.cert, Degenerate_face_check, Cert::Face, e, 0, t + " is too close to degenerate to decide its orientation within the error " +
             number_string((std::max)(S.ferr[f][0], (std::max)(S.ferr[f][1], S.ferr[f][2]))) + " of its corners brought into the chart");
    else if(o == ZERO)
      record(S.cert, Degenerate_face_check, Cert::Face, e, 0, t + " is degenerate: its three points are on one geodesic" +
             std::string(a == b || b == c || a == c ? " (two of them coincide)" : ""));
    else
      record(S.cert, Orientation_check, Cert::Face, e, 0, t + " is negatively oriented (flipped)");
  }
}

// angle_sum and area. Every angle of a positively oriented face is enclosed with certified
// bounds; per vertex whose faces are all positive, the enclosure of its angle sum must lie
// within pi/2 of its cone angle (pi/p at a cone of order p), and with every face positive, the
// area's enclosure within half the orbifold's area of it (see certify_corner_embedding(): the
// possible values are apart by pi (2 pi / p) and by the orbifold's area, so these decide them).
template <class TM>
void check_angle_sums_and_area(Certification<TM>& S, const std::vector<std::size_t>& cones)
{
  typedef Corner_embedding_certificate Cert;
  const std::size_t V = S.M.number_of_vertices(), F = S.M.number_of_faces();
  const bool disk = S.tile.type() == Disk_type;
  std::vector<double> expected(V, 2 * CGAL_PI);
  // the half width of the window the enclosure must lie in: pi/2, and pi/p at a cone of order p,
  // half the spacing of its possible values (multiples of 2 pi / p: the fan closes up to a
  // rotation about the cone's image, one of the group's, by a multiple of 2 pi / p); the same
  // pi/2 for order 2
  std::vector<double> window(V, 0.5 * CGAL_PI);
  if(disk)
    for(std::size_t v : S.M.border_loop)
      expected[v] = CGAL_PI;
  for(std::size_t i = 0; i < cones.size(); ++i) {
    const int j = S.cert.cone_order[i] >= 0 ? S.cert.cone_order[i] : static_cast<int>(i);
    if(S.orders.empty()) {
      expected[cones[i]] = S.tile.signature().cone_angle(j); // 2 pi / order on a sphere, pi / order at a disk's corner
    } else { // (sphere type) the given order's
      expected[cones[i]] = 2.0 * CGAL_PI / S.orders[i];
      window[cones[i]] = CGAL_PI / S.orders[i];
    }
  }
  if(S.angle_tolerance > 0) // a closed surface of genus g >= 1: no group to round the sums to (see certify_corner_embedding())
    window.assign(V, S.angle_tolerance);
  S.angle_sum.assign(V, std::numeric_limits<double>::quiet_NaN());
  std::vector<Enclosure> sum(V);
  std::vector<unsigned int> terms(V, 0); // the degree of each vertex
  std::vector<char> skip(V, 0);
  const double pi_down = CGAL_PI, pi_up = std::nextafter(CGAL_PI, 4.0); // the double below and above pi
  Enclosure area;
  double area_magnitude = 0; // the sum of the terms' magnitudes, for the rounding bound
  bool all_faces = true;
  for(std::size_t f = 0; f < F; ++f)
    if(!S.face_ok[f]) {
      all_faces = false;
      for(int c = 0; c < 3; ++c)
        skip[S.M.face_vertices[f][c]] = 1;
    }
  // by blocks of faces: the angles of a block's positive faces at once (triangle_angles())
  const std::size_t block = 4096;
  std::vector<std::array<C, 3> > triangles;
  std::vector<std::array<Enclosure, 3> > angles;
  for(std::size_t begin = 0; begin < F; begin += block) {
    const std::size_t end = (std::min)(F, begin + block);
    triangles.clear();
    for(std::size_t f = begin; f < end; ++f)
      if(S.face_ok[f])
        triangles.push_back({{S.corner(f, 0), S.corner(f, 1), S.corner(f, 2)}});
    triangle_angles(triangles, angles);
    std::size_t i = 0;
    for(std::size_t f = begin; f < end; ++f) {
      if(!S.face_ok[f])
        continue;
      std::array<Enclosure, 3>& a = angles[i++];
      if(S.mixed(f)) { // corners brought into a chart: within ferr of their places (angle_widening())
        const double w = angle_widening({{S.corner(f, 0), S.corner(f, 1), S.corner(f, 2)}}, S.ferr[f]);
        for(int c = 0; c < 3; ++c) {
          a[c].lo = (std::max)(0.0, a[c].lo - w);
          a[c].hi = (std::min)(pi_up, a[c].hi + w);
        }
      }
      for(int c = 0; c < 3; ++c) {
        const std::size_t v = S.M.face_vertices[f][c];
        add(sum[v], a[c]);
        ++terms[v];
      }
      // the face's area is pi minus its angles
      const Enclosure t{pi_down - (a[0].hi + a[1].hi + a[2].hi), pi_up - (a[0].lo + a[1].lo + a[2].lo)};
      add(area, t);
      area_magnitude += (std::max)(std::abs(t.lo), std::abs(t.hi));
    }
  }
  Cert::Check_result& R = S.cert.checks[Angle_sum_check];
  R.run = true;
  for(std::size_t v = 0; v < V; ++v) {
    if(skip[v])
      continue;
    ++R.checked;
    const Enclosure s = widen_sum(sum[v], terms[v], sum[v].hi);
    const double e = expected[v], w = window[v];
    S.angle_sum[v] = 0.5 * (s.lo + s.hi);
    S.cert.max_angle_sum_deviation = (std::max)(S.cert.max_angle_sum_deviation, std::abs(0.5 * (s.lo + s.hi) - e));
    S.cert.max_angle_sum_uncertainty = (std::max)(S.cert.max_angle_sum_uncertainty, s.hi - s.lo);
    if(s.lo > e - w && s.hi < e + w)
      continue;
    std::ostringstream os;
    os.precision(6);
    os << "vertex " << v << (S.is_cone[v] ? " (a cone)" : (S.on_border[v] ? " (on the boundary)" : ""))
       << " has an angle sum of " << 0.5 * (s.lo + s.hi) << " (certified in [" << s.lo << ", " << s.hi
       << "]), expected " << e << " = " << e / CGAL_PI << " pi";
    if(s.lo <= e + w && s.hi >= e - w)
      os << ": too uncertain to decide";
    else if(s.lo > e && S.angle_tolerance == 0)
      os << ": its faces wind around it " << (0.5 * (s.lo + s.hi)) / e << " times";
    else if(S.angle_tolerance > 0)
      os << ": off by " << 0.5 * (s.lo + s.hi) - e << ", tolerance " << S.angle_tolerance;
    record(S.cert, Angle_sum_check, Cert::Vertex, v, 0, os.str());
  }
  S.cert.checks[Area_check].run = all_faces;
  if(!all_faces)
    return;
  ++S.cert.checks[Area_check].checked;
  // the sum's rounding, and each term's own (three sums of angles up to pi: 9 pi u at most)
  Enclosure A = widen_sum(area, F, area_magnitude);
  A.lo -= static_cast<double>(F) * 10 * CGAL_PI * 1.12e-16;
  A.hi += static_cast<double>(F) * 10 * CGAL_PI * 1.12e-16;
  S.cert.area_lower = A.lo;
  S.cert.area_upper = A.hi;
  const double want = S.cert.expected_area;
  if(!(A.lo > 0.5 * want && A.hi < 1.5 * want)) {
    std::ostringstream os;
    os.precision(9);
    os << "the total hyperbolic area is " << 0.5 * (A.lo + A.hi) << " (certified in [" << A.lo << ", " << A.hi
       << "]), but the orbifold's is " << want << " (" << want / CGAL_PI << " pi): the faces cover it "
       << 0.5 * (A.lo + A.hi) / want << " times";
    record(S.cert, Area_check, Cert::No_element, 0, 0, os.str());
  }
}

// a seam edge: the mesh edge from u to w of face f (corners cf_u, cf_w) and of face g (corners
// cu, cw), f < g, with the points pa (of u) and pb (of w) in f (1) and in g (2)
struct Seam_edge
{
  std::size_t f, g;
  int cf_u, cf_w, cu, cw;
  std::size_t u, w, pa1, pb1, pa2, pb2;
};

// Calls visit(Seam_edge) for every mesh edge whose two faces give different points to an end
// (each edge once, in the order of the faces and their corners), counting them
// (Corner_embedding_certificate::number_of_seam_edges).
template <class TM, class Visit>
void for_each_seam_edge(Certification<TM>& S, Visit visit)
{
  const TM& tm = S.M.tm;
  for(std::size_t f = 0; f < S.M.number_of_faces(); ++f) {
    for(int c = 0; c < 3; ++c) {
      const auto h = S.M.face_halfedges[f][c];
      const auto o = opposite(h, tm);
      if(is_border(o, tm))
        continue;
      const std::size_t g = S.M.index(face(o, tm));
      if(g < f)
        continue; // each edge once
      // h runs from corner (c + 2) % 3 (vertex u) to corner c (vertex w) of f
      const std::size_t u = S.M.face_vertices[f][(c + 2) % 3], w = S.M.face_vertices[f][c];
      int cu = 0, cw = 0;
      while(S.M.face_vertices[g][cu] != u) ++cu;
      while(S.M.face_vertices[g][cw] != w) ++cw;
      const std::size_t pa1 = S.pid[f][(c + 2) % 3], pb1 = S.pid[f][c], pa2 = S.pid[g][cu], pb2 = S.pid[g][cw];
      if(same_point(S, pa1, pa2) && same_point(S, pb1, pb2))
        continue;
      ++S.cert.number_of_seam_edges;
      visit(Seam_edge{f, g, (c + 2) % 3, c, cu, cw, u, w, pa1, pb1, pa2, pb2});
    }
  }
}

// seams: every mesh edge whose two faces give different points to an end; the
// orientation-preserving isometry that maps the first side's copy to the second's is computed
// from them, and must be a side pairing of the tile: the pairing that maps both copies best
// must place them within the tolerance of the edge
template <class TM>
void check_seams(Certification<TM>& S)
{
  typedef Corner_embedding_certificate Cert;
  typedef Hyperbolic_isometry_2<long double> Iso;
  Cert::Check_result& R = S.cert.checks[Seam_check];
  R.run = true;
  std::vector<std::pair<int, Iso> > generators;
  for(int i = 0; i < S.tile.number_of_sides(); ++i)
    if(S.tile.side_pairing(i).is_orientation_preserving())
      generators.emplace_back(i, Iso(S.tile.side_pairing(i)));
  S.cert.seam_edges_per_side.assign(S.tile.number_of_sides(), 0);
  auto same = [&](std::size_t p, std::size_t q) { return same_point(S, p, q); };
  for_each_seam_edge(S, [&](const Seam_edge& e) {
      const std::size_t f = e.f, g = e.g, u = e.u, w = e.w, pa1 = e.pa1, pb1 = e.pb1, pa2 = e.pa2, pb2 = e.pb2;
      if(!(S.valid[pa1] && S.valid[pb1] && S.valid[pa2] && S.valid[pb2]))
        return;
      if(S.charted && (S.face_chart[f] >= 0 || S.face_chart[g] >= 0)) {
        if(!S.face_points_valid(f) || !S.face_points_valid(g))
          return;
        ++R.checked;
        check_charted_seam(S, f, g, e.cf_u, e.cf_w, e.cu, e.cw, generators);
        return;
      }
      ++R.checked;
      const C a1 = S.point(pa1), b1 = S.point(pb1), a2 = S.point(pa2), b2 = S.point(pb2);
      const std::string where = "edge (" + std::to_string(u) + ", " + std::to_string(w) + ") between faces " +
                                std::to_string(S.efface[f]) + " and " + std::to_string(S.efface[g]);
      if(generators.empty()) {
        record(S.cert, Seam_check, Cert::Edge, u, w, where + " is a seam (its faces give vertex " +
               std::to_string(same(pa1, pa2) ? w : u) + " two points), but a disk-type embedding has none: the tile's side pairings are reflections");
        return;
      }
      int best = -1;
      double best_m = std::numeric_limits<double>::infinity();
      for(std::size_t i = 0; i < generators.size(); ++i) {
        const double m = (std::max)(image_distance(generators[i].second, a1, a2), image_distance(generators[i].second, b1, b2));
        if(m < best_m) { best_m = m; best = static_cast<int>(i); }
      }
      const double length = (std::min)(std::abs(a1 - b1), std::abs(a2 - b2));
      const double tol = (std::min)(absolute_tolerance, relative_tolerance * length);
      const Iso h_iso = isometry_from_copies(a1, b1, a2, b2);
      if(!(best_m <= tol)) {
        std::ostringstream os;
        os.precision(6);
        os << where << ": its two sides are related by no side pairing of the tile (the isometry computed from them is "
           << Hyperbolic_isometry_2<double>(h_iso) << "; the nearest, side " << generators[best].first
           << "'s pairing, misplaces a copy by " << best_m << ", tolerance " << tol << ")";
        record(S.cert, Seam_check, Cert::Edge, u, w, os.str());
        return;
      }
      ++S.cert.seam_edges_per_side[generators[best].first];
      S.cert.max_seam_mismatch = (std::max)(S.cert.max_seam_mismatch, best_m);
      S.cert.max_relative_seam_mismatch = (std::max)(S.cert.max_relative_seam_mismatch, best_m / length);
      S.cert.max_seam_isometry_deviation =
        (std::max)(S.cert.max_seam_isometry_deviation, coefficient_distance(h_iso, generators[best].second));
  });
}

} // namespace corner_certificate
} // namespace internal

} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_CERTIFIER_CORNER_EMBEDDING_CHECKS_H
