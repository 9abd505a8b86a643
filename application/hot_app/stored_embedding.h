// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef HOT_APP_STORED_EMBEDDING_H
#define HOT_APP_STORED_EMBEDDING_H

// An embedding read back from the OBJ file `embed` or `collection` wrote, for maps that do not
// embed again (`map --source-embedding/--target-embedding`, collections run as separate jobs).
// The file's numbers are the embedding's, bit for bit: its v and vt lines have 17 significant
// digits, its charts' coefficients too, and the mesh is built from its faces as the reader
// builds a mesh from a file, so that a map from the stored embeddings is the same, number for
// number, as a map computed in the process that embedded.

#include "hot_app/job_input.h"
#include "hot_app/io/embedding_obj_reader.h"
#include "hot_app/io/polygon_soup.h"
#include "hot_app/io/polygon_soup_to_mesh.h"

#include <CGAL/Hyperbolic_orbifold_Tutte/Embedding_locator.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/Hyperbolic_isometry_2.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/check_input.h>

#include <array>
#include <cstddef>
#include <string>
#include <vector>

namespace hot_cli {

struct Stored_embedding
{
  std::string path;
  Surface_mesh mesh;                 // the file's faces on the v lines they use, both in file order
  UV_map uv;
  Chart_map charts;
  std::vector<HOT::Hyperbolic_isometry_2<double> > chart_isometries;
  std::vector<int> chart_corners;
  hot_tools::Embedding_cones cones;  // the orbifold and the cones, in the order of the cut
  // per v line of the file: the vertex of `mesh` it is (its index), or npos if it is on no face
  // (a map file has one line per v line, "-1 0 0 0" for those)
  std::vector<std::size_t> line_vertex;
  std::vector<std::size_t> vertex_line; // per vertex of `mesh`: its v line
  std::vector<std::size_t> corner_vt;   // per halfedge of `mesh`: the vt line (0-based) of its target corner (npos: border)

  static constexpr std::size_t npos = std::size_t(-1);

