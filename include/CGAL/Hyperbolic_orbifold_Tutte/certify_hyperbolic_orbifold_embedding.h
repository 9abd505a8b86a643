// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_CERTIFY_HYPERBOLIC_ORBIFOLD_EMBEDDING_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_CERTIFY_HYPERBOLIC_ORBIFOLD_EMBEDDING_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Hyperbolic_orbifold_Tutte/Embedding_certificate.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/check_input.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/genus.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/landmark_checks.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/Orbifold_embedding.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/Orbifold_tile.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/pipeline/certificate.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/pipeline/cone_chart_solve.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/core/dense_index.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/solver/flat_problem.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/input/input_stage.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/solver/cut_graph_problem.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/core/seam_mesh_storage.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/parameters.h>

#include <CGAL/boost/graph/Seam_mesh.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <boost/property_map/property_map.hpp>

#include <string>
#include <vector>

/// \file certify_hyperbolic_orbifold_embedding.h

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {

namespace internal {

// certify_hyperbolic_orbifold_embedding(): the tile of `type` with `k` cones of orders
// `orders` (empty: all 2), moved by the frame; none on a surface of genus g >= 1 (the polygon
// of the cut graph, built once the cut is recovered)
template <class NamedParameters>
Status tile_to_certify(Orbifold_type type, int k, const std::vector<int>& orders, long long genus,
                       const NamedParameters& np, Orbifold_tile<>& tile)
{
  if(genus > 0) {
    if(!CGAL::parameters::is_default_parameter<NamedParameters, internal_np::frame_t>::value)
      return Status::failure(ERROR_WRONG_PARAMETER, "a frame is for recentred embeddings, which surfaces of genus 1 or more do not have");
    Cone_order_check check; // (here their number; the orders themselves: the cut graph's tile)
    if(!orders.empty() && check_cone_orders(orders, static_cast<std::size_t>(k), &check) != OK &&
       check.problem == Wrong_number_of_cone_orders)
      return Status::failure(ERROR_WRONG_PARAMETER, std::to_string(orders.size()) + " cone orders are given for " +
                                                      std::to_string(k) + " landmarks");
  } else if(!orders.empty()) {
    const Status s = tile_of_cone_orders(type, orders, k, tile, Poincare_disk_traits_2<>());
    if(!s)
      return s;
  } else if(make_orbifold_tile(type, k, tile) != OK)
    return Status::failure(k < 5 ? ERROR_TOO_FEW_LANDMARKS : ERROR_NOT_HYPERBOLIC);
  if constexpr(!CGAL::parameters::is_default_parameter<NamedParameters, internal_np::frame_t>::value) {
    const Hyperbolic_isometry_2<double> frame = CGAL::parameters::get_parameter(np, internal_np::frame);
    if(!frame.is_orientation_preserving())
      return Status::failure(ERROR_WRONG_PARAMETER, "the frame must be an orientation-preserving isometry");
    tile = tile.transformed(frame); // a recentred embedding fills the moved tile
  }
  return Status();
}

// the seams of a corner map: per edge of `tm` (in the order of edges(tm)), whether its two
// sides disagree on a shared corner (or, in a chart, on the chart point)
template <class TriangleMesh, class HalfedgeUVMap, class NamedParameters>
std::vector<char> seams_of_corner_map(const TriangleMesh& tm, HalfedgeUVMap uvmap, const NamedParameters& np)
{
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename GT::edge_descriptor edge_descriptor;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  std::vector<char> seam;
  seam.reserve(num_edges(tm));
  for(edge_descriptor e : edges(tm)) {
    const halfedge_descriptor h = halfedge(e, tm), o = opposite(h, tm);
    if(is_border(h, tm) || is_border(o, tm)) {
      seam.push_back(0);
      continue;
    }
    // corner of target(h) in face(h) vs in face(o); corner of source(h) likewise
    bool differ = get(uvmap, h) != get(uvmap, prev(o, tm)) || get(uvmap, prev(h, tm)) != get(uvmap, o);
    if constexpr(!CGAL::parameters::is_default_parameter<NamedParameters, internal_np::chart_map_t>::value) {
      // (in a chart, two copies of a vertex may have one rounded tile point: their chart points differ)
      const auto cm = CGAL::parameters::get_parameter(np, internal_np::chart_map);
      auto other = [&](halfedge_descriptor a, halfedge_descriptor b) {
        const auto ca = get(cm, a), cb = get(cm, b);
        return ca.chart != cb.chart || (ca.chart >= 0 && ca.point != cb.point);
      };
      differ = differ || other(h, prev(o, tm)) || other(prev(h, tm), o);
    }
    seam.push_back(differ ? 1 : 0);
  }
  return seam;
}

// the first cut-mesh vertex (position in `cut_vertices`) of each halfedge of the mesh, or -1
template <class HalfedgeIndex, class CutVertices>
std::vector<int> cut_vertex_of_halfedges(const HalfedgeIndex& hindex, const CutVertices& cut_vertices, int n)
{
  std::vector<int> index_of(hindex.size(), -1);
  for(int i = 0; i < n; ++i) {
    const std::size_t k = hindex(cut_vertices[i].hd.tmhd);
    if(k != hindex.npos && index_of[k] < 0)
      index_of[k] = i;
  }
  return index_of;
}

// certify_hyperbolic_orbifold_embedding(), genus g >= 1: the flat problem of the polygon of
// the cut graph recovered from the map (`mesh`, cut open, `bhd` on its border), its corner 0
// as the embedding's (the first path of parameters::cut_graph(), when given); on failure, the
// error code and `why`
template <class TriangleMesh, class Mesh, class NamedParameters>
Error_code build_genus_cut_topology(const TriangleMesh& tm, Mesh& mesh,
                                    typename boost::graph_traits<Mesh>::halfedge_descriptor bhd,
                                    const std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>& landmarks,
                                    int genus, const std::vector<int>& orders, const NamedParameters& np, Orbifold_tile<>& tile,
                                    Flat_problem& P,
                                    std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>& base_vertex,
                                    std::vector<typename boost::graph_traits<Mesh>::vertex_descriptor>& cut_vertices,
                                    std::string& why)
{
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  const int k = static_cast<int>(landmarks.size());
  std::pair<int, int> start(-1, -1);
  const auto paths = CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np, internal_np::cut_graph),
                                                        std::vector<std::vector<vertex_descriptor> >());
  if(!paths.empty()) {
    if(paths[0].size() < 2) {
      why = "the cut graph's first path has fewer than 2 vertices";
      return ERROR_WRONG_PARAMETER;
    }
    const internal::Dense_index<vertex_descriptor> vindex(vertices(tm));
    start = std::make_pair(static_cast<int>(vindex(paths[0][0])), static_cast<int>(vindex(paths[0][1])));
  }
  internal::Cut_polygon poly;
  const Status t = internal::cut_graph_tile(mesh, bhd, landmarks, genus,
                                            orders.empty() ? std::vector<int>(k, 2) : orders, start, tile, tile.traits(), poly);
  if(!t) {
    why = t.message;
    return t.code;
  }
  return internal::build_cut_graph_topology(mesh, bhd, landmarks, start, tile, P, base_vertex, cut_vertices, why);
}

