// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The embedding OBJ writer as it was before hot_app/io/embedding_obj.h (then tools/io/) wrote its numbers with
// std::to_chars (commit 3d3c8eb): every number through std::ostream with precision 17, i.e.
// printf's "%.17g". Kept as the reference the new writer must match byte for byte
// (test_input_checks.embedding_obj_bytes) and as the baseline of benchmark/bench_io.

#ifndef HOT_TEST_REFERENCE_EMBEDDING_OBJ_H
#define HOT_TEST_REFERENCE_EMBEDDING_OBJ_H

#include <hot_app/io/embedding_obj.h>

#include <cstddef>
#include <ostream>
#include <type_traits>
#include <utility>
#include <vector>

namespace hot_reference {

namespace HOT = CGAL::Hyperbolic_orbifold_Tutte;

// Writes the vertices of `m` (prefix + point per line) in the files' order: the file's
// vertices, then the ones the repair added (all of `m`'s in order without `in`).
template <class Point_3>
void reference_write_addressed_vertices(std::ostream& os, const CGAL::Surface_mesh<Point_3>& m, const hot_tools::Input_mesh* in, const char* prefix)
{
  if(!in) {
    for(auto v : vertices(m))
      os << prefix << m.point(v) << "\n";
    return;
  }
  for(const auto& p : in->file_points)
    os << prefix << Point_3(p[0], p[1], p[2]) << "\n";
  for(auto v : vertices(m))
    if(in->prep.output_index[v.idx()] >= in->prep.number_of_input_vertices)
      os << prefix << m.point(v) << "\n";
}

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
void reference_write_embedding_obj(std::ostream& os, const CGAL::Surface_mesh<Point_3>& m, const HalfedgeUVMap& uv,
                         const hot_tools::Input_mesh* in = nullptr, const hot_tools::Embedding_charts<HalfedgeChartMap>* charts = nullptr,
                         const hot_tools::Embedding_cones* cones = nullptr)
{
  typedef CGAL::Surface_mesh<Point_3> Mesh;
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
  auto key = [&](typename Mesh::Halfedge_index h) {
    Key k{get(uv, h), -1, Point_2(0, 0)};
    if constexpr(!std::is_same<HalfedgeChartMap, std::nullptr_t>::value)
      if(with_charts) {
        const auto cp = get(charts->map, h);
        k.chart = cp.chart;
        k.q = Point_2(cp.point.x(), cp.point.y());
      }
    return k;
  };
  std::vector<std::vector<std::pair<Key, std::size_t> > > vts(num_vertices(m));
  std::vector<Key> vt_points;
  std::vector<std::size_t> corner_vt(num_halfedges(m), 0);
  for(typename Mesh::Face_index f : faces(m))
    for(typename Mesh::Halfedge_index h : halfedges_around_face(halfedge(f, m), m)) {
      const Key p = key(h);
      auto& list = vts[target(h, m).idx()];
      std::size_t id = std::size_t(-1);
      for(const auto& e : list)
        if(e.first == p) { id = e.second; break; }
      if(id == std::size_t(-1)) {
        id = vt_points.size();
        vt_points.push_back(p);
        list.push_back(std::make_pair(p, id));
      }
      corner_vt[h.idx()] = id;
    }
  os.precision(17);
  os << "# hyperbolic orbifold Tutte embedding: vt = Poincare-disk coordinates\n";
  if(cones)
    hot_tools::write_embedding_cones(os, *cones);
  reference_write_addressed_vertices(os, m, in, "v ");
  if(in) // the file's vertices on no face that became a vertex of the mesh (merged duplicates)
    for(std::size_t i = 0; i < in->prep.prepared_vertex.size(); ++i) {
      const std::size_t p = in->prep.prepared_vertex[i];
      if(p != HOT::Mesh_preparation::npos && in->prep.output_index[p] != i)
        os << "# hot same " << i << " " << in->prep.output_index[p] << "\n";
    }
  for(const auto& p : vt_points)
    os << "vt " << p.p.x() << " " << p.p.y() << "\n";
  if(with_charts) {
    os << "# charts around cone images: faces written in a chart use its coordinates (see the manual)\n";
    for(std::size_t i = 0; i < charts->charts.size(); ++i) {
      const auto& c = charts->charts[i];
      os << "# hot chart " << i << " " << c.a().real() << " " << c.a().imag() << " " << c.b().real() << " " << c.b().imag() << " "
         << (i < charts->corners.size() ? charts->corners[i] : -1) << "\n";
    }
    for(std::size_t k = 0; k < vt_points.size(); ++k)
      if(vt_points[k].chart >= 0)
        os << "# hot vtc " << k + 1 << " " << vt_points[k].chart << " " << vt_points[k].q.x() << " " << vt_points[k].q.y() << "\n";
  }
  for(typename Mesh::Face_index f : faces(m)) {
    os << "f";
    // read_mesh() builds face f with source(halfedge(f)) = the file's first vertex of the face
    for(typename Mesh::Halfedge_index h : halfedges_around_face(prev(halfedge(f, m), m), m))
      os << " " << hot_tools::output_vertex(target(h, m), in) + 1 << "/" << corner_vt[h.idx()] + 1;
    os << "\n";
  }
}

} // namespace hot_reference

#endif // HOT_TEST_REFERENCE_EMBEDDING_OBJ_H
