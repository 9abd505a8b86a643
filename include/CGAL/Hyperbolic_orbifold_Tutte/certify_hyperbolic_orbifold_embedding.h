// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_CERTIFY_HYPERBOLIC_ORBIFOLD_EMBEDDING_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_CERTIFY_HYPERBOLIC_ORBIFOLD_EMBEDDING_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Hyperbolic_orbifold_Tutte/Embedding_certificate.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/check_input.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/Orbifold_tile.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/certificate.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/dense_index.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/flat_problem.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/input_stage.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/seam_mesh_storage.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/parameters.h>

#include <CGAL/boost/graph/Seam_mesh.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <boost/property_map/property_map.hpp>

#include <string>
#include <vector>

/// \file certify_hyperbolic_orbifold_embedding.h

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {

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
\param np optional named parameters `orbifold_type` (default: from the mesh's topology) and
       `frame` (a `Hyperbolic_isometry_2<double>`, default the identity): the map fills the
       tile moved by `frame` (`Embedding_statistics::frame` of a recentred embedding)

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
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename GT::vertex_descriptor vertex_descriptor;
  typedef typename GT::edge_descriptor edge_descriptor;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  typedef typename GT::face_descriptor face_descriptor;
  typedef typename boost::property_traits<HalfedgeUVMap>::value_type Point_2;

  certificate = Embedding_certificate();
  std::string local;
  std::string& msg = message ? *message : local;
  msg.clear();
  auto fail = [&](Error_code ec, const std::string& m) {
    msg = m.empty() ? std::string(error_message(ec)) : m;
    return ec;
  };

  Orbifold_type type = Sphere_type;
  const Status r = internal::prepare_mesh(tm, get_const_property_map(vertex_point, tm), np, type);
  if(!r)
    return fail(r.code, r.message);
  const int k = static_cast<int>(landmarks.size());
  Orbifold_tile<> tile;
  if(make_orbifold_tile(type, k, tile) != OK)
    return fail(k < 5 ? ERROR_TOO_FEW_LANDMARKS : ERROR_NOT_HYPERBOLIC, "");
  if constexpr(!CGAL::parameters::is_default_parameter<NamedParameters, internal_np::frame_t>::value) {
    const Hyperbolic_isometry_2<double> frame = CGAL::parameters::get_parameter(np, internal_np::frame);
    if(!frame.is_orientation_preserving())
      return fail(ERROR_WRONG_PARAMETER, "the frame must be an orientation-preserving isometry");
    tile = tile.transformed(frame); // a recentred embedding fills the moved tile
  }

  // the cut: edges whose two sides disagree on a shared corner
  internal::Seam_mesh_storage<TriangleMesh> seams(tm);
  typedef typename internal::Seam_mesh_storage<TriangleMesh>::Mesh Mesh;
  Mesh& mesh = seams.mesh;
  for(edge_descriptor e : edges(tm)) {
    const halfedge_descriptor h = halfedge(e, tm), o = opposite(h, tm);
    if(is_border(h, tm) || is_border(o, tm))
      continue;
    // corner of target(h) in face(h) vs in face(o); corner of source(h) likewise
    const bool differ = get(uvmap, h) != get(uvmap, prev(o, tm)) || get(uvmap, prev(h, tm)) != get(uvmap, o);
    if(differ)
      mesh.add_seam(source(h, tm), target(h, tm));
  }
  typename boost::graph_traits<Mesh>::halfedge_descriptor bhd;
  if(!seams.border_halfedge(bhd))
    return fail(ERROR_CUT_FAILED, "the map has no cut: a closed mesh must be cut open through the landmarks");

  internal::Flat_problem P;
  std::vector<vertex_descriptor> base_vertex;
  std::vector<typename boost::graph_traits<Mesh>::vertex_descriptor> cut_vertices;
  std::string why;
  const Error_code ec = internal::build_flat_topology(mesh, bhd, landmarks, tile, P, base_vertex, cut_vertices, why);
  if(ec != OK)
    return fail(ec, why);

  // the point of each cut-mesh vertex, from any of its corners (they agree off the cut)
  const internal::Dense_index<halfedge_descriptor> hindex(halfedges(tm));
  std::vector<int> index_of(hindex.size(), -1);
  for(int i = 0; i < P.n; ++i) {
    const std::size_t k = hindex(cut_vertices[i].hd.tmhd);
    if(k != hindex.npos && index_of[k] < 0)
      index_of[k] = i;
  }
  std::vector<std::complex<double> > uv(P.n, std::complex<double>(2.0, 0.0));
  for(face_descriptor f : faces(tm))
    for(halfedge_descriptor h : halfedges_around_face(halfedge(f, tm), tm)) {
      const auto vd = target(typename boost::graph_traits<Mesh>::halfedge_descriptor(h, false), mesh);
      const std::size_t k = hindex(vd.hd.tmhd);
      if(k == hindex.npos || index_of[k] < 0)
        return fail(ERROR_CUT_FAILED, "a corner could not be matched to a vertex of the cut mesh");
      const Point_2 p = get(uvmap, h);
      uv[index_of[k]] = std::complex<double>(CGAL::to_double(p.x()), CGAL::to_double(p.y()));
    }
  certificate = internal::certify_flat(P, tile, uv);
  return OK;
}

} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_CERTIFY_HYPERBOLIC_ORBIFOLD_EMBEDDING_H
