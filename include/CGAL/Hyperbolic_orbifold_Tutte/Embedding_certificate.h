// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_EMBEDDING_CERTIFICATE_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_EMBEDDING_CERTIFICATE_H

#include <cstddef>
#include <ostream>

/// \file Embedding_certificate.h

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {

/*!
\ingroup PkgHyperbolicOrbifoldTutteMainClasses

The verdict of the bijectivity certificate on an embedding of a cut mesh into an
orbifold tile, with the count of each kind of failure (the checks of the user manual's section on
the certificate): every triangle positively oriented (exact predicate on the output
coordinates); hyperbolic angle sums of \f$2\pi\f$ at interior and seam vertices (copies
added), \f$\pi\f$ at sphere-type cones, \f$\pi/2\f$ at disk-type corners and \f$\pi\f$ at
the other disk-boundary vertices; total hyperbolic area equal to the orbifold's; seam
twins related by their side pairing; cones at their tile corners; disk-boundary
vertices on their tile side.
*/
struct Embedding_certificate
{
  /// faces checked (those of the cut mesh); 0 means nothing was certified
  std::size_t number_of_faces = 0;
  std::size_t points_outside_disk = 0;  ///< output points not strictly inside the unit disk (or not finite)
  std::size_t flipped_faces = 0;        ///< faces with negative orientation (exact)
  std::size_t degenerate_faces = 0;     ///< faces with three points on one geodesic (exact)
  std::size_t angle_sum_failures = 0;   ///< mesh vertices whose angle sum is off by more than 0.5 radian (a wrong sum is off by a multiple of 2 pi)
  std::size_t twin_failures = 0;        ///< seam copies not related by their side pairing
  std::size_t cone_failures = 0;        ///< cone copies away from their tile corner
  std::size_t border_failures = 0;      ///< disk-boundary vertices off their tile side
  double max_angle_sum_error = 0;       ///< radians
  double max_twin_error = 0;            ///< hyperbolic distance
  double max_cone_error = 0;            ///< hyperbolic distance
  double max_border_error = 0;          ///< Klein-model distance to the side's line
  double total_area = 0;                ///< signed sum of the triangles' hyperbolic areas
  double expected_area = 0;             ///< the orbifold's area (Gauss-Bonnet)
  /// the absolute difference of `total_area` and `expected_area`
  double area_error = 0;
  /// `true` when every point is inside the disk and `area_error` is within the tolerance
  /// (relative to `expected_area` when it exceeds 1)
  bool area_ok = false;

  /// `true` when every check passed: the embedding is a bijection onto the orbifold
  bool is_bijective() const
  {
    return number_of_faces > 0 && points_outside_disk == 0 && flipped_faces == 0 && degenerate_faces == 0 &&
           angle_sum_failures == 0 && twin_failures == 0 && cone_failures == 0 && border_failures == 0 && area_ok;
  }

  /// writes the verdict and the count of each failure on one line
  friend std::ostream& operator<<(std::ostream& os, const Embedding_certificate& c)
  {
    return os << (c.is_bijective() ? "bijective" : "NOT bijective") << " (faces " << c.number_of_faces
              << ", outside " << c.points_outside_disk << ", flipped " << c.flipped_faces << ", degenerate "
              << c.degenerate_faces << ", angle-sum failures " << c.angle_sum_failures << " [max "
              << c.max_angle_sum_error << "], twin failures " << c.twin_failures << ", cone failures "
              << c.cone_failures << ", border failures " << c.border_failures << ", area " << c.total_area << " vs "
              << c.expected_area << ")";
  }
};

} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_EMBEDDING_CERTIFICATE_H
