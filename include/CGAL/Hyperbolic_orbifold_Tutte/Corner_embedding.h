// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_CORNER_EMBEDDING_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_CORNER_EMBEDDING_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Hyperbolic_orbifold_Tutte/error_code.h>

#include <CGAL/boost/graph/properties.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/number_utils.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <array>
#include <cstddef>
#include <utility>
#include <vector>

/// \file Corner_embedding.h

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {

/*!
\ingroup PkgHyperbolicOrbifoldTutteMainClasses

A map of a triangle mesh into the Poincar&eacute; disk given per face corner, as an OBJ file
holds it (`vt` lines and `f v/vt v/vt v/vt` faces; the format the command-line program's
`embed` writes): a list of points and, per face, its three mesh vertices and the point of
each corner. A vertex whose corners have different points is cut open there (a seam).
It is what `certify_corner_embedding()` checks, whoever computed it.

Where a part of the map converges onto a cone's image (a long protrusion ending at a
landmark: `Chart_point`), its points may also be given in charts around the cone's tile
corners, as the OBJ file's `# hot chart` and `# hot vtc` lines hold them: `charts` (chart `i`
maps a tile point \f$z\f$ to \f$(az + b)/(\bar b z + \bar a)\f$ and its origin is tile corner
`chart_corners[i]`), and per point its chart (`point_charts`, -1: none) and its coordinates
there (`chart_points`). A face is then in the chart of its corners that have one (at most
one chart per face), and its other corners are its chart applied to their points. Without
charts (`charts` empty), the map is its points alone.
*/
struct Corner_embedding
{
  /// the points (Poincar&eacute;-disk coordinates, `x` then `y`): the OBJ file's `vt` lines
  std::vector<std::array<double, 2> > points;
  /// per face, its vertices: 0-based indices of the mesh's vertices in the order of `vertices(tm)`
  /// (for a mesh read from a file, the file's order)
  std::vector<std::array<std::size_t, 3> > face_vertices;
  /// per face, the point of each corner: 0-based indices into `points`
  std::vector<std::array<std::size_t, 3> > face_points;
  /// the charts around cone images, `{a.real(), a.imag(), b.real(), b.imag()}` each (the OBJ
  /// file's `# hot chart` lines); empty for a map given by its points alone
  std::vector<std::array<double, 4> > charts;
  /// per chart, the tile corner at its origin (an index of the tile's corners)
  std::vector<int> chart_corners;
  /// per point, its chart (-1: none), or empty when no point has one (the `# hot vtc` lines)
  std::vector<int> point_charts;
  /// per point, its coordinates in its chart (unused where `point_charts` is -1)
  std::vector<std::array<double, 2> > chart_points;

  /// the number of faces
  std::size_t number_of_faces() const { return face_vertices.size(); }
  /// removes everything
  void clear()
  {
    points.clear();
    face_vertices.clear();
    face_points.clear();
    charts.clear();
    chart_corners.clear();
    point_charts.clear();
    chart_points.clear();
  }
  /// `true` when the map is given partly in charts
  bool has_charts() const { return !charts.empty(); }
};

/*!
\ingroup PkgHyperbolicOrbifoldTutteHelperFunctions

fills a `Corner_embedding` with the map `uvmap` of the triangle mesh `tm` (the output of
`hyperbolic_orbifold_Tutte_embedding()`): one face per face of `tm` in the order of
`faces(tm)`, its vertices numbered in the order of `vertices(tm)`, and one point per vertex
and distinct coordinates (corners of a vertex with equal coordinates share their point).

\tparam TriangleMesh a model of `FaceListGraph` and `VertexListGraph`
\tparam HalfedgeUVMap a model of `ReadablePropertyMap` with
        `boost::graph_traits<TriangleMesh>::%halfedge_descriptor` as key type and a point type
        with `x()` and `y()` as value type
\param tm the mesh
\param uvmap for every halfedge `h` of a face, the point of corner `target(h)` in `face(h)`
\param embedding receives the map (cleared first)
\return `OK`, or `ERROR_NON_TRIANGULAR_MESH` (and `embedding` empty) when a face is not a triangle
*/
template <class TriangleMesh, class HalfedgeUVMap>
Error_code make_corner_embedding(const TriangleMesh& tm, HalfedgeUVMap uvmap, Corner_embedding& embedding)
{
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename GT::vertex_descriptor vertex_descriptor;
  typedef typename GT::face_descriptor face_descriptor;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;

  embedding.clear();
  auto vindex = get(CGAL::dynamic_vertex_property_t<std::size_t>(), tm);
  std::size_t n = 0;
  for(vertex_descriptor v : vertices(tm))
    put(vindex, v, n++);
  // the points of each vertex so far (a vertex has one per side of a cut: a short list)
  std::vector<std::vector<std::pair<std::array<double, 2>, std::size_t> > > points_of(n);
  for(face_descriptor f : faces(tm)) {
    std::array<std::size_t, 3> fv, fp;
    std::size_t c = 0;
    for(halfedge_descriptor h : halfedges_around_face(halfedge(f, tm), tm)) {
      if(c == 3) {
        embedding.clear();
        return ERROR_NON_TRIANGULAR_MESH;
      }
      const auto q = get(uvmap, h);
      const std::array<double, 2> p{{CGAL::to_double(q.x()), CGAL::to_double(q.y())}};
      const std::size_t v = get(vindex, target(h, tm));
      std::size_t id = embedding.points.size();
      for(const auto& e : points_of[v])
        if(e.first == p) { id = e.second; break; }
      if(id == embedding.points.size()) {
        embedding.points.push_back(p);
        points_of[v].push_back(std::make_pair(p, id));
      }
      fv[c] = v;
      fp[c] = id;
      ++c;
    }
    if(c != 3) {
      embedding.clear();
      return ERROR_NON_TRIANGULAR_MESH;
    }
    embedding.face_vertices.push_back(fv);
    embedding.face_points.push_back(fp);
  }
  return OK;
}

} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_CORNER_EMBEDDING_H
