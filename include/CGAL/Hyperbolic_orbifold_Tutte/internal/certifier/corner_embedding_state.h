// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_CERTIFIER_CORNER_EMBEDDING_STATE_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_CERTIFIER_CORNER_EMBEDDING_STATE_H

// The state of one run of certify_corner_embedding(): the mesh, the embedding, the tile, the
// corner points per mesh face (in their frames when the embedding has charts), and the
// tolerances of the positions. Written for the certificate alone.

#include <CGAL/Hyperbolic_orbifold_Tutte/Corner_embedding.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/Corner_embedding_certificate.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/Orbifold_tile.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/Poincare_disk_traits_2.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/certifier/corner_embedding_charts.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/certifier/corner_embedding_geometry.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/certifier/corner_embedding_topology.h>

#include <array>
#include <sstream>
#include <string>
#include <vector>

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {
namespace internal {
namespace corner_certificate {

// the tolerances of the positions (see certify_corner_embedding()'s documentation)
constexpr double absolute_tolerance = 1e-9;
constexpr double relative_tolerance = 1e-6;

inline std::string point_string(const C& z)
{
  std::ostringstream os;
  os.precision(17);
  os << "(" << z.real() << ", " << z.imag() << ")";
  return os.str();
}

inline std::string number_string(double x)
{
  std::ostringstream os;
  os.precision(3);
  os << x;
  return os.str();
}

// The state of one certification: the mesh, the tile, and the corner points per mesh face.
template <class TriangleMesh>
struct Certification
{
  typedef Corner_embedding_certificate Cert;
  typedef Orbifold_tile<Poincare_disk_traits_2<> > Tile;

  const Indexed_mesh<TriangleMesh>& M;
  const Corner_embedding& E;
  const Tile& tile;
  Cert& cert;
  std::vector<std::size_t> efface;           // per mesh face, its embedding face
  std::vector<std::array<std::size_t, 3> > pid; // per mesh face and corner, its point
  std::vector<char> valid;                   // per point: finite and strictly inside the disk
  std::vector<double> tolerance;             // per vertex: min(absolute, relative x shortest incident edge)
  std::vector<char> is_cone;                 // per vertex
  std::vector<char> on_border;               // per vertex
  std::vector<int> orders;                   // per given cone, its order when some order is not 2; empty: all 2
  std::vector<char> face_ok;                 // per mesh face: valid points, positively oriented
  double angle_tolerance = 0;                // > 0 (closed genus g >= 1): the angle sums' window, for every vertex
  std::vector<double> angle_sum;             // per vertex: the middle of its angle sum's enclosure (NaN: not checked)
  // with charts (E.has_charts()): the charts, and each face's corners in its frame
  bool charted = false;
  std::vector<Chart_model> charts;
  std::vector<int> face_chart;               // per mesh face: its chart, -1 for the tile's coordinates
  std::vector<char> frame_ok;                // per mesh face: its chart is sound, its corners in one chart
  std::vector<std::array<C, 3> > fpos;       // per mesh face: its corners in its frame
  std::vector<std::array<double, 3> > ferr;  // and a bound on their error (0: exact, as given)

  Certification(const Indexed_mesh<TriangleMesh>& m, const Corner_embedding& e, const Tile& t, Cert& c)
    : M(m), E(e), tile(t), cert(c) {}

  C point(std::size_t p) const { return C(E.points[p][0], E.points[p][1]); }
  int point_chart(std::size_t p) const { return charted ? E.point_charts[p] : -1; }
  C chart_point(std::size_t p) const { return C(E.chart_points[p][0], E.chart_points[p][1]); }
  // the corner in its face's frame (the tile's coordinates without charts)
  C corner(std::size_t f, int c) const { return charted ? fpos[f][c] : point(pid[f][c]); }
  bool mixed(std::size_t f) const { return charted && (ferr[f][0] > 0 || ferr[f][1] > 0 || ferr[f][2] > 0); }
  C tile_corner(int i) const { return C(CGAL::to_double(tile.corner(i).x()), CGAL::to_double(tile.corner(i).y())); }
  std::string face_name(std::size_t f) const { return "face " + std::to_string(efface[f]); }
  bool face_points_valid(std::size_t f) const
  {
    return valid[pid[f][0]] && valid[pid[f][1]] && valid[pid[f][2]] && (!charted || frame_ok[f]);
  }
};

// two points are the same: one vt, or equal coordinates and charts (and chart points)
template <class TM>
bool same_point(const Certification<TM>& S, std::size_t p, std::size_t q)
{
  if(p == q)
    return true;
  if(S.E.points[p] != S.E.points[q] || S.point_chart(p) != S.point_chart(q))
    return false;
  return S.point_chart(p) < 0 || S.E.chart_points[p] == S.E.chart_points[q];
}

} // namespace corner_certificate
} // namespace internal
} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_CERTIFIER_CORNER_EMBEDDING_STATE_H
