// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_CUT_GRAPH_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_CUT_GRAPH_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Hyperbolic_orbifold_Tutte/error_code.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/genus.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/dense_index.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/genus_cut.h>

#include <boost/graph/graph_traits.hpp>

#include <set>
#include <string>
#include <utility>
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
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  paths.clear();
  const long long genus = closed_mesh_genus(tm);
  if(genus < 1)
    return Status::failure(ERROR_WRONG_TOPOLOGY, "a cut graph is for a closed mesh of genus 1 or more; this one has V-E+F = " +
                                                   std::to_string(euler_characteristic(tm)));
  std::vector<std::pair<int, int> > cut;
  const Status r = internal::compute_genus_cut_graph(tm, vpm, landmarks, genus, cut);
  if(!r)
    return r;
  const std::vector<vertex_descriptor> verts(vertices(tm).begin(), vertices(tm).end());
  const internal::Dense_index<vertex_descriptor> index(vertices(tm));
  std::vector<char> is_landmark(verts.size(), 0);
  for(vertex_descriptor v : landmarks)
    is_landmark[index(v)] = 1;
  // the first path: from the first landmark, else from the node of smallest index, towards its
  // neighbour of smallest index (the default corner 0 of the tile: see set_cut_graph_start())
  const int first = landmarks.empty() ? -1 : static_cast<int>(index(landmarks[0]));
  for(const std::vector<int>& p : internal::cut_graph_paths(static_cast<int>(verts.size()), cut, is_landmark, first)) {
    paths.emplace_back();
    for(int v : p)
      paths.back().push_back(verts[v]);
  }
  return Status();
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
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  const internal::Dense_index<vertex_descriptor> index(vertices(tm));
  if(paths.empty())
    return Status::failure(ERROR_WRONG_PARAMETER, "the cut graph has no path");
  std::set<std::pair<std::size_t, std::size_t> > seen;
  std::vector<char> on_graph(index.size(), 0);
  for(std::size_t i = 0; i < paths.size(); ++i) {
    const std::string which = "path " + std::to_string(i) + " of the cut graph";
    if(paths[i].size() < 2)
      return Status::failure(ERROR_WRONG_PARAMETER, which + " has fewer than 2 vertices");
    for(std::size_t j = 0; j < paths[i].size(); ++j) {
      const std::size_t a = index(paths[i][j]);
      if(a == index.npos)
        return Status::failure(ERROR_LANDMARK_OUT_OF_RANGE, which + ": its vertex " + std::to_string(j) + " is not a vertex of the mesh");
      on_graph[a] = 1;
      if(j == 0)
        continue;
      const std::size_t b = index(paths[i][j - 1]);
      if(!edge(paths[i][j - 1], paths[i][j], tm).second)
        return Status::failure(ERROR_WRONG_PARAMETER, which + ": mesh vertices " + std::to_string(b) + " and " + std::to_string(a) +
                                                        " are not joined by an edge");
      if(!seen.insert(std::make_pair((std::min)(a, b), (std::max)(a, b))).second)
        return Status::failure(ERROR_WRONG_PARAMETER, which + ": the edge between mesh vertices " + std::to_string(b) + " and " +
                                                        std::to_string(a) + " is on the cut graph twice");
    }
  }
  for(std::size_t c = 0; c < landmarks.size(); ++c) {
    const std::size_t a = index(landmarks[c]);
    if(a == index.npos || !on_graph[a])
      return Status::failure(ERROR_WRONG_PARAMETER, "landmark " + std::to_string(c) + " is not on the cut graph");
  }
  return Status();
}

} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_CUT_GRAPH_H
