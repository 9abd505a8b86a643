// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_SELECT_LANDMARKS_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_SELECT_LANDMARKS_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Hyperbolic_orbifold_Tutte/internal/input/landmark_sampling.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/core/mesh_graph.h>

#include <CGAL/boost/graph/helpers.h>

#include <cstddef>

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


/*!
\ingroup PkgHyperbolicOrbifoldTutteMainClasses
a landmark moved onto the boundary by `snap_landmarks_to_border()`.
*/
template <class VertexDescriptor>
struct Landmark_snap
{
  std::size_t landmark = 0; ///< its position in the landmark list
  VertexDescriptor from;    ///< the vertex given
  VertexDescriptor to;      ///< the boundary vertex it was moved to
  double distance = 0;      ///< the length of the shortest edge path between them
};

/*!
\ingroup PkgHyperbolicOrbifoldTutteHelperFunctions

replaces every landmark that is not a boundary vertex of `tm` by the boundary vertex nearest to
it along the edges (Dijkstra over edge lengths; the first of equally near ones in the search's
order), as disk-type corners must lie on the boundary (the authors' MATLAB code snaps its
corners the same way). Landmarks on the boundary are kept. Two landmarks may end on one vertex:
`check_landmarks()` then reports the duplicate.
\tparam TriangleMesh a model of `FaceGraph` and `VertexListGraph` with an internal `vertex_point`
        property map
\return the landmarks moved, in landmark order (none if `tm` has no boundary)
*/
template <class TriangleMesh>
std::vector<Landmark_snap<typename boost::graph_traits<TriangleMesh>::vertex_descriptor> >
snap_landmarks_to_border(const TriangleMesh& tm,
                         std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>& landmarks)
{
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  std::vector<Landmark_snap<vertex_descriptor> > snaps;
  const internal::Mesh_graph<TriangleMesh> g(tm, get(CGAL::vertex_point, tm));
  std::vector<char> on_border(g.size(), 0);
  bool any = false;
  for(std::size_t i = 0; i < g.size(); ++i)
    any |= (on_border[i] = CGAL::is_border(g.verts[i], tm) ? 1 : 0) != 0;
  if(!any)
    return snaps;
  internal::Dijkstra_workspace ws;
  ws.init(g.size());
  for(std::size_t l = 0; l < landmarks.size(); ++l) {
    const std::size_t s = g.index(landmarks[l]);
    if(s == g.index.npos || on_border[s])
      continue;
    ws.begin_run();
    int found = -1;
    internal::dijkstra(g, ws, static_cast<int>(s),
                       [&](int u) { if(found < 0 && on_border[u]) found = u; },
                       [&]() { return found >= 0; });
    if(found < 0)
      continue; // another component: check_landmarks() reports the landmark off the boundary
    Landmark_snap<vertex_descriptor> snap;
    snap.landmark = l;
    snap.from = landmarks[l];
    snap.to = g.verts[static_cast<std::size_t>(found)];
    snap.distance = ws.distance(found);
    landmarks[l] = snap.to;
    snaps.push_back(snap);
  }
  return snaps;
}

} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_SELECT_LANDMARKS_H
