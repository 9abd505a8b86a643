// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_POINCARE_DISK_TRAITS_2_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_POINCARE_DISK_TRAITS_2_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Hyperbolic_orbifold_Tutte/Hyperbolic_isometry_2.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/core/disk_models.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/enum.h>
#include <CGAL/number_utils.h>

#include <array>
#include <cmath>
#include <optional>

/// \file Poincare_disk_traits_2.h

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {

/*!
\ingroup PkgHyperbolicOrbifoldTutteTraitsClasses

A geodesic line of the Poincar&eacute; disk, given by its two ideal end points on
the unit circle (in the direction of travel from `source` to `target`), and, for
drawing, the Euclidean circle or diameter that carries it.
*/
template <class Kernel>
struct Hyperbolic_geodesic_2
{
  /// the number type of the kernel
  typedef typename Kernel::FT FT;
  /// the point type of the kernel
  typedef typename Kernel::Point_2 Point_2;
  Point_2 source;      ///< ideal end point behind the first defining point
  Point_2 target;      ///< ideal end point beyond the second defining point
  bool is_diameter;    ///< `true` when the geodesic is a straight diameter
  Point_2 center;      ///< center of the carrying circle (meaningless for a diameter)
  FT radius;           ///< radius of the carrying circle (0 for a diameter)
};

/*!
\ingroup PkgHyperbolicOrbifoldTutteTraitsClasses

The geometric traits of the package: the Poincar&eacute; disk model of the hyperbolic
plane on top of a CGAL kernel. Points are Poincar&eacute;-disk coordinates stored in
`Kernel::Point_2`, so Euclidean kernel functors still apply to them.

Predicates (`Hyperbolic_orientation_2`, `Side_of_oriented_hyperbolic_segment_2`,
`Bounded_side_of_hyperbolic_triangle_2`) are exact on the input coordinates: with
`Epick` they are filtered (double with a proven error bound, interval arithmetic, then exact
rationals when uncertain);
with a kernel with an exact number type they are evaluated exactly. Constructions are
computed in double precision.

\tparam Kernel a CGAL kernel; `Exact_predicates_inexact_constructions_kernel` by default.

\cgalModels `HyperbolicOrbifoldTraits_2`
*/
template <class Kernel_ = CGAL::Exact_predicates_inexact_constructions_kernel>
class Poincare_disk_traits_2 : public Kernel_
{
public:
  /// the underlying kernel
  typedef Kernel_ Kernel;
  /// the number type of the kernel
  typedef typename Kernel::FT FT;
  /// a point of the open unit disk, in Poincar&eacute; coordinates
  typedef typename Kernel::Point_2 Point_2;
  /// the isometry type (coefficients in double precision)
  typedef Hyperbolic_isometry_2<double> Isometry;
  /// a geodesic line (the result of `Construct_hyperbolic_geodesic_2`)
  typedef Hyperbolic_geodesic_2<Kernel> Geodesic_2;

private:
  typedef std::complex<double> C;
  static C to_c(const Point_2& p) { return C(CGAL::to_double(p.x()), CGAL::to_double(p.y())); }
  static Point_2 to_p(const C& z) { return Point_2(FT(z.real()), FT(z.imag())); }

public:
  /// the traits over the kernel `k`
  Poincare_disk_traits_2(const Kernel& k = Kernel()) : Kernel(k) {}

  /// \name Constructions
  /// @{

  /// maps a Poincar&eacute; point to its Klein point \f$ 2z / (1 + |z|^2) \f$
  struct Construct_Klein_point_2
  {
    /// returns the Klein point of `p`
    Point_2 operator()(const Point_2& p) const
    {
      return to_p(internal::poincare_to_klein(to_c(p)));
    }
  };

  /// maps a Klein point to its Poincar&eacute; point \f$ k / (1 + \sqrt{1 - |k|^2}) \f$
  struct Construct_Poincare_point_2
  {
    /// returns the Poincar&eacute; point of the Klein point `k`
    Point_2 operator()(const Point_2& k) const
    {
      return to_p(internal::klein_to_poincare(to_c(k)));
    }
  };

  /// hyperbolic distance of two Poincar&eacute; points (paper eq. (6)), evaluated as
  /// \f$ 2\,\mathrm{asinh}\big(|z-w| / \sqrt{(1-|z|^2)(1-|w|^2)}\big) \f$, which is the
  /// same number without the cancellation of `acosh` near 1.
  struct Compute_hyperbolic_distance_2
  {
    /// returns the hyperbolic distance of the Poincar&eacute; points `p` and `q`
    FT operator()(const Point_2& p, const Point_2& q) const
    {
      const C z = to_c(p), w = to_c(q);
      const double den = std::sqrt((1.0 - internal::squared_modulus(z)) * (1.0 - internal::squared_modulus(w)));
      return FT(2.0 * std::asinh(std::abs(z - w) / den));
    }
  };

  /// hyperbolic distance of two Klein points (paper eq. (7))
  struct Compute_Klein_distance_2
  {
    /// returns the hyperbolic distance of the Klein points `u` and `v`
    FT operator()(const Point_2& u, const Point_2& v) const
    {
      const C a = to_c(u), b = to_c(v);
      const double c = (1.0 - (a.real() * b.real() + a.imag() * b.imag())) /
                       std::sqrt((1.0 - internal::squared_modulus(a)) * (1.0 - internal::squared_modulus(b)));
      return FT(std::acosh(c < 1.0 ? 1.0 : c));
    }
  };

  /// the M&ouml;bius map \f$ m_p(z) = (z-p)/(1-\bar p z) \f$ moving `p` to the origin
  struct Construct_translation_to_origin_2
  {
    /// returns \f$ m_p \f$
    Isometry operator()(const Point_2& p) const { return Isometry::translation_to_origin(to_c(p)); }
  };

  /// the image of a point by an isometry
  struct Construct_image_by_isometry_2
  {
    /// returns \f$ f(p) \f$
    Point_2 operator()(const Isometry& f, const Point_2& p) const { return to_p(f.apply(to_c(p))); }
  };

  /// the geodesic line through two distinct points
  struct Construct_hyperbolic_geodesic_2
  {
    /// returns the geodesic line through `p` and `q`, oriented from `p` to `q`
    Geodesic_2 operator()(const Point_2& p, const Point_2& q) const
    {
      // Move p to the origin: the geodesic becomes the diameter towards m_p(q).
      const Isometry to0 = Isometry::translation_to_origin(to_c(p));
      const C d0 = to0.apply(to_c(q));
      const C u = d0 / std::abs(d0);
      const Isometry back = to0.inverse();
      const C e1 = back.apply(-u), e2 = back.apply(u);
      Geodesic_2 g;
      g.source = to_p(e1);
      g.target = to_p(e2);
      // The circle through e1, e2 orthogonal to the unit circle has its center at
      // (e1 + e2) / (1 + Re(e1 conj(e2))) and radius |e1 - center|.
      const double c = 1.0 + (e1.real() * e2.real() + e1.imag() * e2.imag());
      // The geodesic is a diameter iff the origin lies on it: exact test on the inputs.
      g.is_diameter = internal::poincare_orientation_sign_exact<FT>(FT(0), FT(0), p.x(), p.y(), q.x(), q.y()) == ZERO ||
                      c < 1e-15;
      if(g.is_diameter) {
        g.center = Point_2(FT(0), FT(0));
        g.radius = FT(0);
      } else {
        const C center = (e1 + e2) / c;
        g.center = to_p(center);
        g.radius = FT(std::abs(e1 - center));
      }
      return g;
    }
  };

  /// the geodesic midpoint of two points
  struct Construct_hyperbolic_midpoint_2
  {
    /// returns the geodesic midpoint of `p` and `q`
    Point_2 operator()(const Point_2& p, const Point_2& q) const
    {
      const Isometry to0 = Isometry::translation_to_origin(to_c(p));
      const C d0 = to0.apply(to_c(q));
      // |d0| = tanh(d/2); the midpoint is at Euclidean radius tanh(d/4) = |d0| / (1 + sqrt(1 - |d0|^2)).
      const C m0 = d0 / (1.0 + std::sqrt(1.0 - internal::squared_modulus(d0)));
      return to_p(to0.inverse().apply(m0));
    }
  };

  /// the angle at `p`, in \f$[0,\pi]\f$, between the geodesics from `p` to `q` and from `p` to `r`
  struct Compute_hyperbolic_angle_2
  {
    /// returns the angle at `p` of the geodesics towards `q` and `r`
    FT operator()(const Point_2& p, const Point_2& q, const Point_2& r) const
    {
      // The model is conformal: after moving p to the origin, geodesics from p are
      // straight rays, so the angle is the angle between m_p(q) and m_p(r).
      const Isometry to0 = Isometry::translation_to_origin(to_c(p));
      const C a = to0.apply(to_c(q)), b = to0.apply(to_c(r));
      const double cross = a.real() * b.imag() - a.imag() * b.real();
      const double dot = a.real() * b.real() + a.imag() * b.imag();
      return FT(std::atan2(std::abs(cross), dot));
    }
  };

  /// the area of the geodesic triangle `pqr`: \f$ \pi \f$ minus its angle sum
  struct Compute_hyperbolic_triangle_area_2
  {
    /// returns the (unsigned) hyperbolic area of the triangle `pqr`
    FT operator()(const Point_2& p, const Point_2& q, const Point_2& r) const
    {
      Compute_hyperbolic_angle_2 angle;
      const double s = CGAL::to_double(angle(p, q, r)) + CGAL::to_double(angle(q, r, p)) +
                       CGAL::to_double(angle(r, p, q));
      return FT(CGAL_PI - s);
    }
  };

  /// the side lengths \f$(l_1, l_2, l_3)\f$ of the hyperbolic triangle with angles
  /// \f$(\theta_1, \theta_2, \theta_3)\f$, \f$ l_i \f$ opposite \f$ \theta_i \f$ (paper, Appendix C):
  /// \f$ \cosh l_i = (\cos\theta_i + \cos\theta_{i+1}\cos\theta_{i+2}) / (\sin\theta_{i+1}\sin\theta_{i+2}) \f$.
  /// Returns nothing when the angles are not all in \f$(0,\pi)\f$ or their sum is not below \f$\pi\f$
  /// (no hyperbolic triangle has them).
  struct Compute_triangle_side_lengths_from_angles_2
  {
    /// returns the side lengths opposite the angles `t1`, `t2`, `t3`, or nothing
    std::optional<std::array<FT, 3> > operator()(const FT& t1, const FT& t2, const FT& t3) const
    {
      const double t[3] = {CGAL::to_double(t1), CGAL::to_double(t2), CGAL::to_double(t3)};
      for(double a : t)
        if(!(a > 0.0 && a < CGAL_PI))
          return std::nullopt;
      if(!(t[0] + t[1] + t[2] < CGAL_PI))
        return std::nullopt;
      std::array<FT, 3> l;
      for(int i = 0; i < 3; ++i) {
        const double a = t[i], b = t[(i + 1) % 3], c = t[(i + 2) % 3];
        l[i] = FT(std::acosh((std::cos(a) + std::cos(b) * std::cos(c)) / (std::sin(b) * std::sin(c))));
      }
      return l;
    }
  };
  /// @}

  /// \name Predicates
  /// @{

  /// orientation of the geodesic triangle `pqr`: the Euclidean orientation of its Klein image, exact
  struct Hyperbolic_orientation_2
  {
    /// the result type
    typedef Orientation result_type;
    /// returns the orientation of the geodesic triangle `pqr` (`LEFT_TURN`, `RIGHT_TURN` or `COLLINEAR`)
    Orientation operator()(const Point_2& p, const Point_2& q, const Point_2& r) const
    {
      return internal::poincare_orientation_sign_exact<FT>(p.x(), p.y(), q.x(), q.y(), r.x(), r.y());
    }
  };

  /// side of `r` with respect to the geodesic through `p` then `q`, oriented from `p` to `q`:
  /// `ON_POSITIVE_SIDE` on its left, exact
  struct Side_of_oriented_hyperbolic_segment_2
  {
    /// the result type
    typedef Oriented_side result_type;
    /// returns the side of `r` with respect to the geodesic from `p` to `q`
    Oriented_side operator()(const Point_2& p, const Point_2& q, const Point_2& r) const
    {
      return internal::poincare_orientation_sign_exact<FT>(p.x(), p.y(), q.x(), q.y(), r.x(), r.y());
    }
  };

  /// position of `t` with respect to the geodesic triangle `pqr` (of either orientation), exact
  /// \pre `pqr` is not degenerate
  struct Bounded_side_of_hyperbolic_triangle_2
  {
    /// the result type
    typedef Bounded_side result_type;
    /// returns the position of `t` with respect to the geodesic triangle `pqr`
    Bounded_side operator()(const Point_2& p, const Point_2& q, const Point_2& r, const Point_2& t) const
    {
      Hyperbolic_orientation_2 orient;
      const Orientation o = orient(p, q, r);
      CGAL_precondition(o != COLLINEAR);
      const Orientation o1 = orient(p, q, t), o2 = orient(q, r, t), o3 = orient(r, p, t);
      if(o1 == -o || o2 == -o || o3 == -o)
        return ON_UNBOUNDED_SIDE;
      if(o1 == COLLINEAR || o2 == COLLINEAR || o3 == COLLINEAR)
        return ON_BOUNDARY;
      return ON_BOUNDED_SIDE;
    }
  };
  /// @}

  /// \name Accessors
  /// @{

  /// returns a `Construct_Klein_point_2` object
  Construct_Klein_point_2 construct_Klein_point_2_object() const { return {}; }
  /// returns a `Construct_Poincare_point_2` object
  Construct_Poincare_point_2 construct_Poincare_point_2_object() const { return {}; }
  /// returns a `Compute_hyperbolic_distance_2` object
  Compute_hyperbolic_distance_2 compute_hyperbolic_distance_2_object() const { return {}; }
  /// returns a `Compute_Klein_distance_2` object
  Compute_Klein_distance_2 compute_Klein_distance_2_object() const { return {}; }
  /// returns a `Construct_translation_to_origin_2` object
  Construct_translation_to_origin_2 construct_translation_to_origin_2_object() const { return {}; }
  /// returns a `Construct_image_by_isometry_2` object
  Construct_image_by_isometry_2 construct_image_by_isometry_2_object() const { return {}; }
  /// returns a `Construct_hyperbolic_geodesic_2` object
  Construct_hyperbolic_geodesic_2 construct_hyperbolic_geodesic_2_object() const { return {}; }
  /// returns a `Construct_hyperbolic_midpoint_2` object
  Construct_hyperbolic_midpoint_2 construct_hyperbolic_midpoint_2_object() const { return {}; }
  /// returns a `Compute_hyperbolic_angle_2` object
  Compute_hyperbolic_angle_2 compute_hyperbolic_angle_2_object() const { return {}; }
  /// returns a `Compute_hyperbolic_triangle_area_2` object
  Compute_hyperbolic_triangle_area_2 compute_hyperbolic_triangle_area_2_object() const { return {}; }
  /// returns a `Compute_triangle_side_lengths_from_angles_2` object
  Compute_triangle_side_lengths_from_angles_2 compute_triangle_side_lengths_from_angles_2_object() const { return {}; }
  /// returns a `Hyperbolic_orientation_2` object
  Hyperbolic_orientation_2 hyperbolic_orientation_2_object() const { return {}; }
  /// returns a `Side_of_oriented_hyperbolic_segment_2` object
  Side_of_oriented_hyperbolic_segment_2 side_of_oriented_hyperbolic_segment_2_object() const { return {}; }
  /// returns a `Bounded_side_of_hyperbolic_triangle_2` object
  Bounded_side_of_hyperbolic_triangle_2 bounded_side_of_hyperbolic_triangle_2_object() const { return {}; }
  /// @}
};

} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_POINCARE_DISK_TRAITS_2_H