// What certify_hyperbolic_orbifold_embedding() recovers from a corner map before it checks it:
// the tile, the flat problem of the cut (the edges whose sides disagree) and the vertex of that
// problem at each face corner. It depends on the corners only through the seams, so maps with
// the same seams (the refinement's iterates: every move keeps the cut) share it.
struct Certificate_topology
{
  Orbifold_tile<> tile;
  Flat_problem P;
  std::vector<char> seams;         // per edge (seams_of_corner_map())
  std::vector<int> corner_vertex;  // per halfedge (in the order of halfedges(tm)): its corner's vertex of P (-1: border)
};

// certify_hyperbolic_orbifold_embedding()'s recovery of `topo` from the corners `uvmap`: OK, or
// the error and `why`
template <class TriangleMesh, class HalfedgeUVMap, class NamedParameters>
Error_code recover_certificate_topology(const TriangleMesh& tm,
                                        const std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>& landmarks,
                                        HalfedgeUVMap uvmap, const NamedParameters& np, Certificate_topology& topo, std::string& why)
{
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename GT::vertex_descriptor vertex_descriptor;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;

  Orbifold_type type = Sphere_type;
  const Status r = prepare_mesh(tm, get_const_property_map(vertex_point, tm), np, type);
  if(!r) {
    why = r.message;
    return r.code;
  }
  const int k = static_cast<int>(landmarks.size());
  const std::vector<int> orders =
    CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np, internal_np::cone_orders), std::vector<int>());
  const long long genus = type == Sphere_type ? closed_mesh_genus(tm) : 0;
  const Status t = tile_to_certify(type, k, orders, genus, np, topo.tile);
  if(!t) {
    why = t.message;
    return t.code;
  }

  // the cut: edges whose two sides disagree on a shared corner
  Seam_mesh_storage<TriangleMesh> storage(tm);
  typedef typename Seam_mesh_storage<TriangleMesh>::Mesh Mesh;
  Mesh& mesh = storage.mesh;
  topo.seams = seams_of_corner_map(tm, uvmap, np);
  std::size_t e = 0;
  for(const auto ed : edges(tm))
    if(topo.seams[e++])
      mesh.add_seam(source(halfedge(ed, tm), tm), target(halfedge(ed, tm), tm));
  typename boost::graph_traits<Mesh>::halfedge_descriptor bhd;
  if(!storage.border_halfedge(bhd)) {
    why = "the map has no cut: a closed mesh must be cut open through the landmarks";
    return ERROR_CUT_FAILED;
  }

  std::vector<vertex_descriptor> base_vertex;
  std::vector<typename boost::graph_traits<Mesh>::vertex_descriptor> cut_vertices;
  const Error_code ec =
    genus > 0 // genus g >= 1: the polygon of the recovered cut graph, its corner 0 as the embedding's
      ? build_genus_cut_topology(tm, mesh, bhd, landmarks, static_cast<int>(genus), orders, np, topo.tile, topo.P, base_vertex,
                                 cut_vertices, why)
      : build_flat_topology(mesh, bhd, landmarks, topo.tile, topo.P, base_vertex, cut_vertices, why);
  if(ec != OK)
    return ec;

  const Dense_index<halfedge_descriptor> hindex(halfedges(tm));
  const std::vector<int> index_of = cut_vertex_of_halfedges(hindex, cut_vertices, topo.P.n);
  topo.corner_vertex.clear();
  topo.corner_vertex.reserve(hindex.size());
  for(halfedge_descriptor h : halfedges(tm)) {
    if(is_border(h, tm)) {
      topo.corner_vertex.push_back(-1);
      continue;
    }
    const auto vd = target(typename boost::graph_traits<Mesh>::halfedge_descriptor(h, false), mesh);
    const std::size_t kd = hindex(vd.hd.tmhd);
    if(kd == hindex.npos || index_of[kd] < 0) {
      why = "a corner could not be matched to a vertex of the cut mesh";
      return ERROR_CUT_FAILED;
    }
    topo.corner_vertex.push_back(index_of[kd]);
  }
  return OK;
}

