// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_GENUS_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_GENUS_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Hyperbolic_orbifold_Tutte/Orbifold_type.h>

#include <CGAL/boost/graph/helpers.h>

#include <boost/graph/graph_traits.hpp>

#include <cstddef>

/// \file genus.h
/// The Euler characteristic and the genus of a mesh, computed once for the whole package, and
/// `Mesh_info`, what `check_mesh()` learns about a mesh's topology.

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {

/*!
\ingroup PkgHyperbolicOrbifoldTutteMainClasses
what `check_mesh()` learnt about the mesh; fields are filled as far as the checks got.
*/
struct Mesh_info
{
  std::size_t number_of_vertices = 0;     ///< V
  std::size_t number_of_edges = 0;        ///< E
  std::size_t number_of_faces = 0;        ///< F
  std::size_t number_of_border_loops = 0; ///< the number of boundary loops
  long long euler_characteristic = 0;     ///< V - E + F
  long long genus = -1;                   ///< (2 - border loops - (V-E+F)) / 2, or -1 if not computed
  bool type_known = false;                ///< true once the topology check passed
  Orbifold_type type = Sphere_type;       ///< the required or detected orbifold type
};

/*!
\ingroup PkgHyperbolicOrbifoldTutteHelperFunctions
the Euler characteristic \f$ V - E + F \f$ of `tm` (`num_vertices(tm) - num_edges(tm) + num_faces(tm)`).
\tparam FaceGraph a model of `FaceGraph`
*/
template <class FaceGraph>
long long euler_characteristic(const FaceGraph& tm)
{
  return static_cast<long long>(num_vertices(tm)) - static_cast<long long>(num_edges(tm)) +
         static_cast<long long>(num_faces(tm));
}

/*!
\ingroup PkgHyperbolicOrbifoldTutteHelperFunctions
the genus \f$ (2 - b - \chi) / 2 \f$ of a connected surface of Euler characteristic `chi`
with `border_loops` boundary loops (rounded towards zero when \f$ 2 - b - \chi \f$ is odd).
*/
inline long long genus_of_surface(long long chi, std::size_t border_loops)
{
  return (2 - static_cast<long long>(border_loops) - chi) / 2;
}

/*!
\ingroup PkgHyperbolicOrbifoldTutteHelperFunctions
the genus of the closed connected mesh `tm` from its Euler characteristic
(`euler_characteristic()`), or -1 when that is odd or above 2 (not a closed connected surface).
The orbifold of a closed mesh of genus \f$ g \ge 1 \f$ is cut along a cut graph; of genus 0, along
a path through the landmarks.
\tparam FaceGraph a model of `FaceGraph`
*/
template <class FaceGraph>
long long closed_mesh_genus(const FaceGraph& tm)
{
  const long long chi = euler_characteristic(tm);
  return (chi > 2 || (chi % 2) != 0) ? -1 : genus_of_surface(chi, 0);
}

} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_GENUS_H
