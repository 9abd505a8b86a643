// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_SOLVER_CONVEX_POLYGON_DOMAIN_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_SOLVER_CONVEX_POLYGON_DOMAIN_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Hyperbolic_orbifold_Tutte/Hyperbolic_isometry_2.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/Orbifold_type.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/Poincare_disk_traits_2.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/error_code.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/certifier/corner_embedding_geometry.h> // strictly_inside_unit_disk
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/core/dense_index.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/core/disk_models.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/core/mesh_graph.h>

#include <cmath>
#include <complex>
#include <cstddef>
#include <string>
#include <vector>

// The target of the fixed-boundary hyperbolic Tutte embedding (the paper's Theorem 1): a
// strictly convex polygon of the Poincare disk, its checks, and the polygon seen as the
// "tile" of the flat problem's disk type, so that the flat problem, the Tutte initialisation
// and the certificate of the orbifold embeddings serve it unchanged.

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {
namespace internal {

// A strictly convex polygon, corners counterclockwise, with the interface of Orbifold_tile
// that build_flat_topology(), initialize_embedding(), certify_flat() and the one-ring repairs
// use: disk type, corner i is corner i's landmark, every side alone (the boundary vertices
// between two corners lie on the side's geodesic), the expected angle sum at corner i is the
// polygon's interior angle there, the expected area the polygon's.
template <class Traits_ = Poincare_disk_traits_2<> >
class Convex_polygon_domain
{
public:
  typedef Traits_ Traits;
  typedef typename Traits::Point_2 Point_2;
  typedef typename Traits::Isometry Isometry;

  // what the certificate asks of a signature: the angle at each corner
  class Corner_angles
  {
  public:
    double cone_angle(int i) const { return angles_[static_cast<std::size_t>(i)]; }

  private:
    friend class Convex_polygon_domain;
    std::vector<double> angles_;
  };

  // \pre `corners` is a strictly convex polygon, counterclockwise, strictly inside the disk
  explicit Convex_polygon_domain(const std::vector<std::complex<double> >& corners, const Traits& traits = Traits())
    : traits_(traits)
  {
    for(const std::complex<double>& z : corners)
      corners_.push_back(Point_2(z.real(), z.imag()));
    const int n = number_of_corners();
    const auto angle = traits_.compute_hyperbolic_angle_2_object();
    double sum = 0;
    for(int i = 0; i < n; ++i) {
      const double a = CGAL::to_double(angle(corners_[i], corners_[(i + 1) % n], corners_[(i + n - 1) % n]));
      angles_.angles_.push_back(a);
      sum += a;
    }
    area_ = (n - 2) * CGAL_PI - sum; // Gauss-Bonnet
  }

  Orbifold_type type() const { return Disk_type; }
  int number_of_corners() const { return static_cast<int>(corners_.size()); }
  const Point_2& corner(int i) const { return corners_[static_cast<std::size_t>(i)]; }
  int corner_cone(int i) const { return i; }
  double corner_angle(int i) const { return angles_.cone_angle(i); }
  const Corner_angles& signature() const { return angles_; }
  double area() const { return area_; }
  int side_source(int i) const { return i; }
  int side_target(int i) const { return (i + 1) % number_of_corners(); }
  int paired_side(int i) const { return i; }
  // (the disk type glues a side to itself by the reflection in it; only the sphere type's
  // seams use pairings)
  Isometry side_pairing(int i) const
  {
    const Point_2& p = corner(side_source(i));
    const Point_2& q = corner(side_target(i));
    return Isometry::reflection_in_geodesic(std::complex<double>(CGAL::to_double(p.x()), CGAL::to_double(p.y())),
                                            std::complex<double>(CGAL::to_double(q.x()), CGAL::to_double(q.y())));
  }
  const Traits& traits() const { return traits_; }

private:
  std::vector<Point_2> corners_;
  Corner_angles angles_;
  double area_ = 0;
  Traits traits_;
};

// Checks that `p` is a strictly convex polygon (in either orientation, which `counterclockwise`
// receives) with every corner finite and strictly inside the unit disk, all exactly on the
// given doubles: every turn of the Klein polygon has the same strict orientation (exact
// predicate) and the turns add up to one full turn (their angles sum to 2 pi w for a winding
// number w >= 1; w = 1 is told apart from w >= 2 far above rounding). Linear time.
inline Status check_convex_polygon(const std::vector<std::complex<double> >& p, bool& counterclockwise)
{
  typedef std::complex<double> C;
  const std::size_t n = p.size();
  for(std::size_t i = 0; i < n; ++i)
    if(!std::isfinite(p[i].real()) || !std::isfinite(p[i].imag()) ||
       !corner_certificate::strictly_inside_unit_disk(p[i].real(), p[i].imag()))
      return Status::failure(ERROR_POLYGON_NOT_CONVEX, "polygon corner " + std::to_string(i) +
                                                          " is not a finite point strictly inside the unit disk");
  Sign turn = ZERO;
  double turning = 0;
  for(std::size_t i = 0; i < n; ++i) {
    const C& a = p[i];
    const C& b = p[(i + 1) % n];
    const C& c = p[(i + 2) % n];
    const Sign s = poincare_orientation_sign_exact<double>(a.real(), a.imag(), b.real(), b.imag(), c.real(), c.imag());
    if(s == ZERO || (turn != ZERO && s != turn))
      return Status::failure(ERROR_POLYGON_NOT_CONVEX,
                             "the polygon is not strictly convex: its corners " + std::to_string(i) + ", " +
                               std::to_string((i + 1) % n) + ", " + std::to_string((i + 2) % n) +
                               (s == ZERO ? " are on one geodesic" : " turn the other way than the others"));
    turn = s;
    const C u = poincare_to_klein(b) - poincare_to_klein(a), v = poincare_to_klein(c) - poincare_to_klein(b);
    turning += std::abs(std::atan2(u.real() * v.imag() - u.imag() * v.real(), u.real() * v.real() + u.imag() * v.imag()));
  }
  if(!(turning < 3 * CGAL_PI))
    return Status::failure(ERROR_POLYGON_NOT_CONVEX, "the polygon is not simple: its boundary winds " +
                                                       std::to_string(static_cast<int>(std::lround(turning / (2 * CGAL_PI)))) +
                                                       " times around its interior (a star polygon)");
  counterclockwise = turn == POSITIVE;
  return Status();
}

// Checks that the distinct border vertices `corners` of a mesh with one boundary loop come
// in the order of the loop, in either direction; `counterclockwise` receives whether they go
// around the mesh counterclockwise (the interior on their left, as in its faces). Linear time.
template <class TriangleMesh>
Status check_boundary_order(const TriangleMesh& tm,
                            const std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>& corners,
                            bool& counterclockwise)
{
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  typedef typename boost::graph_traits<TriangleMesh>::halfedge_descriptor halfedge_descriptor;
  const auto loops = border_loops(tm);
  if(loops.size() != 1)
    return Status::failure(ERROR_WRONG_TOPOLOGY, "the mesh does not have exactly one boundary loop");
  // positions along next(): border halfedges have the mesh on their right (clockwise)
  const Dense_index<vertex_descriptor> index(vertices(tm));
  std::vector<std::size_t> position(index.size(), 0);
  std::size_t L = 0;
  for(halfedge_descriptor h : loops.front())
    position[index(target(h, tm))] = L++;
  const std::size_t n = corners.size();
  std::size_t forward = 0, backward = 0; // the steps from each corner to the next, both ways
  for(std::size_t i = 0; i < n; ++i) {
    const std::size_t a = position[index(corners[i])], b = position[index(corners[(i + 1) % n])];
    forward += (b + L - a) % L;
    backward += (a + L - b) % L;
  }
  // distinct corners: each step is in [1, L-1]; one turn around the loop exactly when in order
  if(forward != L && backward != L) {
    // name the first corner out of the order the first two set
    const std::size_t p0 = position[index(corners[0])];
    const bool along_next = (position[index(corners[1 % n])] + L - p0) % L <= (p0 + L - position[index(corners[1 % n])]) % L;
    std::size_t last = 0, culprit = 1;
    for(std::size_t i = 1; i < n; ++i) {
      const std::size_t p = position[index(corners[i])];
      const std::size_t d = along_next ? (p + L - p0) % L : (p0 + L - p) % L;
      if(d < last) {
        culprit = i;
        break;
      }
      last = d;
    }
    return Status::failure(ERROR_CORNERS_NOT_IN_BOUNDARY_ORDER,
                           "the corner vertices are not in the order of the boundary loop (in either direction): corner " +
                             std::to_string(culprit) + " (vertex " + std::to_string(index(corners[culprit])) +
                             ") is not between corners " + std::to_string(culprit - 1) + " and " +
                             std::to_string((culprit + 1) % n) + " along it");
  }
  counterclockwise = backward == L;
  return Status();
}

// The point at the fraction t of the geodesic segment from a to b (in hyperbolic length)
inline std::complex<double> point_on_geodesic_segment(const std::complex<double>& a, const std::complex<double>& b, double t)
{
  typedef Hyperbolic_isometry_2<double> Isometry;
  const Isometry to0 = Isometry::translation_to_origin(a);
  const std::complex<double> b0 = to0.apply(b);
  const double r = std::abs(b0); // tanh(d(a, b) / 2)
  return r > 0 ? to0.inverse().apply(b0 * (std::tanh(t * std::atanh(r)) / r)) : a;
}

} // namespace internal
} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_SOLVER_CONVEX_POLYGON_DOMAIN_H
