// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_SELECT_LANDMARKS_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_SELECT_LANDMARKS_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Hyperbolic_orbifold_Tutte/internal/landmark_sampling.h>

#include <vector>

/// \file select_landmarks.h

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {

/*!
\ingroup PkgHyperbolicOrbifoldTutteHelperFunctions

returns `k` well-spread vertices of `tm`, deterministically: for a closed mesh,
farthest-point sampling on graph distance (Dijkstra over edges weighted by their length,
starting from the vertex farthest from the first vertex); for a mesh with a border, `k`
vertices of the longest border loop spaced evenly by arc length, in border order (usable
as disk-type corners). Fewer are returned when the border has fewer vertices.

\tparam TriangleMesh a model of `FaceGraph` and `VertexListGraph` (e.g. `Surface_mesh`,
        `Polyhedron_3`) with an internal `vertex_point` property map
\param tm the mesh
\param k the number of landmarks
\return the landmarks, at most `k` of them
*/
template <class TriangleMesh>
std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>
select_landmarks(const TriangleMesh& tm, std::size_t k)
{
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  std::vector<vertex_descriptor> verts;
  for(vertex_descriptor v : vertices(tm))
    verts.push_back(v);
  std::vector<vertex_descriptor> result;
  for(std::size_t i : internal::sample_landmarks(tm, get(CGAL::vertex_point, tm), k))
    result.push_back(verts[i]);
  return result;
}

} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_SELECT_LANDMARKS_H
