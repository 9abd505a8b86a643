// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_ORBIFOLD_EMBEDDING_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_ORBIFOLD_EMBEDDING_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Hyperbolic_orbifold_Tutte/Chart_point.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/Embedding_layout.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/Embedding_statistics.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <cstddef>
#include <type_traits>
#include <vector>

/// \file Orbifold_embedding.h

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {

/*!
\ingroup PkgHyperbolicOrbifoldTutteMainClasses
The result of an embedding: the mesh, its corner coordinates and everything needed to read
them (`Embedding_layout`: the orbifold and its tile, the order of the landmarks, the frame, the
charts, the cut), apart from what the computation did (`Embedding_statistics`: times, counts,
the solver's progress). `hyperbolic_orbifold_Tutte_embedding()` fills it; `Embedding_locator`,
`map_vertices()` and `certify_hyperbolic_orbifold_embedding()` take it, so that the reading
of the layout (which tile, which charts, which frame, which cut graph) is written once.

The coordinates stay in the property maps the user gives (the object holds the maps, not
copies of the values): for every halfedge `h` of a face, `uv_map()` holds the Poincar&eacute;
point of corner `target(h)` in `face(h)`, and `chart_map()` (if any) its `Chart_point`.

\tparam TriangleMesh a model of `FaceGraph` (e.g. `Surface_mesh`, `Polyhedron_3`)
\tparam HalfedgeUVMap a model of `ReadWritePropertyMap` from halfedges to `Point_2`
\tparam HalfedgeChartMap a model of `ReadWritePropertyMap` from halfedges to `Chart_point<Point_2>`,
        or the default (no chart map: an embedding that needs charts is refused)
*/
template <class TriangleMesh, class HalfedgeUVMap, class HalfedgeChartMap = internal::No_chart_map>
class Orbifold_embedding
{
public:
  typedef TriangleMesh Triangle_mesh;                                              ///< the mesh type
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;     ///< vertex of the mesh
  typedef typename boost::graph_traits<TriangleMesh>::halfedge_descriptor halfedge_descriptor; ///< halfedge of the mesh
  typedef typename boost::property_traits<HalfedgeUVMap>::value_type Point_2;     ///< the corner coordinates' point type
  typedef HalfedgeUVMap UV_map;                                                    ///< the corner coordinates
  typedef HalfedgeChartMap Chart_map;                                              ///< the corners' chart points
  /// whether the embedding has a chart map (it can then be written partly in charts)
  static constexpr bool has_chart_map = !std::is_same<HalfedgeChartMap, internal::No_chart_map>::value;

  /// an empty embedding (`is_valid()` is `false`)
  Orbifold_embedding() {}

  /// an embedding of `tm` to be computed into `uv` (and `chart_map`), or one computed before
  /// whose layout is then set with `layout()` and `set_landmarks()`
  Orbifold_embedding(const TriangleMesh& tm, HalfedgeUVMap uv, HalfedgeChartMap chart_map = HalfedgeChartMap())
    : tm_(&tm), uv_(uv), chart_map_(chart_map)
  {}

  /// whether the embedding holds coordinates (it was computed, or its layout set)
  bool is_valid() const { return tm_ != nullptr && computed_; }
  /// marks the coordinates as set (the one-call function does so when it returns `OK`)
  void set_valid(bool valid = true) { computed_ = valid; }

  /// whether the object was built from a mesh
  bool has_mesh() const { return tm_ != nullptr; }
  /// the mesh (`has_mesh()` must be `true`)
  const TriangleMesh& mesh() const { return *tm_; }
  /// the corner coordinates: for every halfedge `h` of a face, the point of corner `target(h)` in `face(h)`
  HalfedgeUVMap uv_map() const { return uv_; }
  /// the corners' chart points (\ref HOT_Charts)
  HalfedgeChartMap chart_map() const { return chart_map_; }
  /// the point of corner `target(h)` in `face(h)`
  Point_2 point(halfedge_descriptor h) const { return get(uv_, h); }

  /// everything needed to read the coordinates
  const Embedding_layout& layout() const { return layout_; }
  /// the same, to set it (an embedding computed elsewhere, e.g. read from a file)
  Embedding_layout& layout() { return layout_; }
  /// whether some faces are written in charts
  bool has_charts() const { return !layout_.charts.empty(); }

  /// the landmarks, as given
  const std::vector<vertex_descriptor>& landmarks() const { return landmarks_; }
  /// sets the landmarks as given (`Embedding_layout::landmark_order` orders them)
  void set_landmarks(const std::vector<vertex_descriptor>& landmarks) { landmarks_ = landmarks; }
  /// the landmarks in the order of the cut: landmark `i` is at cone `i` of the tile
  std::vector<vertex_descriptor> ordered_landmarks() const
  {
    if(layout_.landmark_order.size() != landmarks_.size())
      return landmarks_;
    std::vector<vertex_descriptor> r;
    r.reserve(landmarks_.size());
    for(std::size_t i : layout_.landmark_order)
      r.push_back(landmarks_[i]);
    return r;
  }
  /// genus \f$ g \ge 1 \f$: the cut graph as vertex paths (empty for genus 0)
  std::vector<std::vector<vertex_descriptor> > cut_graph() const
  {
    std::vector<std::vector<vertex_descriptor> > paths;
    if(layout_.cut_graph.empty())
      return paths;
    const std::vector<vertex_descriptor> all(vertices(*tm_).begin(), vertices(*tm_).end());
    for(const auto& path : layout_.cut_graph) {
      paths.emplace_back();
      for(std::size_t i : path)
        paths.back().push_back(all[i]);
    }
    return paths;
  }

  /// the signature of the orbifold
  Orbifold_signature signature() const { return layout_.signature(); }
  /// the tile the coordinates were computed in (`make_embedding_tile()`; a recentred
  /// embedding fills `tile.transformed(layout().frame)`)
  template <class Traits>
  Error_code tile(Orbifold_tile<Traits>& tile, const Traits& traits = Traits()) const
  {
    return make_embedding_tile(layout_, tile, traits);
  }

private:
  const TriangleMesh* tm_ = nullptr;
  HalfedgeUVMap uv_;
  HalfedgeChartMap chart_map_;
  Embedding_layout layout_;
  std::vector<vertex_descriptor> landmarks_;
  bool computed_ = false;
};

} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_ORBIFOLD_EMBEDDING_H