// the points of the corners `uvmap` per vertex of topo.P (any corner of a vertex: they agree off
// the cut)
template <class TriangleMesh, class HalfedgeUVMap>
std::vector<std::complex<double> > corner_points(const TriangleMesh& tm, HalfedgeUVMap uvmap, const Certificate_topology& topo)
{
  std::vector<std::complex<double> > uv(topo.P.n, std::complex<double>(2.0, 0.0));
  std::size_t i = 0;
  for(auto h : halfedges(tm)) {
    const int v = topo.corner_vertex[i++];
    if(v >= 0) {
      const auto p = get(uvmap, h);
      uv[v] = std::complex<double>(CGAL::to_double(p.x()), CGAL::to_double(p.y()));
    }
  }
  return uv;
}

} // namespace internal

/*!
\ingroup PkgHyperbolicOrbifoldTutteHelperFunctions

certifies any map of a mesh into a hyperbolic orbifold given as Poincar&eacute;
coordinates per face corner (the output format of `hyperbolic_orbifold_Tutte_embedding()`),
whoever computed it: the cut is recovered from the corners whose coordinates differ on the
two sides of an edge, then every check of `Embedding_certificate` is run, with the exact
orientation predicate on the given coordinates.

\tparam TriangleMesh a model of `FaceGraph` (e.g. `Surface_mesh`, `Polyhedron_3`)
\tparam HalfedgeUVMap a model of `ReadablePropertyMap` with
        `boost::graph_traits<TriangleMesh>::%halfedge_descriptor` as key type and a
        point type with `x()`, `y()` and `!=` as value type (e.g. `Point_2` of a %CGAL kernel)
\tparam NamedParameters a sequence of named parameters

\param tm the mesh
\param landmarks the landmark vertices in cone order (the order the map was computed with,
       e.g. `Embedding_statistics::landmark_order` applied to the given landmarks)
\param uvmap for every halfedge `h` of a face, the point of corner `target(h)` in `face(h)`
\param certificate receives the verdict and the count of each failure
\param message if not null, receives a one-line explanation of an error
\param np optional named parameters `orbifold_type` (default: from the mesh's topology),
       `frame` (a `Hyperbolic_isometry_2<double>`, default the identity): the map fills the
       tile moved by `frame` (`Embedding_statistics::frame` of a recentred embedding), and
       `chart_map` with `charts` for an embedding written partly in charts around cone images
       (\ref HOT_Charts): its faces there are checked in their charts' coordinates, and the
       seam pairings between two charts centred at corners of one cone are exact rotations,
       and `cone_orders` (a `std::vector<int>`, one per landmark in cone order, default 2 for
       all: `Embedding_statistics::cone_orders`) for cones of other angles. A closed mesh of
       genus \f$ g \ge 1 \f$ (\ref HOT_Genus): the cut graph is recovered from the corners, and
       the tile is its polygon's, with corner 0 set as `hyperbolic_orbifold_Tutte_embedding()`
       sets it: by the named parameter `cut_graph` (the one the embedding was given), or by
       default as for a computed cut graph

\return `OK` when the map could be analysed (read `certificate.is_bijective()`), otherwise the
reason (invalid mesh or landmarks, or a cut that is not a simple path through the landmarks
in order, which no map onto the orbifold's tile has: `ERROR_CUT_FAILED`); `message` (if not
null) gets a one-line explanation.
*/
template <class TriangleMesh, class HalfedgeUVMap, class NamedParameters = CGAL::parameters::Default_named_parameters>
Error_code certify_hyperbolic_orbifold_embedding(
  const TriangleMesh& tm,
  const std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>& landmarks,
  HalfedgeUVMap uvmap,
  Embedding_certificate& certificate,
  std::string* message = nullptr,
  const NamedParameters& np = CGAL::parameters::default_values())
{
  typedef typename boost::graph_traits<TriangleMesh>::halfedge_descriptor halfedge_descriptor;

  certificate = Embedding_certificate();
  std::string local;
  std::string& msg = message ? *message : local;
  msg.clear();
  auto fail = [&](Error_code ec, const std::string& m) {
    msg = m.empty() ? std::string(error_message(ec)) : m;
    return ec;
  };

  internal::Certificate_topology topo;
  const Error_code ec = internal::recover_certificate_topology(tm, landmarks, uvmap, np, topo, msg);
  if(ec != OK)
    return fail(ec, msg);
  const std::vector<std::complex<double> > uv = internal::corner_points(tm, uvmap, topo);
  const internal::Flat_problem& P = topo.P;
  if constexpr(!CGAL::parameters::is_default_parameter<NamedParameters, internal_np::chart_map_t>::value) {
    static_assert(!CGAL::parameters::is_default_parameter<NamedParameters, internal_np::charts_t>::value,
                  "parameters::chart_map() needs parameters::charts()");
    const std::vector<Hyperbolic_isometry_2<double> > charts = CGAL::parameters::get_parameter(np, internal_np::charts);
    std::vector<int> chart_of(P.n, -2); // (-2: not seen yet)
    std::vector<std::complex<double> > chart_local(P.n);
    std::size_t ih = 0;
    for(halfedge_descriptor h : halfedges(tm)) {
      const int i = topo.corner_vertex[ih++];
      if(i < 0)
        continue;
      const auto cp = get(CGAL::parameters::get_parameter(np, internal_np::chart_map), h);
      if(cp.chart < -1 || cp.chart >= static_cast<int>(charts.size()))
        return fail(ERROR_WRONG_PARAMETER, "a corner's chart " + std::to_string(cp.chart) + " is not one of the " +
                                             std::to_string(charts.size()) + " charts");
      if(chart_of[i] != -2 && chart_of[i] != cp.chart)
        return fail(ERROR_WRONG_PARAMETER, "two corners of one vertex (off the cut) are in different charts");
      chart_of[i] = cp.chart;
      chart_local[i] = std::complex<double>(CGAL::to_double(cp.point.x()), CGAL::to_double(cp.point.y()));
    }
    for(const auto& m : charts)
      if(!m.is_orientation_preserving())
        return fail(ERROR_WRONG_PARAMETER, "a chart must be an orientation-preserving isometry");
    for(int& c : chart_of)
      c = (std::max)(c, -1);
    internal::Cone_charts ch;
    if(!charts.empty()) {
      if(!internal::charts_of_written_embedding(P, topo.tile, uv, charts, chart_of, chart_local, ch))
        return fail(ERROR_WRONG_PARAMETER, "the charts do not make separate regions (a face or an edge joins two charts, "
                                           "or a seam copy is in a chart and its twin is not)");
      certificate = internal::certify_flat(P, topo.tile, uv, 1e-6, &ch);
      return OK;
    }
  }
  certificate = internal::certify_flat(P, topo.tile, uv);
  return OK;
}

