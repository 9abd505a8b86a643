// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef HOT_APP_VIEW_H
#define HOT_APP_VIEW_H

// What the `view` job writes: a folder that opens offline in any browser (index.html, data.js, viewer.js and
// Debian's three.js, three.min.js), showing an embedding (the surface textured by the hyperbolic
// tiling, beside the Poincare disk with the mesh and the cut), a map (the two surfaces, a colour
// field carried across, numbered landmarks, per-face distortion, unreliable vertices, picking)
// or a collection (the shapes side by side, the first one's colour field carried to all).
// The page's files are tools/viewer/*, embedded at build time (hot_viewer_assets.h, generated
// by tools/viewer/CMakeLists.txt: target Hyperbolic_orbifold_Tutte_viewer_assets). Shared by the
// program (tools/jobs/view.h) and the Python module (python/src/view.cpp): View_input,
// view_embedding(), view_maps(), write_view_folder().

#include "hot_app/job_support.h" // Failure, write_file_atomically()
#include "hot_app/stored_embedding.h"
#include "hot_app/io/files.h"
#include "hot_app/io/map_files.h" // input_order_barycentric()
#include "hot_viewer_assets.h"    // hot_viewer::index_html, hot_viewer::viewer_js (generated)

#include <CGAL/Hyperbolic_orbifold_Tutte/Orbifold_tile.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/Poincare_disk_traits_2.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/map_distortion.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/map_reliability.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/surface_maps.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <ostream>
#include <string>
#include <stdexcept>
#include <system_error>
#include <vector>

// Debian's libjs-three (r111), copied into every view folder (HOT_THREE_JS in the environment
// names another copy)
#ifndef HOT_THREE_JS_PATH
#define HOT_THREE_JS_PATH "/usr/share/javascript/three/three.min.js"
#endif

