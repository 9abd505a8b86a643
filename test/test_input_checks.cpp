// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Tests of the input checks (check_input.h) and the tool's readers (application/hot_app/io/):
// a corpus of hostile files is written into a temporary directory, and every case
// must give its exact Error_code and a one-line message, never a crash or a hang.
// Real meshes come from Debian's libcgal-demo (`--data DIR` with DIR/meshes/*.off).

#include "test_harness.h"
#include "generated_meshes.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/IO/polygon_soup_io.h>

#include <CGAL/Hyperbolic_orbifold_Tutte/certify_hyperbolic_orbifold_embedding.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/hyperbolic_orbifold_Tutte_embedding.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/check_input.h>

#include <hot_app/io/read_and_check.h>
#include <hot_app/io/embedding_obj.h>
#include <hot_app/io/text_buffer.h>

#include "reference_embedding_obj.h"

#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <limits>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <unistd.h>
#include <vector>

namespace HOT = CGAL::Hyperbolic_orbifold_Tutte;
namespace HI = CGAL::Hyperbolic_orbifold_Tutte::internal;

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;
typedef CGAL::Surface_mesh<Point> SM;
typedef CGAL::Polyhedron_3<K> Poly;

namespace {

// ---------------------------------------------------------------------------
// helpers
// ---------------------------------------------------------------------------

struct Temp_dir
{
  std::string path;
  Temp_dir()
  {
    std::string templ = (std::filesystem::temp_directory_path() / "hot_input_checks_XXXXXX").string();
    if(mkdtemp(&templ[0]) != nullptr)
      path = templ;
  }
  ~Temp_dir()
  {
    std::error_code ec;
    if(!path.empty())
      std::filesystem::remove_all(path, ec);
  }
};

const std::string& tmp_dir()
{
  static Temp_dir d;
  return d.path;
}

std::string write_file(const std::string& name, const std::string& content)
{
  const std::string p = tmp_dir() + "/" + name;
  std::ofstream out(p, std::ios::binary);
  out.write(content.data(), static_cast<std::streamsize>(content.size()));
  return p;
}

std::string mesh_path(const std::string& name)
{
  return hot_test::data_dir() + "/meshes/" + name;
}

bool contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

bool one_line(const HOT::Status& r) { return r.message.find('\n') == std::string::npos; }

// checks code, a message fragment and that the message is one line
#define CHECK_RESULT(r, expected_code, fragment)                                                     \
  do {                                                                                               \
    const HOT::Status hot_r_ = (r);                                                             \
    CHECK_MSG(hot_r_.code == (expected_code), "code " << hot_r_.code << ", expected " << (expected_code) \
              << ": " << hot_r_.message);                                                            \
    CHECK_MSG(contains(hot_r_.message, fragment), "message '" << hot_r_.message << "' lacks '" << fragment << "'"); \
    CHECK_MSG(one_line(hot_r_), "multi-line message: " << hot_r_.message);                          \
    CHECK_MSG(hot_r_.code == HOT::OK ? bool(hot_r_) : !bool(hot_r_), "operator bool");              \
  } while(0)

HOT::Status read_text(const std::string& name, const std::string& content, SM& sm)
{
  return hot_tools::read_mesh(write_file(name, content), sm);
}

// a file that must not be read: its name, what follows the common head, and a fragment of
// the message
struct Unreadable_file
{
  const char* name;
  const char* tail;
  const char* fragment;
};

// for each file in order: CHECK_RESULT(read_text(name, head + tail, sm), ERROR_READ_FAILED,
// fragment); the name of the file follows any failure (the CHECK lines point here)
void check_unreadable(SM& sm, const std::string& head, std::initializer_list<Unreadable_file> files)
{
  for(const Unreadable_file& f : files) {
    const int before = hot_test::failures();
    CHECK_RESULT(read_text(f.name, head + f.tail, sm), HOT::ERROR_READ_FAILED, f.fragment);
    if(hot_test::failures() != before)
      std::cerr << "  (in the case of " << f.name << ")" << std::endl;
  }
}

// the result of read_mesh() then, if it succeeded, check_mesh()
template <class Mesh>
HOT::Status read_and_check(const std::string& path, Mesh& m, std::optional<HOT::Orbifold_type> type,
                                HOT::Mesh_info* info = nullptr)
{
  HOT::Status r = hot_tools::read_mesh(path, m);
  if(!r)
    return r;
  return HOT::check_mesh(m, type, info);
}

// --- small meshes (OFF text) -------------------------------------------------

const char* const tetra_vertices = "0 0 0\n1 0 0\n0 1 0\n0 0 1\n";
const char* const tetra_faces = "3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";

std::string tetra_off() { return std::string("OFF\n4 4 0\n") + tetra_vertices + tetra_faces; }

// octahedron: 6 vertices, closed, genus 0
const char* const octa_vertices = "1 0 0\n-1 0 0\n0 1 0\n0 -1 0\n0 0 1\n0 0 -1\n";
const std::vector<std::string> octa_faces = { "3 0 2 4", "3 2 1 4", "3 1 3 4", "3 3 0 4",
                                              "3 2 0 5", "3 1 2 5", "3 3 1 5", "3 0 3 5" };

std::string octa_off(const std::vector<std::size_t>& skip = std::vector<std::size_t>())
{
  std::string faces;
  std::size_t n = 0;
  for(std::size_t i = 0; i < octa_faces.size(); ++i) {
    if(std::find(skip.begin(), skip.end(), i) != skip.end())
      continue;
    faces += octa_faces[i] + "\n";
    ++n;
  }
  return "OFF\n6 " + std::to_string(n) + " 0\n" + octa_vertices + faces;
}

// a disk: center 0, ring 1..6 (all ring vertices on the border)
std::string hexagon_fan_off()
{
  std::string s = "OFF\n7 6 0\n0 0 0\n";
  for(int k = 0; k < 6; ++k) {
    const double a = 2 * 3.14159265358979 * k / 6;
    s += std::to_string(std::cos(a)) + " " + std::to_string(std::sin(a)) + " 0\n";
  }
  for(int k = 1; k <= 6; ++k)
    s += "3 0 " + std::to_string(k) + " " + std::to_string(k % 6 + 1) + "\n";
  return s;
}

// a torus: n x n grid, genus 1
std::string torus_off(int n)
{
  std::string s = "OFF\n" + std::to_string(n * n) + " " + std::to_string(2 * n * n) + " 0\n";
  const double pi = 3.14159265358979;
  for(int i = 0; i < n; ++i)
    for(int j = 0; j < n; ++j) {
      const double u = 2 * pi * i / n, v = 2 * pi * j / n;
      s += std::to_string((2 + std::cos(v)) * std::cos(u)) + " " + std::to_string((2 + std::cos(v)) * std::sin(u))
         + " " + std::to_string(std::sin(v)) + "\n";
    }
  auto id = [n](int i, int j) { return std::to_string(((i + n) % n) * n + (j + n) % n); };
  for(int i = 0; i < n; ++i)
    for(int j = 0; j < n; ++j) {
      s += "3 " + id(i, j) + " " + id(i + 1, j) + " " + id(i + 1, j + 1) + "\n";
      s += "3 " + id(i, j) + " " + id(i + 1, j + 1) + " " + id(i, j + 1) + "\n";
    }
  return s;
}

// --- binary helpers ----------------------------------------------------------

void put_u32_be(std::string& s, std::uint32_t v)
{
  for(int k = 3; k >= 0; --k)
    s += static_cast<char>((v >> (8 * k)) & 0xff);
}
void put_u32_le(std::string& s, std::uint32_t v)
{
  for(int k = 0; k < 4; ++k)
    s += static_cast<char>((v >> (8 * k)) & 0xff);
}
std::uint32_t float_bits(float f)
{
  std::uint32_t u;
  std::memcpy(&u, &f, 4);
  return u;
}
void put_f32_be(std::string& s, float f) { put_u32_be(s, float_bits(f)); }
void put_f32_le(std::string& s, float f) { put_u32_le(s, float_bits(f)); }

std::string garbage(std::size_t n, std::uint32_t seed)
{
  std::string s;
  for(std::size_t i = 0; i < n; ++i) {
    seed = seed * 1664525u + 1013904223u;
    s += static_cast<char>(seed >> 24);
  }
  return s;
}

const float tetra_coords[4][3] = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 } };
const int tetra_tris[4][3] = { { 0, 2, 1 }, { 0, 1, 3 }, { 0, 3, 2 }, { 1, 2, 3 } };

std::string binary_off_tetra(bool truncate = false)
{
  std::string s = "OFF BINARY\n";
  put_u32_be(s, 4);
  put_u32_be(s, 4);
  put_u32_be(s, 0);
  for(auto& p : tetra_coords)
    for(float c : p)
      put_f32_be(s, c);
  for(auto& t : tetra_tris) {
    put_u32_be(s, 3);
    for(int i : t)
      put_u32_be(s, std::uint32_t(i));
    put_u32_be(s, 0); // no color
  }
  if(truncate)
    s.resize(s.size() - 10);
  return s;
}

std::string binary_stl_tetra(std::uint32_t announced = 4, bool truncate = false)
{
  std::string s(80, ' ');
  put_u32_le(s, announced);
  for(auto& t : tetra_tris) {
    for(int k = 0; k < 3; ++k)
      put_f32_le(s, 0.f); // normal
    for(int i : t)
      for(float c : tetra_coords[i])
        put_f32_le(s, c);
    s += std::string(2, '\0');
  }
  if(truncate)
    s.resize(s.size() - 7);
  return s;
}

std::string ascii_stl_tetra()
{
  std::string s = "solid tetra\n";
  for(auto& t : tetra_tris) {
    s += "  facet normal 0 0 0\n    outer loop\n";
    for(int i : t)
      s += "      vertex " + std::to_string(tetra_coords[i][0]) + " " + std::to_string(tetra_coords[i][1]) + " "
         + std::to_string(tetra_coords[i][2]) + "\n";
    s += "    endloop\n  endfacet\n";
  }
  s += "endsolid tetra\n";
  return s;
}

// vertex i's coordinates
template <class Mesh>
Point vertex_point(const Mesh& m, std::size_t i)
{
  auto it = vertices(m).begin();
  std::advance(it, i);
  return get(CGAL::vertex_point, m, *it);
}

// the polygon soup of a mesh in iteration order, faces starting at source(halfedge(f))
template <class Mesh>
void mesh_to_soup(const Mesh& m, std::vector<Point>& points, std::vector<std::vector<std::size_t> >& faces_out)
{
  HI::Dense_index<typename boost::graph_traits<Mesh>::vertex_descriptor> vindex(vertices(m));
  points.clear();
  faces_out.clear();
  for(auto v : vertices(m))
    points.push_back(get(CGAL::vertex_point, m, v));
  for(auto f : faces(m)) {
    faces_out.emplace_back();
    auto h = halfedge(f, m);
    for(auto hh : CGAL::halfedges_around_face(h, m))
      faces_out.back().push_back(vindex(source(hh, m)));
  }
}

} // namespace

// ===========================================================================
// check_mesh on valid and invalid meshes
// ===========================================================================

TEST_CASE(valid_small_meshes)
{
  SM sm;
  HOT::Mesh_info info;
  CHECK_RESULT(read_and_check(write_file("tetra.off", tetra_off()), sm, HOT::Sphere_type, &info), HOT::OK, "");
  CHECK(info.number_of_vertices == 4 && info.number_of_faces == 4 && info.number_of_edges == 6);
  CHECK(info.euler_characteristic == 2 && info.genus == 0 && info.number_of_border_loops == 0);
  CHECK(info.type_known && info.type == HOT::Sphere_type);

  CHECK_RESULT(read_and_check(write_file("octa.off", octa_off()), sm, std::nullopt, &info), HOT::OK, "");
  CHECK(info.type_known && info.type == HOT::Sphere_type);

  CHECK_RESULT(read_and_check(write_file("fan.off", hexagon_fan_off()), sm, std::nullopt, &info), HOT::OK, "");
  CHECK(info.type == HOT::Disk_type && info.number_of_border_loops == 1 && info.euler_characteristic == 1);
  CHECK_RESULT(HOT::check_mesh(sm, HOT::Disk_type), HOT::OK, "");
  CHECK_RESULT(HOT::check_mesh(sm, get(CGAL::vertex_point, sm), HOT::Disk_type), HOT::OK, "");

  Poly poly;
  CHECK_RESULT(read_and_check(write_file("octa_p.off", octa_off()), poly, HOT::Sphere_type, &info), HOT::OK, "");
  CHECK(info.number_of_vertices == 6 && info.number_of_faces == 8);
  CHECK_RESULT(read_and_check(write_file("fan_p.off", hexagon_fan_off()), poly, HOT::Disk_type), HOT::OK, "");
}

TEST_CASE(empty_mesh)
{
  SM sm;
  CHECK_RESULT(HOT::check_mesh(sm), HOT::ERROR_EMPTY_MESH, "no face");
  Poly poly;
  CHECK_RESULT(HOT::check_mesh(poly, HOT::Sphere_type), HOT::ERROR_EMPTY_MESH, "no face");
  // vertices but no face: read fine, then empty
  CHECK_RESULT(read_text("nofaces.off", "OFF\n3 0 0\n0 0 0\n1 0 0\n0 1 0\n", sm), HOT::OK, "");
  CHECK(num_vertices(sm) == 3);
  CHECK_RESULT(HOT::check_mesh(sm), HOT::ERROR_EMPTY_MESH, "3 vertices");
  CHECK_RESULT(read_text("zero.off", "OFF\n0 0 0\n", sm), HOT::OK, "");
  CHECK_RESULT(HOT::check_mesh(sm), HOT::ERROR_EMPTY_MESH, "no face");
}

TEST_CASE(isolated_vertex)
{
  // the reader keeps the unreferenced vertex (to keep the numbering); check_mesh rejects it
  const std::string off = std::string("OFF\n5 4 0\n") + tetra_vertices + "5 5 5\n" + tetra_faces;
  SM sm;
  CHECK_RESULT(read_text("isolated.off", off, sm), HOT::OK, "");
  CHECK(num_vertices(sm) == 5);
  CHECK_RESULT(HOT::check_mesh(sm), HOT::ERROR_NON_MANIFOLD, "vertex 4 is isolated");
  Poly poly;
  CHECK_RESULT(read_and_check(write_file("isolated_p.off", off), poly, HOT::Sphere_type), HOT::ERROR_NON_MANIFOLD,
               "vertex 4 is isolated");
  // an isolated vertex first in the file
  const std::string off0 = "OFF\n5 4 0\n9 9 9\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 1 3 2\n3 1 2 4\n3 1 4 3\n3 2 3 4\n";
  CHECK_RESULT(read_and_check(write_file("isolated0.off", off0), sm, HOT::Sphere_type), HOT::ERROR_NON_MANIFOLD,
               "vertex 0 is isolated");
}

