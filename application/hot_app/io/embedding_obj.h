// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_TOOLS_IO_EMBEDDING_OBJ_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_TOOLS_IO_EMBEDDING_OBJ_H

// The OBJ file of an embedding (the `embed` and `collection` commands' output).

#include <CGAL/Surface_mesh.h>

#include <boost/property_map/property_map.hpp>

#include <CGAL/Hyperbolic_orbifold_Tutte/Hyperbolic_isometry_2.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/Orbifold_embedding.h>

#include <cstddef>
#include "embedding_cones.h"
#include "prepared_input.h"
#include "text_buffer.h"

#include <ostream>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

#include <CGAL/disable_warnings.h>

/// \file embedding_obj.h

namespace hot_tools {

// the index of a vertex of a mesh read by read_input_mesh() in the files written for it
template <class Vertex_index>
std::size_t output_vertex(Vertex_index v, const Input_mesh* in)
{
  return in ? in->prep.output_index[v.idx()] : std::size_t(v.idx());
}

namespace embedding_obj_impl {

// the lines "prefix x y z" of the vertices of `m` in the files' order (write_addressed_vertices())
template <class Point_3>
void write_vertex_lines(std::ostream& os, const CGAL::Surface_mesh<Point_3>& m, const Input_mesh* in, const char* prefix)
{
  typedef typename CGAL::Surface_mesh<Point_3>::Vertex_index Vertex_index;
  const std::string_view pre(prefix);
  auto put_point = [&](io_impl::Text_buffer& t, double x, double y, double z) {
    t.put(pre).put(x).put(' ').put(y).put(' ').put(z).put('\n');
  };
  std::vector<Vertex_index> vs; // (the mesh's, or the ones the repair added after the file's)
  for(Vertex_index v : vertices(m))
    if(!in || in->prep.output_index[v.idx()] >= in->prep.number_of_input_vertices)
      vs.push_back(v);
  const std::size_t nf = in ? in->file_points.size() : 0;
  io_impl::write_lines(os, nf + vs.size(), [&](std::size_t i, io_impl::Text_buffer& t) {
    if(i < nf) {
      const auto& p = in->file_points[i];
      put_point(t, p[0], p[1], p[2]);
    } else {
      const Point_3& p = m.point(vs[i - nf]);
      put_point(t, CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
    }
  });
}

} // namespace embedding_obj_impl

// Writes the vertices of `m` (prefix + point per line, coordinates as printf("%.17g"), the
// precision the callers set on `os`) in the files' order: the file's vertices, then the ones
// the repair added (all of `m`'s in order without `in`).
template <class Point_3>
void write_addressed_vertices(std::ostream& os, const CGAL::Surface_mesh<Point_3>& m, const Input_mesh* in, const char* prefix)
{
  embedding_obj_impl::write_vertex_lines(os, m, in, prefix);
}

// The charts of an embedding written partly in charts around cone images (HOT::Chart_point):
// the chart points of the corners and the charts' isometries.
template <class HalfedgeChartMap>
struct Embedding_charts
{
  HalfedgeChartMap map;
  std::vector<CGAL::Hyperbolic_orbifold_Tutte::Hyperbolic_isometry_2<double> > charts;
  std::vector<int> corners; // the tile corner at each chart's origin
};

// Writes an embedding as OBJ: v = input vertices, vt = one Poincare point per cut-mesh
// vertex (corners of a vertex with equal points share their vt), f = input faces in input
// order with their corners' vt. `uv` maps each halfedge to the point of its target corner.
// With `in` (a prepared mesh, see prepared_input.h), the vertices are addressed as the file's:
// v lines = the file's vertices in file order, then the vertices the repair added; f lines =
// the prepared mesh's faces.
// With `charts` (not empty), the chart table and the chart point of every vt written in a
// chart follow the vt lines, as comments (any OBJ reader skips them):
//   # hot chart I AR AI BR BI C   chart I maps a tile point z to (a z + b) / (conj(b) z + conj(a)),
//                                 a = AR + i AI, b = BR + i BI; its origin is tile corner C
//   # hot vtc K I X Y             vt K (1-based) is the point (X, Y) of chart I; its vt line
//                                 holds its tile point rounded to double
// A face is written in the chart of any of its vt that has one (at most one chart per face);
// its other corners are the chart applied to their tile points (HOT::chart_coordinates()).
// With `cones`, the orbifold and cone lines (Embedding_cones) follow the first comment line.
// With `in`, a file vertex on no face of the prepared mesh that became one of its vertices (a
// merged duplicate) gets a line `# hot same J K` after the v lines (v line J is v line K; 0-based).
template <class Point_3, class HalfedgeUVMap, class HalfedgeChartMap = std::nullptr_t>
void write_embedding_obj(std::ostream& os, const CGAL::Surface_mesh<Point_3>& m, const HalfedgeUVMap& uv,
                         const Input_mesh* in = nullptr, const Embedding_charts<HalfedgeChartMap>* charts = nullptr,
                         const Embedding_cones* cones = nullptr)
{
  typedef CGAL::Surface_mesh<Point_3> Mesh;
  typedef typename Mesh::Face_index Face_index;
  typedef typename Mesh::Halfedge_index Halfedge_index;
  typedef typename boost::property_traits<HalfedgeUVMap>::value_type Point_2;
  // a corner's key: its tile point, and its chart point (chart -1: none)
  struct Key
  {
    Point_2 p;
    int chart;
    Point_2 q;
    bool operator==(const Key& o) const { return p == o.p && chart == o.chart && (chart < 0 || q == o.q); }
  };
  const bool with_charts = charts != nullptr && !charts->charts.empty();
  auto key = [&](Halfedge_index h) {
    Key k{get(uv, h), -1, Point_2(0, 0)};
    if constexpr(!std::is_same<HalfedgeChartMap, std::nullptr_t>::value)
      if(with_charts) {
        const auto cp = get(charts->map, h);
        k.chart = cp.chart;
        k.q = Point_2(cp.point.x(), cp.point.y());
      }
    return k;
  };
  // the vt of each corner: the distinct keys of a vertex's corners, numbered in the order the
  // faces first reach them; a vertex's vt are chained (first_vt, next_vt: no list per vertex)
  const std::size_t none = std::size_t(-1);
  std::vector<Face_index> fs(faces(m).begin(), faces(m).end());
  std::vector<std::size_t> first_vt(m.num_vertices(), none), next_vt;
  std::vector<Key> vt_points;
  std::vector<std::size_t> corner_vt(m.num_halfedges(), 0);
  vt_points.reserve(num_vertices(m) + num_vertices(m) / 8);
  next_vt.reserve(vt_points.capacity());
  for(Face_index f : fs)
    for(Halfedge_index h : halfedges_around_face(halfedge(f, m), m)) {
      const Key p = key(h);
      std::size_t* link = &first_vt[target(h, m).idx()];
      while(*link != none && !(vt_points[*link] == p))
        link = &next_vt[*link];
      std::size_t id = *link;
      if(id == none) {
        id = *link = vt_points.size();
        vt_points.push_back(p);
        next_vt.push_back(none); // (after the write through `link`, which may point into next_vt)
      }
      corner_vt[h.idx()] = id;
    }
  os.precision(17); // (the numbers are written as with this precision: printf's "%.17g")
  io_impl::Text_buffer head;
  head.put("# hyperbolic orbifold Tutte embedding: vt = Poincare-disk coordinates\n");
  head.flush_to(os);
  if(cones)
    write_embedding_cones(os, *cones);
  embedding_obj_impl::write_vertex_lines(os, m, in, "v ");
  if(in) { // the file's vertices on no face that became a vertex of the mesh (merged duplicates)
    for(std::size_t i = 0; i < in->prep.prepared_vertex.size(); ++i) {
      const std::size_t p = in->prep.prepared_vertex[i];
      if(p != HOT::Mesh_preparation::npos && in->prep.output_index[p] != i)
        head.put("# hot same ").put(i).put(' ').put(in->prep.output_index[p]).put('\n');
    }
    head.flush_to(os);
  }
  io_impl::write_lines(os, vt_points.size(), [&](std::size_t k, io_impl::Text_buffer& t) {
    t.put("vt ").put(CGAL::to_double(vt_points[k].p.x())).put(' ').put(CGAL::to_double(vt_points[k].p.y())).put('\n');
  });
  if(with_charts) {
    head.put("# charts around cone images: faces written in a chart use its coordinates (see the manual)\n");
    for(std::size_t i = 0; i < charts->charts.size(); ++i) {
      const auto& c = charts->charts[i];
      head.put("# hot chart ").put(i).put(' ').put(double(c.a().real())).put(' ').put(double(c.a().imag())).put(' ')
        .put(double(c.b().real())).put(' ').put(double(c.b().imag())).put(' ')
        .put(i < charts->corners.size() ? charts->corners[i] : -1).put('\n');
    }
    for(std::size_t k = 0; k < vt_points.size(); ++k)
      if(vt_points[k].chart >= 0)
        head.put("# hot vtc ").put(k + 1).put(' ').put(vt_points[k].chart).put(' ').put(CGAL::to_double(vt_points[k].q.x()))
          .put(' ').put(CGAL::to_double(vt_points[k].q.y())).put('\n');
    head.flush_to(os);
  }
  io_impl::write_lines(os, fs.size(), [&](std::size_t j, io_impl::Text_buffer& t) {
    t.put('f');
    // read_mesh() builds face f with source(halfedge(f)) = the file's first vertex of the face
    for(Halfedge_index h : halfedges_around_face(prev(halfedge(fs[j], m), m), m))
      t.put(' ').put(output_vertex(target(h, m), in) + 1).put('/').put(corner_vt[h.idx()] + 1);
    t.put('\n');
  });
}

// Writes an embedding result (HOT::Orbifold_embedding) as OBJ: its corners, and its charts as
// its layout gives them (write_embedding_obj() above).
template <class Point_3, class HalfedgeUVMap, class HalfedgeChartMap>
void write_embedding_obj(std::ostream& os,
                         const CGAL::Hyperbolic_orbifold_Tutte::Orbifold_embedding<CGAL::Surface_mesh<Point_3>, HalfedgeUVMap, HalfedgeChartMap>& e,
                         const Input_mesh* in = nullptr, const Embedding_cones* cones = nullptr)
{
  const Embedding_charts<HalfedgeChartMap> charts{e.chart_map(), e.layout().charts, e.layout().chart_corners};
  write_embedding_obj(os, e.mesh(), e.uv_map(), in, &charts, cones);
}

} // namespace hot_tools

#include <CGAL/enable_warnings.h>

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_TOOLS_IO_EMBEDDING_OBJ_H
