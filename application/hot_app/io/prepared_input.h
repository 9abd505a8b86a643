// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_TOOLS_IO_PREPARED_INPUT_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_TOOLS_IO_PREPARED_INPUT_H

// A mesh file read for a job, as is (checked) or prepared (--repair), with its addressing by
// the file's vertices, and its landmarks read in the file's numbering (--snap-landmarks moves
// disk corners onto the boundary). Without --repair the addressing is the identity and every
// message is the one of read_and_check.h.

#include "read_and_check.h"

#include <CGAL/Hyperbolic_orbifold_Tutte/prepare_mesh_for_embedding.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/select_landmarks.h>

#include <CGAL/Polygon_mesh_processing/bbox.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include <CGAL/disable_warnings.h>

/// \file prepared_input.h

namespace hot_tools {

/// the command line's repair options
struct Repair_options
{
  bool repair = false;            ///< --repair
  bool largest_component = false; ///< --largest-component
  bool snap_landmarks = false;    ///< --snap-landmarks
  double max_hole = 0.5;          ///< --max-hole (bounding box diagonals)
  bool max_hole_given = false;    ///< --max-hole was given (with landmarks, the loops are otherwise closed whatever their length)
  long long target_genus = -1;    ///< --target-genus (-1: keep the genus)
  double max_handle = 0.2;        ///< --max-handle (bounding box diagonals)
};

/// a mesh file as a job sees it: the file's vertices and how the (prepared) mesh's vertices
/// are addressed by them (`HOT::Mesh_preparation`; the identity without --repair)
struct Input_mesh
{
  std::string path;
  bool repaired = false;
  std::vector<std::array<double, 3> > file_points; // the file's vertices, in file order
  HOT::Mesh_preparation prep;
};

/// a landmark moved onto the boundary, in the file's numbering
struct Landmark_snap_record
{
  std::size_t landmark = 0, from = 0, to = 0;
  double distance = 0;
};

namespace prepared_input_impl {

inline void identity_addressing(const std::vector<std::array<double, 3> >& points, HOT::Orbifold_type type,
                                HOT::Mesh_preparation& prep)
{
  prep = HOT::Mesh_preparation();
  prep.number_of_input_vertices = points.size();
  prep.prepared_vertex.resize(points.size());
  prep.output_index.resize(points.size());
  for(std::size_t i = 0; i < points.size(); ++i)
    prep.prepared_vertex[i] = prep.output_index[i] = i;
  prep.type = type;
}

} // namespace prepared_input_impl

/*!
true if the soup, built as without --repair (`mesh`), passes `check_mesh()` and the
preparation would not change it: closed, or a disk without inner edge joining two boundary
vertices whose boundary is not a hole to fill (a disk is required, or its boundary is longer
than `opt.max_hole` bounding box diagonals) and holds `landmarks` (file vertex numbers, in
range) on its boundary. A clean mesh then costs nothing more than without --repair and gives
the same files.
*/
template <class TriangleMesh>
bool needs_no_repair(const Polygon_soup& soup, std::optional<HOT::Orbifold_type> required_type, const Repair_options& opt,
                     const std::vector<std::size_t>& landmarks, TriangleMesh& mesh, HOT::Mesh_info& mi)
{
  namespace PMP = CGAL::Polygon_mesh_processing;
  if(!polygon_soup_to_mesh(soup, mesh) || !HOT::check_mesh(mesh, required_type, &mi))
    return false;
  if(mi.type == HOT::Sphere_type)
    return opt.target_genus < 0 || (mi.genus >= 0 && mi.genus <= opt.target_genus); // (else handles to cut)
  if(!landmarks.empty()) { // a landmark inside a disk asks for a sphere: the loop is a hole
    const std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor> verts(vertices(mesh).begin(), vertices(mesh).end());
    for(std::size_t i : landmarks)
      if(!CGAL::is_border(verts[i], mesh))
        return false;
  }
  for(auto e : edges(mesh)) {
    const auto h = halfedge(e, mesh);
    if(!CGAL::is_border_edge(h, mesh) && CGAL::is_border(source(h, mesh), mesh) && CGAL::is_border(target(h, mesh), mesh))
      return false; // a chord to split
  }
  if(required_type)
    return true;
  double length = 0;
  for(auto h : halfedges(mesh))
    if(CGAL::is_border(h, mesh))
      length += std::sqrt(CGAL::to_double(CGAL::squared_distance(get(CGAL::vertex_point, mesh, source(h, mesh)),
                                                                  get(CGAL::vertex_point, mesh, target(h, mesh)))));
  const CGAL::Bbox_3 b = PMP::bbox(mesh);
  const double diagonal = std::sqrt(CGAL::square(b.xmax() - b.xmin()) + CGAL::square(b.ymax() - b.ymin()) +
                                    CGAL::square(b.zmax() - b.zmin()));
  return length > opt.max_hole * diagonal; // else a hole to fill
}

/*!
Reads the mesh file `path` into `mesh`: with `opt.repair`, its polygon soup is prepared
(`HOT::prepare_polygon_soup_for_embedding()`), otherwise read and checked as
`read_and_check_mesh()` does. `info` (if not null) receives the sizes and the type.
`landmarks` (the file's vertex numbers; ignored if one is out of range, which the landmark
check says later) make the repair aim at the orbifold they ask for (`input_landmarks`: the
component that holds them, holes under them closed). Every message starts with the file name.
*/
template <class TriangleMesh>
HOT::Status read_input_mesh(const std::string& path, std::optional<HOT::Orbifold_type> required_type,
                            const Repair_options& opt, TriangleMesh& mesh, Input_mesh& in, HOT::Mesh_info* info = nullptr,
                            std::vector<std::size_t> landmarks = {})
{
  in = Input_mesh();
  in.path = path;
  in.repaired = opt.repair;
  HOT::Mesh_info local;
  HOT::Mesh_info& mi = info ? *info : local;
  if(!opt.repair) {
    HOT::Status r = read_and_check_mesh(path, required_type, mesh, &mi);
    if(!r) {
      switch(r.code) { // the defects the preparation mends: said, with the option
      case HOT::ERROR_NON_TRIANGULAR_MESH: case HOT::ERROR_NON_MANIFOLD: case HOT::ERROR_SEVERAL_COMPONENTS:
      case HOT::ERROR_DEGENERATE_FACE: case HOT::ERROR_BOUNDARY_CHORD:
        r.message += " (--repair mends such meshes)";
        break;
      case HOT::ERROR_WRONG_TOPOLOGY: // a disk with handles (topological noise)
        if(r.message.find("needs a topological disk, but the mesh has genus") != std::string::npos)
          r.message += " (--repair cuts the handles of a disk, up to --max-handle)";
        break;
      default:
        break;
      }
      return r;
    }
    for(auto v : vertices(mesh)) {
      const auto& p = get(CGAL::vertex_point, mesh, v);
      in.file_points.push_back({{CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())}});
    }
    prepared_input_impl::identity_addressing(in.file_points, mi.type, in.prep);
    timings().phase("addressing");
    return r;
  }
  Polygon_soup soup;
  CGAL::clear(mesh);
  HOT::Status r = read_polygon_soup_file(path, soup); // its messages start with the file name
  if(!r) return r;
  for(std::size_t i : landmarks)
    if(i >= soup.number_of_points()) {
      landmarks.clear(); // (read_input_landmarks() says which)
      break;
    }
  if(needs_no_repair(soup, required_type, opt, landmarks, mesh, mi)) { // as without --repair: same mesh, same bits
    in.file_points = std::move(soup.points);
    prepared_input_impl::identity_addressing(in.file_points, mi.type, in.prep);
    return r;
  }
  CGAL::clear(mesh);
  std::vector<std::vector<std::size_t> > polygons(soup.number_of_faces());
  for(std::size_t j = 0; j < polygons.size(); ++j) {
    polygons[j].assign(soup.face_vertices.begin() + soup.face_begin[j], soup.face_vertices.begin() + soup.face_begin[j + 1]);
    for(std::size_t v : polygons[j])
      if(v >= soup.number_of_points()) // a file error, said as validate_polygon_soup() says it
        return HOT::Status::failure(HOT::ERROR_READ_FAILED, path + ": " + soup.face_name(j) + ": vertex index " + std::to_string(v) +
                                                              " is out of range (the file has " + std::to_string(soup.number_of_points()) + " vertices)");
  }
  namespace P = HOT::parameters;
  // with landmarks and no --max-hole, every loop but a disk's boundary is closed, whatever its length
  const double max_hole = opt.max_hole_given || landmarks.empty() ? opt.max_hole : std::numeric_limits<double>::infinity();
  const auto np = P::input_landmarks(landmarks, P::keep_largest_component(opt.largest_component, P::maximum_hole_length(max_hole,
                                     P::target_genus(opt.target_genus, P::maximum_handle_length(opt.max_handle)))));
  r = required_type ? HOT::prepare_polygon_soup_for_embedding(soup.points, polygons, mesh, in.prep, P::orbifold_type(*required_type, np))
                    : HOT::prepare_polygon_soup_for_embedding(soup.points, polygons, mesh, in.prep, np);
  if(r) r = HOT::check_mesh(mesh, in.prep.type, &mi);
  if(!r) {
    CGAL::clear(mesh);
    r.message = path + ": " + r.message;
    return r;
  }
  in.file_points = std::move(soup.points);
  return r;
}

