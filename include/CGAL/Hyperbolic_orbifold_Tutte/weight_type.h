// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_WEIGHT_TYPE_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_WEIGHT_TYPE_H

/// \file weight_type.h

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {

/*!
\ingroup PkgHyperbolicOrbifoldTutteEnums
The edge weights \f$ w_{ij} \f$ of the Dirichlet energy. All are positive, as the
bijectivity theorem requires.
*/
enum Weight_type
{
  Cotangent,  ///< \f$ (\cot\alpha + \cot\beta)/2 \f$, clamped below at a small \f$\epsilon > 0\f$ (paper: \f$10^{-6}\f$)
  Mean_value, ///< Floater's mean-value weights, symmetrized: \f$ (w_{ij} + w_{ji})/2 \f$
  Uniform     ///< 1 for every edge (combinatorial)
};

} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_WEIGHT_TYPE_H
