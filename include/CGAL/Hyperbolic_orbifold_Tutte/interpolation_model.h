// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERPOLATION_MODEL_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERPOLATION_MODEL_H

/// \file interpolation_model.h

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {

/*!
\ingroup PkgHyperbolicOrbifoldTutteEnums
How `Embedding_locator` parameterises a face of an embedding by the face's geodesic
triangle, i.e. how its barycentric coordinates are defined. Both map the face onto the
same geodesic triangle (straight in the Klein model), its vertices onto the corners.
*/
enum Interpolation_model
{
  /// barycentric coordinates of the Klein points: the map is affine in the Klein model of
  /// the mesh's own frame. Isometries are projective, not affine, maps of the Klein disk, so
  /// the two faces on either side of a cut edge (stored in frames related by a side pairing)
  /// parameterise the common edge differently: a surface point on the cut, other than a
  /// vertex, has two slightly different disk points (the map is not seamless there), and
  /// the coordinates depend on where the cut runs.
  Klein_linear,
  /// barycentric coordinates of the points of the hyperboloid model (Minkowski space),
  /// where isometries are linear maps: invariant under the orbifold group, hence seamless
  /// across the cut and independent of it (the default). Related to the Klein coordinates
  /// \f$\mu\f$ by \f$\lambda_i \sim \mu_i (1 - |z_i|^2) / (1 + |z_i|^2)\f$, \f$z_i\f$ the
  /// Poincar&eacute; corners.
  Hyperboloid_linear
};

} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERPOLATION_MODEL_H
