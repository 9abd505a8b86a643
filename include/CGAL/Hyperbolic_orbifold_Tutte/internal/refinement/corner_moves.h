// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_REFINEMENT_CORNER_MOVES_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_REFINEMENT_CORNER_MOVES_H

// The refinement's moves of A's corners in the Poincare disk (see arap_on_target.h for the
// subsystem). Every vertex that moves has one primary corner (the one map_vertices() locates);
// its other corners, copies across the seams, are the primary's images by the side pairings
// read once from the embedding (the isometry taking a cut edge's two endpoints on one side to
// the other side), so the copies stay related by the orbifold group as they move. The moves of
// the vertices of a face that would turn over are undone, so each iterate has all faces
// oriented as before by the exact predicate.

#include <CGAL/Hyperbolic_orbifold_Tutte/Hyperbolic_isometry_2.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/certifier/corner_embedding_geometry.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/core/dense_index.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/core/disk_models.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/core/filtered_predicates.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <Eigen/Dense>

#include <array>
#include <cmath>
#include <complex>
#include <vector>

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {
namespace internal {

template <class TriangleMesh>
class Corner_moves
{
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename GT::vertex_descriptor vertex_descriptor;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  typedef typename GT::face_descriptor face_descriptor;
  typedef std::complex<double> C;
  typedef Hyperbolic_isometry_2<long double> Iso;

public:
  // `corners[hidx(h)]`: the point of corner target(h) in face(h) (border halfedges unused);
  // `fixed[vidx(v)]`: vertices that do not move (landmarks, border vertices and isolated ones
  // are added here)
  Corner_moves(const TriangleMesh& tm, const Dense_index<vertex_descriptor>& vidx, const Dense_index<halfedge_descriptor>& hidx,
               const std::vector<C>& corners, std::vector<char>& fixed)
    : tm_(tm), vidx_(vidx), hidx_(hidx), primary_(num_vertices(tm), GT::null_halfedge()), pairing_(corners.size(), -1),
      checked_(corners.size(), 0)
  {
    for(vertex_descriptor v : vertices(tm)) {
      const std::size_t i = vidx(v);
      const halfedge_descriptor h0 = halfedge(v, tm);
      if(h0 == GT::null_halfedge() || is_border(v, tm)) {
        fixed[i] = 1;
        if(h0 != GT::null_halfedge())
          for(halfedge_descriptor h : halfedges_around_target(h0, tm))
            if(!is_border(h, tm)) {
              primary_[i] = h;
              break;
            }
        continue;
      }
      primary_[i] = h0; // (an inner vertex: no border halfedge around it)
      if(!fixed[i])
        read_pairings(h0, corners);
    }
  }

  // the primary corner of vertex i (null for an isolated vertex)
  halfedge_descriptor primary(std::size_t i) const { return primary_[i]; }

  // puts vertex i's corners at the images of `z` (a point of the primary corner's frame)
  void place(std::size_t i, const C& z, std::vector<C>& corners) const
  {
    const halfedge_descriptor h0 = primary_[i];
    for(halfedge_descriptor h : halfedges_around_target(h0, tm_)) {
      const int p = pairing_[hidx_(h)];
      if(p < 0)
        corners[hidx_(h)] = z;
      else {
        const std::complex<long double> w = isometries_[p].apply(std::complex<long double>(z.real(), z.imag()));
        corners[hidx_(h)] = C(static_cast<double>(w.real()), static_cast<double>(w.imag()));
      }
    }
  }

  // puts vertex i's corners back to `old` (bitwise)
  void restore(std::size_t i, const std::vector<C>& old, std::vector<C>& corners) const
  {
    for(halfedge_descriptor h : halfedges_around_target(primary_[i], tm_))
      if(!is_border(h, tm_))
        corners[hidx_(h)] = old[hidx_(h)];
  }

  // the sign of face f's corners: the sign of det[(x_i, y_i, 1 + x_i^2 + y_i^2)]
  // (filtered_predicates.h), first in double with rows 1 and 2 less row 0 (accurate for the
  // tiny triangles near the disk's rim, where the static filter of the exact predicate fails),
  // trusted when it exceeds 1e-12 of the sum of its terms' magnitudes, else the exact predicate
  Sign orientation(face_descriptor f, const std::vector<C>& corners) const
  {
    std::array<C, 3> z;
    int k = 0;
    for(halfedge_descriptor h : halfedges_around_face(halfedge(f, tm_), tm_))
      z[k++] = corners[hidx_(h)];
    const double x0 = z[0].real(), y0 = z[0].imag();
    const double dx1 = z[1].real() - x0, dy1 = z[1].imag() - y0, dx2 = z[2].real() - x0, dy2 = z[2].imag() - y0;
    const double dw1 = dx1 * (z[1].real() + x0) + dy1 * (z[1].imag() + y0), dw2 = dx2 * (z[2].real() + x0) + dy2 * (z[2].imag() + y0);
    const double w0 = 1 + x0 * x0 + y0 * y0;
    const double det = x0 * (dy1 * dw2 - dw1 * dy2) - y0 * (dx1 * dw2 - dw1 * dx2) + w0 * (dx1 * dy2 - dy1 * dx2);
    const double size = std::abs(x0) * (std::abs(dy1 * dw2) + std::abs(dw1 * dy2)) + std::abs(y0) * (std::abs(dx1 * dw2) + std::abs(dw1 * dx2)) +
                        w0 * (std::abs(dx1 * dy2) + std::abs(dy1 * dx2));
    if(det > 1e-12 * size)
      return POSITIVE;
    if(det < -1e-12 * size)
      return NEGATIVE;
    return poincare_orientation_sign_filtered(z[0].real(), z[0].imag(), z[1].real(), z[1].imag(), z[2].real(), z[2].imag());
  }

  // Moves every vertex i with `moves[i]` to `to[i]` (a point of its primary corner's frame),
  // then undoes the moves of the vertices of every face whose orientation is not `sign` until
  // none is left (each round undoes at least one move, and a face whose vertices are all back
  // is as it was). Sets `undone[i]` for the undone moves and returns their number.
  std::size_t move(const std::vector<C>& to, const std::vector<char>& moves, const std::vector<C>& old, std::vector<C>& corners, Sign sign,
                   std::vector<char>& undone_flag) const
  {
    std::vector<char> moved_flag(moves.size(), 0);
    std::vector<std::size_t> moved;
    for(std::size_t i = 0; i < moves.size(); ++i)
      if(moves[i]) {
        place(i, to[i], corners);
        moved.push_back(i);
        moved_flag[i] = 1;
      }
    std::size_t undone = 0;
    while(!moved.empty()) {
      std::vector<std::size_t> bad;
      ++stamp_;
      for(std::size_t i : moved)
        for(halfedge_descriptor h : halfedges_around_target(primary_[i], tm_)) {
          if(is_border(h, tm_) || checked_[hidx_(h)] == stamp_)
            continue;
          for(halfedge_descriptor g : halfedges_around_face(h, tm_))
            checked_[hidx_(g)] = stamp_; // (a face once per round)
          if(orientation(face(h, tm_), corners) != sign)
            for(vertex_descriptor v : vertices_around_face(h, tm_))
              if(moved_flag[vidx_(v)]) {
                moved_flag[vidx_(v)] = 0;
                undone_flag[vidx_(v)] = 1;
                restore(vidx_(v), old, corners);
                bad.push_back(vidx_(v));
              }
        }
      undone += bad.size();
      moved.swap(bad); // the faces to check again: those around the vertices just put back
    }
    return undone;
  }

private:
  // the side pairings around inner vertex v, from its primary corner h0's frame: the corners
  // of one fan (one point) share one pairing, so they stay bitwise equal as they move
  void read_pairings(halfedge_descriptor h0, const std::vector<C>& corners)
  {
    std::vector<std::pair<C, int> > fans{{corners[hidx_(h0)], -1}};
    Iso g; // primary frame -> frame of the current face
    halfedge_descriptor h = h0;
    do {
      const halfedge_descriptor n = opposite(next(h, tm_), tm_); // the next face around v
      if(n == h0)
        break;
      const C zv = corners[hidx_(h)], zw = corners[hidx_(next(h, tm_))];
      const C zv2 = corners[hidx_(n)], zw2 = corners[hidx_(prev(n, tm_))];
      if(!(zv == zv2 && zw == zw2))
        g = corner_certificate::isometry_from_copies(zv, zw, zv2, zw2) * g;
      int p = -2;
      for(const auto& fan : fans)
        if(fan.first == zv2)
          p = fan.second;
      if(p == -2) {
        p = static_cast<int>(isometries_.size());
        isometries_.push_back(g);
        fans.push_back({zv2, p});
      }
      pairing_[hidx_(n)] = p;
      h = n;
    } while(true);
  }

  const TriangleMesh& tm_;
  const Dense_index<vertex_descriptor>& vidx_;
  const Dense_index<halfedge_descriptor>& hidx_;
  std::vector<halfedge_descriptor> primary_;
  std::vector<int> pairing_; // per halfedge: index in isometries_, -1 for the primary frame
  std::vector<Iso> isometries_;
  mutable std::vector<unsigned> checked_; // per halfedge: the round its face was last checked
  mutable unsigned stamp_ = 0;
};

} // namespace internal
} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_REFINEMENT_CORNER_MOVES_H
