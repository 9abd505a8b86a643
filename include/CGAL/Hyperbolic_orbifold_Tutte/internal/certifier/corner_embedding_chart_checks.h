// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_CERTIFIER_CORNER_EMBEDDING_CHART_CHECKS_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_CERTIFIER_CORNER_EMBEDDING_CHART_CHECKS_H

// The checks of certify_corner_embedding() that concern charts around cone images
// (Corner_embedding::charts): the chart table and the chart points (the check "charts"), each
// face's corners in its frame, and the seams with a face in a chart. The numbers are in
// corner_embedding_charts.h. Written for the certificate alone: it shares the isometries and
// the tile with the solver, nothing else.

#include <CGAL/Hyperbolic_orbifold_Tutte/Corner_embedding_certificate.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/Hyperbolic_isometry_2.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/certifier/corner_embedding_charts.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/certifier/corner_embedding_geometry.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/certifier/corner_embedding_state.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/certifier/corner_embedding_topology.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {
namespace internal {
namespace corner_certificate {

// check_charts(): the chart table
template <class TM>
void check_chart_table(Certification<TM>& S)
{
  typedef Corner_embedding_certificate Cert;
  Cert::Check_result& R = S.cert.checks[Chart_check];
  S.charts.assign(S.E.charts.size(), Chart_model());
  for(std::size_t i = 0; i < S.charts.size(); ++i) {
    Chart_model& m = S.charts[i];
    m.a = C(S.E.charts[i][0], S.E.charts[i][1]);
    m.b = C(S.E.charts[i][2], S.E.charts[i][3]);
    m.corner = S.E.chart_corners[i];
    m.abs_a = std::abs(m.a);
    m.abs_b = std::abs(m.b);
    ++R.checked;
    const std::string who = "chart " + std::to_string(i);
    if(!(std::isfinite(m.a.real()) && std::isfinite(m.a.imag()) && std::isfinite(m.b.real()) && std::isfinite(m.b.imag()))) {
      record(S.cert, Chart_check, Cert::Chart, i, 0, who + " has a coefficient that is not finite");
      continue;
    }
    if(m.corner < 0 || m.corner >= S.tile.number_of_corners()) {
      record(S.cert, Chart_check, Cert::Chart, i, 0, who + " is centred at tile corner " + std::to_string(m.corner) +
             ", but the tile has " + std::to_string(S.tile.number_of_corners()) + " corners");
      continue;
    }
    if(!is_disk_automorphism(m.a, m.b)) {
      record(S.cert, Chart_check, Cert::Chart, i, 0, who + " is not an isometry of the disk: |a| = " + number_string(m.abs_a) +
             " is not above |b| = " + number_string(m.abs_b));
      continue;
    }
    const double defect = normalization_defect(m.a, m.b), nb = chart_normalization_bound * (m.abs_a + m.abs_b) * (m.abs_a + m.abs_b);
    if(!(defect <= nb)) {
      record(S.cert, Chart_check, Cert::Chart, i, 0, who + " is not normalized: |a|^2 - |b|^2 differs from 1 by up to " + number_string(defect) +
             " (bound " + number_string(nb) + ": the chart's rounding)");
      continue;
    }
    m.c = S.tile_corner(m.corner);
    m.offset = origin_offset(m.a, m.b, m.c);
    S.cert.max_chart_origin_offset = (std::max)(S.cert.max_chart_origin_offset, m.offset);
    if(!(m.offset <= chart_origin_bound)) {
      const C o = -m.b / m.a;
      record(S.cert, Chart_check, Cert::Chart, i, 0, who + "'s origin is the tile point " + point_string(o) + ", " +
             number_string(std::abs(o - m.c)) + " away from tile corner " + std::to_string(m.corner) + " " + point_string(m.c) +
             " (bound " + number_string(chart_origin_bound) + ": the chart's rounding)");
      continue;
    }
    m.ok = true;
  }
}

// check_charts(): the chart points, in the embedding's face order (the first failure is the
// first in the file); `mesh_face_of`: the mesh face of each face of the embedding
template <class TM>
void check_chart_points(Certification<TM>& S, const std::vector<std::size_t>& mesh_face_of)
{
  typedef Corner_embedding_certificate Cert;
  Cert::Check_result& R = S.cert.checks[Chart_check];
  std::vector<char> seen(S.E.points.size(), 0);
  for(std::size_t e = 0; e < S.E.number_of_faces(); ++e) {
    const std::size_t f = mesh_face_of[e];
    for(int c = 0; c < 3; ++c) {
      const std::size_t p = S.pid[f][c];
      const int k = S.point_chart(p);
      if(k < 0 || seen[p])
        continue;
      seen[p] = 1;
      ++S.cert.number_of_chart_points;
      ++R.checked;
      const std::size_t v = S.M.face_vertices[f][c];
      const C w = S.chart_point(p);
      const std::string who = "vertex " + std::to_string(v) + " (vt " + std::to_string(p + 1) + ", in face " + std::to_string(e) +
                              ") has its chart point " + point_string(w) + " in chart " + std::to_string(k);
      if(!std::isfinite(w.real()) || !std::isfinite(w.imag())) {
        record(S.cert, Chart_check, Cert::Vertex, v, 0, who + ": not a finite point");
        S.valid[p] = 0;
        continue;
      }
      if(!strictly_inside_unit_disk(w.real(), w.imag())) {
        record(S.cert, Chart_check, Cert::Vertex, v, 0, who + ": not strictly inside the unit disk");
        S.valid[p] = 0;
        continue;
      }
      if(!S.charts[k].ok) {
        S.valid[p] = 0;
        continue;
      }
      if(!S.valid[p])
        continue; // its vt line is not a point of the disk (reported)
      C z;
      double radius = 0, rounding = 0;
      tile_point_of_chart_point(S.charts[k], w, z, radius, rounding);
      const double d = std::abs(z - S.point(p)) * (1 + 4 * unit_roundoff), bound = radius + rounding;
      S.cert.max_chart_point_offset = (std::max)(S.cert.max_chart_point_offset, d / bound);
      if(!(d <= bound)) {
        record(S.cert, Chart_check, Cert::Vertex, v, 0, who + ", the tile point " + point_string(z) + ", " + number_string(d) +
               " away from its vt line " + point_string(S.point(p)) + " (bound " + number_string(bound) + ": their rounding)");
        S.valid[p] = 0;
      }
    }
  }
}

// check_charts(): each face in one chart, its corners in its frame
template <class TM>
void place_faces_in_charts(Certification<TM>& S, const std::vector<std::size_t>& mesh_face_of)
{
  typedef Corner_embedding_certificate Cert;
  Cert::Check_result& R = S.cert.checks[Chart_check];
  const std::size_t F = S.M.number_of_faces();
  S.face_chart.assign(F, -1);
  S.frame_ok.assign(F, 1);
  S.fpos.resize(F);
  S.ferr.resize(F);
  for(std::size_t e = 0; e < S.E.number_of_faces(); ++e) {
    const std::size_t f = mesh_face_of[e];
    int k = -1;
    for(int c = 0; c < 3; ++c) {
      const int kc = S.point_chart(S.pid[f][c]);
      if(kc < 0)
        continue;
      if(k >= 0 && kc != k) {
        ++R.checked;
        record(S.cert, Chart_check, Cert::Face, e, 0, "face " + std::to_string(e) + " " + triangle_string(S.M.face_vertices[f]) +
               " has corners in charts " + std::to_string(k) + " and " + std::to_string(kc) + ": a face is written in one chart");
        S.frame_ok[f] = 0;
      }
      k = kc;
    }
    S.face_chart[f] = k;
    if(k >= 0 && S.frame_ok[f]) {
      ++S.cert.number_of_charted_faces;
      if(!S.charts[k].ok)
        S.frame_ok[f] = 0;
    }
    bool mixed = false;
    for(int c = 0; c < 3; ++c) {
      const std::size_t p = S.pid[f][c];
      S.ferr[f][c] = 0;
      if(k < 0 || !S.frame_ok[f]) {
        S.fpos[f][c] = S.point(p);
      } else if(S.point_chart(p) == k) {
        S.fpos[f][c] = S.chart_point(p);
      } else {
        mixed = true;
        if(!S.valid[p]) {
          S.fpos[f][c] = C(0, 0);
          continue;
        }
        S.fpos[f][c] = chart_coordinates(S.charts[k], S.point(p), S.ferr[f][c]);
        S.cert.max_mixed_corner_error = (std::max)(S.cert.max_mixed_corner_error, S.ferr[f][c]);
      }
    }
    if(mixed && k >= 0 && S.frame_ok[f])
      ++S.cert.number_of_mixed_faces;
  }
}

// charts (embeddings given partly in charts around cone images, Corner_embedding::charts):
// the chart table (finite, isometries of the disk, normalized, centred at their tile corners
// within chart_origin_bound), every chart point finite, strictly inside the disk (exact) and
// consistent with its point (its tile point within the rounding bound of it), every face's
// charted corners in one chart; then each face's corners in its frame (S.fpos, S.ferr).
// Without charts: run, nothing checked.
template <class TM>
void check_charts(Certification<TM>& S)
{
  typedef Corner_embedding_certificate Cert;
  Cert::Check_result& R = S.cert.checks[Chart_check];
  R.run = true;
  if(!S.charted)
    return;
  const std::size_t F = S.M.number_of_faces();
  S.cert.number_of_charts = S.E.charts.size();
  check_chart_table(S);
  // the chart points, in the embedding's face order (the first failure is the first in the file)
  std::vector<std::size_t> mesh_face_of(S.E.number_of_faces());
  for(std::size_t f = 0; f < F; ++f)
    mesh_face_of[S.efface[f]] = f;
  check_chart_points(S, mesh_face_of);
  place_faces_in_charts(S, mesh_face_of);
}

// A seam edge with a face in a chart: corners (ca, cb) of face f and (da, db) of face g are
// its ends' two copies, each in its face's frame. Between two charts of one cone glued by a
// side pairing that maps the one's corner onto the other's, the pairing conjugated by the
// ideal charts is a rotation about the origin (seam_rotation()): the copies must match by it
// within its rounding, relative to their distance to the origin (any depth). Otherwise (a
// chart and the tile's coordinates, or charts of two cones) the pairing conjugated by the
// stored charts, in long double, must match them within the certificate's position tolerance
// (of the edge's length in the frames), plus the error bounds of the corners and of the charts.
template <class TM, class Generators>
void check_charted_seam(Certification<TM>& S, std::size_t f, std::size_t g, int ca, int cb, int da, int db,
                        const Generators& generators)
{
  typedef Corner_embedding_certificate Cert;
  typedef Hyperbolic_isometry_2<long double> Iso;
  typedef std::complex<long double> CL;
  const std::size_t u = S.M.face_vertices[f][ca], w = S.M.face_vertices[f][cb];
  const int kf = S.face_chart[f], kg = S.face_chart[g];
  const C a1 = S.corner(f, ca), b1 = S.corner(f, cb), a2 = S.corner(g, da), b2 = S.corner(g, db);
  const double e1 = (std::max)(S.ferr[f][ca], S.ferr[f][cb]), e2 = (std::max)(S.ferr[g][da], S.ferr[g][db]);
  auto frame_name = [](int k) { return k < 0 ? std::string("the tile's coordinates") : "chart " + std::to_string(k); };
  const std::string where = "edge (" + std::to_string(u) + ", " + std::to_string(w) + ") between faces " + std::to_string(S.efface[f]) +
                            " (in " + frame_name(kf) + ") and " + std::to_string(S.efface[g]) + " (in " + frame_name(kg) + ")";
  if(generators.empty()) {
    record(S.cert, Seam_check, Cert::Edge, u, w, where + " is a seam, but a disk-type embedding has none: the tile's side pairings are reflections");
    return;
  }
  auto stored = [&](int k) {
    if(k < 0)
      return Iso();
    const Chart_model& m = S.charts[k];
    return Iso(CL(m.a.real(), m.a.imag()), CL(m.b.real(), m.b.imag()));
  };
  // the frame's deviation from the ideal chart at the seam's copies (chart_coordinates())
  auto deviation = [&](int k, const C& p, const C& q) {
    if(k < 0)
      return 0.0;
    const Chart_model& m = S.charts[k];
    const double gap = 1 - std::abs(m.c) * (1 + 4 * unit_roundoff) - m.offset;
    (void)p; (void)q;
    return gap > 0 ? 2 * m.offset / gap : std::numeric_limits<double>::infinity();
  };
  const bool one_cone = kf >= 0 && kg >= 0 && S.tile.corner_cone(S.charts[kf].corner) == S.tile.corner_cone(S.charts[kg].corner);
  int best = -1;
  bool best_rotation = false;
  double best_ratio = std::numeric_limits<double>::infinity(), best_m = 0, best_tol = 0, best_scale = 0;
  const double length = (std::min)(std::abs(a1 - b1), std::abs(a2 - b2));
  for(std::size_t i = 0; i < generators.size(); ++i) {
    const Hyperbolic_isometry_2<double> gi(generators[i].second);
    bool rotation = false;
    double m = 0, tol = 0, scale = 0;
    if(one_cone && std::abs(gi.apply(S.charts[kf].c) - S.charts[kg].c) <= absolute_tolerance) {
      // a rotation about the cone's image
      rotation = true;
      double angle_error = 0;
      const C rot = seam_rotation(S.charts[kf], S.charts[kg], gi, angle_error);
      m = (std::max)(std::abs(rot * a1 - a2), std::abs(rot * b1 - b2));
      scale = (std::max)((std::max)(std::abs(a1), std::abs(b1)), (std::max)(std::abs(a2), std::abs(b2)));
      auto norm = [](const Chart_model& x) { return x.abs_a + x.abs_b; };
      const double writer = 16 * unit_roundoff * norm(S.charts[kf]) * norm(S.charts[kg]) * (std::abs(gi.a()) + std::abs(gi.b())) + 16 * unit_roundoff;
      tol = (2 * angle_error + writer) * scale + e1 + e2;
    } else {
      const Iso M = stored(kg) * generators[i].second * stored(kf).inverse();
      m = (std::max)(image_distance(M, a1, a2), image_distance(M, b1, b2));
      const CL d1 = M.derivative(CL(a1.real(), a1.imag())), d2 = M.derivative(CL(b1.real(), b1.imag()));
      const double stretch = static_cast<double>((std::max)(std::abs(d1), std::abs(d2)));
      tol = (std::min)(absolute_tolerance, relative_tolerance * length) +
            2 * ((e1 + deviation(kf, a1, b1)) * (std::max)(1.0, stretch) + e2 + deviation(kg, a2, b2));
      scale = length;
    }
    const double ratio = m / tol;
    if(ratio < best_ratio) {
      best_ratio = ratio; best = static_cast<int>(i); best_rotation = rotation; best_m = m; best_tol = tol; best_scale = scale;
    }
  }
  if(!(best_ratio <= 1)) {
    std::ostringstream os;
    os.precision(6);
    os << where << ": its two sides are related by no side pairing of the tile (the nearest, side " << generators[best].first
       << "'s pairing" << (best_rotation ? ", between the charts a rotation about the cone's image," : " conjugated by the charts,")
       << " misplaces a copy by " << best_m << (best_rotation ? " (" + number_string(best_m / best_scale) + " of its distance to the origin)" : std::string())
       << ", tolerance " << best_tol << ")";
    record(S.cert, Seam_check, Cert::Edge, u, w, os.str());
    return;
  }
  ++S.cert.seam_edges_per_side[generators[best].first];
  if(best_rotation) {
    ++S.cert.number_of_chart_seam_edges;
    S.cert.max_chart_seam_mismatch = (std::max)(S.cert.max_chart_seam_mismatch, best_m / best_scale);
  } else {
    S.cert.max_seam_mismatch = (std::max)(S.cert.max_seam_mismatch, best_m);
    if(length > 0)
      S.cert.max_relative_seam_mismatch = (std::max)(S.cert.max_relative_seam_mismatch, best_m / length);
  }
}

} // namespace corner_certificate
} // namespace internal
} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_CERTIFIER_CORNER_EMBEDDING_CHART_CHECKS_H