/*!
Reads the landmark file `path` (the mesh file's vertex numbers), converts them to vertices of
`mesh` through the addressing of `in`, with `snap` moves disk-type corners that are not on the
boundary onto it (recorded in `snaps`, in the file's numbering), and checks them
(`check_landmarks()`). Every message starts with the landmark file's name.
*/
template <class TriangleMesh>
HOT::Status read_input_landmarks(const std::string& path, const TriangleMesh& mesh, const Input_mesh& in,
                                 HOT::Orbifold_type type, bool snap,
                                 std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>& landmarks,
                                 std::vector<Landmark_snap_record>* snaps = nullptr,
                                 std::size_t minimum = HOT::minimum_number_of_landmarks)
{
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  if(!in.repaired && !snap)
    return read_and_check_landmarks(path, mesh, type, landmarks, minimum);
  landmarks.clear();
  minimum = HOT::minimum_number_of_landmarks_of(mesh, type, minimum); // (genus g >= 1: 1 or none)
  std::vector<std::size_t> ids;
  HOT::Status r = read_landmarks(path, ids, minimum <= 1);
  if(!r) return r;
  const HOT::Mesh_preparation& prep = in.prep;
  const std::size_t n = prep.number_of_input_vertices;
  auto fail = [&](HOT::Error_code code, const std::string& m) { return HOT::Status::failure(code, path + ": " + m); };
  std::vector<std::size_t> prepared(ids.size());
  for(std::size_t i = 0; i < ids.size(); ++i) {
    const std::string which = "landmark " + std::to_string(i) + " (vertex " + std::to_string(ids[i]) + ")";
    if(ids[i] >= n)
      return fail(HOT::ERROR_LANDMARK_OUT_OF_RANGE, which + " is not a vertex of the mesh file, which has " + std::to_string(n) + " vertices");
    if(prep.prepared_vertex[ids[i]] == HOT::Mesh_preparation::npos)
      return fail(HOT::ERROR_LANDMARK_OUT_OF_RANGE, which + " is on no face of the repaired mesh (an isolated vertex or one of a dropped component)");
    prepared[i] = prep.prepared_vertex[ids[i]];
  }
  const std::vector<vertex_descriptor> verts(vertices(mesh).begin(), vertices(mesh).end());
  if(snap && type == HOT::Disk_type) {
    std::vector<vertex_descriptor> lm;
    for(std::size_t p : prepared) lm.push_back(verts[p]);
    for(const auto& s : HOT::snap_landmarks_to_border(mesh, lm)) {
      const std::size_t to = static_cast<std::size_t>(std::find(verts.begin(), verts.end(), s.to) - verts.begin());
      prepared[s.landmark] = to;
      if(snaps) snaps->push_back({s.landmark, ids[s.landmark], prep.output_index[to], s.distance});
    }
  }
  // duplicates and corners off the boundary, in the file's numbering
  std::vector<std::size_t> first(verts.size(), HOT::Mesh_preparation::npos);
  for(std::size_t i = 0; i < prepared.size(); ++i) {
    const std::size_t j = first[prepared[i]];
    if(j == HOT::Mesh_preparation::npos) { first[prepared[i]] = i; continue; }
    if(ids[i] == ids[j])
      return fail(HOT::ERROR_DUPLICATE_LANDMARK, "vertex " + std::to_string(ids[i]) + " is given twice, as landmarks " +
                                                   std::to_string(j) + " and " + std::to_string(i));
    return fail(HOT::ERROR_DUPLICATE_LANDMARK, "landmarks " + std::to_string(j) + " and " + std::to_string(i) + " (vertices " +
                                                 std::to_string(ids[j]) + " and " + std::to_string(ids[i]) +
                                                 ") are one vertex of the repaired mesh (equal positions, or snapped to one boundary vertex)");
  }
  if(type == HOT::Disk_type)
    for(std::size_t i = 0; i < prepared.size(); ++i)
      if(!CGAL::is_border(verts[prepared[i]], mesh))
        return fail(HOT::ERROR_LANDMARK_NOT_ON_BORDER, "landmark " + std::to_string(i) + " (vertex " + std::to_string(ids[i]) +
                                                         ") is not on the boundary loop; disk-type orbifold corners must be boundary"
                                                         " vertices (--snap-landmarks moves them to the nearest one)");
  r = HOT::check_landmarks(mesh, prepared, type, landmarks, minimum); // the number of landmarks
  if(!r) r.message = path + ": " + r.message;
  return r;
}

} // namespace hot_tools

#include <CGAL/enable_warnings.h>

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_TOOLS_IO_PREPARED_INPUT_H
