// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_CUT_GRAPH_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_CUT_GRAPH_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Hyperbolic_orbifold_Tutte/error_code.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/input/genus_cut.h>

#include <boost/graph/graph_traits.hpp>

#include <vector>

/// \file cut_graph.h
/// The cut graph of a closed mesh of genus g >= 1 through its landmarks.

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {

/*!
\ingroup PkgHyperbolicOrbifoldTutteHelperFunctions

computes a cut graph of the closed connected mesh `tm` of genus \f$ g \ge 1 \f$ through its
landmarks (\ref HOT_Genus): cut along it, the mesh is a topological disk, whose border is the
tile's polygon. Tree-cotree construction: the shortest-path tree from the root (the first
landmark, else the first vertex) on edge lengths; among the other edges, a spanning tree of the
dual graph that keeps out the edges closing the longest loops (root, along the tree to one end,
the edge, back along the tree); the \f$2g\f$ edges left close the handle loops, the shortest
system of loops through the root (Erickson and Whittlesey 2005). The graph is the tree with
those edges, pruned of its leaves that are not landmarks: \f$2g\f$ loops through the root and the
tree paths from the landmarks to them.

`paths` receives it as vertex paths between its nodes (vertices of degree other than 2, and
landmarks), each edge on one path, the first path starting at the first landmark (else at the
node of smallest index) towards its neighbour of smallest index on the graph, which is where the
tile's corner 0 goes by default (so embedding along this graph given or not gives the same
result). Linear time plus a
Dijkstra search and a sort of the edges, O(n log n).

\return `OK`, or `ERROR_WRONG_TOPOLOGY` (not a closed connected mesh of genus g >= 1),
`ERROR_LANDMARK_OUT_OF_RANGE` (a landmark that is not a vertex, or twice) with a message.
*/
template <class TriangleMesh, class VertexPointMap>
Status compute_cut_graph(const TriangleMesh& tm,
                         const std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>& landmarks,
                         VertexPointMap vpm,
                         std::vector<std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor> >& paths)
{
  return internal::cut_graph_through_landmarks(tm, landmarks, vpm, paths);
}

/*!
\ingroup PkgHyperbolicOrbifoldTutteHelperFunctions

checks a cut graph given as vertex paths (a user's, or read from a file): at least one path;
every path of at least 2 vertices of `tm`, consecutive ones joined by an edge; no edge on two
paths or twice on one; every landmark on a path. Whether it cuts the mesh into a disk is decided
when the mesh is cut (`ERROR_CUT_FAILED` then). Linear time.

\return `OK`, or `ERROR_WRONG_PARAMETER` / `ERROR_LANDMARK_OUT_OF_RANGE` with a message naming
the path and the vertices (their positions in `vertices(tm)`).
*/
template <class TriangleMesh>
Status check_cut_graph(const TriangleMesh& tm,
                       const std::vector<std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor> >& paths,
                       const std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>& landmarks)
{
  return internal::check_cut_graph_paths(tm, paths, landmarks);
}

} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_CUT_GRAPH_H