namespace internal {

// certify_hyperbolic_orbifold_embedding() of a sequence of corner maps of one mesh (the
// refinement's iterates): the topology is recovered again only when the seams differ from the
// last map's, so each verdict is the function's at the cost of its checks alone
template <class TriangleMesh, class NamedParameters>
class Corner_map_certifier
{
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;

public:
  Corner_map_certifier(const TriangleMesh& tm, const std::vector<vertex_descriptor>& landmarks, const NamedParameters& np)
    : tm_(tm), landmarks_(landmarks), np_(np)
  {}

  // as certify_hyperbolic_orbifold_embedding(tm, landmarks, uvmap, certificate, &why, np)
  template <class HalfedgeUVMap>
  Error_code operator()(HalfedgeUVMap uvmap, Embedding_certificate& certificate, std::string& why)
  {
    if constexpr(!CGAL::parameters::is_default_parameter<NamedParameters, internal_np::chart_map_t>::value)
      return certify_hyperbolic_orbifold_embedding(tm_, landmarks_, uvmap, certificate, &why, np_);
    else {
      certificate = Embedding_certificate();
      why.clear();
      if(!recovered_ || seams_of_corner_map(tm_, uvmap, np_) != topo_.seams) {
        recovered_ = false;
        const Error_code ec = recover_certificate_topology(tm_, landmarks_, uvmap, np_, topo_, why);
        if(ec != OK) {
          if(why.empty())
            why = error_message(ec);
          return ec;
        }
        recovered_ = true;
      }
      certificate = certify_flat(topo_.P, topo_.tile, corner_points(tm_, uvmap, topo_));
      return OK;
    }
  }

private:
  const TriangleMesh& tm_;
  const std::vector<vertex_descriptor>& landmarks_;
  const NamedParameters& np_;
  Certificate_topology topo_;
  bool recovered_ = false;
};

} // namespace internal

