// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// hyperbolic_orbifold_tutte: the package's main jobs from the command line.
//
//   hyperbolic_orbifold_tutte tile --orbifold sphere|disk --cones K --svg FILE [--depth D]
//
// Every error ends the program with a non-zero status and one line on stderr;
// output files are written to a temporary name and renamed only when complete.

// the mesh's header first: Seam_mesh calls CGAL::halfedges(tm) etc. qualified
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>

#include <CGAL/Hyperbolic_orbifold_Tutte/Orbifold_tile.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/hyperbolic_orbifold_Tutte_embedding.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/Embedding_locator.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/Orbifold_collection.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/surface_maps.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/landmark_sampling.h>

#include "io/read_and_check.h"
#include "io/svg.h"

#include <sys/stat.h>

#include <array>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <string>

namespace HOT = CGAL::Hyperbolic_orbifold_Tutte;

namespace {

struct Usage_error
{
  std::string message;
};

const char* const usage_text =
  "usage:\n"
  "  hyperbolic_orbifold_tutte tile --orbifold sphere|disk --cones K --svg FILE [--depth D]\n"
  "      draws the basic tile of the orbifold with K cones and its images under the group\n"
  "      (products of at most D side pairings, default 3) in the Poincare disk\n"
  "  hyperbolic_orbifold_tutte embed --mesh IN --cones CONES [--orbifold sphere|disk]\n"
  "      [--weights cotan|mvc|uniform] [--order given|tsp] --out OUT.obj [--svg PICTURE.svg]\n"
  "      [--report REPORT.json] [--recentre]\n"
  "      embeds the mesh into the hyperbolic orbifold whose cones are the landmarks CONES\n"
  "      (0-based vertex indices); OUT.obj holds the input vertices (v), one Poincare point\n"
  "      per cut-mesh vertex (vt) and the input faces (f v/vt); the result is certified\n"
  "      bijective or the program fails. --order defaults to tsp for sphere type.\n"
  "      --recentre: a part too squeezed for double in the tile (a long protrusion without\n"
  "      landmarks) may be solved in a moved frame; the report then gives the frame.\n";

// --name value options, and --flag options without value (listed in `flags`).
class Options
{
public:
  Options(int argc, char** argv, int first, const std::set<std::string>& known,
          const std::set<std::string>& flags = std::set<std::string>())
  {
    for(int i = first; i < argc; ++i) {
      const std::string a = argv[i];
      if(a.size() < 3 || a.compare(0, 2, "--") != 0)
        throw Usage_error{"unexpected argument '" + a + "'"};
      const std::string name = a.substr(2);
      if(flags.count(name)) {
        if(values_.count(name))
          throw Usage_error{"option '" + a + "' given twice"};
        values_[name] = "1";
        continue;
      }
      if(!known.count(name))
        throw Usage_error{"unknown option '" + a + "'"};
      if(i + 1 >= argc)
        throw Usage_error{"option '" + a + "' needs a value"};
      if(values_.count(name))
        throw Usage_error{"option '" + a + "' given twice"};
      values_[name] = argv[++i];
    }
  }
  bool has(const std::string& name) const { return values_.count(name) != 0; }
  std::string get(const std::string& name) const
  {
    auto it = values_.find(name);
    if(it == values_.end())
      throw Usage_error{"missing option --" + name};
    return it->second;
  }
  long get_int(const std::string& name, long lo, long hi) const
  {
    const std::string s = get(name);
    errno = 0;
    char* end = nullptr;
    const long v = std::strtol(s.c_str(), &end, 10);
    if(s.empty() || *end != '\0' || errno != 0)
      throw Usage_error{"--" + name + " must be an integer, got '" + s + "'"};
    if(v < lo || v > hi)
      throw Usage_error{"--" + name + " must be between " + std::to_string(lo) + " and " + std::to_string(hi) +
                        ", got " + s};
    return v;
  }

private:
  std::map<std::string, std::string> values_;
};

// Writes a file atomically: the content goes to FILE.tmp, renamed to FILE on success.
void write_file_atomically(const std::string& path, const std::function<void(std::ostream&)>& writer)
{
  const std::string tmp = path + ".tmp";
  {
    std::ofstream out(tmp);
    if(!out)
      throw std::runtime_error("cannot write '" + path + "'");
    writer(out);
    out.flush();
    if(!out) {
      out.close();
      std::remove(tmp.c_str());
      throw std::runtime_error("error while writing '" + path + "'");
    }
  }
  if(std::rename(tmp.c_str(), path.c_str()) != 0) {
    std::remove(tmp.c_str());
    throw std::runtime_error("cannot write '" + path + "'");
  }
}

HOT::Orbifold_type parse_orbifold(const std::string& s)
{
  if(s == "sphere")
    return HOT::Sphere_type;
  if(s == "disk")
    return HOT::Disk_type;
  throw Usage_error{"--orbifold must be 'sphere' or 'disk', got '" + s + "'"};
}

int run_tile(int argc, char** argv)
{
  const Options opt(argc, argv, 2, {"orbifold", "cones", "svg", "depth"});
  const HOT::Orbifold_type type = parse_orbifold(opt.get("orbifold"));
  const long k = opt.get_int("cones", -1000000, 1000000);
  const int depth = opt.has("depth") ? static_cast<int>(opt.get_int("depth", 0, 6)) : 3;
  const std::string svg = opt.get("svg");
  if(k > 200)
    throw Usage_error{"--cones must be at most 200 for a picture, got " + std::to_string(k)};

  HOT::Orbifold_tile<> tile;
  const HOT::Error_code ec = HOT::make_orbifold_tile(type, static_cast<int>(k), tile);
  if(ec != HOT::OK)
    throw std::runtime_error(std::string(HOT::error_message(ec)) + ": got " + std::to_string(k) + " cones");

  const std::string pi = "&#960;";
  const std::string multiple = (k == 5) ? std::string() : std::to_string(k - 4);
  std::ostringstream title;
  if(type == HOT::Sphere_type)
    title << "sphere-type orbifold, " << k << " cones of angle " << pi << ", tile with " << tile.number_of_corners()
          << " corners, area " << multiple << pi;
  else
    title << "disk-type orbifold, " << k << " corners of angle " << pi << "/2, area " << multiple << pi << "/2";
  write_file_atomically(svg, [&](std::ostream& os) { hot_tools::write_tile_svg(os, tile, depth, title.str()); });
  std::cout << "wrote " << svg << " (" << (type == HOT::Sphere_type ? "sphere" : "disk") << ", " << k
            << " cones, depth " << depth << ")" << std::endl;
  return EXIT_SUCCESS;
}

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef CGAL::Surface_mesh<Kernel::Point_3> Surface_mesh;
typedef boost::graph_traits<Surface_mesh>::vertex_descriptor SM_vertex;
typedef boost::graph_traits<Surface_mesh>::halfedge_descriptor SM_halfedge;
typedef boost::graph_traits<Surface_mesh>::face_descriptor SM_face;

struct Failure
{
  HOT::Error_code code;
  std::string message;
};

std::string json_escape(const std::string& s)
{
  std::string r;
  for(char c : s) {
    if(c == '"' || c == '\\') { r += '\\'; r += c; }
    else if(static_cast<unsigned char>(c) < 0x20) { char b[8]; std::snprintf(b, sizeof(b), "\\u%04x", c); r += b; }
    else r += c;
  }
  return r;
}

// Writes the embedding's SVG: the tiling (faded tile copies), the embedded mesh in the
// tile and its images around it, cones in distinct colours (paper, Figure 1).
void write_embedding_svg(std::ostream& os, const Surface_mesh& m,
                         const Surface_mesh::Property_map<SM_halfedge, Kernel::Point_2>& uv,
                         const HOT::Orbifold_tile<>& tile, const std::vector<SM_vertex>& landmarks,
                         const std::string& title)
{
  typedef std::complex<double> C;
  hot_tools::Poincare_svg svg;
  svg.begin(os, title);
  const int n = tile.number_of_corners();
  std::vector<C> corners;
  for(int i = 0; i < n; ++i)
    corners.push_back(C(tile.corner(i).x(), tile.corner(i).y()));
  // copies of the mesh: as many group elements as keep the picture below ~400k segments
  const std::size_t edges_per_copy = 3 * num_faces(m);
  int depth = 2;
  while(depth > 0 && tile.group_elements(depth).size() * edges_per_copy > 400000)
    --depth;
  const std::vector<HOT::Orbifold_tile<>::Isometry> group = tile.group_elements(std::max(depth, 2));
  for(std::size_t e = 1; e < group.size(); ++e) {
    std::vector<C> img;
    for(const C& c : corners)
      img.push_back(group[e].apply(c));
    svg.path(os, svg.geodesic_path(img, true), "#e3ebf3", "#9fb3c8", 0.6);
  }
  std::vector<HOT::Orbifold_tile<>::Isometry> copies(group.begin(), group.begin() + (depth > 0 ? tile.group_elements(depth).size() : 1));
  for(std::size_t e = 0; e < copies.size(); ++e) {
    std::ostringstream d;
    d.precision(6);
    for(SM_face f : faces(m)) {
      // each edge once per face: draw the face's three edges as straight segments (short edges)
      bool first = true;
      for(SM_halfedge h : halfedges_around_face(halfedge(f, m), m)) {
        const C z = copies[e].apply(C(get(uv, h).x(), get(uv, h).y()));
        d << (first ? "M" : "L") << svg.X(z) << "," << svg.Y(z);
        first = false;
      }
      d << "Z";
    }
    svg.path(os, d.str(), "none", e == 0 ? "#1d3557" : "#9aa7b8", e == 0 ? 0.25 : 0.15);
  }
  svg.path(os, svg.geodesic_path(corners, true), "none", "#c1121f", 1.5);
  for(int i = 0; i < n; ++i)
    svg.dot(os, corners[i], 6, hot_tools::Poincare_svg::palette(tile.corner_cone(i), tile.number_of_cones(), 0.75, 1.0));
  (void)landmarks;
  svg.end(os);
}

// OUT.obj of `embed`: v = input vertices, vt = one Poincare point per cut-mesh vertex,
// f = input faces in input order with their corners' vt
template <class HalfedgeUVMap>
void write_embedding_obj(std::ostream& os, const Surface_mesh& m, const HalfedgeUVMap& uv)
{
  std::vector<std::vector<std::pair<Kernel::Point_2, std::size_t> > > vts(num_vertices(m));
  std::vector<Kernel::Point_2> vt_points;
  std::vector<std::size_t> corner_vt(num_halfedges(m), 0);
  for(SM_face f : faces(m))
    for(SM_halfedge h : halfedges_around_face(halfedge(f, m), m)) {
      const Kernel::Point_2 p = get(uv, h);
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
  for(SM_vertex v : vertices(m))
    os << "v " << m.point(v) << "\n";
  for(const auto& p : vt_points)
    os << "vt " << p.x() << " " << p.y() << "\n";
  for(SM_face f : faces(m)) {
    os << "f";
    // read_mesh() builds face f with source(halfedge(f)) = the file's first vertex of the face
    for(SM_halfedge h : halfedges_around_face(prev(halfedge(f, m), m), m))
      os << " " << target(h, m).idx() + 1 << "/" << corner_vt[h.idx()] + 1;
    os << "\n";
  }
}

int run_embed(int argc, char** argv)
{
  const Options opt(argc, argv, 2, {"mesh", "cones", "orbifold", "weights", "order", "out", "svg", "report"}, {"recentre"});
  const std::string mesh_path = opt.get("mesh"), cones_path = opt.get("cones"), out_path = opt.get("out");
  HOT::Weight_type weights = HOT::Cotangent;
  std::string weights_name = "cotan";
  if(opt.has("weights")) {
    weights_name = opt.get("weights");
    if(weights_name == "cotan") weights = HOT::Cotangent;
    else if(weights_name == "mvc") weights = HOT::Mean_value;
    else if(weights_name == "uniform") weights = HOT::Uniform;
    else throw Usage_error{"--weights must be cotan, mvc or uniform, got '" + weights_name + "'"};
  }
  std::string order_name = opt.has("order") ? opt.get("order") : std::string();
  if(!order_name.empty() && order_name != "given" && order_name != "tsp")
    throw Usage_error{"--order must be given or tsp, got '" + order_name + "'"};

  std::optional<HOT::Orbifold_type> required_type;
  if(opt.has("orbifold"))
    required_type = parse_orbifold(opt.get("orbifold"));

  // reading and checking: the same calls as the fuzz target (fuzz/fuzz_mesh_reader.cpp)
  Surface_mesh m;
  HOT::internal::Mesh_info info;
  HOT::internal::Check_result r = hot_tools::read_and_check_mesh(mesh_path, required_type, m, &info);
  if(!r)
    throw Failure{r.code, r.message};
  const HOT::Orbifold_type type = info.type;
  if(order_name.empty())
    order_name = (type == HOT::Sphere_type) ? "tsp" : "given";
  std::vector<SM_vertex> landmarks;
  r = hot_tools::read_and_check_landmarks(cones_path, m, type, landmarks);
  if(!r)
    throw Failure{r.code, r.message};
  std::vector<std::size_t> cone_indices;
  for(SM_vertex v : landmarks)
    cone_indices.push_back(v.idx()); // read_mesh() keeps the file's vertex order: idx() is the file's index

  Surface_mesh::Property_map<SM_halfedge, Kernel::Point_2> uv =
    m.add_property_map<SM_halfedge, Kernel::Point_2>("h:uv", Kernel::Point_2(0, 0)).first;
  HOT::Embedding_statistics st;
  const HOT::Error_code ec = HOT::hyperbolic_orbifold_Tutte_embedding(
    m, landmarks, uv,
    HOT::parameters::recentring(
      opt.has("recentre"),
      HOT::parameters::embedding_statistics(
        &st, HOT::parameters::landmark_order(order_name == "tsp" ? HOT::Tsp_order : HOT::Given_order,
                                             HOT::parameters::weight_type(weights, HOT::parameters::orbifold_type(type))))));
  if(ec != HOT::OK)
    throw Failure{ec, st.message};

  HOT::Orbifold_tile<> tile;
  HOT::make_orbifold_tile(type, static_cast<int>(landmarks.size()), tile);
  if(st.recentred)
    tile = tile.transformed(st.frame); // the tile of the written coordinates

  std::vector<std::string> written;
  try {
    write_file_atomically(out_path, [&](std::ostream& os) { write_embedding_obj(os, m, uv); });
    written.push_back(out_path);
    if(opt.has("svg")) {
      const std::string svg = opt.get("svg");
      std::ostringstream title;
      title << (type == HOT::Sphere_type ? "sphere" : "disk") << "-type orbifold, " << landmarks.size() << " cones, "
            << num_vertices(m) << " vertices, certified bijective";
      write_file_atomically(svg, [&](std::ostream& os) { write_embedding_svg(os, m, uv, tile, landmarks, title.str()); });
      written.push_back(svg);
    }
    if(opt.has("report")) {
      const std::string rep = opt.get("report");
      write_file_atomically(rep, [&](std::ostream& os) {
        const HOT::Embedding_certificate& c = st.certificate;
        os.precision(17);
        os << "{\n  \"mesh\": \"" << json_escape(mesh_path) << "\",\n"
           << "  \"vertices\": " << num_vertices(m) << ",\n  \"faces\": " << num_faces(m) << ",\n"
           << "  \"cones\": [";
        for(std::size_t i = 0; i < cone_indices.size(); ++i) os << (i ? ", " : "") << cone_indices[i];
        os << "],\n  \"orbifold\": \"" << (type == HOT::Sphere_type ? "sphere" : "disk") << "\",\n"
           << "  \"weights\": \"" << weights_name << "\",\n  \"order\": \"" << order_name << "\",\n"
           << "  \"landmark_order_used\": [";
        for(std::size_t i = 0; i < st.landmark_order.size(); ++i)
          os << (i ? ", " : "") << cone_indices[st.landmark_order[i]];
        os << "],\n  \"landmark_order_reversed\": " << (st.landmark_order_reversed ? "true" : "false") << ",\n"
           << "  \"cut_mesh_vertices\": " << st.number_of_vertices << ",\n"
           << "  \"time_seconds\": {\"setup_and_cut\": " << st.time_setup << ", \"initialization\": "
           << st.time_initialization << ", \"optimization\": " << st.time_optimization << ", \"certificate\": "
           << st.time_certificate << "},\n"
           << "  \"iterations\": " << st.iterations << ",\n  \"initial_energy\": " << st.initial_energy << ",\n"
           << "  \"energy\": " << st.energy << ",\n  \"relative_gradient_norm\": " << st.relative_gradient_norm << ",\n"
           << "  \"rounding_floor\": " << st.rounding_floor << ",\n  \"converged_at_rounding_floor\": "
           << (st.converged_at_rounding_floor ? "true" : "false") << ",\n  \"polishing_iterations\": " << st.polishing_iterations
           << ",\n  \"repaired_vertices\": " << st.repaired_vertices << ",\n"
           << "  \"recentred\": " << (st.recentred ? "true" : "false") << ",\n  \"frame\": {\"a\": ["
           << st.frame.a().real() << ", " << st.frame.a().imag() << "], \"b\": [" << st.frame.b().real() << ", " << st.frame.b().imag()
           << "]},\n"
           << "  \"certificate\": {\"bijective\": " << (c.is_bijective() ? "true" : "false")
           << ", \"faces\": " << c.number_of_faces << ", \"points_outside_disk\": " << c.points_outside_disk
           << ", \"flipped_faces\": " << c.flipped_faces << ", \"degenerate_faces\": " << c.degenerate_faces
           << ", \"angle_sum_failures\": " << c.angle_sum_failures << ", \"max_angle_sum_error\": " << c.max_angle_sum_error
           << ", \"twin_failures\": " << c.twin_failures << ", \"cone_failures\": " << c.cone_failures
           << ", \"border_failures\": " << c.border_failures << ", \"total_area\": " << c.total_area
           << ", \"expected_area\": " << c.expected_area << "}\n}\n";
      });
      written.push_back(rep);
    }
  } catch(...) {
    for(const std::string& f : written)
      std::remove(f.c_str());
    throw;
  }
  std::cout << "embedded " << mesh_path << " (" << num_vertices(m) << " vertices, " << landmarks.size() << " cones, "
            << (type == HOT::Sphere_type ? "sphere" : "disk") << " type) in "
            << st.time_setup + st.time_initialization + st.time_optimization + st.time_certificate << " s, "
            << st.iterations << " Newton iterations, certified bijective"
            << (st.recentred ? " in a recentred frame (given in the report)" : "") << "; wrote " << out_path << std::endl;
  return EXIT_SUCCESS;
}

// Reads, checks and embeds one mesh of a map or a collection with landmarks in cone order.
struct Embedded
{
  Surface_mesh mesh;
  HOT::Orbifold_type type = HOT::Sphere_type;
  std::vector<SM_vertex> landmarks;                  // as read
  std::vector<SM_vertex> ordered;                    // in cone order
  Surface_mesh::Property_map<SM_halfedge, Kernel::Point_2> uv;
  HOT::Embedding_statistics stats;
};

void read_and_check(const std::string& mesh_path, const std::string& cones_path, Embedded& e)
{
  HOT::internal::Mesh_info info;
  HOT::internal::Check_result r = hot_tools::read_and_check_mesh(mesh_path, std::nullopt, e.mesh, &info);
  if(!r) throw Failure{r.code, r.message};
  e.type = info.type;
  r = hot_tools::read_and_check_landmarks(cones_path, e.mesh, e.type, e.landmarks);
  if(!r) throw Failure{r.code, r.message};
}

void embed_in_order(Embedded& e, const std::vector<std::size_t>& order, const std::string& name)
{
  e.ordered.clear();
  for(std::size_t i : order) e.ordered.push_back(e.landmarks[i]);
  e.uv = e.mesh.add_property_map<SM_halfedge, Kernel::Point_2>("h:uv", Kernel::Point_2(0, 0)).first;
  const HOT::Error_code ec = HOT::hyperbolic_orbifold_Tutte_embedding(
    e.mesh, e.ordered, e.uv, HOT::parameters::orbifold_type(e.type, HOT::parameters::embedding_statistics(&e.stats)));
  if(ec != HOT::OK)
    throw Failure{ec, name + ": " + e.stats.message};
}

typedef HOT::Embedding_locator<Surface_mesh, Surface_mesh::Property_map<SM_halfedge, Kernel::Point_2> > Locator;

// barycentric coordinates w.r.t. the face's vertices in input order (read_mesh() builds face f
// with source(halfedge(f)) = its first vertex in the file)
template <class SM_locator>
std::array<double, 3> input_order_barycentric(const Surface_mesh& m, const SM_locator& loc, const typename SM_locator::Location& l)
{
  std::array<double, 3> b{{0, 0, 0}};
  int j = 0;
  for(SM_halfedge h : halfedges_around_face(prev(halfedge(l.face, m), m), m)) {
    const std::size_t v = target(h, m).idx();
    for(int c = 0; c < 3; ++c)
      if(loc.corner_vertex_index(l.face_index, c) == v) b[j] = l.barycentric[c];
    ++j;
  }
  return b;
}

int run_map(int argc, char** argv)
{
  const Options opt(argc, argv, 2, {"source", "source-cones", "target", "target-cones", "out", "colors-out"});
  const std::string out = opt.get("out");
  Embedded A, B;
  read_and_check(opt.get("source"), opt.get("source-cones"), A);
  read_and_check(opt.get("target"), opt.get("target-cones"), B);
  if(A.type != B.type)
    throw Failure{HOT::ERROR_WRONG_TOPOLOGY, "the source is " + std::string(A.type == HOT::Sphere_type ? "closed" : "a disk") +
                                           " but the target is " + (B.type == HOT::Sphere_type ? "closed" : "a disk")};
  if(A.landmarks.size() != B.landmarks.size())
    throw Failure{HOT::ERROR_WRONG_PARAMETER, "the source has " + std::to_string(A.landmarks.size()) +
                                              " landmarks and the target " + std::to_string(B.landmarks.size())};
  // one cone order for both: the paper's tour on the source (sphere type), the given one (disk)
  std::vector<std::size_t> order(A.landmarks.size());
  for(std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  if(A.type == HOT::Sphere_type) {
    order = HOT::internal::compute_tsp_landmark_order(A.mesh, A.landmarks, get(CGAL::vertex_point, A.mesh));
    if(order.size() != A.landmarks.size())
      throw Failure{HOT::ERROR_CUT_FAILED, "the landmark tour could not be computed on the source"};
  }
  embed_in_order(A, order, "source");
  embed_in_order(B, order, "target");
  if(A.stats.landmark_order_reversed != B.stats.landmark_order_reversed)
    throw Failure{HOT::ERROR_WRONG_PARAMETER, "the landmarks run clockwise around one boundary and counterclockwise around the other: "
                                              "the correspondence would reverse orientation"};
  const int k = static_cast<int>(order.size());
  const Locator locB(B.mesh, B.uv, B.type, k, HOT::Hyperboloid_linear);
  const std::vector<Locator::Location> f = HOT::map_vertices(A.mesh, A.uv, locB);
  for(std::size_t i = 0; i < f.size(); ++i)
    if(!f[i].success)
      throw Failure{HOT::ERROR_POINT_NOT_LOCATED, "vertex " + std::to_string(i) + " of the source could not be located on the target"};
  std::vector<std::string> written;
  try {
    write_file_atomically(out, [&](std::ostream& os) {
      os.precision(17);
      for(const Locator::Location& l : f) {
        const std::array<double, 3> b = input_order_barycentric(B.mesh, locB, l);
        os << l.face_index << " " << b[0] << " " << b[1] << " " << b[2] << "\n";
      }
    });
    written.push_back(out);
    if(opt.has("colors-out")) {
      // a smooth colouring of A (its bounding box mapped to RGB), carried to B by f_BA
      const Locator locA(A.mesh, A.uv, A.type, k, HOT::Hyperboloid_linear);
      const std::vector<Locator::Location> g = HOT::map_vertices(B.mesh, B.uv, locA);
      const CGAL::Bbox_3 bb = CGAL::Polygon_mesh_processing::bbox(A.mesh);
      auto colour = [&](const Kernel::Point_3& p) {
        return Kernel::Vector_3((p.x() - bb.xmin()) / (bb.xmax() - bb.xmin() + 1e-300),
                                (p.y() - bb.ymin()) / (bb.ymax() - bb.ymin() + 1e-300),
                                (p.z() - bb.zmin()) / (bb.zmax() - bb.zmin() + 1e-300));
      };
      std::vector<Kernel::Vector_3> colA;
      for(SM_vertex v : vertices(A.mesh)) colA.push_back(colour(A.mesh.point(v)));
      const std::string path = opt.get("colors-out");
      write_file_atomically(path, [&](std::ostream& os) {
        os << "ply\nformat ascii 1.0\nelement vertex " << num_vertices(B.mesh)
           << "\nproperty double x\nproperty double y\nproperty double z\nproperty uchar red\nproperty uchar green\nproperty uchar blue\n"
           << "element face " << num_faces(B.mesh) << "\nproperty list uchar int vertex_indices\nend_header\n";
        os.precision(17);
        std::size_t i = 0;
        for(SM_vertex v : vertices(B.mesh)) {
          const Locator::Location& l = g[i++];
          Kernel::Vector_3 c(0.5, 0.5, 0.5);
          if(l.success)
            c = l.barycentric[0] * colA[locA.corner_vertex_index(l.face_index, 0)] +
                l.barycentric[1] * colA[locA.corner_vertex_index(l.face_index, 1)] +
                l.barycentric[2] * colA[locA.corner_vertex_index(l.face_index, 2)];
          auto byte = [](double t) { return static_cast<int>(std::lround(255 * std::min(1.0, std::max(0.0, t)))); };
          os << B.mesh.point(v) << " " << byte(c.x()) << " " << byte(c.y()) << " " << byte(c.z()) << "\n";
        }
        for(SM_face fc : faces(B.mesh)) {
          os << "3";
          for(SM_halfedge h : halfedges_around_face(prev(halfedge(fc, B.mesh), B.mesh), B.mesh))
            os << " " << target(h, B.mesh).idx();
          os << "\n";
        }
      });
      written.push_back(path);
    }
  } catch(...) {
    for(const std::string& w : written) std::remove(w.c_str());
    throw;
  }
  std::cout << "mapped " << num_vertices(A.mesh) << " vertices of " << opt.get("source") << " onto "
            << opt.get("target") << "; wrote " << out << std::endl;
  return EXIT_SUCCESS;
}

typedef HOT::Orbifold_collection<Surface_mesh, CGAL::Parallel_tag> Collection;
typedef std::vector<std::pair<std::string, std::string> > Manifest; // (mesh path, cones path) per line

// the manifest's entries, relative paths resolved against the manifest's folder
Manifest read_manifest(const std::string& manifest)
{
  std::string manifest_text; // a missing file, a directory etc. get their own reason
  const HOT::internal::Check_result mr = hot_tools::read_file_contents(manifest, manifest_text);
  if(!mr)
    throw Failure{mr.code, mr.message};
  std::istringstream in(manifest_text);
  const std::string base = manifest.find('/') == std::string::npos ? std::string(".") : manifest.substr(0, manifest.find_last_of('/'));
  auto resolve = [&](const std::string& f) { return (!f.empty() && f[0] == '/') ? f : base + "/" + f; };
  Manifest entries;
  std::string line;
  std::size_t line_no = 0;
  while(std::getline(in, line)) {
    ++line_no;
    const std::size_t hash = line.find('#');
    if(hash != std::string::npos) line = line.substr(0, hash);
    std::istringstream ls(line);
    std::vector<std::string> fields;
    for(std::string f; ls >> f;)
      fields.push_back(f);
    if(fields.empty()) continue;
    if(fields.size() != 2)
      throw Failure{HOT::ERROR_READ_FAILED, manifest + ": line " + std::to_string(line_no) + ": expected 'mesh_path cones_path', found " +
                                            std::to_string(fields.size()) + (fields.size() == 1 ? " field" : " fields")};
    entries.push_back(std::make_pair(resolve(fields[0]), resolve(fields[1])));
  }
  if(entries.size() < 2)
    throw Failure{HOT::ERROR_WRONG_PARAMETER, manifest + ": the manifest lists " + std::to_string(entries.size()) +
                                              " mesh" + (entries.size() == 1 ? "" : "es") + ", a collection needs at least 2"};
  return entries;
}

// reads and checks every mesh of the manifest into the collection; returns the orbifold type
HOT::Orbifold_type read_collection(const Manifest& entries, Collection& coll)
{
  HOT::Orbifold_type type = HOT::Sphere_type;
  std::size_t k = 0;
  for(std::size_t i = 0; i < entries.size(); ++i) {
    Embedded e;
    read_and_check(entries[i].first, entries[i].second, e);
    if(i == 0) {
      type = e.type;
      k = e.landmarks.size();
    }
    if(e.type != type || e.landmarks.size() != k)
      throw Failure{HOT::ERROR_WRONG_PARAMETER, entries[i].first + ": its topology or number of landmarks differs from the first mesh's"};
    coll.add_mesh(e.mesh, e.landmarks);
  }
  return type;
}

// embeds the collection (in parallel), progress on stderr; a failure names the mesh's file
void embed_collection(const Manifest& entries, Collection& coll)
{
  const std::size_t N = entries.size();
  std::vector<HOT::Error_code> codes(N, HOT::OK);
  coll.set_progress_callback([&](const Collection::Progress& p) {
    if(p.stage == Collection::Progress::Mesh_embedded) {
      codes[p.source] = p.code;
      std::cerr << "  embedded " << p.done << "/" << p.total << ": " << entries[p.source].first << " (" << p.seconds << " s)" << std::endl;
    } else if(p.done == p.total || p.done % std::max<std::size_t>(1, p.total / 20) == 0) {
      std::cerr << "  mapped " << p.done << "/" << p.total << " pairs (last: " << p.source << " -> " << p.target << ", "
                << p.seconds << " s)" << std::endl;
    }
  });
  const HOT::Error_code ec = coll.embed();
  if(ec == HOT::OK)
    return;
  for(std::size_t i = 0; i < N; ++i)
    if(codes[i] != HOT::OK)
      throw Failure{codes[i], entries[i].first + ": " + coll.statistics(i).message};
  for(std::size_t i = 1; i < N; ++i)
    if(coll.statistics(i).landmark_order_reversed != coll.statistics(0).landmark_order_reversed)
      throw Failure{HOT::ERROR_WRONG_PARAMETER, entries[i].first + ": its landmarks run around the boundary the other way than the first mesh's: "
                                                "the correspondence would reverse orientation"};
  if(ec == HOT::ERROR_CUT_FAILED && coll.order().size() != coll.landmarks(0).size())
    throw Failure{ec, "the landmark tour could not be computed on the first mesh"};
  throw Failure{ec, coll.message()};
}

// the maps the command needs, and the cycle consistency: f_bc(f_ab(x)) against f_ac(x),
// relative to c's bounding-box diagonal, over every triple (all of them up to 6 meshes, else N
// consecutive triples); with --all-pairs f_ab for every ordered pair too
struct Collection_maps
{
  std::vector<std::vector<char> > used; // used[a][b]: f_ab computed (and reported)
  double cycle = 0;
  std::size_t triples = 0;
};

Collection_maps map_collection(Collection& coll, bool all_pairs)
{
  const std::size_t N = coll.number_of_meshes();
  std::vector<std::array<std::size_t, 3> > triples;
  if(N >= 3) {
    if(N <= 6) {
      for(std::size_t a = 0; a < N; ++a)
        for(std::size_t b = 0; b < N; ++b)
          for(std::size_t c = 0; c < N; ++c)
            if(a != b && b != c && a != c) triples.push_back({{a, b, c}});
    } else {
      for(std::size_t a = 0; a < N; ++a) triples.push_back({{a, (a + 1) % N, (a + 2) % N}});
    }
  }
  std::vector<std::pair<std::size_t, std::size_t> > pairs;
  for(const auto& t : triples) {
    pairs.emplace_back(t[0], t[1]);
    pairs.emplace_back(t[0], t[2]);
  }
  if(all_pairs)
    for(std::size_t a = 0; a < N; ++a)
      for(std::size_t b = 0; b < N; ++b)
        if(a != b) pairs.emplace_back(a, b);
  coll.compute_maps(pairs); // in parallel
  // failures are reported in the order the maps are used
  Collection_maps r;
  r.used.assign(N, std::vector<char>(N, 0));
  auto use_map = [&](std::size_t a, std::size_t b) {
    const std::vector<Collection::Location>& f = coll.map(a, b);
    if(r.used[a][b]) return;
    r.used[a][b] = 1;
    for(std::size_t v = 0; v < f.size(); ++v)
      if(!f[v].success)
        throw Failure{HOT::ERROR_POINT_NOT_LOCATED, "vertex " + std::to_string(v) + " of mesh " + std::to_string(a) + " could not be located on mesh " + std::to_string(b)};
  };
  for(const auto& t : triples) {
    use_map(t[0], t[1]);
    use_map(t[0], t[2]);
    const double e = coll.cycle_consistency_error(t[0], t[1], t[2]);
    if(std::isinf(e))
      throw Failure{HOT::ERROR_POINT_NOT_LOCATED, "a point of mesh " + std::to_string(t[1]) + " could not be located on mesh " + std::to_string(t[2])};
    r.cycle = std::max(r.cycle, e);
    ++r.triples;
  }
  if(all_pairs)
    for(std::size_t a = 0; a < N; ++a)
      for(std::size_t b = 0; b < N; ++b)
        if(a != b) use_map(a, b);
  return r;
}

void write_collection_report(std::ostream& os, const Manifest& entries, Collection& coll, HOT::Orbifold_type type,
                             const Collection_maps& maps)
{
  const std::size_t N = entries.size();
  os.precision(17);
  os << "{\n  \"meshes\": [\n";
  for(std::size_t i = 0; i < N; ++i) {
    const HOT::Embedding_statistics& st = coll.statistics(i);
    os << "    {\"index\": " << i << ", \"mesh\": \"" << json_escape(entries[i].first) << "\", \"vertices\": "
       << num_vertices(coll.mesh(i)) << ", \"embedding_seconds\": "
       << st.time_setup + st.time_initialization + st.time_optimization + st.time_certificate << ", \"iterations\": "
       << st.iterations << ", \"relative_gradient_norm\": " << st.relative_gradient_norm
       << ", \"bijective\": " << (st.certificate.is_bijective() ? "true" : "false") << "}" << (i + 1 < N ? "," : "") << "\n";
  }
  os << "  ],\n  \"orbifold\": \"" << (type == HOT::Sphere_type ? "sphere" : "disk") << "\",\n  \"cones\": " << coll.order().size()
     << ",\n  \"landmark_order_used\": [";
  for(std::size_t i = 0; i < coll.order().size(); ++i) os << (i ? ", " : "") << coll.order()[i];
  os << "],\n  \"pairs\": [\n";
  bool first = true;
  for(std::size_t a = 0; a < N; ++a)
    for(std::size_t b = 0; b < N; ++b)
      if(maps.used[a][b]) {
        os << (first ? "" : ",\n") << "    {\"source\": " << a << ", \"target\": " << b << ", \"map_seconds\": " << coll.map_seconds(a, b) << "}";
        first = false;
      }
  os << "\n  ],\n  \"triples_checked\": " << maps.triples << ",\n  \"cycle_consistency_max_rel_error\": " << maps.cycle << "\n}\n";
}

int run_collection(int argc, char** argv)
{
  const Options opt(argc, argv, 2, {"manifest", "out"}, {"all-pairs"});
  const std::string manifest = opt.get("manifest"), dir = opt.get("out");
  const bool all_pairs = opt.has("all-pairs");
  const Manifest entries = read_manifest(manifest);
  const std::size_t N = entries.size();
  Collection coll;
  const HOT::Orbifold_type type = read_collection(entries, coll);
  embed_collection(entries, coll);
  const Collection_maps maps = map_collection(coll, all_pairs);
  auto stem = [&](std::size_t i) {
    std::string f = entries[i].first.substr(entries[i].first.find_last_of('/') + 1);
    return std::to_string(i) + "_" + f.substr(0, f.find_last_of('.'));
  };
  // files
  if(mkdir(dir.c_str(), 0777) != 0 && errno != EEXIST)
    throw std::runtime_error("cannot create the folder '" + dir + "'");
  std::vector<std::string> written;
  try {
    for(std::size_t i = 0; i < N; ++i) {
      const std::string path = dir + "/" + stem(i) + ".obj";
      write_file_atomically(path, [&](std::ostream& os) { write_embedding_obj(os, coll.mesh(i), coll.uv_map(i)); });
      written.push_back(path);
    }
    if(all_pairs)
      for(std::size_t a = 0; a < N; ++a)
        for(std::size_t b = 0; b < N; ++b) {
          if(a == b) continue;
          const auto& f = coll.map(a, b);
          const std::string path = dir + "/" + std::to_string(a) + "_to_" + std::to_string(b) + ".map.txt";
          write_file_atomically(path, [&](std::ostream& os) {
            os.precision(17);
            for(const Collection::Location& l : f) {
              const std::array<double, 3> bc = input_order_barycentric(coll.mesh(b), coll.locator(b), l);
              os << l.face_index << " " << bc[0] << " " << bc[1] << " " << bc[2] << "\n";
            }
          });
          written.push_back(path);
        }
    const std::string rep = dir + "/report.json";
    write_file_atomically(rep, [&](std::ostream& os) { write_collection_report(os, entries, coll, type, maps); });
    written.push_back(rep);
  } catch(...) {
    for(const std::string& w : written) std::remove(w.c_str());
    throw;
  }
  std::cout << "collection of " << N << " meshes embedded" << (all_pairs ? " and mapped pairwise" : "") << "; "
            << maps.triples << " triples checked, cycle consistency " << maps.cycle << "; wrote " << dir << std::endl;
  return EXIT_SUCCESS;
}

int run_landmarks(int argc, char** argv)
{
  const Options opt(argc, argv, 2, {"mesh", "count", "out"});
  const std::string mesh_path = opt.get("mesh"), out = opt.get("out");
  const long k = opt.get_int("count", 1, 100000);
  Surface_mesh m;
  const HOT::internal::Check_result r = hot_tools::read_and_check_mesh(mesh_path, std::nullopt, m);
  if(!r)
    throw Failure{r.code, r.message};
  if(static_cast<std::size_t>(k) > num_vertices(m))
    throw Usage_error{"--count is larger than the number of vertices (" + std::to_string(num_vertices(m)) + ")"};
  const std::vector<std::size_t> lm = HOT::internal::sample_landmarks(m, get(CGAL::vertex_point, m), static_cast<std::size_t>(k));
  if(lm.size() != static_cast<std::size_t>(k))
    throw Failure{HOT::ERROR_WRONG_PARAMETER, "the boundary has fewer than " + std::to_string(k) + " vertices"};
  write_file_atomically(out, [&](std::ostream& os) {
    for(std::size_t i : lm)
      os << i << "\n";
  });
  std::cout << "wrote " << k << " landmarks of " << mesh_path << " to " << out << std::endl;
  return EXIT_SUCCESS;
}

} // namespace

int main(int argc, char** argv)
{
  try {
    if(argc < 2)
      throw Usage_error{"missing command"};
    const std::string command = argv[1];
    if(command == "--help" || command == "-h" || command == "help") {
      std::cout << usage_text;
      return EXIT_SUCCESS;
    }
    if(command == "tile")
      return run_tile(argc, argv);
    if(command == "embed")
      return run_embed(argc, argv);
    if(command == "landmarks")
      return run_landmarks(argc, argv);
    if(command == "map")
      return run_map(argc, argv);
    if(command == "collection")
      return run_collection(argc, argv);
    throw Usage_error{"unknown command '" + command + "'"};
  } catch(const Failure& e) {
    std::cerr << "hyperbolic_orbifold_tutte: " << HOT::error_message(e.code) << ": " << e.message << std::endl;
    return 3;
  } catch(const Usage_error& e) {
    std::cerr << "hyperbolic_orbifold_tutte: " << e.message << " (see --help)" << std::endl;
    return 2;
  } catch(const std::exception& e) {
    std::cerr << "hyperbolic_orbifold_tutte: " << e.what() << std::endl;
    return 1;
  }
}
