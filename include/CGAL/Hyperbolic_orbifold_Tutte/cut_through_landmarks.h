// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_CUT_THROUGH_LANDMARKS_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_CUT_THROUGH_LANDMARKS_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Hyperbolic_orbifold_Tutte/internal/input/cut_paths.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/core/mesh_graph.h>

#include <CGAL/boost/graph/iterator.h>         // halfedges_around_target

#include <boost/graph/graph_traits.hpp>

#include <cstddef>
#include <sstream>
#include <string>
#include <unordered_set>
#include <vector>

/// \file cut_through_landmarks.h
/// Cutting a closed genus-0 mesh into a topological disk through its landmarks.
//
// Why not `Surface_mesh_parameterization::compute_shortest_paths_between_cones`:
// it computes each shortest path independently, so consecutive paths may share
// edges or vertices and the union is then not a tree, i.e. not a valid cut.
// Here the paths are computed one after the other, each one forbidden to touch
// the vertices used by the paths already computed and the other landmarks.

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {

/*!
\ingroup PkgHyperbolicOrbifoldTutteMainClasses

the result of `compute_cut_through_landmarks()`.

When `ok` is `true`, `paths[i]` (for `i` = 0..k-2) is the ordered list of halfedges of the
mesh going from `landmarks[i]` to `landmarks[i+1]`: `source(paths[i].front()) == landmarks[i]`,
`target(paths[i].back()) == landmarks[i+1]` and `target(paths[i][j]) == source(paths[i][j+1])`.
The union of the paths is a simple path through all landmarks in order.
When `ok` is `false`, `message` gives a one-line reason and `paths` is empty.

\tparam TriangleMesh the mesh type
*/
template <class TriangleMesh>
struct Cut_result
{
  /// the mesh's halfedge type
  typedef typename boost::graph_traits<TriangleMesh>::halfedge_descriptor halfedge_descriptor;

  bool ok = false;          ///< `true` iff the cut was found
  std::string message;      ///< the reason of the failure; empty on success
  std::vector<std::vector<halfedge_descriptor> > paths; ///< the pieces of the cut
  /// the number of path orders tried (1 when the plain p1->p2->... order worked)
  std::size_t number_of_attempts = 0;

  /// the number of edges of the cut
  std::size_t number_of_cut_edges() const
  {
    std::size_t n = 0;
    for(const auto& p : paths) n += p.size();
    return n;
  }

  /// the number of vertices of the cut (a simple path with E edges has E+1 vertices)
  std::size_t number_of_cut_vertices() const
  {
    return ok ? number_of_cut_edges() + 1 : 0;
  }
};

/*!
\ingroup PkgHyperbolicOrbifoldTutteMainClasses

the tuning of `compute_cut_through_landmarks()`.
*/
struct Cut_options
{
  /// Soft penalty discouraging "chords" (non-cut edges whose two endpoints are
  /// on the cut): the length of an edge entering a vertex that is adjacent to
  /// the cut (or to a landmark) is multiplied by `1 + chord_penalty`.
  /// 0 gives plain shortest paths.  It never blocks anything; it only makes
  /// paths keep one ring away from the rest of the cut when that is cheap.
  /// Measured on tour-ordered landmarks (k = 8..50, meshes of 1k-40k
  /// vertices): 2.0 removes 80-100% of the chords of plain shortest paths
  /// for a total cut length 1-6% longer.  Chords also matter for robustness:
  /// a chord closes a loop of cut vertices, which can separate the remaining
  /// free vertices and make a later path impossible.
  double chord_penalty = internal::default_chord_penalty;

  /// the maximal number of path orders tried (0 means: the number of landmarks)
  std::size_t max_attempts = 0;
};

/*!
\ingroup PkgHyperbolicOrbifoldTutteHelperFunctions

computes a cut of the closed genus-0 mesh `tm` that is a simple path through
`landmarks[0] -> landmarks[1] -> ... -> landmarks[k-1]`.

Each piece `landmarks[i] -> landmarks[i+1]` is a shortest path (on edge lengths, slightly
biased away from the rest of the cut by `options.chord_penalty`) among the vertices that
are neither on an already computed piece nor another landmark.  The pieces are therefore
vertex-disjoint except for the shared landmarks, and their union is a tree (a simple path),
which cuts a sphere into a disk.

Order of computation: the pieces are first computed in chain order (piece 0, then 1, ...).
Being greedy, an early piece can wall in the two endpoints of a later one.  If piece `i`
cannot be found, it is moved to the front of the computation order and everything is
recomputed (the chain p1 -> ... -> pk itself is unchanged; only who gets the "free"
shortest path changes).  This is repeated at most `options.max_attempts` times (default
k).  If the failing piece is already computed first, only the other landmarks are in its
way and no reordering can help.

Never asserts: invalid input (fewer than 3 landmarks, a landmark that is not a vertex of
`tm`, duplicates, a mesh with a border, a mesh that is not a connected genus-0 surface)
gives `ok == false` and a message.

Landmark order matters: in an arbitrary (e.g. random) order, each new piece has to wind
around the previous ones, the cut length explodes and for k >~ 15 the free vertices run out
(measured on 1k-40k vertex meshes: random orders fail for most k = 16 sets and all k = 25
sets, while tour-ordered sets up to k = 50 always succeeded).  Order the landmarks with
`compute_landmark_tour()` first.

Cost: O(n) to build the adjacency plus k A* searches, each at most O(n log n); typically a
small fraction of the mesh is explored (0.9 s in total on a 2.6M-vertex mesh, k = 50).
When no cut exists, up to `max_attempts` full rounds are tried, i.e. O(k^2) searches.

\tparam TriangleMesh a model of `FaceListGraph` and `HalfedgeListGraph` (e.g.
        `Surface_mesh`, `Polyhedron_3`)
\tparam VertexPointMap a model of `ReadablePropertyMap` with
        `boost::graph_traits<TriangleMesh>::%vertex_descriptor` as key type and a point of a
        CGAL kernel as value type
\param tm the mesh
\param landmarks the landmarks, in the order of the cut
\param vpm the vertex points
\param options the tuning
\return the cut, or the reason why none was found
\sa `add_cut_to_seam_mesh()`
*/
template <class TriangleMesh, class VertexPointMap>
Cut_result<TriangleMesh>
compute_cut_through_landmarks(
  const TriangleMesh& tm,
  const std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>& landmarks,
  VertexPointMap vpm,
  const Cut_options& options)
{
  Cut_result<TriangleMesh> res;
  res.message = internal::cut_through_landmarks(tm, landmarks, vpm, options.chord_penalty, options.max_attempts,
                                                res.paths, res.number_of_attempts);
  res.ok = res.message.empty();
  return res;
}

/*!
\ingroup PkgHyperbolicOrbifoldTutteHelperFunctions
same as above with the default `Cut_options`.
*/
template <class TriangleMesh, class VertexPointMap>
Cut_result<TriangleMesh>
compute_cut_through_landmarks(
  const TriangleMesh& tm,
  const std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>& landmarks,
  VertexPointMap vpm)
{
  return compute_cut_through_landmarks(tm, landmarks, vpm, Cut_options());
}

/*!
\ingroup PkgHyperbolicOrbifoldTutteHelperFunctions

returns the number of edges of `tm` that are not on the cut but whose two endpoints are on
the cut ("chords", see `Cut_options::chord_penalty`); 0 for a failed cut.
*/
template <class TriangleMesh>
std::size_t count_cut_chords(const TriangleMesh& tm, const Cut_result<TriangleMesh>& cut)
{
  typedef boost::graph_traits<TriangleMesh>         GT;
  typedef typename GT::vertex_descriptor            vertex_descriptor;
  typedef typename GT::halfedge_descriptor          halfedge_descriptor;

  if(!cut.ok) return 0;
  std::unordered_set<vertex_descriptor> cut_vertices;
  std::unordered_set<halfedge_descriptor> cut_halfedges;
  for(const auto& path : cut.paths) {
    for(halfedge_descriptor h : path) {
      cut_vertices.insert(source(h, tm));
      cut_vertices.insert(target(h, tm));
      cut_halfedges.insert(h);
      cut_halfedges.insert(opposite(h, tm));
    }
  }
  // Every chord is seen once from each endpoint.
  std::size_t twice = 0;
  for(vertex_descriptor v : cut_vertices) {
    for(halfedge_descriptor h : halfedges_around_target(v, tm)) {
      if(cut_halfedges.count(h) == 0 && cut_vertices.count(source(h, tm)) != 0) ++twice;
    }
  }
  return twice / 2;
}

/*!
\ingroup PkgHyperbolicOrbifoldTutteHelperFunctions

marks every edge of `cut` as a seam of `mesh` (a `CGAL::Seam_mesh` built on `tm`).

`add_seam` takes two vertices, so on a mesh with parallel edges it may pick another edge
between the same vertices than the cut's halfedge.

About `num_vertices(mesh)` (CGAL 5.5): `Seam_mesh` caches the number of its vertices in a
private mutable member, computed lazily on the first call to `num_vertices()` and never
invalidated by `add_seam()`; there is no public member to reset it
(`set_seam_edges_number()` only sets the seam edge counter).  Hence:
 - add all seams (call this function) before anything calls `num_vertices(mesh)` (the
   parameterizers do, to size their systems); this function itself never calls it, so a
   fresh `Seam_mesh` is left in a state where the cached count, once computed, is correct;
 - if the cache was already filled, build a new `Seam_mesh` on the same (now filled) seam
   property maps and call `set_seam_edges_number(cut.number_of_cut_edges())` on it, since
   the seam edge counter also lives in the `Seam_mesh` object.

`count_seam_mesh_vertices()` counts the vertices by iteration and does not depend on the
cache.

\return `true` iff the cut is valid and every edge was newly marked (`Seam_mesh::add_seam`
        refuses border edges and edges already marked, so the seam property maps should
        start all-false)
*/
template <class SeamMesh, class TriangleMesh>
bool add_cut_to_seam_mesh(SeamMesh& mesh, const TriangleMesh& tm,
                          const Cut_result<TriangleMesh>& cut)
{
  return cut.ok && internal::mark_seams(mesh, tm, cut.paths);
}

/*!
\ingroup PkgHyperbolicOrbifoldTutteHelperFunctions

returns the number of vertices of a seam mesh, counted by iterating over `vertices(mesh)`
(immune to the stale `num_vertices()` cache described at `add_cut_to_seam_mesh()`).  For a
cut that is a simple path with V_c vertices on a mesh with n vertices, this is n + V_c - 2:
every interior cut vertex is duplicated once.
*/
template <class SeamMesh>
std::size_t count_seam_mesh_vertices(const SeamMesh& mesh)
{
  std::size_t n = 0;
  for(auto v : vertices(mesh)) { (void)v; ++n; }
  return n;
}

} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_CUT_THROUGH_LANDMARKS_H