  std::size_t number_of_cones() const { return cones.landmark.size(); }
  // the embedding as the library's result type (genus 0: the file has no cut graph); its
  // landmarks are not known here (a map needs none)
  Embedding_result result() const
  {
    HOT::Embedding_layout layout;
    layout.type = cones.type;
    layout.cone_orders = cones.order;
    layout.charts = chart_isometries;
    layout.chart_corners = chart_corners;
    return embedding_result(mesh, uv, charts, layout, std::vector<SM_vertex>());
  }
  // the signature of the orbifold (cone orders in the order of the cut)
  HOT::Orbifold_signature signature() const { return HOT::Orbifold_signature(cones.type, cones.order); }
};


// Reads the embedding `path`; a file without the orbifold line (not written by `embed` or
// `collection` of this version), or faces that do not make a closed or disk mesh fail; so does
// a closed mesh of genus g >= 1 when the embedding is to be mapped (`for_map`: its tile depends
// on its cut graph, which the file does not hold, so it has no locator).
inline void read_stored_embedding(const std::string& path, Stored_embedding& e, bool for_map = true)
{
  e.path = path;
  HOT::Corner_embedding ce;
  std::size_t nv = 0;
  hot_tools::Embedding_obj_extras extras;
  require(hot_tools::read_embedding_obj(path, ce, nv, nullptr, &extras));
  if(!extras.has_cones)
    throw Failure{HOT::ERROR_READ_FAILED, path + ": the file has no '# hot orbifold' line (it was not written by embed or collection of"
                                                " this version): embed the mesh again, or map from the meshes (--source, --target)"};
  e.cones = extras.cones;
  if(for_map && e.cones.genus > 0)
    throw Failure{HOT::ERROR_WRONG_TOPOLOGY, path + ": a closed mesh of genus " + std::to_string(e.cones.genus) +
                                               ": its tile depends on its cut graph, which the file does not hold; map from the meshes"
                                               " (--source, --target, with their cut graphs)"};
  // the v lines on faces, in file order, are the mesh's vertices
  e.line_vertex.assign(nv, Stored_embedding::npos);
  for(const auto& f : ce.face_vertices)
    for(std::size_t v : f) e.line_vertex[v] = 0;
  hot_tools::Polygon_soup soup;
  e.vertex_line.clear();
  for(std::size_t j = 0; j < nv; ++j)
    if(e.line_vertex[j] != Stored_embedding::npos) {
      e.line_vertex[j] = e.vertex_line.size();
      e.vertex_line.push_back(j);
      soup.points.push_back(extras.vertex_points[j]);
    }
  for(const auto& f : ce.face_vertices) {
    for(std::size_t v : f) soup.face_vertices.push_back(e.line_vertex[v]);
    soup.face_begin.push_back(soup.face_vertices.size());
  }
  for(const auto& s : extras.same)
    if(e.line_vertex[s.first] == Stored_embedding::npos)
      e.line_vertex[s.first] = e.line_vertex[s.second];
  HOT::Status r = hot_tools::polygon_soup_to_mesh(soup, e.mesh);
  if(!r)
    throw Failure{r.code, path + ": " + r.message};
  r = HOT::check_mesh(e.mesh, e.cones.type);
  if(!r)
    throw Failure{r.code, path + ": " + r.message};
  for(std::size_t i = 0; i < e.cones.vertex.size(); ++i)
    if(e.line_vertex[e.cones.vertex[i]] == Stored_embedding::npos)
      throw Failure{HOT::ERROR_READ_FAILED, path + ": cone " + std::to_string(i) + " is at vertex " + std::to_string(e.cones.vertex[i]) +
                                              ", on no face"};
  // the corners: face j's k-th corner (the file's order) is the target of the k-th halfedge
  // from prev(halfedge(j)) (the builder makes source(halfedge(j)) the face's first vertex)
  e.uv = e.mesh.add_property_map<SM_halfedge, Kernel::Point_2>("h:uv", Kernel::Point_2(0, 0)).first;
  e.charts = e.mesh.add_property_map<SM_halfedge, HOT::Chart_point<Kernel::Point_2> >("h:chart").first;
  const bool with_charts = !ce.point_charts.empty();
  e.corner_vt.assign(num_halfedges(e.mesh), Stored_embedding::npos);
  std::size_t j = 0;
  for(SM_face f : faces(e.mesh)) {
    int k = 0;
    for(SM_halfedge h : halfedges_around_face(prev(halfedge(f, e.mesh), e.mesh), e.mesh)) {
      const std::size_t t = ce.face_points[j][k++];
      e.corner_vt[h.idx()] = t;
      put(e.uv, h, Kernel::Point_2(ce.points[t][0], ce.points[t][1]));
      if(with_charts && ce.point_charts[t] >= 0)
        put(e.charts, h, HOT::Chart_point<Kernel::Point_2>{ce.point_charts[t], Kernel::Point_2(ce.chart_points[t][0], ce.chart_points[t][1])});
    }
    ++j;
  }
  e.chart_isometries.clear();
  for(const auto& c : ce.charts)
    e.chart_isometries.push_back(HOT::Hyperbolic_isometry_2<double>::from_coefficients(std::complex<double>(c[0], c[1]),
                                                                                       std::complex<double>(c[2], c[3])));
  e.chart_corners = ce.chart_corners;
}

// the locator of a stored embedding (as a collection builds it: in the tile of its signature, with its charts)
inline Locator stored_locator(const Stored_embedding& e)
{
  return Locator(e.result(), HOT::Hyperboloid_linear);
}

// a map from `a` onto `b` joins cone c of `a` to cone c of `b`: the same orbifold, the same
// landmarks at the same cones, of the same orders, and the same orientation
inline void check_stored_pair(const Stored_embedding& a, const Stored_embedding& b)
{
  const hot_tools::Embedding_cones &ca = a.cones, &cb = b.cones;
  if(ca.type != cb.type)
    throw Failure{HOT::ERROR_WRONG_TOPOLOGY, "the source embedding is " + std::string(ca.type == HOT::Sphere_type ? "closed" : "a disk") +
                                               " but the target embedding " + (cb.type == HOT::Sphere_type ? "closed" : "a disk")};
  if(ca.landmark.size() != cb.landmark.size())
    throw Failure{HOT::ERROR_WRONG_PARAMETER, "the source embedding has " + std::to_string(ca.landmark.size()) +
                                                " cones and the target embedding " + std::to_string(cb.landmark.size())};
  if(ca.landmark != cb.landmark)
    throw Failure{HOT::ERROR_WRONG_PARAMETER, "the two embeddings put the landmarks at different cones (the landmark order used differs):"
                                                " embed the target with the source's order (--order given, landmarks listed in the"
                                                " source's landmark_order_used)"};
  if(ca.order != cb.order)
    throw Failure{HOT::ERROR_WRONG_PARAMETER, "the cones of the two embeddings have different orders (--cone-orders)"};
  if(ca.reversed != cb.reversed)
    throw Failure{HOT::ERROR_WRONG_PARAMETER, "the landmarks run clockwise around one boundary and counterclockwise around the other: "
                                                "the correspondence would reverse orientation"};
}

} // namespace hot_cli

#endif // HOT_APP_STORED_EMBEDDING_H