namespace hot_cli {

// ---- what the page shows (data.js; the format is described at the head of tools/viewer/viewer.js)
struct View_shape
{
  std::string name;
  std::vector<double> positions;                    // x y z per vertex
  std::vector<std::size_t> faces;                  // three vertices per face, in the file's order
  std::vector<double> colors;                       // r g b per vertex (empty: none)
  std::vector<std::size_t> landmark_numbers, landmark_vertices;
  std::vector<double> conformal, area;              // per face (empty: none)
  std::vector<double> uv;                           // u v per face corner (embedding)
  std::vector<std::size_t> cut;                     // vertex pairs
  std::vector<double> cut_uv;                       // u0 v0 u1 v1 per cut edge side
  std::vector<double> fold;                         // x y per corner of the folding polygon
};

struct View_map
{
  std::size_t from = 0, to = 0;
  std::vector<std::size_t> face;   // per vertex of `from`
  std::vector<double> bary;        // 3 per vertex of `from` (w.r.t. the face's vertices in file order)
  std::vector<std::size_t> unreliable;
};

struct View_data
{
  std::string kind, title;
  std::vector<View_shape> shapes;
  std::vector<View_map> maps;
};

// an embedded mesh to view: the mesh (vertices and faces in the file's order), its corner
// embedding, its locator, and its landmarks (number in the landmark file, vertex)
struct View_input
{
  std::string name;
  const Surface_mesh* mesh = nullptr;
  UV_map uv;
  Chart_map charts;
  std::vector<HOT::Hyperbolic_isometry_2<double> > chart_isometries;
  const Locator* locator = nullptr;
  std::vector<std::size_t> landmark_numbers, landmark_vertices;
  HOT::Orbifold_signature signature;
  long long genus = 0;
};

namespace view_impl {

inline void number(std::string& s, double x, int digits)
{
  if(!std::isfinite(x)) {
    s += "null";
    return;
  }
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.*g", digits, x);
  s += buf;
}

// "key":[e0,e1,...], element i written by put(i)
template <class Put>
void list(std::string& s, const char* key, std::size_t n, Put put)
{
  s += "\"";
  s += key;
  s += "\":[";
  for(std::size_t i = 0; i < n; ++i) {
    if(i) s += ",";
    put(i);
  }
  s += "]";
}

// numbers to `digits` significant digits; an empty array is null (the page: "none")
inline void array(std::string& s, const char* key, const std::vector<double>& v, int digits)
{
  if(v.empty()) {
    s += "\"";
    s += key;
    s += "\":null";
    return;
  }
  list(s, key, v.size(), [&](std::size_t i) { number(s, v[i], digits); });
}

inline void array(std::string& s, const char* key, const std::vector<std::size_t>& v)
{
  list(s, key, v.size(), [&](std::size_t i) { s += std::to_string(v[i]); });
}

inline std::string quoted(const std::string& t)
{
  std::string r = "\"";
  for(char c : t) {
    if(c == '"' || c == '\\') { r += '\\'; r += c; }
    else if(static_cast<unsigned char>(c) < 0x20) r += ' ';
    else if(c == '<') r += "\\u003c"; // (no "</script>" in the page's data)
    else r += c;
  }
  return r + "\"";
}

inline std::string file_name(const std::string& path)
{
  return std::filesystem::path(path).filename().string();
}

} // namespace view_impl

// data.js: `window.HOT_VIEW = {...};`
inline std::string view_data_js(const View_data& d)
{
  using namespace view_impl;
  std::string s = "// written by hyperbolic_orbifold_tutte view: the data tools/viewer/viewer.js draws\nwindow.HOT_VIEW = {";
  s += "\"kind\":" + quoted(d.kind) + ",\"title\":" + quoted(d.title) + ",\"shapes\":[";
  for(std::size_t i = 0; i < d.shapes.size(); ++i) {
    const View_shape& sh = d.shapes[i];
    s += i ? ",\n{" : "\n{";
    s += "\"name\":" + quoted(sh.name) + ",";
    array(s, "positions", sh.positions, 9);
    s += ",\n";
    array(s, "faces", sh.faces);
    s += ",\n";
    array(s, "colors", sh.colors, 4);
    s += ",";
    array(s, "landmark_numbers", sh.landmark_numbers);
    s += ",";
    array(s, "landmark_vertices", sh.landmark_vertices);
    s += ",\n\"distortion\":";
    if(sh.conformal.empty())
      s += "null";
    else {
      s += "{";
      array(s, "conformal", sh.conformal, 5);
      s += ",";
      array(s, "area", sh.area, 5);
      s += "}";
    }
    s += ",\n";
    array(s, "uv", sh.uv, 12);
    s += ",";
    array(s, "cut", sh.cut);
    s += ",";
    array(s, "cut_uv", sh.cut_uv, 9);
    s += ",";
    array(s, "fold", sh.fold, 17);
    s += "}";
  }
  s += "],\n\"maps\":[";
  for(std::size_t i = 0; i < d.maps.size(); ++i) {
    const View_map& m = d.maps[i];
    s += i ? ",\n{" : "\n{";
    s += "\"from\":" + std::to_string(m.from) + ",\"to\":" + std::to_string(m.to) + ",";
    array(s, "face", m.face);
    s += ",\n";
    array(s, "bary", m.bary, 17);
    s += ",\n";
    array(s, "unreliable", m.unreliable);
    s += "}";
  }
  s += "]};\n";
  return s;
}

// the mesh: vertices and faces (each face's vertices in the file's order: read_mesh() builds
// face f with source(halfedge(f)) its first vertex)
inline View_shape view_shape(const std::string& name, const Surface_mesh& m)
{
  View_shape s;
  s.name = name;
  for(SM_vertex v : vertices(m)) {
    const Kernel::Point_3& p = m.point(v);
    s.positions.insert(s.positions.end(), {p.x(), p.y(), p.z()});
  }
  for(SM_face f : faces(m))
    for(SM_halfedge h : halfedges_around_face(prev(halfedge(f, m), m), m))
      s.faces.push_back(target(h, m).idx());
  return s;
}

// the colour field: the bounding box of `m` mapped onto RGB (as map --colors-out colours)
inline std::vector<double> position_colours(const Surface_mesh& m)
{
  const CGAL::Bbox_3 bb = CGAL::Polygon_mesh_processing::bbox(m);
  std::vector<double> c;
  for(SM_vertex v : vertices(m)) {
    const Kernel::Point_3& p = m.point(v);
    c.push_back((p.x() - bb.xmin()) / (bb.xmax() - bb.xmin() + 1e-300));
    c.push_back((p.y() - bb.ymin()) / (bb.ymax() - bb.ymin() + 1e-300));
    c.push_back((p.z() - bb.zmin()) / (bb.zmax() - bb.zmin() + 1e-300));
  }
  return c;
}

// the polygon whose reflections tile the disk, the orbifold's tile being made of two copies of
// it (sphere type: corners 0..k-1 of the tile) or being it (disk type); empty for genus g >= 1
inline std::vector<double> fold_polygon(const HOT::Orbifold_signature& signature, long long genus)
{
  std::vector<double> r;
  if(genus > 0)
    return r;
  HOT::Orbifold_tile<HOT::Poincare_disk_traits_2<> > tile;
  if(HOT::make_orbifold_tile(signature, tile) != HOT::OK)
    return r;
  const int k = signature.number_of_cones();
  for(int i = 0; i < k && i < tile.number_of_corners(); ++i) {
    r.push_back(CGAL::to_double(tile.corner(i).x()));
    r.push_back(CGAL::to_double(tile.corner(i).y()));
  }
  return r;
}

inline void add_landmarks(View_shape& s, const View_input& in)
{
  s.landmark_numbers = in.landmark_numbers;
  s.landmark_vertices = in.landmark_vertices;
}

// the embedding view: the surface with its corners' Poincare-disk points and its cut
inline View_data view_embedding(const View_input& in)
{
  const Surface_mesh& m = *in.mesh;
  View_data d;
  d.kind = "embedding";
  d.title = in.name;
  d.shapes.push_back(view_shape(in.name, m));
  View_shape& s = d.shapes.back();
  add_landmarks(s, in);
  for(SM_face f : faces(m))
    for(SM_halfedge h : halfedges_around_face(prev(halfedge(f, m), m), m)) {
      const Kernel::Point_2& p = get(in.uv, h);
      s.uv.push_back(p.x());
      s.uv.push_back(p.y());
    }
  // the cut: edges whose two sides have different points (and a disk's boundary)
  for(SM_face f : faces(m))
    for(SM_halfedge h : halfedges_around_face(halfedge(f, m), m)) {
      const SM_halfedge o = opposite(h, m);
      const bool border = is_border(o, m);
      if(!border && get(in.uv, h) == get(in.uv, prev(o, m)) && get(in.uv, prev(h, m)) == get(in.uv, o))
        continue;
      const Kernel::Point_2 &a = get(in.uv, prev(h, m)), &b = get(in.uv, h);
      s.cut_uv.insert(s.cut_uv.end(), {a.x(), a.y(), b.x(), b.y()});
      if(border || h.idx() < o.idx()) {
        s.cut.push_back(source(h, m).idx());
        s.cut.push_back(target(h, m).idx());
      }
    }
  s.fold = fold_polygon(in.signature, in.genus);
  if(s.fold.empty()) // genus g >= 1: no tiling to draw; the colour field shows where each face went
    s.colors = position_colours(m);
  return d;
}

// the map from `a` onto `b` (the vertices of a located on b) as the viewer reads it
inline View_map view_map(std::size_t ia, const View_input& a, std::size_t ib, const View_input& b,
                         std::vector<Locator::Location>& f)
{
  f = HOT::map_vertices(*a.mesh, a.uv, a.charts, a.chart_isometries, *b.locator);
  View_map vm;
  vm.from = ia;
  vm.to = ib;
  for(std::size_t i = 0; i < f.size(); ++i) {
    if(!f[i].success)
      throw Failure{HOT::ERROR_POINT_NOT_LOCATED, "vertex " + std::to_string(i) + " of " + a.name + " could not be located on " + b.name};
    const std::array<double, 3> bc = hot_tools::input_order_barycentric(*b.mesh, *b.locator, f[i]);
    vm.face.push_back(f[i].face_index);
    vm.bary.insert(vm.bary.end(), bc.begin(), bc.end());
  }
  const HOT::Map_reliability r = HOT::map_reliability(*a.mesh, a.uv, *b.mesh, b.uv, *b.locator, f);
  vm.unreliable = r.unreliable_vertices;
  std::sort(vm.unreliable.begin(), vm.unreliable.end());
  return vm;
}

// a map (two inputs) or a collection: the first shape's colour field carried to every other
// shape through the map from that shape onto the first (its vertices located on the first
// shape: the colour there, interpolated in the face), the maps from the first shape onto each
// other one and back (for picking), the distortion of the map from the first shape onto the
// second on the first's faces, and of the map from shape k onto the first on shape k's faces
inline View_data view_maps(const std::vector<View_input>& in, const std::string& kind, const std::string& title)
{
  View_data d;
  d.kind = kind;
  d.title = title;
  for(const View_input& x : in) {
    d.shapes.push_back(view_shape(x.name, *x.mesh));
    add_landmarks(d.shapes.back(), x);
  }
  d.shapes[0].colors = position_colours(*in[0].mesh);
  const std::vector<double>& c0 = d.shapes[0].colors;
  for(std::size_t k = 1; k < in.size(); ++k) {
    std::vector<Locator::Location> f, g;
    d.maps.push_back(view_map(0, in[0], k, in[k], f));
    if(k == 1) {
      const HOT::Map_distortion dist = HOT::map_distortion(*in[0].mesh, *in[k].mesh, *in[k].locator, f);
      d.shapes[0].conformal = dist.conformal;
      d.shapes[0].area = dist.area;
    }
    d.maps.push_back(view_map(k, in[k], 0, in[0], g));
    const HOT::Map_distortion back = HOT::map_distortion(*in[k].mesh, *in[0].mesh, *in[0].locator, g);
    d.shapes[k].conformal = back.conformal;
    d.shapes[k].area = back.area;
    std::vector<double>& ck = d.shapes[k].colors;
    for(const Locator::Location& l : g)
      for(int j = 0; j < 3; ++j) {
        double x = 0;
        for(int c = 0; c < 3; ++c)
          x += l.barycentric[c] * c0[3 * in[0].locator->corner_vertex_index(l.face_index, c) + j];
        ck.push_back(std::min(1.0, std::max(0.0, x)));
      }
  }
  return d;
}

// Writes the folder DIR (index.html, data.js, viewer.js, three.min.js): built as DIR.tmp, then
// renamed into place; an existing DIR is replaced only when it is a view folder (it holds
// index.html and data.js) or empty. A failure leaves DIR as it was and no DIR.tmp.
inline void write_view_folder(const std::string& dir, const View_data& d)
{
  namespace fs = std::filesystem;
  if(dir.empty())
    throw std::runtime_error("no folder name given for the view");
  const char* env = std::getenv("HOT_THREE_JS");
  const std::string three_path = env && *env ? env : HOT_THREE_JS_PATH;
  std::string three;
  const HOT::Status r = hot_tools::read_file_contents(three_path, three);
  if(!r)
    throw std::runtime_error("three.js: " + r.message + " (Debian package libjs-three, or HOT_THREE_JS=FILE)");
  std::error_code ec;
  fs::path target(dir);
  if(target.filename().empty())
    target = target.parent_path();
  const bool exists = fs::exists(fs::symlink_status(target, ec));
  if(exists) {
    if(!fs::is_directory(target, ec))
      throw std::runtime_error("'" + dir + "' exists and is not a folder");
    if(!fs::is_empty(target, ec) && !(fs::exists(target / "index.html", ec) && fs::exists(target / "data.js", ec)))
      throw std::runtime_error("'" + dir + "' exists and is not a view folder (no index.html and data.js): choose another --out");
  }
  const fs::path tmp = target.string() + ".tmp", old = target.string() + ".old.tmp";
  fs::remove_all(tmp, ec);
  if(!fs::create_directory(tmp, ec) || ec)
    throw std::runtime_error("cannot write '" + tmp.string() + "'" + (ec ? ": " + ec.message() : std::string()));
  try {
    write_file_atomically((tmp / "index.html").string(), [&](std::ostream& os) { os << hot_viewer::index_html; });
    write_file_atomically((tmp / "viewer.js").string(), [&](std::ostream& os) { os << hot_viewer::viewer_js; });
    write_file_atomically((tmp / "three.min.js").string(), [&](std::ostream& os) { os << three; });
    const std::string js = view_data_js(d);
    write_file_atomically((tmp / "data.js").string(), [&](std::ostream& os) { os << js; });
    if(exists) {
      fs::remove_all(old, ec);
      fs::rename(target, old);
    }
    try {
      fs::rename(tmp, target);
    } catch(...) {
      if(exists)
        fs::rename(old, target, ec);
      throw;
    }
    if(exists)
      fs::remove_all(old, ec);
  } catch(const fs::filesystem_error& e) {
    fs::remove_all(tmp, ec);
    throw std::runtime_error("cannot write '" + dir + "': " + e.code().message());
  } catch(...) {
    fs::remove_all(tmp, ec);
    throw;
  }
}

// a stored embedding (embed's or collection's OBJ file) as the viewer's input; `loc` may be null
// for an embedding shown alone (view_embedding() does not locate points)
inline View_input view_input(const Stored_embedding& e, const Locator* loc)
{
  View_input in;
  in.name = view_impl::file_name(e.path);
  in.mesh = &e.mesh;
  in.uv = e.uv;
  in.charts = e.charts;
  in.chart_isometries = e.chart_isometries;
  in.locator = loc;
  for(std::size_t i = 0; i < e.cones.vertex.size(); ++i) {
    in.landmark_numbers.push_back(i < e.cones.landmark.size() ? e.cones.landmark[i] : i);
    in.landmark_vertices.push_back(e.line_vertex[e.cones.vertex[i]]);
  }
  in.signature = e.signature();
  in.genus = e.cones.genus;
  return in;
}

// the collection's embeddings, DIR/<i>_<name>.obj, in the order of i
inline std::vector<std::string> collection_embeddings(const std::string& dir)
{
  namespace fs = std::filesystem;
  std::error_code ec;
  if(!fs::is_directory(dir, ec))
    throw Failure{HOT::ERROR_READ_FAILED, "'" + dir + "' is not a folder (a collection's --out)"};
  std::vector<std::pair<long, std::string> > found;
  for(const fs::directory_entry& e : fs::directory_iterator(dir, ec)) {
    const std::string name = e.path().filename().string();
    std::size_t digits = 0;
    while(digits < name.size() && name[digits] >= '0' && name[digits] <= '9') ++digits;
    if(digits == 0 || digits > 9 || digits >= name.size() || name[digits] != '_' || name.size() < 4 ||
       name.compare(name.size() - 4, 4, ".obj") != 0 || !e.is_regular_file(ec))
      continue;
    found.emplace_back(std::stol(name.substr(0, digits)), e.path().string());
  }
  std::sort(found.begin(), found.end());
  std::vector<std::string> r;
  for(const auto& p : found) r.push_back(p.second);
  if(r.size() < 2)
    throw Failure{HOT::ERROR_READ_FAILED, "'" + dir + "' holds " + std::to_string(r.size()) +
                                            " embeddings <i>_<name>.obj (a collection's --out holds one per mesh, at least 2)"};
  return r;
}

} // namespace hot_cli

#endif // HOT_APP_VIEW_H
