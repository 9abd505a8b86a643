// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_TOOLS_IO_MAP_FILES_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_TOOLS_IO_MAP_FILES_H

// The files of a map between two meshes (the `map` and `collection` commands' output): the
// map itself (one located point of the target per source vertex) and the target coloured
// by a colouring of the source carried over by the map.

#include <CGAL/Bbox_3.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include "embedding_obj.h"
#include "prepared_input.h"

#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <ostream>
#include <vector>

#include <CGAL/disable_warnings.h>

/// \file map_files.h

namespace hot_tools {

// barycentric coordinates of a location on `m` w.r.t. its face's vertices in input order
// (read_mesh() builds face f with source(halfedge(f)) = its first vertex in the file)
template <class Point_3, class Locator>
std::array<double, 3> input_order_barycentric(const CGAL::Surface_mesh<Point_3>& m, const Locator& loc,
                                              const typename Locator::Location& l)
{
  std::array<double, 3> b{{0, 0, 0}};
  int j = 0;
  for(typename CGAL::Surface_mesh<Point_3>::Halfedge_index h : halfedges_around_face(prev(halfedge(l.face, m), m), m)) {
    const std::size_t v = target(h, m).idx();
    for(int c = 0; c < 3; ++c)
      if(loc.corner_vertex_index(l.face_index, c) == v) b[j] = l.barycentric[c];
    ++j;
  }
  return b;
}

// Writes the map f as write_map() does, one line per entry of `line_vertex`: the line of source
// vertex line_vertex[j], or `-1 0 0 0` where it is npos (a vertex of the source's file on no face).
template <class Point_3, class Locator>
void write_map(std::ostream& os, const CGAL::Surface_mesh<Point_3>& target_mesh, const Locator& target_locator,
               const std::vector<typename Locator::Location>& f, const std::vector<std::size_t>& line_vertex)
{
  os.precision(17);
  for(std::size_t v : line_vertex) {
    if(v == std::size_t(-1)) {
      os << "-1 0 0 0\n";
      continue;
    }
    const std::array<double, 3> b = input_order_barycentric(target_mesh, target_locator, f[v]);
    os << f[v].face_index << " " << b[0] << " " << b[1] << " " << b[2] << "\n";
  }
}

// Writes the map f from a source mesh onto `target_mesh` (located by `target_locator`): one line
// `face b0 b1 b2` per source vertex in input order, face = the 0-based face of the target in
// input order, b = barycentric coordinates w.r.t. that face's vertices in input order.
// With `source` (a prepared source mesh), one line per vertex of the source's files (the file's
// vertices, then the added ones): `-1 0 0 0` for a file vertex on no face of the prepared mesh.
template <class Point_3, class Locator>
void write_map(std::ostream& os, const CGAL::Surface_mesh<Point_3>& target_mesh, const Locator& target_locator,
               const std::vector<typename Locator::Location>& f, const Input_mesh* source = nullptr)
{
  std::vector<std::size_t> line_vertex;
  if(!source) {
    for(std::size_t v = 0; v < f.size(); ++v) line_vertex.push_back(v);
  } else {
    const HOT::Mesh_preparation& prep = source->prep;
    line_vertex = prep.prepared_vertex; // (npos: -1 0 0 0)
    for(std::size_t p = 0; p < prep.output_index.size(); ++p)
      if(prep.output_index[p] >= prep.number_of_input_vertices) line_vertex.push_back(p);
  }
  write_map(os, target_mesh, target_locator, f, line_vertex);
}

// Writes a mesh read by read_input_mesh() as OFF in the files' addressing (the file's vertices,
// then the added ones; the faces of the prepared mesh in order, as MAP.txt numbers them).
template <class Point_3>
void write_addressed_off(std::ostream& os, const CGAL::Surface_mesh<Point_3>& m, const Input_mesh& in)
{
  os.precision(17);
  os << "OFF\n" << in.file_points.size() + in.prep.number_of_added_vertices() << " " << num_faces(m) << " 0\n";
  write_addressed_vertices(os, m, &in, "");
  for(auto fc : faces(m)) {
    os << "3";
    for(auto h : halfedges_around_face(prev(halfedge(fc, m), m), m))
      os << " " << output_vertex(target(h, m), &in);
    os << "\n";
  }
}

// Writes `target_mesh` as an ASCII PLY coloured by a smooth colouring of `source_mesh` (its bounding
// box mapped to RGB) carried over by g, the map from the target onto the source (located by
// `source_locator`); grey where a vertex was not located. With `target_input` (a prepared target), the
// vertices are addressed as in its files (the file's vertices, grey if on no face, then the added
// ones).
template <class Point_3, class Locator>
void write_coloured_ply(std::ostream& os, const CGAL::Surface_mesh<Point_3>& source_mesh, const Locator& source_locator,
                        const CGAL::Surface_mesh<Point_3>& target_mesh, const std::vector<typename Locator::Location>& g,
                        const Input_mesh* target_input = nullptr)
{
  typedef CGAL::Surface_mesh<Point_3> Mesh;
  typedef typename CGAL::Kernel_traits<Point_3>::Kernel::Vector_3 Vector_3;
  const CGAL::Bbox_3 bb = CGAL::Polygon_mesh_processing::bbox(source_mesh);
  auto colour = [&](const Point_3& p) {
    return Vector_3((p.x() - bb.xmin()) / (bb.xmax() - bb.xmin() + 1e-300),
                    (p.y() - bb.ymin()) / (bb.ymax() - bb.ymin() + 1e-300),
                    (p.z() - bb.zmin()) / (bb.zmax() - bb.zmin() + 1e-300));
  };
  std::vector<Vector_3> source_colours;
  for(typename Mesh::Vertex_index v : vertices(source_mesh)) source_colours.push_back(colour(source_mesh.point(v)));
  const Vector_3 grey(0.5, 0.5, 0.5);
  auto carried = [&](std::size_t p) { // the colour of the target's prepared vertex p
    const typename Locator::Location& l = g[p];
    if(!l.success) return grey;
    return l.barycentric[0] * source_colours[source_locator.corner_vertex_index(l.face_index, 0)] +
           l.barycentric[1] * source_colours[source_locator.corner_vertex_index(l.face_index, 1)] +
           l.barycentric[2] * source_colours[source_locator.corner_vertex_index(l.face_index, 2)];
  };
  auto byte = [](double t) { return static_cast<int>(std::lround(255 * std::min(1.0, std::max(0.0, t)))); };
  auto line = [&](const Point_3& p, const Vector_3& c) {
    os << p << " " << byte(c.x()) << " " << byte(c.y()) << " " << byte(c.z()) << "\n";
  };
  const std::size_t nv = target_input ? target_input->file_points.size() + target_input->prep.number_of_added_vertices() : num_vertices(target_mesh);
  os << "ply\nformat ascii 1.0\nelement vertex " << nv
     << "\nproperty double x\nproperty double y\nproperty double z\nproperty uchar red\nproperty uchar green\nproperty uchar blue\n"
     << "element face " << num_faces(target_mesh) << "\nproperty list uchar int vertex_indices\nend_header\n";
  os.precision(17);
  if(!target_input) {
    for(typename Mesh::Vertex_index v : vertices(target_mesh)) line(target_mesh.point(v), carried(v.idx()));
  } else {
    const HOT::Mesh_preparation& prep = target_input->prep;
    for(std::size_t i = 0; i < target_input->file_points.size(); ++i) {
      const auto& q = target_input->file_points[i];
      line(Point_3(q[0], q[1], q[2]), prep.prepared_vertex[i] == HOT::Mesh_preparation::npos ? grey : carried(prep.prepared_vertex[i]));
    }
    for(typename Mesh::Vertex_index v : vertices(target_mesh))
      if(prep.output_index[v.idx()] >= prep.number_of_input_vertices) line(target_mesh.point(v), carried(v.idx()));
  }
  for(typename Mesh::Face_index fc : faces(target_mesh)) {
    os << "3";
    for(typename Mesh::Halfedge_index h : halfedges_around_face(prev(halfedge(fc, target_mesh), target_mesh), target_mesh))
      os << " " << output_vertex(target(h, target_mesh), target_input);
    os << "\n";
  }
}

} // namespace hot_tools

#include <CGAL/enable_warnings.h>

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_TOOLS_IO_MAP_FILES_H