TEST_CASE(non_manifold_edge)
{
  // three triangles on the edge (0, 1)
  SM sm;
  CHECK_RESULT(read_text("nm_edge.off", "OFF\n5 3 0\n0 0 0\n1 0 0\n0 1 0\n0 -1 0\n0 0 1\n3 0 1 2\n3 1 0 3\n3 0 1 4\n", sm),
               HOT::ERROR_NON_MANIFOLD, "non-manifold edge: the edge (0, 1) is shared by 3 faces");
  CHECK(num_vertices(sm) == 0); // left empty on failure
}

TEST_CASE(non_manifold_vertex)
{
  // two closed tetrahedra (cones) touching at vertex 0
  const std::string two_cones =
    "OFF\n7 8 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n-1 0 0\n0 -1 0\n0 0 -1\n"
    "3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n"
    "3 0 5 4\n3 0 4 6\n3 0 6 5\n3 4 5 6\n";
  SM sm;
  CHECK_RESULT(read_text("two_cones.off", two_cones, sm), HOT::ERROR_NON_MANIFOLD,
               "non-manifold vertex: the faces around vertex 0 (line 3) form more than one fan");
  // a bowtie (two open fans)
  CHECK_RESULT(read_text("bowtie.off", "OFF\n5 2 0\n0 0 0\n1 0 0\n1 1 0\n-1 0 0\n-1 -1 0\n3 0 1 2\n3 0 3 4\n", sm),
               HOT::ERROR_NON_MANIFOLD, "non-manifold vertex");

  // check_mesh on a bowtie built directly with Euler::add_face (which accepts it)
  SM bow;
  std::vector<SM::Vertex_index> v;
  const double c[5][3] = { { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { -1, 0, 0 }, { -1, -1, 0 } };
  for(auto& p : c)
    v.push_back(bow.add_vertex(Point(p[0], p[1], p[2])));
  const bool added = CGAL::Euler::add_face(std::vector<SM::Vertex_index>{ v[0], v[1], v[2] }, bow) != SM::null_face()
                  && CGAL::Euler::add_face(std::vector<SM::Vertex_index>{ v[0], v[3], v[4] }, bow) != SM::null_face();
  CHECK(added);
  if(added)
    CHECK_RESULT(HOT::check_mesh(bow), HOT::ERROR_NON_MANIFOLD, "vertex 0 is non-manifold");
}

TEST_CASE(invalid_structures_and_garbage)
{
  // two closed tetrahedra glued at one vertex by relinking halfedges (Euler::add_face()
  // refuses to build this): CGAL::is_valid_polygon_mesh() fails, the diagnosis names the vertex
  const std::string two = "OFF\n8 8 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n0 0 0\n-1 0 0\n0 -1 0\n0 0 -1\n"
                          "3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n3 4 6 5\n3 4 5 7\n3 4 7 6\n3 5 6 7\n";
  SM sm;
  CHECK(hot_tools::read_mesh(write_file("glue.off", two), sm));
  const SM::Vertex_index v0(0), v4(4);
  std::vector<SM::Halfedge_index> to4;
  for(auto h : halfedges(sm))
    if(target(h, sm) == v4)
      to4.push_back(h);
  for(auto h : to4)
    set_target(h, v0, sm);
  sm.remove_vertex(v4); // leaves garbage: indices are no longer contiguous
  CHECK(!CGAL::is_valid_polygon_mesh(sm));
  CHECK_RESULT(HOT::check_mesh(sm), HOT::ERROR_NON_MANIFOLD,
               "vertex 0 is non-manifold: its incident faces form more than one fan (3 of its 6");

  // a Surface_mesh with removed elements (garbage) is checked in iteration order
  SM octa;
  CHECK(hot_tools::read_mesh(write_file("garbage_octa.off", octa_off()), octa));
  CGAL::Euler::remove_face(halfedge(*std::next(faces(octa).begin(), 7), octa), octa);
  CHECK(octa.has_garbage());
  HOT::Mesh_info info;
  CHECK_RESULT(HOT::check_mesh(octa, std::nullopt, &info), HOT::OK, "");
  CHECK(info.type == HOT::Disk_type && info.number_of_faces == 7 && info.number_of_vertices == 6);
  std::vector<SM::Vertex_index> lm;
  CHECK_RESULT(HOT::check_landmarks(octa, { 0, 1, 2, 3, 5 }, HOT::Sphere_type, lm), HOT::OK, "");
  CHECK(lm.size() == 5 && get(CGAL::vertex_point, octa, lm[4]) == Point(0, 0, -1));
  // the removed face 7 was (0, 3, 5): those are the border vertices
  CHECK_RESULT(HOT::check_landmarks(octa, { 0, 3, 5, 1, 2 }, HOT::Disk_type, lm), HOT::ERROR_LANDMARK_NOT_ON_BORDER,
               "landmark 3 (vertex 1)");
  // removing face 0 = (0, 2, 4) too makes vertex 0 a "bowtie" (two boundary gaps)
  CGAL::Euler::remove_face(halfedge(*faces(octa).begin(), octa), octa);
  CHECK(CGAL::is_valid_polygon_mesh(octa));
  CHECK_RESULT(HOT::check_mesh(octa, std::nullopt), HOT::ERROR_NON_MANIFOLD, "vertex 0 is non-manifold");
}

TEST_CASE(inconsistent_orientation)
{
  SM sm;
  const std::string flipped = std::string("OFF\n4 4 0\n") + tetra_vertices + "3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 3 2\n";
  CHECK_RESULT(read_text("flipped.off", flipped, sm), HOT::ERROR_NON_MANIFOLD, "inconsistent face orientation");
  // a duplicated face (see also the test case duplicated_faces)
  const std::string dup = "OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n3 0 1 2\n";
  CHECK_RESULT(read_text("dup_face.off", dup, sm), HOT::ERROR_NON_MANIFOLD,
               "duplicated face: face 1 (line 7) repeats face 0 (line 6) (the same vertices in the same order)");
  // a duplicated face on a closed mesh (it would also put three faces on its edges)
  const std::string dup3 = std::string("OFF\n4 5 0\n") + tetra_vertices + tetra_faces + "3 0 2 1\n";
  CHECK_RESULT(read_text("dup_face3.off", dup3, sm), HOT::ERROR_NON_MANIFOLD, "face 4 (line 11) repeats face 0 (line 7)");
  // the same face with the other orientation is not a repetition: three faces on its edges
  const std::string flip3 = std::string("OFF\n4 5 0\n") + tetra_vertices + tetra_faces + "3 1 2 0\n";
  CHECK_RESULT(read_text("flip_face3.off", flip3, sm), HOT::ERROR_NON_MANIFOLD, "the edge (0, 1) is shared by 3 faces (face 0 (line 7), face 1 (line 8), face 4 (line 11))");
  // CGAL's own shuffled test meshes are not consistently oriented
  CHECK_RESULT(hot_tools::read_mesh(mesh_path("tet-shuffled.off"), sm), HOT::ERROR_NON_MANIFOLD, "inconsistent face orientation");
}

TEST_CASE(several_components)
{
  const std::string two = "OFF\n8 8 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n5 0 0\n6 0 0\n5 1 0\n5 0 1\n"
                          "3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n3 4 6 5\n3 4 5 7\n3 4 7 6\n3 5 6 7\n";
  SM sm;
  CHECK_RESULT(read_and_check(write_file("two.off", two), sm, std::nullopt), HOT::ERROR_SEVERAL_COMPONENTS,
               "2 connected components (faces 0 and 4 are not connected");
  Poly poly;
  CHECK_RESULT(read_and_check(write_file("two_p.off", two), poly, HOT::Sphere_type), HOT::ERROR_SEVERAL_COMPONENTS,
               "2 connected components");
}

TEST_CASE(wrong_topology)
{
  SM sm;
  HOT::Mesh_info info;
  // sphere with a hole (octahedron minus a face) given as sphere type
  const std::string holed = write_file("holed.off", octa_off({ 7 }));
  CHECK_RESULT(read_and_check(holed, sm, HOT::Sphere_type), HOT::ERROR_WRONG_TOPOLOGY,
               "sphere-type (closed) orbifold needs a closed mesh, but the mesh has 1 boundary loop");
  CHECK_RESULT(HOT::check_mesh(sm, HOT::Disk_type), HOT::OK, "");
  CHECK_RESULT(HOT::check_mesh(sm, std::nullopt, &info), HOT::OK, "");
  CHECK(info.type == HOT::Disk_type);
  // a closed mesh given as disk type
  CHECK_RESULT(read_and_check(write_file("octa2.off", octa_off()), sm, HOT::Disk_type), HOT::ERROR_WRONG_TOPOLOGY,
               "the mesh is closed");
  // an annulus (two boundary loops)
  CHECK_RESULT(read_and_check(write_file("annulus.off", octa_off({ 0, 6 })), sm, std::nullopt),
               HOT::ERROR_WRONG_TOPOLOGY, "2 boundary loops");
  CHECK_RESULT(HOT::check_mesh(sm, HOT::Disk_type), HOT::ERROR_WRONG_TOPOLOGY, "has 2 boundary loops");
  // a torus: a closed mesh of genus 1 (V-E+F = 0), accepted for the closed (sphere) type, which
  // cuts it along a graph; its genus is reported
  CHECK(static_cast<bool>(read_and_check(write_file("torus.off", torus_off(6)), sm, HOT::Sphere_type, &info)));
  CHECK(info.genus == 1 && info.euler_characteristic == 0 && info.number_of_border_loops == 0 && info.type_known);
  CHECK(static_cast<bool>(HOT::check_mesh(sm, std::nullopt, &info)) && info.type == HOT::Sphere_type);
  Poly poly;
  CHECK(static_cast<bool>(read_and_check(write_file("torus_p.off", torus_off(5)), poly, std::nullopt, &info)));
  CHECK(info.genus == 1 && info.type == HOT::Sphere_type);
  // a torus with a hole as disk type
  std::string torus_holed = torus_off(6);
  torus_holed = torus_holed.substr(0, torus_holed.rfind("3 "));  // drop the last face
  torus_holed.replace(torus_holed.find(" 72 0"), 5, " 71 0");
  CHECK_RESULT(read_and_check(write_file("torus_holed.off", torus_holed), sm, HOT::Disk_type),
               HOT::ERROR_WRONG_TOPOLOGY, "needs a topological disk, but the mesh has genus 1");
}

TEST_CASE(detect_type)
{
  SM sm;
  HOT::Orbifold_type t = HOT::Disk_type;
  CHECK(!HOT::detect_orbifold_type(sm, t)); // empty
  CHECK(hot_tools::read_mesh(write_file("d_octa.off", octa_off()), sm));
  CHECK(HOT::detect_orbifold_type(sm, t) && t == HOT::Sphere_type);
  CHECK(HOT::count_border_loops(sm) == 0);
  CHECK(hot_tools::read_mesh(write_file("d_holed.off", octa_off({ 3 })), sm));
  CHECK(HOT::detect_orbifold_type(sm, t) && t == HOT::Disk_type);
  CHECK(hot_tools::read_mesh(write_file("d_annulus.off", octa_off({ 0, 6 })), sm));
  t = HOT::Sphere_type;
  CHECK(!HOT::detect_orbifold_type(sm, t) && t == HOT::Sphere_type);
  CHECK(HOT::count_border_loops(sm) == 2);
  Poly poly;
  CHECK(hot_tools::read_mesh(write_file("d_holed_p.off", octa_off({ 3 })), poly));
  CHECK(HOT::detect_orbifold_type(poly, t) && t == HOT::Disk_type);
}

TEST_CASE(non_triangular)
{
  const std::string cube = "OFF\n8 6 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n"
                           "4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n4 1 2 6 5\n4 2 3 7 6\n4 3 0 4 7\n";
  SM sm;
  CHECK_RESULT(read_text("cube_quads.off", cube, sm), HOT::OK, ""); // polygons are read
  CHECK_RESULT(HOT::check_mesh(sm, HOT::Sphere_type), HOT::ERROR_NON_TRIANGULAR_MESH, "face 0 has 4 vertices");
  // a single quad after triangles
  const std::string mixed = "OFF\n5 5 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0.5 0.5 1\n"
                            "3 0 1 4\n3 1 2 4\n3 2 3 4\n3 3 0 4\n4 0 3 2 1\n";
  CHECK_RESULT(read_and_check(write_file("pyramid.off", mixed), sm, HOT::Sphere_type), HOT::ERROR_NON_TRIANGULAR_MESH,
               "face 4 has 4 vertices");
}

TEST_CASE(non_finite_coordinates)
{
  SM sm;
  for(const char* bad : { "nan", "NaN", "inf", "-inf", "Infinity", "1e400", "-1e999" }) {
    const std::string off = std::string("OFF\n4 4 0\n0 0 0\n1 ") + bad + " 0\n0 1 0\n0 0 1\n" + tetra_faces;
    CHECK_RESULT(read_text("nan.off", off, sm), HOT::ERROR_NON_FINITE_COORDINATES, "vertex 1 (line 4)");
  }
  // huge but finite coordinates: the exact predicates still work (big_flat below), but the
  // squared edge lengths overflow (see the test case coordinate_range)
  const std::string big = "OFF\n4 4 0\n0 0 0\n1e308 0 0\n0 1e308 0\n0 0 1e308\n" + std::string(tetra_faces);
  CHECK_RESULT(read_and_check(write_file("big.off", big), sm, HOT::Sphere_type), HOT::ERROR_NON_FINITE_COORDINATES,
               "face 0 is out of the range of double-precision geometry: its squared edge lengths overflow");
  const std::string big_flat = "OFF\n4 4 0\n0 0 0\n1e308 0 0\n-1e308 0 0\n0 0 1e308\n" + std::string(tetra_faces);
  CHECK_RESULT(read_and_check(write_file("big_flat.off", big_flat), sm, HOT::Sphere_type), HOT::ERROR_DEGENERATE_FACE,
               "face 0 has zero area");
  // check_mesh on a mesh whose point became NaN in memory
  CHECK(hot_tools::read_mesh(write_file("tetra_nan.off", tetra_off()), sm));
  const double nan = std::numeric_limits<double>::quiet_NaN();
  put(get(CGAL::vertex_point, sm), *std::next(vertices(sm).begin(), 2), Point(0, nan, 0));
  CHECK_RESULT(HOT::check_mesh(sm, HOT::Sphere_type), HOT::ERROR_NON_FINITE_COORDINATES, "vertex 2 has a non-finite");
  put(get(CGAL::vertex_point, sm), *std::next(vertices(sm).begin(), 2),
      Point(0, std::numeric_limits<double>::infinity(), 0));
  CHECK_RESULT(HOT::check_mesh(sm, HOT::Sphere_type), HOT::ERROR_NON_FINITE_COORDINATES, "vertex 2");
  // 4OFF with w = 0
  const std::string w0 = "4OFF\n4 4 0\n0 0 0 1\n1 0 0 1\n0 1 0 0\n0 0 1 1\n" + std::string(tetra_faces);
  CHECK_RESULT(read_text("w0.off", w0, sm), HOT::ERROR_NON_FINITE_COORDINATES, "vertex 2");
}

TEST_CASE(degenerate_faces)
{
  SM sm;
  CHECK_RESULT(read_text("repeat.off", std::string("OFF\n4 4 0\n") + tetra_vertices + "3 0 0 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n", sm),
               HOT::ERROR_DEGENERATE_FACE, "face 0 (line 7) is degenerate: it uses vertex 0 more than once");
  CHECK_RESULT(read_text("two.off", std::string("OFF\n4 2 0\n") + tetra_vertices + "3 0 2 1\n2 0 1\n", sm),
               HOT::ERROR_DEGENERATE_FACE, "face 1 (line 8) is degenerate: it has only 2 vertices");
  CHECK_RESULT(read_text("zero_face.off", std::string("OFF\n4 1 0\n") + tetra_vertices + "0\n", sm),
               HOT::ERROR_DEGENERATE_FACE, "only 0 vertices");
  // collinear vertices: vertex 3 on the line of vertices 0 and 1
  CHECK_RESULT(read_and_check(write_file("collinear.off", std::string("OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n2 0 0\n") + tetra_faces),
                              sm, HOT::Sphere_type),
               HOT::ERROR_DEGENERATE_FACE, "face 1 has zero area: its vertices 0, 1, 3 are collinear");
  // two vertices of a face at the same position
  CHECK_RESULT(read_and_check(write_file("coincide.off", std::string("OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n1 0 0\n") + tetra_faces),
                              sm, HOT::Sphere_type),
               HOT::ERROR_DEGENERATE_FACE, "have the same coordinates");
  // a nearly flat but not flat triangle is fine (exact predicate)
  CHECK_RESULT(read_and_check(write_file("thin.off", std::string("OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n2 1e-300 0\n") + tetra_faces),
                              sm, HOT::Sphere_type),
               HOT::OK, "");
}

TEST_CASE(duplicate_points_allowed)
{
  // a pentagon fan cut open along one spoke: vertices 1 and 6 have the same position but
  // no face holds both; the mesh is a valid disk and is accepted
  std::string s = "OFF\n7 5 0\n0 0 0\n";
  for(int k = 0; k < 5; ++k)
    s += std::to_string(std::cos(2 * 3.14159265358979 * k / 5)) + " " + std::to_string(std::sin(2 * 3.14159265358979 * k / 5)) + " 0\n";
  s += "1 0 0\n3 0 1 2\n3 0 2 3\n3 0 3 4\n3 0 4 5\n3 0 5 6\n";
  SM sm;
  HOT::Mesh_info info;
  CHECK_RESULT(read_and_check(write_file("cut_fan.off", s), sm, std::nullopt, &info), HOT::OK, "");
  CHECK(info.type == HOT::Disk_type && info.number_of_vertices == 7);
  CHECK(vertex_point(sm, 1) == vertex_point(sm, 6));
}

// ===========================================================================
// OFF reader
// ===========================================================================

TEST_CASE(off_syntax)
{
  SM sm;
  // comments, blank lines, counts on the keyword line, trailing color fields
  const std::string commented = "# a tetrahedron\nOFF 4 4 6\n\n# vertices\n0 0 0 # origin\n1 0 0\n0 1 0\n0 0 1\n"
                                "3 0 2 1 255 0 0\n3 0 1 3\n3 0 3 2\n3 1 2 3\n# trailing comment\n";
  CHECK_RESULT(read_and_check(write_file("commented.off", commented), sm, HOT::Sphere_type), HOT::OK, "");
  // COFF / NOFF / 4OFF / CRLF
  CHECK_RESULT(read_text("coff.off", "COFF\n4 4 0\n0 0 0 1 0 0 1\n1 0 0 0 1 0 1\n0 1 0 0 0 1 1\n0 0 1 1 1 1 1\n" + std::string(tetra_faces), sm),
               HOT::OK, "");
  CHECK_RESULT(read_text("noff.off", "NOFF\n4 4 0\n0 0 0 0 0 1\n1 0 0 0 0 1\n0 1 0 0 0 1\n0 0 1 0 0 1\n" + std::string(tetra_faces), sm),
               HOT::OK, "");
  CHECK_RESULT(read_text("4off.off", "4OFF\n4 4 0\n0 0 0 2\n2 0 0 2\n0 2 0 2\n0 0 2 2\n" + std::string(tetra_faces), sm), HOT::OK, "");
  CHECK(vertex_point(sm, 1) == Point(1, 0, 0));
  CHECK_RESULT(read_text("crlf.off", "OFF\r\n4 4 0\r\n0 0 0\r\n1 0 0\r\n0 1 0\r\n0 0 1\r\n3 0 2 1\r\n3 0 1 3\r\n3 0 3 2\r\n3 1 2 3\r\n", sm),
               HOT::OK, "");
  CHECK(num_faces(sm) == 4);

  CHECK_RESULT(read_text("nokw.off", "4 4 0\n" + std::string(tetra_vertices) + tetra_faces, sm), HOT::ERROR_READ_FAILED,
               "line 1: '4' is not an OFF header keyword");
  CHECK_RESULT(read_text("skel.off", "SKEL\n1 0\n0 0 0\n", sm), HOT::ERROR_READ_FAILED, "not an OFF header keyword");
  CHECK_RESULT(read_text("blank.off", "  \n\n# only a comment\n", sm), HOT::ERROR_READ_FAILED, "no OFF header");
  CHECK_RESULT(read_text("badcoord.off", "OFF\n4 4 0\n0 0 0\n1 0 abc\n0 1 0\n0 0 1\n" + std::string(tetra_faces), sm),
               HOT::ERROR_READ_FAILED, "line 4: vertex 1: coordinate 'abc' is not a number");
  CHECK_RESULT(read_text("coordjunk.off", "OFF\n4 4 0\n0 0 0\n1 0 0.5x\n0 1 0\n0 0 1\n" + std::string(tetra_faces), sm),
               HOT::ERROR_READ_FAILED, "'0.5x'");
  CHECK_RESULT(read_text("twocoords.off", "OFF\n4 4 0\n0 0 0\n1 0\n0 1 0\n0 0 1\n" + std::string(tetra_faces), sm),
               HOT::ERROR_READ_FAILED, "line 4: vertex 1 has 2 coordinates, 3 expected");
}

TEST_CASE(off_bad_faces)
{
  SM sm;
  const std::string head = std::string("OFF\n4 4 0\n") + tetra_vertices;
  check_unreadable(sm, head, {
    { "range.off", "3 0 2 1\n3 0 1 7\n3 0 3 2\n3 1 2 3\n", "line 8: face 1: vertex index '7' is out of range (the file has 4 vertices)" },
    { "range2.off", "3 0 2 1\n3 0 1 4\n3 0 3 2\n3 1 2 3\n", "out of range" },
    { "neg.off", "3 0 2 1\n3 0 -1 3\n3 0 3 2\n3 1 2 3\n", "line 8: face 1: negative vertex index '-1'" },
    { "hugeidx.off", "3 0 2 1\n3 0 1 99999999999999999999999\n3 0 3 2\n3 1 2 3\n", "out of range" },
    { "garbidx.off", "3 0 2 1\n3 0 1 x\n3 0 3 2\n3 1 2 3\n", "line 8: face 1: 'x' is not a vertex index" },
    { "floatidx.off", "3 0 2 1\n3 0 1.5 3\n3 0 3 2\n3 1 2 3\n", "'1.5' is not a vertex index" },
    { "short.off", "3 0 2 1\n5 0 1 3\n3 0 3 2\n3 1 2 3\n", "line 8: face 1 announces 5 vertices but lists only 3" },
    { "hugen.off", "3 0 2 1\n4000000000 0 1 3\n3 0 3 2\n3 1 2 3\n", "announces 4000000000 vertices" },
    { "negn.off", "3 0 2 1\n-3 0 1 3\n3 0 3 2\n3 1 2 3\n", "the vertex count '-3' is not a non-negative integer" },
  });
}

TEST_CASE(off_bad_headers)
{
  SM sm;
  const auto t0 = std::chrono::steady_clock::now();
  CHECK_RESULT(read_text("huge.off", "OFF\n1000000000000 1 0\n0 0 0\n", sm), HOT::ERROR_READ_FAILED,
               "announces 1000000000000 vertices and 1 faces, but only");
  CHECK_RESULT(read_text("huge2.off", "OFF\n2000000000 2000000000 0\n" + std::string(tetra_vertices), sm),
               HOT::ERROR_READ_FAILED, "truncated file or wrong header");
  CHECK_RESULT(read_text("huge3.off", "OFF\n4 1000000000000 0\n" + std::string(tetra_vertices) + tetra_faces, sm),
               HOT::ERROR_READ_FAILED, "truncated file or wrong header");
  CHECK_RESULT(read_text("overflow.off", "OFF\n99999999999999999999999 1 0\n", sm), HOT::ERROR_READ_FAILED,
               "vertex count '99999999999999999999999' in the OFF header is too large");
  CHECK_RESULT(read_text("negv.off", "OFF\n-4 4 0\n" + std::string(tetra_vertices) + tetra_faces, sm), HOT::ERROR_READ_FAILED,
               "negative vertex count '-4'");
  CHECK_RESULT(read_text("negf.off", "OFF\n4 -4 0\n" + std::string(tetra_vertices) + tetra_faces, sm), HOT::ERROR_READ_FAILED,
               "negative face count");
  CHECK_RESULT(read_text("nocounts.off", "OFF\n", sm), HOT::ERROR_READ_FAILED, "no vertex count");
  CHECK_RESULT(read_text("twocounts.off", "OFF\n4 4", sm), HOT::ERROR_READ_FAILED, "no edge count");
  CHECK_RESULT(read_text("badcount.off", "OFF\n4x 4 0\n", sm), HOT::ERROR_READ_FAILED, "vertex count '4x' is not");
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  CHECK_MSG(seconds < 1.0, "hostile headers took " << seconds << " s");
}

TEST_CASE(off_truncated)
{
  SM sm;
  const std::string full = tetra_off();
  // cut after the third face
  const std::string no_last_face = full.substr(0, full.rfind("3 1 2 3"));
  CHECK_RESULT(read_text("trunc_face.off", no_last_face, sm), HOT::ERROR_READ_FAILED,
               "the file ends after 3 of the 4 faces announced by the OFF header (truncated file?)");
  // cut inside a face record
  CHECK_RESULT(read_text("trunc_face2.off", full.substr(0, full.size() - 3), sm), HOT::ERROR_READ_FAILED,
               "face 3 announces 3 vertices but lists only 2");
  // cut inside the vertices
  CHECK_RESULT(read_text("trunc_vert.off", "OFF\n4 0 0\n0 0 0\n1 0 0\n0 1", sm), HOT::ERROR_READ_FAILED,
               "announces 4 vertices and 0 faces, but only 16 bytes follow (truncated file or wrong header)");
  CHECK_RESULT(read_text("trunc_vert1.off", "OFF\n2 0 0\n0 0 0\n1 0", sm), HOT::ERROR_READ_FAILED,
               "line 4: vertex 1 has 2 coordinates, 3 expected");
  CHECK_RESULT(read_text("trunc_vert2.off", "OFF\n4 0 0\n0 0 0\n1 0 0\n0 1 0\n", sm), HOT::ERROR_READ_FAILED,
               "the file ends after 3 of the 4 vertices");
  // every prefix of a valid file (but the one without the final end of line) is an error
  int failures = 0;
  for(std::size_t n = 0; n + 1 < full.size(); ++n) {
    HOT::Status r = read_text("prefix.off", full.substr(0, n), sm);
    if(r.code != HOT::ERROR_READ_FAILED)
      ++failures;
  }
  CHECK_MSG(failures == 0, failures << " prefixes of a valid OFF file were not READ_FAILED");
}

TEST_CASE(off_binary)
{
  SM sm;
  CHECK_RESULT(read_and_check(write_file("bin.off", binary_off_tetra()), sm, HOT::Sphere_type), HOT::OK, "");
  CHECK(num_vertices(sm) == 4 && num_faces(sm) == 4 && vertex_point(sm, 3) == Point(0, 0, 1));
  CHECK_RESULT(read_text("bin_trunc.off", binary_off_tetra(true), sm), HOT::ERROR_READ_FAILED, "binary OFF");
  std::string huge = "OFF BINARY\n";
  put_u32_be(huge, 2000000000u);
  put_u32_be(huge, 2000000000u);
  put_u32_be(huge, 0);
  CHECK_RESULT(read_text("bin_huge.off", huge, sm), HOT::ERROR_READ_FAILED, "truncated file or wrong header");
  std::string bigface = binary_off_tetra();
  bigface.replace(11 + 12 + 48, 4, std::string("\x7f\xff\xff\xff", 4)); // first face: n = 2^31-1
  CHECK_RESULT(read_text("bin_bigface.off", bigface, sm), HOT::ERROR_READ_FAILED, "face 0 announces 2147483647 vertices");
  std::string nanv = binary_off_tetra();
  nanv.replace(11 + 12 + 12, 4, std::string("\x7f\xc0\x00\x00", 4)); // vertex 1, x = NaN
  CHECK_RESULT(read_text("bin_nan.off", nanv, sm), HOT::ERROR_NON_FINITE_COORDINATES, "vertex 1 has a non-finite");
  CHECK_RESULT(read_text("bin_coff.off", "COFF BINARY\n" + binary_off_tetra().substr(11), sm), HOT::ERROR_READ_FAILED,
               "binary OFF is supported only without");
}

TEST_CASE(garbage_files)
{
  SM sm;
  for(const char* ext : { "off", "obj", "ply", "stl" }) {
    for(std::uint32_t seed = 1; seed <= 20; ++seed) {
      std::string g = garbage(64 + 200 * seed, seed);
      HOT::Status r = read_text(std::string("garbage.") + ext, g, sm);
      CHECK_MSG(r.code == HOT::ERROR_READ_FAILED, ext << " seed " << seed << ": " << r.code << " " << r.message);
      CHECK(one_line(r));
      r = read_text(std::string("garbage2.") + ext, (std::string(ext) == "off" ? "OFF\n" : "") + g, sm);
      CHECK_MSG(r.code == HOT::ERROR_READ_FAILED, ext << " seed " << seed << " with header: " << r.code << " " << r.message);
    }
  }
  CHECK_RESULT(read_text("empty.off", "", sm), HOT::ERROR_READ_FAILED, "the file is empty");
  CHECK_RESULT(read_text("empty.ply", "", sm), HOT::ERROR_READ_FAILED, "the file is empty");
}

TEST_CASE(file_errors)
{
  SM sm;
  CHECK_RESULT(hot_tools::read_mesh(tmp_dir() + "/does_not_exist.off", sm), HOT::ERROR_READ_FAILED, "does_not_exist.off': no such file");
  std::filesystem::create_directories(tmp_dir() + "/dir.off");
  CHECK_RESULT(hot_tools::read_mesh(tmp_dir() + "/dir.off", sm), HOT::ERROR_READ_FAILED, "is a directory");
  CHECK_RESULT(hot_tools::read_mesh(write_file("mesh.xyz", tetra_off()), sm), HOT::ERROR_READ_FAILED, "unsupported file extension 'xyz'");
  CHECK_RESULT(hot_tools::read_mesh(write_file("noext", tetra_off()), sm), HOT::ERROR_READ_FAILED, "unsupported file extension");
  CHECK_RESULT(hot_tools::read_mesh("", sm), HOT::ERROR_READ_FAILED, "no file name");
  CHECK_RESULT(hot_tools::read_mesh(tmp_dir() + "/missing.ts", sm), HOT::ERROR_READ_FAILED, "no such file");
  CHECK_RESULT(hot_tools::read_mesh(write_file("UPPER.OFF", tetra_off()), sm), HOT::OK, ""); // extension case
  // a mesh that is not empty is cleared first, and left empty on failure
  CHECK(num_faces(sm) == 4);
  CHECK_RESULT(hot_tools::read_mesh(write_file("bad.off", "OFF\n-1 0 0\n"), sm), HOT::ERROR_READ_FAILED, "negative");
  CHECK(num_vertices(sm) == 0 && num_faces(sm) == 0);
}

// ===========================================================================
// other formats
// ===========================================================================

TEST_CASE(obj_reader)
{
  SM sm;
  const std::string obj = "# tetra\nmtllib x.mtl\no tetra\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1 1.0\nvt 0 0\nvn 0 0 1\n"
                          "g group\nusemtl m\ns off\nf 1/1/1 3/1/1 2/1/1\nf 1//1 2//1 4//1\nf -4 -1 -2\nf 2 3 4\n";
  CHECK_RESULT(read_and_check(write_file("tetra.obj", obj), sm, HOT::Sphere_type), HOT::OK, "");
  CHECK(num_vertices(sm) == 4 && vertex_point(sm, 3) == Point(0, 0, 1));
  const std::string v4 = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n";
  CHECK_RESULT(read_text("zero.obj", v4 + "f 0 1 2\n", sm), HOT::ERROR_READ_FAILED, "line 5: face 0: vertex index 0 is invalid");
  // the index as written in the file (1-based)
  CHECK_RESULT(read_text("range.obj", v4 + "f 1 3 2\nf 1 2 5\n", sm), HOT::ERROR_READ_FAILED,
               "line 6: face 1: vertex index 5 is out of range (the file has 4 vertices)");
  CHECK_RESULT(read_text("forward.obj", "f 1 2 3\n" + v4, sm), HOT::OK, ""); // forward references
  CHECK_RESULT(read_text("forward_range.obj", "f 1 2 7\n" + v4, sm), HOT::ERROR_READ_FAILED,
               "line 1: face 0: vertex index 7 is out of range (the file has 4 vertices)");
  CHECK_RESULT(read_text("rel.obj", v4 + "f -1 -2 -5\n", sm), HOT::ERROR_READ_FAILED, "refers to a vertex before the first");
  CHECK_RESULT(read_text("unknown.obj", v4 + "frobnicate 1 2\n", sm), HOT::ERROR_READ_FAILED, "line 5: unknown OBJ statement 'frobnicate'");
  CHECK_RESULT(read_text("badref.obj", v4 + "f 1 2 3x\n", sm), HOT::ERROR_READ_FAILED, "'3x' is not a vertex reference");
  CHECK_RESULT(read_text("badv.obj", "v 0 0\n", sm), HOT::ERROR_READ_FAILED, "line 1: vertex 0 has 2 coordinates");
  CHECK_RESULT(read_text("nan.obj", "v 0 0 nan\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", sm), HOT::ERROR_NON_FINITE_COORDINATES,
               "vertex 0 (line 1)");
  CHECK_RESULT(read_text("short.obj", v4 + "f 1 2\n", sm), HOT::ERROR_DEGENERATE_FACE, "only 2 vertices");
}

TEST_CASE(ply_reader)
{
  SM sm;
  const std::string ascii = "ply\nformat ascii 1.0\ncomment tetra\nelement vertex 4\nproperty float x\nproperty float y\n"
                            "property float z\nproperty uchar red\nelement face 4\nproperty list uchar int vertex_indices\n"
                            "end_header\n0 0 0 255\n1 0 0 255\n0 1 0 255\n0 0 1 255\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";
  CHECK_RESULT(read_and_check(write_file("tetra.ply", ascii), sm, HOT::Sphere_type), HOT::OK, "");
  CHECK(num_vertices(sm) == 4);

  auto binary_ply = [](bool little, std::uint32_t list_size_face0, bool nan) {
    std::string s = std::string("ply\nformat ") + (little ? "binary_little_endian" : "binary_big_endian")
                  + " 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
                    "element face 4\nproperty list int int vertex_indices\nelement edge 0\nproperty int a\nend_header\n";
    auto u32 = [&](std::uint32_t v) { little ? put_u32_le(s, v) : put_u32_be(s, v); };
    for(int i = 0; i < 4; ++i)
      for(int k = 0; k < 3; ++k)
        u32(float_bits(nan && i == 2 && k == 1 ? std::numeric_limits<float>::quiet_NaN() : tetra_coords[i][k]));
    for(int f = 0; f < 4; ++f) {
      u32(f == 0 ? list_size_face0 : 3);
      for(int i : tetra_tris[f])
        u32(std::uint32_t(i));
    }
    return s;
  };
  CHECK_RESULT(read_and_check(write_file("le.ply", binary_ply(true, 3, false)), sm, HOT::Sphere_type), HOT::OK, "");
  CHECK(vertex_point(sm, 2) == Point(0, 1, 0));
  CHECK_RESULT(read_and_check(write_file("be.ply", binary_ply(false, 3, false)), sm, HOT::Sphere_type), HOT::OK, "");
  CHECK(vertex_point(sm, 3) == Point(0, 0, 1));
  const auto t0 = std::chrono::steady_clock::now();
  CHECK_RESULT(read_text("biglist.ply", binary_ply(true, 0x7fffffffu, false), sm), HOT::ERROR_READ_FAILED,
               "face 0: the list size 2147483647 is larger than the rest of the file holds (only 60 bytes left: truncated file?)");
  CHECK_RESULT(read_text("neglist.ply", binary_ply(true, 0xffffffffu, false), sm), HOT::ERROR_READ_FAILED,
               "face 0: negative list size -1");
  CHECK_RESULT(read_text("nan.ply", binary_ply(true, 3, true), sm), HOT::ERROR_NON_FINITE_COORDINATES, "vertex 2");
  std::string trunc = binary_ply(true, 3, false);
  trunc.resize(trunc.size() - 5);
  CHECK_RESULT(read_text("trunc.ply", trunc, sm), HOT::ERROR_READ_FAILED, "face 3: ");
  trunc.resize(trunc.size() - 40);
  CHECK_RESULT(read_text("trunc2.ply", trunc, sm), HOT::ERROR_READ_FAILED, "face 1: the file ends early (truncated file?)");
  CHECK_RESULT(read_text("hugecount.ply",
                         "ply\nformat ascii 1.0\nelement vertex 1000000000000\nproperty float x\nproperty float y\n"
                         "property float z\nend_header\n0 0 0\n", sm),
               HOT::ERROR_READ_FAILED, "announces 1000000000000 'vertex' elements");
  // an element without property holds no data, whatever its count: no loop, no hang
  CHECK_RESULT(read_text("noprop.ply", "ply\nformat ascii 1.0\nelement nothing 1000000000000000\n" + ascii.substr(ascii.find("element vertex")), sm),
               HOT::OK, "");
  CHECK_RESULT(read_text("noend.ply", "ply\nformat ascii 1.0\nelement vertex 1\n", sm), HOT::ERROR_READ_FAILED, "no end_header");
  CHECK_RESULT(read_text("noply.ply", "plx\n", sm), HOT::ERROR_READ_FAILED, "not a PLY file");
  CHECK_RESULT(read_text("badtype.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty quad x\nend_header\n", sm),
               HOT::ERROR_READ_FAILED, "unknown PLY property type 'quad'");
  CHECK_RESULT(read_text("noxyz.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nend_header\n0\n", sm),
               HOT::ERROR_READ_FAILED, "no x, y and z");
  std::string bad = ascii;
  bad.replace(bad.find("1 0 0 255"), 9, "1 0 zz 255");
  CHECK_RESULT(read_text("asciibad.ply", bad, sm), HOT::ERROR_READ_FAILED, "line 13: vertex 1: 'zz' is not a number");
  CHECK_RESULT(read_text("negidx.ply", ascii.substr(0, ascii.find("3 0 2 1")) + "3 0 -2 1\n", sm), HOT::ERROR_READ_FAILED,
               "negative vertex index -2");
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  CHECK_MSG(seconds < 1.0, "hostile PLY files took " << seconds << " s");
}

TEST_CASE(stl_reader)
{
  SM sm;
  HOT::Mesh_info info;
  CHECK_RESULT(read_and_check(write_file("bin.stl", binary_stl_tetra()), sm, HOT::Sphere_type, &info), HOT::OK, "");
  CHECK(info.number_of_vertices == 4); // 12 corners merged into 4 points
  CHECK(vertex_point(sm, 0) == Point(0, 0, 0) && vertex_point(sm, 1) == Point(0, 1, 0)); // order of first appearance
  CHECK_RESULT(read_and_check(write_file("ascii.stl", ascii_stl_tetra()), sm, HOT::Sphere_type, &info), HOT::OK, "");
  CHECK(info.number_of_vertices == 4);
  CHECK_RESULT(read_text("bin_trunc.stl", binary_stl_tetra(4, true), sm), HOT::ERROR_READ_FAILED,
               "the header announces 4 triangles, i.e. 284 bytes, but the file has 277 bytes");
  CHECK_RESULT(read_text("bin_huge.stl", binary_stl_tetra(0xffffffffu), sm), HOT::ERROR_READ_FAILED, "4294967295 triangles");
  std::string quad = ascii_stl_tetra();
  quad.insert(quad.find("    endloop"), "      vertex 5 5 5\n");
  CHECK_RESULT(read_text("quad.stl", quad, sm), HOT::ERROR_READ_FAILED, "'endloop' expected, 'vertex' found");
  std::string noend = ascii_stl_tetra();
  noend.resize(noend.find("endsolid"));
  CHECK_RESULT(read_text("noend.stl", noend, sm), HOT::ERROR_READ_FAILED, "no 'endsolid'");
  std::string nan = ascii_stl_tetra();
  nan.replace(nan.find("vertex 1.000000"), 15, "vertex nan");
  CHECK_RESULT(read_text("nan.stl", nan, sm), HOT::ERROR_NON_FINITE_COORDINATES, "non-finite");
  CHECK_RESULT(read_text("short.stl", "hello", sm), HOT::ERROR_READ_FAILED, "not an STL file");
}

TEST_CASE(gocad_reader)
{
  // .ts files: our GOCAD TSurf parser, then our validation
  const std::string ts = "GOCAD TSurf 1\nHEADER {\nname:tetra\n}\nTFACE\nVRTX 0 0 0 0\nVRTX 1 1 0 0\nVRTX 2 0 1 0\n"
                         "VRTX 3 0 0 1\nTRGL 0 2 1\nTRGL 0 1 3\nTRGL 0 3 2\nTRGL 1 2 3\nEND\n";
  SM sm;
  CHECK_RESULT(read_and_check(write_file("tetra.ts", ts), sm, HOT::Sphere_type), HOT::OK, "");
  CHECK(num_vertices(sm) == 4 && vertex_point(sm, 1) == Point(1, 0, 0));
  std::string bad = ts;
  bad.replace(bad.find("TRGL 1 2 3"), 10, "TRGL 1 2 9");
  CHECK_RESULT(read_text("range.ts", bad, sm), HOT::ERROR_READ_FAILED,
               "range.ts: line 13: triangle 3: vertex id 9 is not defined (no VRTX, PVRTX or ATOM with that id)");
  CHECK_RESULT(read_text("garbage.ts", garbage(500, 3), sm), HOT::ERROR_READ_FAILED, "no TFACE line: not a GOCAD TSurf file");
}

// ===========================================================================
// order of vertices and faces; agreement with CGAL's readers; validity
// ===========================================================================

TEST_CASE(order_is_kept)
{
  for(const char* name : { "bear.off", "mannequin-devil.off", "sphere.ply", "colored_tetra.ply", "sphere.stl", "cube-ouvert.off" }) {
    std::vector<Point> cgal_points;
    std::vector<std::vector<std::size_t> > cgal_faces;
    CHECK_MSG(CGAL::IO::read_polygon_soup(mesh_path(name), cgal_points, cgal_faces), name);

    SM sm;
    CHECK_RESULT(hot_tools::read_mesh(mesh_path(name), sm), HOT::OK, "");
    std::vector<Point> points;
    std::vector<std::vector<std::size_t> > fcs;
    mesh_to_soup(sm, points, fcs);
    CHECK_MSG(points == cgal_points, name << ": Surface_mesh vertices differ from the file's");
    CHECK_MSG(fcs == cgal_faces, name << ": Surface_mesh faces differ from the file's");
    const bool isolated = std::string(name) == "cube-ouvert.off";
    CHECK_MSG(isolated || CGAL::is_valid_polygon_mesh(sm), name);

    Poly poly;
    CHECK_RESULT(hot_tools::read_mesh(mesh_path(name), poly), HOT::OK, "");
    mesh_to_soup(poly, points, fcs);
    CHECK_MSG(points == cgal_points, name << ": Polyhedron_3 vertices differ from the file's");
    CHECK_MSG(fcs == cgal_faces, name << ": Polyhedron_3 faces differ from the file's");
    CHECK_MSG(isolated || CGAL::is_valid_polygon_mesh(poly), name);
  }
}

TEST_CASE(soup_matches_cgal)
{
  // our parsers give exactly the soup of CGAL::IO::read_polygon_soup() on valid files
  for(const char* name : { "armadillo.off", "elephant-with-holes.off", "b9.ply", "pig.stl", "mesh_with_colors.off",
                           "cube-shuffled.off", "polygon_mesh.off", "3torus.off" }) {
    std::vector<Point> cgal_points;
    std::vector<std::vector<std::size_t> > cgal_faces;
    CHECK_MSG(CGAL::IO::read_polygon_soup(mesh_path(name), cgal_points, cgal_faces), name);
    hot_tools::Polygon_soup soup;
    CHECK_RESULT(hot_tools::read_polygon_soup_file(mesh_path(name), soup), HOT::OK, "");
    bool same = soup.points.size() == cgal_points.size() && soup.number_of_faces() == cgal_faces.size();
    for(std::size_t i = 0; same && i < cgal_points.size(); ++i)
      same = Point(soup.points[i][0], soup.points[i][1], soup.points[i][2]) == cgal_points[i];
    for(std::size_t j = 0; same && j < cgal_faces.size(); ++j)
      same = std::vector<std::size_t>(soup.face_vertices.begin() + soup.face_begin[j],
                                      soup.face_vertices.begin() + soup.face_begin[j + 1]) == cgal_faces[j];
    CHECK_MSG(same, name << ": soup differs from CGAL's");
  }
}

// ===========================================================================
// real meshes of libcgal-demo
// ===========================================================================

TEST_CASE(real_meshes)
{
  struct Expected { const char* name; HOT::Error_code code; HOT::Orbifold_type type; std::size_t nv; long long genus = 0; };
  const Expected expected[] = {
    // closed genus 0 (sphere type)
    { "bear.off", HOT::OK, HOT::Sphere_type, 13826 },
    { "homer.off", HOT::OK, HOT::Sphere_type, 4930 },
    { "camel.off", HOT::OK, HOT::Sphere_type, 9770 },
    { "hand.off", HOT::OK, HOT::Sphere_type, 1197 },
    { "armadillo.off", HOT::OK, HOT::Sphere_type, 26002 },
    { "bunny00.off", HOT::OK, HOT::Sphere_type, 37706 },
    { "diplodocus.off", HOT::OK, HOT::Sphere_type, 23982 },
    { "triceratops.off", HOT::OK, HOT::Sphere_type, 2832 },
    { "man.off", HOT::OK, HOT::Sphere_type, 17495 },
    { "fandisk.off", HOT::OK, HOT::Sphere_type, 6475 },
    { "cow.off", HOT::OK, HOT::Sphere_type, 2904 },
    { "bull.off", HOT::OK, HOT::Sphere_type, 6200 },
    { "dino.off", HOT::OK, HOT::Sphere_type, 3916 },
    { "sphere.off", HOT::OK, HOT::Sphere_type, 162 },
    // one boundary loop, genus 0 (disk type)
    { "mannequin-devil.off", HOT::OK, HOT::Disk_type, 12977 },
    { "lion-head.off", HOT::OK, HOT::Disk_type, 8356 },
    { "mushroom.off", HOT::OK, HOT::Disk_type, 2337 },
    { "nefertiti.off", HOT::OK, HOT::Disk_type, 299 },
    { "cylinder.off", HOT::OK, HOT::Disk_type, 1200 },
    { "three_peaks.off", HOT::OK, HOT::Disk_type, 1907 },
    // closed, genus 3 and 1 (V - E + F = -4 and 0): the closed type, cut along a graph
    { "elephant.off", HOT::OK, HOT::Sphere_type, 2775, 3 },
    { "knot1.off", HOT::OK, HOT::Sphere_type, 3200, 1 },
    // rejected
    { "head.off", HOT::ERROR_WRONG_TOPOLOGY, HOT::Sphere_type, 1487 },      // 3 boundary loops
    { "lion.off", HOT::ERROR_WRONG_TOPOLOGY, HOT::Sphere_type, 7529 },      // 5 boundary loops
    { "blobby_3cc.off", HOT::ERROR_SEVERAL_COMPONENTS, HOT::Sphere_type, 1820 },
    { "cube_quad.off", HOT::ERROR_NON_TRIANGULAR_MESH, HOT::Sphere_type, 8 },
    { "degtri_sliding.off", HOT::ERROR_DEGENERATE_FACE, HOT::Sphere_type, 8 },
    { "cube-ouvert.off", HOT::ERROR_NON_MANIFOLD, HOT::Sphere_type, 9 },    // isolated vertex
  };
  for(const Expected& e : expected) {
    SM sm;
    HOT::Mesh_info info;
    const HOT::Status r = read_and_check(mesh_path(e.name), sm, std::nullopt, &info);
    CHECK_MSG(r.code == e.code, e.name << ": " << r.code << " " << r.message);
    CHECK_MSG(info.number_of_vertices == e.nv, e.name << ": " << info.number_of_vertices << " vertices");
    if(e.code == HOT::OK)
      CHECK_MSG(info.type_known && info.type == e.type && info.genus == e.genus, e.name);
  }
  // files that cannot become a mesh
  SM sm;
  CHECK_RESULT(hot_tools::read_mesh(mesh_path("pig.stl"), sm), HOT::ERROR_NON_MANIFOLD, "non-manifold vertex");
  CHECK_RESULT(hot_tools::read_mesh(mesh_path("polygon_mesh.off"), sm), HOT::ERROR_NON_MANIFOLD, "non-manifold vertex");
  CHECK_RESULT(hot_tools::read_mesh(mesh_path("cube-shuffled.off"), sm), HOT::ERROR_NON_MANIFOLD, "inconsistent face orientation");
  // Polyhedron_3 agrees
  Poly poly;
  HOT::Mesh_info info;
  CHECK_RESULT(read_and_check(mesh_path("mannequin-devil.off"), poly, HOT::Disk_type, &info), HOT::OK, "");
  CHECK(info.number_of_vertices == 12977);
  CHECK_RESULT(read_and_check(mesh_path("elephant.off"), poly, HOT::Sphere_type, &info), HOT::OK, "");
  CHECK(info.genus == 3);
}

// ===========================================================================
// landmarks
// ===========================================================================

TEST_CASE(check_landmarks)
{
  SM octa;
  CHECK(hot_tools::read_mesh(write_file("l_octa.off", octa_off()), octa));
  std::vector<SM::Vertex_index> out;
  CHECK_RESULT(HOT::check_landmarks(octa, { 5, 3, 1, 0, 2 }, HOT::Sphere_type, out), HOT::OK, "");
  CHECK(out.size() == 5 && out[0] == SM::Vertex_index(5) && out[1] == SM::Vertex_index(3));
  CHECK_RESULT(HOT::check_landmarks(octa, { 0, 1, 2, 3 }, HOT::Sphere_type, out), HOT::ERROR_TOO_FEW_LANDMARKS,
               "4 landmarks are given, but the sphere-type orbifold needs at least 5");
  CHECK(out.empty());
  CHECK_RESULT(HOT::check_landmarks(octa, {}, HOT::Disk_type, out), HOT::ERROR_TOO_FEW_LANDMARKS, "0 landmarks");
  CHECK_RESULT(HOT::check_landmarks(octa, { 0, 1, 2, 3, 6 }, HOT::Sphere_type, out), HOT::ERROR_LANDMARK_OUT_OF_RANGE,
               "landmark 4 is vertex 6, but the mesh has only 6 vertices");
  CHECK_RESULT(HOT::check_landmarks(octa, { 0, 1, 2, 3, std::size_t(-1) }, HOT::Sphere_type, out),
               HOT::ERROR_LANDMARK_OUT_OF_RANGE, "landmark 4");
  CHECK_RESULT(HOT::check_landmarks(octa, { 0, 1, 2, 1, 4 }, HOT::Sphere_type, out), HOT::ERROR_DUPLICATE_LANDMARK,
               "vertex 1 is given twice, as landmarks 1 and 3");
  CHECK(out.empty());

  SM fan;
  CHECK(hot_tools::read_mesh(write_file("l_fan.off", hexagon_fan_off()), fan));
  CHECK_RESULT(HOT::check_landmarks(fan, { 1, 2, 3, 4, 5 }, HOT::Disk_type, out), HOT::OK, "");
  CHECK_RESULT(HOT::check_landmarks(fan, { 1, 2, 0, 4, 5 }, HOT::Disk_type, out), HOT::ERROR_LANDMARK_NOT_ON_BORDER,
               "landmark 2 (vertex 0) is not on the boundary loop");
  CHECK_RESULT(HOT::check_landmarks(fan, { 1, 2, 0, 4, 5 }, HOT::Sphere_type, out), HOT::OK, ""); // no border rule

  Poly pfan;
  std::vector<boost::graph_traits<Poly>::vertex_descriptor> pout;
  CHECK(hot_tools::read_mesh(write_file("l_fan_p.off", hexagon_fan_off()), pfan));
  CHECK_RESULT(HOT::check_landmarks(pfan, { 6, 2, 3, 4, 5 }, HOT::Disk_type, pout), HOT::OK, "");
  CHECK(pout.size() == 5 && pout[0]->point() == vertex_point(pfan, 6));
  CHECK_RESULT(HOT::check_landmarks(pfan, { 6, 2, 3, 4, 0 }, HOT::Disk_type, pout), HOT::ERROR_LANDMARK_NOT_ON_BORDER, "vertex 0");
}

TEST_CASE(read_landmarks)
{
  std::vector<std::size_t> ids;
  CHECK_RESULT(hot_tools::read_landmarks(write_file("a.cones.txt", "12\n7\n3\n\n9\n1\n"), ids), HOT::OK, "");
  CHECK((ids == std::vector<std::size_t>{ 12, 7, 3, 9, 1 }));
  CHECK_RESULT(hot_tools::read_landmarks(write_file("line.txt", "  5 4 3\t2 1  \n\n"), ids), HOT::OK, "");
  CHECK((ids == std::vector<std::size_t>{ 5, 4, 3, 2, 1 }));
  CHECK_RESULT(hot_tools::read_landmarks(write_file("crlf.txt", "# cones\r\n1\r\n+2\r\n3 # third\r\n"), ids), HOT::OK, "");
  CHECK((ids == std::vector<std::size_t>{ 1, 2, 3 }));
  CHECK_RESULT(hot_tools::read_landmarks(write_file("bear.selection.txt", "5745 3093 7079\n\n1 2 3 4\n"), ids), HOT::OK, "");
  CHECK((ids == std::vector<std::size_t>{ 5745, 3093, 7079 }));
  CHECK_RESULT(hot_tools::read_landmarks(write_file("faces.selection.txt", "\n1 2 3\n"), ids), HOT::ERROR_READ_FAILED,
               "line 1 of the selection file holds no vertex index");
  CHECK(ids.empty());
  CHECK_RESULT(hot_tools::read_landmarks(write_file("amb.txt", "1 2 3\n4 5\n"), ids), HOT::ERROR_READ_FAILED,
               "line 1: ambiguous layout");
  CHECK_RESULT(hot_tools::read_landmarks(write_file("amb2.txt", "1\n2\n3 4\n"), ids), HOT::ERROR_READ_FAILED, "line 3: ambiguous layout");
  CHECK_RESULT(hot_tools::read_landmarks(write_file("garbage.txt", "1\n2\nfoo\n"), ids), HOT::ERROR_READ_FAILED,
               "line 3: 'foo' is not a vertex index");
  CHECK(ids.empty());
  CHECK_RESULT(hot_tools::read_landmarks(write_file("neg.txt", "1\n-3\n"), ids), HOT::ERROR_READ_FAILED, "line 2: negative vertex index '-3'");
  CHECK_RESULT(hot_tools::read_landmarks(write_file("huge.txt", "1\n99999999999999999999999\n"), ids), HOT::ERROR_READ_FAILED,
               "line 2: vertex index '99999999999999999999999' is too large");
  CHECK_RESULT(hot_tools::read_landmarks(write_file("trail.txt", "12abc\n"), ids), HOT::ERROR_READ_FAILED, "line 1: '12abc' is not");
  CHECK_RESULT(hot_tools::read_landmarks(write_file("float.txt", "1.0\n"), ids), HOT::ERROR_READ_FAILED, "'1.0' is not");
  CHECK_RESULT(hot_tools::read_landmarks(write_file("empty.txt", ""), ids), HOT::ERROR_READ_FAILED, "holds no vertex index");
  CHECK_RESULT(hot_tools::read_landmarks(write_file("blank.txt", " \n# nothing\n"), ids), HOT::ERROR_READ_FAILED, "holds no vertex index");
  CHECK_RESULT(hot_tools::read_landmarks(tmp_dir() + "/nope.txt", ids), HOT::ERROR_READ_FAILED, "no such file");
  const HOT::Status g = hot_tools::read_landmarks(write_file("bin.txt", garbage(300, 7)), ids);
  CHECK(g.code == HOT::ERROR_READ_FAILED && one_line(g));
}

TEST_CASE(landmarks_end_to_end)
{
  // disk mesh: 5 boundary vertices spread along the loop, written one per line
  SM sm;
  CHECK_RESULT(read_and_check(mesh_path("mannequin-devil.off"), sm, HOT::Disk_type), HOT::OK, "");
  HI::Dense_index<SM::Vertex_index> vindex(vertices(sm));
  std::vector<std::size_t> border;
  SM::Halfedge_index h0;
  for(auto h : halfedges(sm))
    if(is_border(h, sm)) { h0 = h; break; }
  for(auto h : CGAL::halfedges_around_face(h0, sm))
    border.push_back(vindex(target(h, sm)));
  std::string file;
  for(int k = 0; k < 5; ++k)
    file += std::to_string(border[k * border.size() / 5]) + "\n";
  std::vector<std::size_t> ids;
  CHECK_RESULT(hot_tools::read_landmarks(write_file("devil.cones.txt", file), ids), HOT::OK, "");
  std::vector<SM::Vertex_index> lm;
  CHECK_RESULT(HOT::check_landmarks(sm, ids, HOT::Disk_type, lm), HOT::OK, "");
  CHECK(lm.size() == 5);
  std::size_t interior = 0;
  for(auto v : vertices(sm)) {
    if(!CGAL::is_border(v, sm))
      break;
    ++interior;
  }
  ids[2] = interior;
  CHECK_RESULT(HOT::check_landmarks(sm, ids, HOT::Disk_type, lm), HOT::ERROR_LANDMARK_NOT_ON_BORDER,
               "landmark 2 (vertex " + std::to_string(interior) + ")");
  ids[2] = 12977;
  CHECK_RESULT(HOT::check_landmarks(sm, ids, HOT::Disk_type, lm), HOT::ERROR_LANDMARK_OUT_OF_RANGE, "vertex 12977");
}

// ===========================================================================
// large meshes: built and checked (their timings are benchmark/bench_input_checks.cpp's,
// run by scripts/benchmark.sh: linear time is measured there, not asserted here)
// ===========================================================================

TEST_CASE(large_meshes_are_built_and_checked)
{
  // a closed genus-0 mesh: the surface of an n x n x n grid cube (6 n^2 + 2 vertices,
  // 12 n^2 triangles)
  const int n = 200;
  const hot_tools::Polygon_soup soup = hot_generated::cube_surface(n);
  SM sm;
  CHECK_RESULT(hot_tools::polygon_soup_to_mesh(soup, sm), HOT::OK, "");
  HOT::Mesh_info info;
  CHECK_RESULT(HOT::check_mesh(sm, HOT::Sphere_type, &info), HOT::OK, "");
  CHECK(info.number_of_vertices == std::size_t(6 * n * n + 2));
  CHECK(num_faces(sm) == std::size_t(12 * n * n));
  CHECK(CGAL::is_valid_polygon_mesh(sm));

  // a fan of 200K triangles around one vertex (a disk; Euler::add_face would be quadratic
  // here, the builder is not: benchmark/bench_input_checks.cpp times it)
  const std::size_t k = 200000;
  const hot_tools::Polygon_soup fan = hot_generated::fan(k);
  CHECK_RESULT(hot_tools::polygon_soup_to_mesh(fan, sm), HOT::OK, "");
  CHECK(num_vertices(sm) == k + 2 && num_faces(sm) == k);
  CHECK_RESULT(HOT::check_mesh(sm, HOT::Disk_type), HOT::OK, "");
  std::vector<SM::Vertex_index> lm;
  CHECK_RESULT(HOT::check_landmarks(sm, { 0, 1, 1000, 100000, k + 1 }, HOT::Disk_type, lm), HOT::OK, "");
  CHECK(lm.size() == 5);
}

// ===========================================================================
// numbers written and read: the writers' numbers are the bytes of printf("%.17g"),
// the readers' fast paths give the doubles of strtod; the embedding OBJ's bytes are those
// of the former std::ostream writer
// ===========================================================================

namespace {

// doubles to write: edge cases, powers of 2 and 10 with their neighbours, integers, random
// bit patterns (all exponents, NaNs and infinities among them) and random points of the disk
std::vector<double> number_writer_values()
{
  const double inf = std::numeric_limits<double>::infinity(), nan = std::numeric_limits<double>::quiet_NaN();
  std::vector<double> v = { 0.0, -0.0, 1.0, -1.0, 0.1, -0.1, 1.0 / 3, 2.0 / 3, 0.5, 1e-5, 1e-4, 9.9999999999999995e-5,
                            1e15, 1e16, 1e17, 1e22, 1e23, 123456789012345678.0, 9007199254740992.0, 9007199254740993.0,
                            99999999999999999.0, 12345678901234567.0, 0.30000000000000004,
                            std::numeric_limits<double>::min(), std::numeric_limits<double>::max(),
                            std::numeric_limits<double>::denorm_min(), -std::numeric_limits<double>::denorm_min(),
                            std::numeric_limits<double>::epsilon(), 2.2250738585072009e-308, inf, -inf, nan, -nan };
  for(int e = -1074; e <= 1023; ++e)
    for(double s : { 1.0, -1.0 }) {
      const double x = s * std::ldexp(1.0, e);
      v.insert(v.end(), { x, std::nextafter(x, 0.0), std::nextafter(x, s * inf) });
    }
  for(int e = -323; e <= 308; ++e) {
    const double x = std::strtod(("1e" + std::to_string(e)).c_str(), nullptr);
    v.insert(v.end(), { x, -x, std::nextafter(x, 0.0), std::nextafter(x, inf), 5 * x, 9.5 * x });
  }
  for(int i = -1000; i <= 1000; ++i)
    v.push_back(i);
  std::mt19937_64 rng(20260101);
  for(int i = 0; i < 200000; ++i) {
    const std::uint64_t bits = rng();
    double x;
    std::memcpy(&x, &bits, 8);
    v.push_back(x);
  }
  std::uniform_real_distribution<double> disk(-1, 1);
  for(int i = 0; i < 100000; ++i)
    v.push_back(disk(rng));
  // the writer's exact fast path (1e-6 <= |x| < 1e17) and around it: random mantissas of every
  // binary exponent from 2^-30 to 2^70, exact ties of the 17th digit (short binary fractions
  // m 2^-s: printf rounds them to even), 10^k and its neighbours
  for(int i = 0; i < 200000; ++i) {
    const std::uint64_t m = (rng() & ((std::uint64_t(1) << 52) - 1)) | (std::uint64_t(1) << 52);
    const double x = std::ldexp(double(m), int(rng() % 100) - 30 - 52);
    v.push_back(i % 2 ? x : -x);
  }
  for(int i = 0; i < 50000; ++i) {
    const double m = double(1 + 2 * (rng() % 100000));
    v.insert(v.end(), { std::ldexp(m, -int(rng() % 80)), std::ldexp(m, int(rng() % 40)) });
  }
  for(int k = -8; k <= 18; ++k) {
    double up = std::pow(10.0, k), down = up;
    for(int j = 0; j < 30; ++j, up = std::nextafter(up, inf), down = std::nextafter(down, 0.0))
      v.insert(v.end(), { up, -up, down, -down });
  }
  return v;
}

} // namespace

TEST_CASE(number_writer)
{
  // write_double() (application/hot_app/io/text_buffer.h: its exact 128-bit fast path, else std::to_chars)
  // gives the bytes of printf("%.17g") and of an std::ostream with precision 17 (the former
  // writer's), and strtod and our reader read the same double back
  const std::vector<double> values = number_writer_values();
  std::size_t printf_mismatches = 0, stream_mismatches = 0, round_trip_failures = 0;
  std::string first;
  for(std::size_t i = 0; i < values.size(); ++i) {
    const double x = values[i];
    char expected[64], ours[64];
    std::snprintf(expected, sizeof(expected), "%.17g", x);
    *hot_tools::io_impl::write_double(ours, x) = '\0';
    if(std::strcmp(expected, ours) != 0 && printf_mismatches++ == 0)
      first = std::string("printf '") + expected + "', to_chars '" + ours + "'";
    if(i % 8 == 0) { // the former writer: an std::ostream with precision 17
      std::ostringstream os;
      os.precision(17);
      os << x;
      if(os.str() != ours && stream_mismatches++ == 0)
        first = "ostream '" + os.str() + "', to_chars '" + ours + "'";
    }
    if(std::isfinite(x)) { // 17 digits give the double back, to strtod and to our reader
      double back = 0;
      const double b = std::strtod(ours, nullptr);
      if((!hot_tools::io_impl::parse_real(ours, back) || std::memcmp(&back, &x, 8) != 0 || std::memcmp(&b, &x, 8) != 0) &&
         round_trip_failures++ == 0)
        first = std::string("round trip of '") + ours + "'";
    }
  }
  hot_tools::io_impl::Text_buffer t; // the buffer's integers and doubles
  t.put("v ").put(-0.0).put(' ').put(std::size_t(18446744073709551615ull)).put(' ').put(-9223372036854775807ll - 1).put(' ').put(-1)
    .put(' ').put(0.1).put('\n');
  CHECK_MSG(std::string(t.data(), t.size()) == "v -0 18446744073709551615 -9223372036854775808 -1 0.10000000000000001\n",
            std::string(t.data(), t.size()));
  CHECK_MSG(values.size() > 600000, values.size());
  CHECK_MSG(printf_mismatches == 0, printf_mismatches << " of " << values.size() << " differ from printf(\"%.17g\"), first: " << first);
  CHECK_MSG(stream_mismatches == 0, stream_mismatches << " differ from std::ostream, first: " << first);
  CHECK_MSG(round_trip_failures == 0, round_trip_failures << " do not round-trip, first: " << first);
}

TEST_CASE(reader_numbers_match_strtod)
{
  // random decimal strings (signs, leading and trailing dots, exponents beyond the range of
  // double, long mantissas) as coordinates of OFF, OBJ and ASCII PLY files: the readers (their
  // fast paths, and the general path where a '+' sends them) give exactly strtod's doubles
  std::mt19937_64 rng(7);
  auto digits = [&](int n) {
    std::string d;
    for(int i = 0; i < n; ++i)
      d += char('0' + rng() % 10);
    return d;
  };
  std::vector<std::string> numbers = { "0", "-0", "1e400", "-1e400", "1e-400", "4.9406564584124654e-324", "2e-324",
                                       "2.2250738585072011e-308", "1.7976931348623157e308", "1.7976931348623159e308",
                                       "nan", "inf", "-inf", "+1.5", "0.1", ".5", "5.", "-.5e-3", "1E5", "+0" };
  for(int i = 0; i < 60000; ++i) {
    std::string s;
    const int sign = int(rng() % 10);
    if(sign == 0) s += '-';
    if(sign == 1 && i % 50 == 0) s += '+';
    const int n = 1 + int(rng() % 25), dot = int(rng() % (n + 2));
    const std::string m = digits(n);
    s += dot <= n ? m.substr(0, std::size_t(dot)) + "." + m.substr(std::size_t(dot)) : m;
    if(s.back() == '.' && s.size() == 1) s += '0';
    if(rng() % 3 != 0) {
      s += (rng() % 2) ? 'e' : 'E';
      const int e = int(rng() % 700) - 350;
      s += (e >= 0 && rng() % 2) ? "+" + std::to_string(e) : std::to_string(e);
    }
    numbers.push_back(s);
  }
  while(numbers.size() % 3 != 0)
    numbers.push_back("1");
  const std::size_t np = numbers.size() / 3;
  std::string off = "OFF\n" + std::to_string(np) + " 1 0\n", obj, ply = "ply\nformat ascii 1.0\nelement vertex " + std::to_string(np) +
    "\nproperty double x\nproperty double y\nproperty double z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";
  for(std::size_t i = 0; i < np; ++i) {
    const std::string line = numbers[3 * i] + " " + numbers[3 * i + 1] + " " + numbers[3 * i + 2] + "\n";
    off += line;
    obj += "v " + line;
    ply += line;
  }
  off += "3 0 1 2\n";
  obj += "f 1 2 3\n";
  ply += "3 0 1 2\n";
  const std::string files[3][2] = { { "numbers.off", off }, { "numbers.obj", obj }, { "numbers.ply", ply } };
  for(const auto& f : files) {
    hot_tools::Polygon_soup soup;
    CHECK_RESULT(hot_tools::read_polygon_soup_file(write_file(f[0], f[1]), soup), HOT::OK, "");
    std::size_t mismatches = 0;
    std::string first;
    for(std::size_t i = 0; i < numbers.size() && soup.points.size() == np; ++i) {
      const double expected = std::strtod(numbers[i].c_str(), nullptr), got = soup.points[i / 3][i % 3];
      if(std::memcmp(&expected, &got, 8) != 0 && !(std::isnan(expected) && std::isnan(got)) && mismatches++ == 0)
        first = numbers[i];
    }
    CHECK_MSG(soup.points.size() == np && mismatches == 0, f[0] << ": " << mismatches << " numbers differ from strtod's, first '" << first << "'");
  }
}

namespace {

// the bytes of the OBJ writer and of the former one (test/reference_embedding_obj.h)
template <class UV, class Charts = std::nullptr_t>
void check_same_obj_bytes(const std::string& what, const SM& m, const UV& uv, const hot_tools::Input_mesh* in = nullptr,
                          const hot_tools::Embedding_charts<Charts>* charts = nullptr, const hot_tools::Embedding_cones* cones = nullptr)
{
  std::ostringstream now, before;
  hot_tools::write_embedding_obj(now, m, uv, in, charts, cones);
  hot_reference::reference_write_embedding_obj(before, m, uv, in, charts, cones);
  const std::string a = now.str(), b = before.str();
  std::size_t at = 0;
  while(at < a.size() && at < b.size() && a[at] == b[at])
    ++at;
  CHECK_MSG(a == b, what << ": the OBJ differs from the former writer's at byte " << at << " of " << b.size() << ": '"
                         << a.substr(at < 40 ? 0 : at - 40, 80) << "' vs '" << b.substr(at < 40 ? 0 : at - 40, 80) << "'");
  CHECK_MSG(a.size() > std::size_t(60 * num_faces(m)), what << ": " << a.size() << " bytes");
}

} // namespace

TEST_CASE(embedding_obj_bytes)
{
  typedef SM::Property_map<SM::Halfedge_index, K::Point_2> UV;
  // a real embedding (seams: vertices with several vt)
  {
    SM m;
    CHECK_RESULT(read_and_check(mesh_path("hand.off"), m, HOT::Sphere_type), HOT::OK, "");
    const auto landmarks = HOT::select_landmarks(m, 7);
    UV uv = m.add_property_map<SM::Halfedge_index, K::Point_2>("h:uv").first;
    HOT::Embedding_statistics st;
    CHECK(HOT::hyperbolic_orbifold_Tutte_embedding(m, landmarks, uv, HOT::parameters::embedding_statistics(&st)) == HOT::OK);
    hot_tools::Embedding_cones cones;
    cones.landmark = st.landmark_order;
    for(std::size_t i : st.landmark_order) {
      cones.vertex.push_back(landmarks[i].idx());
      cones.order.push_back(2);
    }
    check_same_obj_bytes("hand.off", m, uv, nullptr, static_cast<const hot_tools::Embedding_charts<std::nullptr_t>*>(nullptr), &cones);
  }
  // bear.off (several blocks of lines: formatted in parallel with TBB), synthetic points with
  // seams, charts, and numbers of every size
  {
    SM m;
    CHECK_RESULT(read_and_check(mesh_path("bear.off"), m, HOT::Sphere_type), HOT::OK, "");
    UV uv = m.add_property_map<SM::Halfedge_index, K::Point_2>("h:uv").first;
    typedef SM::Property_map<SM::Halfedge_index, HOT::Chart_point<K::Point_2> > Chart_map;
    Chart_map cm = m.add_property_map<SM::Halfedge_index, HOT::Chart_point<K::Point_2> >("h:chart").first;
    std::mt19937_64 rng(3);
    for(SM::Face_index f : faces(m))
      for(SM::Halfedge_index h : halfedges_around_face(halfedge(f, m), m)) {
        const K::Point_3& p = m.point(target(h, m));
        const double s = f.idx() % 5 == 0 ? 0.8 : (f.idx() % 17 == 0 ? 1e-300 : 0.9);
        put(uv, h, K::Point_2(s * p.x() / 400, (f.idx() % 101 == 0 ? -0.0 : s * p.y() / 400)));
        if(target(h, m).idx() % 50 == 0)
          put(cm, h, HOT::Chart_point<K::Point_2>{ int(target(h, m).idx() % 3), K::Point_2(p.z() * 1e-120, 1.0 / (1 + f.idx())) });
      }
    check_same_obj_bytes("bear.off", m, uv);
    hot_tools::Embedding_charts<Chart_map> charts{ cm, {}, { 0, 4 } };
    for(int i = 0; i < 3; ++i)
      charts.charts.emplace_back(std::complex<double>(1.0 + i / 3.0, -0.25), std::complex<double>(0.5 / (i + 1), 1e-17 * i));
    check_same_obj_bytes("bear.off with charts", m, uv, nullptr, &charts);
  }
  // a prepared mesh (--repair): the file's vertices, then the added ones
  {
    SM m;
    hot_tools::Input_mesh in;
    hot_tools::Repair_options opt;
    opt.repair = true;
    HOT::Mesh_info info;
    CHECK_RESULT(hot_tools::read_input_mesh(mesh_path("mannequin-devil.off"), std::nullopt, opt, m, in, &info), HOT::OK, "");
    CHECK(num_vertices(m) > in.file_points.size()); // (its boundary chords are split)
    UV uv = m.add_property_map<SM::Halfedge_index, K::Point_2>("h:uv").first;
    for(SM::Halfedge_index h : halfedges(m))
      put(uv, h, K::Point_2(std::sin(double(h.idx())), std::cos(double(target(h, m).idx())) / 3));
    check_same_obj_bytes("mannequin-devil.off prepared", m, uv, &in);
  }
}

// ===========================================================================
// regressions of the hostile-input corpus (test/test_hostile_inputs.sh) and of the
// fuzz target (fuzz/fuzz_mesh_reader.cpp)
// ===========================================================================

// GOCAD TSurf: our parser (CGAL::IO::read_GOCAD() computed indices as int offsets from
// the file's ids: signed overflow, i.e. undefined behaviour, on the id -2147483648)
TEST_CASE(gocad_parser)
{
  SM sm;
  const std::string head = "GOCAD TSurf 1\nHEADER {\nname:t\n}\nTFACE\n";
  // the ids that overflowed in CGAL's reader
  CHECK_RESULT(read_text("int_min.ts", head + "VRTX -2147483648 0 0 0\nVRTX -2147483647 1 0 0\nVRTX -2147483646 0 1 0\n"
                                              "TRGL -2147483648 -2147483647 -2147483646\nEND\n", sm), HOT::OK, "");
  CHECK(num_vertices(sm) == 3 && num_faces(sm) == 1 && vertex_point(sm, 1) == Point(1, 0, 0));
  // ids are ids: not consecutive, triangles before vertices, PVRTX with properties, ATOM
  const std::string ids = head + "TRGL 10 30 20\nVRTX 10 0 0 0\nPVRTX 20 1 0 0 7.5 8\nVRTX 30 0 1 0\nVRTX 40 0 0 1\n"
                                 "ATOM 41 40\nTRGL 10 20 41\nTRGL 10 40 30\nTFACE\nTRGL 20 30 40\nBSTONE 10\nEND\nanything\n";
  HOT::Mesh_info info;
  CHECK_RESULT(read_and_check(write_file("ids.ts", ids), sm, HOT::Sphere_type, &info), HOT::OK, "");
  CHECK(num_vertices(sm) == 4 && vertex_point(sm, 3) == Point(0, 0, 1));
  std::vector<Point> pts;
  std::vector<std::vector<std::size_t> > fcs;
  mesh_to_soup(sm, pts, fcs);
  CHECK((fcs == std::vector<std::vector<std::size_t> >{ { 0, 2, 1 }, { 0, 1, 3 }, { 0, 3, 2 }, { 1, 2, 3 } }));
  // errors, each with its reason and line
  check_unreadable(sm, head, {
    { "noend.ts", "VRTX 1 0 0 0\n", "the file ends without END (truncated file?)" },
    { "twice.ts", "VRTX 1 0 0 0\nVRTX 1 1 0 0\nEND\n", "line 7: vertex id 1 is defined twice" },
    { "undef.ts", "VRTX 1 0 0 0\nTRGL 1 2 3\nEND\n", "line 7: triangle 0: vertex id 2 is not defined" },
    { "atom.ts", "ATOM 2 1\nEND\n", "line 6: ATOM 2 refers to vertex id 1, which is not defined before it" },
    { "bigid.ts", "VRTX 99999999999999999999 0 0 0\nEND\n", "line 6: vertex id '99999999999999999999' is too large" },
    { "badid.ts", "VRTX one 0 0 0\nEND\n", "line 6: 'one' is not a vertex id" },
    { "short.ts", "VRTX 1 0 0\nEND\n", "line 6: vertex 0: 'VRTX id x y z' expected, 3 fields found" },
    { "coord.ts", "VRTX 1 0 zero 0\nEND\n", "coordinate 'zero' is not a number" },
    { "trgl.ts", "TRGL 1 2\nEND\n", "line 6: triangle 0: 'TRGL a b c' expected" },
    { "kw.ts", "FROB 1\nEND\n", "line 6: unknown GOCAD TSurf keyword 'FROB'" },
  });
  CHECK_RESULT(read_text("nan.ts", head + "VRTX 1 0 0 0\nVRTX 2 nan 0 0\nVRTX 3 0 1 0\nTRGL 1 2 3\nEND\n", sm),
               HOT::ERROR_NON_FINITE_COORDINATES, "vertex 1 (line 7) has a non-finite coordinate");
  CHECK_RESULT(read_text("notface.ts", "GOCAD PLine 1\nVRTX 1 0 0 0\nEND\n", sm), HOT::ERROR_READ_FAILED, "no TFACE line");
  // every prefix of a valid file that stops before END is an error
  const std::string full = head + "VRTX 0 0 0 0\nVRTX 1 1 0 0\nVRTX 2 0 1 0\nVRTX 3 0 0 1\n"
                                  "TRGL 0 2 1\nTRGL 0 1 3\nTRGL 0 3 2\nTRGL 1 2 3\nEND\n";
  CHECK_RESULT(read_and_check(write_file("full.ts", full), sm, HOT::Sphere_type), HOT::OK, "");
  int not_failed = 0;
  for(std::size_t n = 0; n < full.rfind("END"); ++n)
    if(read_text("prefix.ts", full.substr(0, n), sm).code != HOT::ERROR_READ_FAILED)
      ++not_failed;
  CHECK_MSG(not_failed == 0, not_failed << " prefixes of a valid GOCAD file were not READ_FAILED");
}

// a face repeated with the same cyclic order: its own reason (it used to be reported as a
// non-manifold edge or an inconsistent orientation)
TEST_CASE(duplicated_faces)
{
  SM sm;
  const std::string v = "OFF\n5 4 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0.5 0.5 1\n";
  CHECK_RESULT(read_text("rot.off", v + "3 0 1 4\n3 1 2 4\n3 4 0 1\n3 2 3 4\n", sm), HOT::ERROR_NON_MANIFOLD,
               "duplicated face: face 2 (line 10) repeats face 0 (line 8) (the same vertices in the same order)");
  CHECK(num_vertices(sm) == 0);
  CHECK_RESULT(read_text("quad.off", v + "4 0 1 2 3\n3 0 1 4\n4 2 3 0 1\n3 2 3 4\n", sm), HOT::ERROR_NON_MANIFOLD,
               "face 2 (line 10) repeats face 0 (line 8)");
  // the same vertices in another order are not a repetition
  std::string other = v + "4 0 1 2 3\n4 0 2 1 3\n";
  other.replace(other.find("5 4 0"), 5, "5 2 0");
  CHECK_RESULT(read_text("other.off", other, sm), HOT::ERROR_NON_MANIFOLD, "inconsistent face orientation");
  CHECK_RESULT(read_text("fan.off", v + "3 0 1 4\n3 1 2 4\n3 2 3 4\n3 3 0 4\n", sm), HOT::OK, "");
  // binary STL: a triangle written twice
  std::string stl = binary_stl_tetra(5);
  stl += stl.substr(84, 50);
  CHECK_RESULT(read_text("twice.stl", stl, sm), HOT::ERROR_NON_MANIFOLD, "duplicated face: face 4 repeats face 0");
  // many faces (hash chains): a closed mesh has no false positive
  HOT::Mesh_info info;
  CHECK_RESULT(read_and_check(write_file("torus_dup.off", torus_off(40)), sm, std::nullopt, &info), HOT::OK, "");
  CHECK(info.genus == 1 && info.number_of_faces == 2 * 40 * 40);
}

// ASCII PLY: the line of a vertex or a face is the line where the record starts (it was
// the line of the previous record)
TEST_CASE(ply_record_lines)
{
  SM sm;
  const std::string head = "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
                           "element face 4\nproperty list uchar int vertex_indices\nend_header\n";
  // line 10: vertex 0, ..., line 14: face 0
  CHECK_RESULT(read_text("range.ply", head + tetra_vertices + "3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 9\n", sm),
               HOT::ERROR_READ_FAILED, "face 3 (line 17): vertex index 9 is out of range (the file has 4 vertices)");
  CHECK_RESULT(read_text("nan.ply", head + "0 0 0\n1 0 0\n\n\n0 nan 0\n0 0 1\n" + tetra_faces, sm),
               HOT::ERROR_NON_FINITE_COORDINATES, "vertex 2 (line 14) has a non-finite coordinate");
  CHECK_RESULT(read_text("rep.ply", head + tetra_vertices + "3 0 2 1\n3 0 1 3\n\n3 0 3 3\n3 1 2 3\n", sm),
               HOT::ERROR_DEGENERATE_FACE, "face 2 (line 17) is degenerate: it uses vertex 3 more than once");
}

// coordinates so large or so small that squared lengths or areas overflow or underflow in
// double precision: their own reason (the embedding used to fail with "the landmark tour
// could not be computed" or "a sparse linear system could not be solved")
TEST_CASE(coordinate_range)
{
  auto scaled_octa = [](double s, int far_vertex = -1, double far = 0) {
    std::ostringstream os;
    os.precision(17);
    os << "OFF\n6 8 0\n";
    const double c[6][3] = { { 1, 0, 0 }, { -1, 0, 0 }, { 0, 1, 0 }, { 0, -1, 0 }, { 0, 0, 1 }, { 0, 0, -1 } };
    for(int i = 0; i < 6; ++i) {
      const double f = (i == far_vertex) ? far : s;
      os << c[i][0] * f << " " << c[i][1] * f << " " << c[i][2] * f << "\n";
    }
    for(const std::string& f : octa_faces)
      os << f << "\n";
    return os.str();
  };
  SM sm;
  CHECK_RESULT(read_and_check(write_file("s1e308.off", scaled_octa(1e308)), sm, HOT::Sphere_type), HOT::ERROR_NON_FINITE_COORDINATES,
               "face 0 is out of the range of double-precision geometry: its squared edge lengths overflow (coordinates too large");
  CHECK_RESULT(read_and_check(write_file("s1e100.off", scaled_octa(1e100)), sm, HOT::Sphere_type), HOT::ERROR_NON_FINITE_COORDINATES,
               "its longest edge has length 1.41e+100, so its squared area overflows (coordinates too large: rescale the mesh)");
  CHECK_RESULT(read_and_check(write_file("s1e-100.off", scaled_octa(1e-100)), sm, HOT::Sphere_type), HOT::ERROR_NON_FINITE_COORDINATES,
               "its longest edge has length 1.41e-100, so its squared area underflows (coordinates too small: rescale the mesh)");
  CHECK_RESULT(read_and_check(write_file("s1e-310.off", scaled_octa(1e-310)), sm, HOT::Sphere_type), HOT::ERROR_NON_FINITE_COORDINATES,
               "its longest edge has length 1.41e-310, so its squared area underflows");
  // one far vertex in a normal mesh: the faces around it
  CHECK_RESULT(read_and_check(write_file("far.off", scaled_octa(1, 5, 1e100)), sm, HOT::Sphere_type), HOT::ERROR_NON_FINITE_COORDINATES,
               "face 4 is out of the range of double-precision geometry: its longest edge has length 1e+100, so its squared area overflows");
  CHECK_RESULT(read_and_check(write_file("far2.off", scaled_octa(1, 5, 1e200)), sm, HOT::Sphere_type), HOT::ERROR_NON_FINITE_COORDINATES,
               "face 4 is out of the range of double-precision geometry: its squared edge lengths overflow");
  // within the range: fine
  for(double s : { 1e76, 1e-76, 1e-30, 1e30 })
    CHECK_RESULT(read_and_check(write_file("s_ok.off", scaled_octa(s)), sm, HOT::Sphere_type), HOT::OK, "");
  // a thin face of normal size is not a range problem
  CHECK_RESULT(read_and_check(write_file("thin2.off", std::string("OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n2 1e-300 0\n") + tetra_faces),
                              sm, HOT::Sphere_type), HOT::OK, "");
  // Polyhedron_3 and the error message's code
  Poly poly;
  CHECK_RESULT(read_and_check(write_file("p1e100.off", scaled_octa(1e100)), poly, HOT::Sphere_type),
               HOT::ERROR_NON_FINITE_COORDINATES, "squared area overflows");
  CHECK(contains(HOT::error_message(HOT::ERROR_NON_FINITE_COORDINATES), "too large or too small for double precision"));
}

// a sphere-type mesh cut open by an unwelded duplicate vertex: the topology message names it
TEST_CASE(coincident_border_vertices)
{
  // octahedron; vertex 6 repeats vertex 0 in faces 0 and 4 (adjacent around vertex 0)
  std::string seam = "OFF\n7 8 0\n" + std::string(octa_vertices) + "1 0 0\n";
  for(std::size_t i = 0; i < octa_faces.size(); ++i) {
    std::string f = octa_faces[i];
    if(i == 0 || i == 4)
      f = (i == 0) ? "3 6 2 4" : "3 2 6 5";
    seam += f + "\n";
  }
  SM sm;
  CHECK_RESULT(read_and_check(write_file("seam.off", seam), sm, HOT::Sphere_type), HOT::ERROR_WRONG_TOPOLOGY,
               "but the mesh has 1 boundary loop (border vertices 0 and 6 have the same coordinates: duplicated vertices that should be one?)");
  // as a disk it is a valid mesh (a surface cut open, as duplicate_points_allowed)
  HOT::Mesh_info info;
  CHECK_RESULT(HOT::check_mesh(sm, std::nullopt, &info), HOT::OK, "");
  CHECK(info.type == HOT::Disk_type);
  // boundary loops without coincident vertices: no such hint
  const HOT::Status r = read_and_check(write_file("annulus_h.off", octa_off({ 0, 6 })), sm, std::nullopt);
  CHECK(r.code == HOT::ERROR_WRONG_TOPOLOGY && !contains(r.message, "same coordinates"));
  // two disks touching at duplicated border points
  const std::string two = "OFF\n6 2 0\n0 0 0\n1 0 0\n0 1 0\n1 0 0\n0 1 0\n1 1 0\n3 0 1 2\n3 3 5 4\n";
  CHECK_RESULT(read_and_check(write_file("two_tris.off", two), sm, std::nullopt), HOT::ERROR_SEVERAL_COMPONENTS, "2 connected components");
}

// the reading + checking path of the command-line program (and of the fuzz target)
TEST_CASE(read_and_check_path)
{
  SM sm;
  HOT::Mesh_info info;
  // no face, automatic type: "no face" (it used to be "neither closed nor a disk")
  const std::string nofaces = write_file("rc_nofaces.off", "OFF\n3 0 0\n0 0 0\n1 0 0\n0 1 0\n");
  CHECK_RESULT(hot_tools::read_and_check_mesh(nofaces, std::nullopt, sm, &info), HOT::ERROR_EMPTY_MESH,
               nofaces + ": the mesh has no face (it has 3 vertices but no face)");
  // two disks: several components, not "neither closed nor a disk"
  const std::string two = write_file("rc_two.off", "OFF\n6 2 0\n0 0 0\n1 0 0\n0 1 0\n5 0 0\n6 0 0\n5 1 0\n3 0 1 2\n3 3 4 5\n");
  CHECK_RESULT(hot_tools::read_and_check_mesh(two, std::nullopt, sm, &info), HOT::ERROR_SEVERAL_COMPONENTS, "rc_two.off: the mesh has 2");
  // reading errors keep their own prefix; the type is detected or required
  CHECK_RESULT(hot_tools::read_and_check_mesh(tmp_dir() + "/rc_none.off", std::nullopt, sm), HOT::ERROR_READ_FAILED, "rc_none.off': no such file");
  const std::string fan = write_file("rc_fan.off", hexagon_fan_off());
  CHECK_RESULT(hot_tools::read_and_check_mesh(fan, std::nullopt, sm, &info), HOT::OK, "");
  CHECK(info.type_known && info.type == HOT::Disk_type);
  CHECK_RESULT(hot_tools::read_and_check_mesh(fan, HOT::Sphere_type, sm, &info), HOT::ERROR_WRONG_TOPOLOGY, "rc_fan.off: the sphere-type");
  CHECK_RESULT(hot_tools::read_and_check_mesh(fan, HOT::Disk_type, sm, &info), HOT::OK, "");
  // landmarks: the file name, then the reason; refused landmarks are not returned
  std::vector<SM::Vertex_index> lm;
  const std::string inner = write_file("rc_inner.txt", "1 2 0 4 5\n");
  CHECK_RESULT(hot_tools::read_and_check_landmarks(inner, sm, HOT::Disk_type, lm), HOT::ERROR_LANDMARK_NOT_ON_BORDER,
               inner + ": landmark 2 (vertex 0) is not on the boundary loop");
  CHECK(lm.empty());
  CHECK_RESULT(hot_tools::read_and_check_landmarks(write_file("rc_ok.txt", "6\n2\n3\n4\n5\n"), sm, HOT::Disk_type, lm), HOT::OK, "");
  CHECK(lm.size() == 5 && lm[0] == SM::Vertex_index(6));
  // a bad token is reported before the layout (binary garbage used to be an "ambiguous layout")
  CHECK_RESULT(hot_tools::read_and_check_landmarks(write_file("rc_tok.txt", "1 2 x\n3 4\n"), sm, HOT::Disk_type, lm),
               HOT::ERROR_READ_FAILED, "line 1: 'x' is not a vertex index");
  const HOT::Status g = hot_tools::read_and_check_landmarks(write_file("rc_bin.txt", garbage(500, 3)), sm, HOT::Disk_type, lm);
  CHECK_MSG(g.code == HOT::ERROR_READ_FAILED && !contains(g.message, "ambiguous") && one_line(g), g.message);
  CHECK_RESULT(hot_tools::read_and_check_landmarks(write_file("rc_amb.txt", "1 2 3\n4 5\n"), sm, HOT::Disk_type, lm),
               HOT::ERROR_READ_FAILED, "line 1: ambiguous layout");

  // the one-call embedding of the library gives check_mesh()'s reason too when the type
  // cannot be detected (it used to say "neither closed nor a disk" for an empty mesh)
  SM empty;
  auto uv = empty.add_property_map<SM::Halfedge_index, K::Point_2>("h:uv").first;
  HOT::Embedding_statistics st;
  CHECK(HOT::hyperbolic_orbifold_Tutte_embedding(empty, std::vector<SM::Vertex_index>(), uv,
                                                 HOT::parameters::embedding_statistics(&st)) == HOT::ERROR_EMPTY_MESH);
  CHECK_MSG(contains(st.message, "the mesh has no face"), st.message);
  SM disks;
  CHECK(hot_tools::read_mesh(two, disks));
  auto uv2 = disks.add_property_map<SM::Halfedge_index, K::Point_2>("h:uv").first;
  CHECK(HOT::hyperbolic_orbifold_Tutte_embedding(disks, std::vector<SM::Vertex_index>(), uv2,
                                                 HOT::parameters::embedding_statistics(&st)) == HOT::ERROR_SEVERAL_COMPONENTS);
  SM annulus;
  CHECK(hot_tools::read_mesh(write_file("rc_annulus.off", octa_off({ 0, 6 })), annulus));
  auto uv3 = annulus.add_property_map<SM::Halfedge_index, K::Point_2>("h:uv").first;
  CHECK(HOT::hyperbolic_orbifold_Tutte_embedding(annulus, std::vector<SM::Vertex_index>(), uv3,
                                                 HOT::parameters::embedding_statistics(&st)) == HOT::ERROR_WRONG_TOPOLOGY);
  CHECK_MSG(contains(st.message, "2 boundary loops"), st.message);
  // and so does the certificate
  HOT::Embedding_certificate cert;
  std::string msg;
  CHECK(HOT::certify_hyperbolic_orbifold_embedding(empty, std::vector<SM::Vertex_index>(), uv, cert, &msg) == HOT::ERROR_EMPTY_MESH);
  CHECK_MSG(contains(msg, "the mesh has no face"), msg);
  CHECK(HOT::certify_hyperbolic_orbifold_embedding(disks, std::vector<SM::Vertex_index>(), uv2, cert, &msg)
        == HOT::ERROR_SEVERAL_COMPONENTS);
}

// Inputs for the fuzz target, in its layout (byte 0: selector, bytes 1-2: landmark length,
// mesh file, landmark file), run through the same calls and contract checks: every input
// that made the target crash, leak, hit undefined behaviour or break the contract.
namespace {

void run_fuzz_input(const std::string& name, const std::string& input)
{
  if(input.size() < 3)
    return;
  static const char* const extensions[] = { "off", "obj", "ply", "stl", "ts" };
  const unsigned s = static_cast<unsigned char>(input[0]);
  std::optional<HOT::Orbifold_type> type;
  if((s / 5) % 3 == 1) type = HOT::Sphere_type;
  if((s / 5) % 3 == 2) type = HOT::Disk_type;
  const std::size_t rest = input.size() - 3;
  const std::size_t L = (std::min)(std::size_t(static_cast<unsigned char>(input[1]))
                                   | (std::size_t(static_cast<unsigned char>(input[2])) << 8), rest);
  const std::string mesh = write_file(name + "." + extensions[s % 5], input.substr(3, rest - L));
  const std::string cones = write_file(name + ((s / 15) % 2 ? ".selection.txt" : ".txt"), input.substr(3 + rest - L));
  SM sm;
  HOT::Mesh_info info;
  const HOT::Status r = hot_tools::read_and_check_mesh(mesh, type, sm, &info);
  CHECK_MSG(r.code >= 0 && r.code < HOT::number_of_error_codes && one_line(r) && (r || !r.message.empty()), name << ": " << r.message);
  if(!r)
    return;
  CHECK_MSG(info.type_known && CGAL::is_valid_polygon_mesh(sm), name);
  std::vector<SM::Vertex_index> lm;
  const HOT::Status rl = hot_tools::read_and_check_landmarks(cones, sm, info.type, lm);
  CHECK_MSG(one_line(rl) && (rl || (!rl.message.empty() && lm.empty())), name << ": " << rl.message);
  CHECK_MSG(!rl || std::set<SM::Vertex_index>(lm.begin(), lm.end()).size() == lm.size(), name);
}

} // namespace

TEST_CASE(fuzz_regressions)
{
  // UndefinedBehaviorSanitizer in CGAL::IO::read_GOCAD() (GOCAD.h:123, "signed integer
  // overflow: 0 - -2147483648 cannot be represented in type 'int'"), through the .ts path of
  // read_mesh(); fixed by our GOCAD parser
  const std::string gocad = "GOCAD TSurf 1\nHEADER {\nname:x\n}\nTFACE\nVRTX -2147483648 0 0 0\nVRTX -2147483647 1 0 0\n"
                            "VRTX -2147483646 0 1 0\nTRGL -2147483648 -2147483647 -2147483646\nEND\n";
  run_fuzz_input("fuzz_gocad_int_min", std::string("\x04\x09\x00", 3) + gocad + "0 1 2 3 4");
  SM sm;
  CHECK_RESULT(hot_tools::read_mesh(tmp_dir() + "/fuzz_gocad_int_min.ts", sm), HOT::OK, "");
  CHECK(num_vertices(sm) == 3 && num_faces(sm) == 1);
}

TEST_CASE(landmark_and_cone_order_checks)
{
  // check_cone_orders() (landmark_checks.h), the check of every entry point, in its order:
  // the number, the orders of at least 2, then (with a signature) hyperbolicity
  HOT::Cone_order_check c;
  CHECK(HOT::check_cone_orders(std::vector<int>{2, 3, 7}, 3, &c) == HOT::OK && c.problem == HOT::No_cone_order_problem &&
        c.message.empty());
  CHECK(HOT::check_cone_orders(std::vector<int>{2, 3}, 3, &c) == HOT::ERROR_WRONG_PARAMETER &&
        c.problem == HOT::Wrong_number_of_cone_orders);
  CHECK_MSG(c.message == "2 cone orders are given for 3 landmarks (one per landmark is needed)", c.message);
  CHECK(HOT::check_cone_orders(std::vector<int>{2, 1, 0}, 3, &c) == HOT::ERROR_WRONG_PARAMETER &&
        c.problem == HOT::Cone_order_below_two && c.index == 1);
  CHECK_MSG(c.message == "the cone orders (2,1,0) must be integers of at least 2 (a cone of order p has angle 2 pi / p)", c.message);
  CHECK(HOT::check_cone_orders(HOT::Orbifold_signature(HOT::Sphere_type, {2, 3, 7}), 3) == HOT::OK);
  CHECK(HOT::check_cone_orders(HOT::Orbifold_signature(HOT::Sphere_type, {2, 3, 6}), 3, &c) == HOT::ERROR_NOT_HYPERBOLIC &&
        c.problem == HOT::Cone_orders_not_hyperbolic);
  CHECK_MSG(c.message == "the orbifold with cones of orders (2,3,6) is not hyperbolic: the sum of 1 - 1/p over its cones is 2, "
                         "it must exceed 2 (e.g. (2,3,7), (2,2,2,3), or 5 cones of order 2)", c.message);
  CHECK(HOT::check_cone_orders(HOT::Orbifold_signature::sphere(4), 4) == HOT::ERROR_NOT_HYPERBOLIC);
  CHECK(HOT::check_cone_orders(HOT::Orbifold_signature::sphere(5), 5) == HOT::OK);
  CHECK(HOT::check_cone_orders(HOT::Orbifold_signature::disk(4), 4) == HOT::ERROR_NOT_HYPERBOLIC);
  CHECK(HOT::check_cone_orders(HOT::Orbifold_signature::disk(5), 5) == HOT::OK);
  CHECK(HOT::check_cone_orders(HOT::Orbifold_signature(HOT::Disk_type, {3, 3}), 2) == HOT::OK); // (not built: make_orbifold_tile() says)
  CHECK(HOT::check_cone_orders(HOT::Orbifold_signature(1, std::vector<int>()), 0, &c) == HOT::ERROR_NOT_HYPERBOLIC);
  CHECK_MSG(c.message == "the orbifold of genus 1 with 0 cones is not hyperbolic (genus 1 needs at least one cone)", c.message);
  CHECK(HOT::check_cone_orders(HOT::Orbifold_signature(1, std::vector<int>{2}), 1) == HOT::OK);
  CHECK(HOT::check_cone_orders(HOT::Orbifold_signature(2, std::vector<int>()), 0) == HOT::OK);
  // the landmarks the orbifolds need at least
  CHECK(HOT::minimum_number_of_landmarks_for(HOT::Sphere_type, 0, false) == 5 &&
        HOT::minimum_number_of_landmarks_for(HOT::Sphere_type, 0, true) == 3 &&
        HOT::minimum_number_of_landmarks_for(HOT::Sphere_type, 1, false) == 1 &&
        HOT::minimum_number_of_landmarks_for(HOT::Sphere_type, 2, false) == 0 &&
        HOT::minimum_number_of_landmarks_for(HOT::Disk_type, 0, true) == 5);
  // the genus (genus.h): a tetrahedron (genus 0), a disk (not closed: -1)
  SM tet;
  const auto v0 = tet.add_vertex(Point(0, 0, 0)), v1 = tet.add_vertex(Point(1, 0, 0)), v2 = tet.add_vertex(Point(0, 1, 0));
  tet.add_face(v0, v2, v1);
  CHECK(HOT::euler_characteristic(tet) == 1 && HOT::closed_mesh_genus(tet) == -1 && HOT::genus_of_surface(1, 1) == 0);
  const auto v3 = tet.add_vertex(Point(0, 0, 1));
  tet.add_face(v0, v1, v3);
  tet.add_face(v1, v2, v3);
  tet.add_face(v2, v0, v3);
  CHECK(HOT::euler_characteristic(tet) == 2 && HOT::closed_mesh_genus(tet) == 0);
  CHECK(HOT::genus_of_surface(0, 0) == 1 && HOT::genus_of_surface(-2, 0) == 2 && HOT::genus_of_surface(-1, 1) == 1);
}

HOT_TEST_MAIN