/*!
\ingroup PkgHyperbolicOrbifoldTutteHelperFunctions

`certify_hyperbolic_orbifold_embedding()` of an embedding result (`Orbifold_embedding`): its
landmarks in the order of the cut, its corner coordinates, and what its layout says of them
(the orbifold type and cone orders, the frame of a recentred embedding, the charts, the cut
graph of a closed mesh of genus \f$ g \ge 1 \f$) as the named parameters of the other overload.

\return as the other overload; `ERROR_WRONG_PARAMETER` for an embedding that holds no coordinates
*/
template <class TriangleMesh, class HalfedgeUVMap, class HalfedgeChartMap>
Error_code certify_hyperbolic_orbifold_embedding(const Orbifold_embedding<TriangleMesh, HalfedgeUVMap, HalfedgeChartMap>& embedding,
                                                 Embedding_certificate& certificate, std::string* message = nullptr)
{
  certificate = Embedding_certificate();
  if(!embedding.is_valid()) {
    if(message)
      *message = "the embedding holds no coordinates (it was not computed)";
    return ERROR_WRONG_PARAMETER;
  }
  const Embedding_layout& layout = embedding.layout();
  const auto landmarks = embedding.ordered_landmarks();
  auto certify = [&](const auto& np) {
    if constexpr(Orbifold_embedding<TriangleMesh, HalfedgeUVMap, HalfedgeChartMap>::has_chart_map)
      if(!layout.charts.empty())
        return certify_hyperbolic_orbifold_embedding(embedding.mesh(), landmarks, embedding.uv_map(), certificate, message,
                                                     parameters::chart_map(embedding.chart_map(), parameters::charts(layout.charts, np)));
    return certify_hyperbolic_orbifold_embedding(embedding.mesh(), landmarks, embedding.uv_map(), certificate, message, np);
  };
  const auto np = parameters::cone_orders(layout.cone_orders, parameters::orbifold_type(layout.type));
  if(layout.genus > 0)
    return certify(parameters::cut_graph(embedding.cut_graph(), np));
  if(layout.recentred)
    return certify(parameters::frame(layout.frame, np));
  return certify(np);
}

} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_CERTIFY_HYPERBOLIC_ORBIFOLD_EMBEDDING_H
