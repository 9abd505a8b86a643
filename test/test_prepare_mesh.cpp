// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Tests of prepare_polygon_soup_for_embedding() / prepare_mesh_for_embedding(): each case
// builds a soup whose defects are known by construction (generated meshes, or libcgal-demo
// meshes edited by the test) and checks the counts, the topology (Euler's formula) and the
// addressing of the result against what the construction implies, never against values
// taken from the program's own output. Every result also goes through check_result(): a
// success passes check_mesh() and keeps the input's coordinates; a failure leaves `out` empty.

#include "test_harness.h"
#include "test_common_meshes.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/Polyhedron_iostream.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Hyperbolic_orbifold_Tutte/check_input.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/prepare_mesh_for_embedding.h>
// (the steps themselves, tested one by one: their definitions, behind the door in the project's builds)
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/preparation/mesh_preparation_steps.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <limits>
#include <map>
#include <numeric>
#include <set>
#include <vector>

namespace HOT = CGAL::Hyperbolic_orbifold_Tutte;

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;
typedef CGAL::Surface_mesh<Point> SM;
typedef CGAL::Polyhedron_3<K> Poly;
typedef std::vector<std::size_t> Polygon;
typedef std::array<std::size_t, 3> Triple;

namespace {

const std::size_t npos = HOT::Mesh_preparation::npos;

struct Soup
{
  std::vector<Point> points;
  std::vector<Polygon> faces;
};

// --- soups: from meshes, generated ---------------------------------------------

Soup soup_of(const SM& m) // vertex i: the i-th vertex (file order for a mesh read from OFF)
{
  Soup s;
  for(SM::Vertex_index v : vertices(m)) s.points.push_back(m.point(v));
  for(SM::Face_index f : faces(m)) {
    s.faces.emplace_back();
    for(SM::Vertex_index v : vertices_around_face(halfedge(f, m), m)) s.faces.back().push_back(v.idx());
  }
  return s;
}

Soup demo_soup(const std::string& name)
{
  SM m;
  CHECK_MSG(hot_test::read_demo_mesh(name, m), "cannot read " << name << " (pass --data)");
  return soup_of(m);
}

// the icosahedron, each face split in 4 `subdivisions` times, on the unit sphere around `c`
Soup icosphere(int subdivisions, const Point& c = Point(0, 0, 0))
{
  typedef K::Vector_3 V;
  const double t = (1 + std::sqrt(5.0)) / 2;
  std::vector<V> p = {V(-1, t, 0), V(1, t, 0), V(-1, -t, 0), V(1, -t, 0), V(0, -1, t), V(0, 1, t),
                      V(0, -1, -t), V(0, 1, -t), V(t, 0, -1), V(t, 0, 1), V(-t, 0, -1), V(-t, 0, 1)};
  std::vector<Polygon> f = { {0, 11, 5}, {0, 5, 1}, {0, 1, 7}, {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                             {11, 10, 2}, {10, 7, 6}, {7, 1, 8}, {3, 9, 4}, {3, 4, 2}, {3, 2, 6}, {3, 6, 8},
                             {3, 8, 9}, {4, 9, 5}, {2, 4, 11}, {6, 2, 10}, {8, 6, 7}, {9, 8, 1} };
  for(int s = 0; s < subdivisions; ++s) {
    std::map<std::pair<std::size_t, std::size_t>, std::size_t> mid;
    auto m = [&](std::size_t a, std::size_t b) {
      const auto ins = mid.emplace(std::make_pair(std::min(a, b), std::max(a, b)), p.size());
      if(ins.second) p.push_back((p[a] + p[b]) / 2);
      return ins.first->second;
    };
    std::vector<Polygon> g;
    for(const Polygon& q : f) {
      const std::size_t ab = m(q[0], q[1]), bc = m(q[1], q[2]), ca = m(q[2], q[0]);
      g.insert(g.end(), {{q[0], ab, ca}, {q[1], bc, ab}, {q[2], ca, bc}, {ab, bc, ca}});
    }
    f.swap(g);
  }
  Soup r{{}, f};
  for(const V& x : p) r.points.push_back(c + x / std::sqrt(x.squared_length()));
  return r;
}

// the surface of the cube [0,n]^3 as n x n quads per side, integer coordinates, outward
Soup quad_box(int n)
{
  Soup s;
  std::map<std::array<int, 3>, std::size_t> index;
  auto id = [&](const std::array<int, 3>& c) {
    const auto ins = index.emplace(c, s.points.size());
    if(ins.second) s.points.emplace_back(c[0], c[1], c[2]);
    return ins.first->second;
  };
  for(int a = 0; a < 3; ++a)
    for(int side : {0, n}) {
      const int b = (a + 1) % 3, c = (a + 2) % 3; // e_b x e_c = e_a: counterclockwise seen from +a
      for(int i = 0; i < n; ++i)
        for(int j = 0; j < n; ++j) {
          Polygon q;
          for(auto d : {std::array<int, 2>{0, 0}, {1, 0}, {1, 1}, {0, 1}}) {
            std::array<int, 3> x;
            x[a] = side, x[b] = i + d[0], x[c] = j + d[1];
            q.push_back(id(x));
          }
          if(side == 0) std::reverse(q.begin(), q.end());
          s.faces.push_back(q);
        }
    }
  return s;
}

Soup torus(int n)
{
  Soup s;
  const double pi = 3.14159265358979;
  for(int i = 0; i < n; ++i)
    for(int j = 0; j < n; ++j) {
      const double u = 2 * pi * i / n, v = 2 * pi * j / n;
      s.points.emplace_back((2 + std::cos(v)) * std::cos(u), (2 + std::cos(v)) * std::sin(u), std::sin(v));
    }
  auto id = [n](int i, int j) { return std::size_t(((i + n) % n) * n + (j + n) % n); };
  for(int i = 0; i < n; ++i)
    for(int j = 0; j < n; ++j) {
      s.faces.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      s.faces.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  return s;
}

// b's points after a's, b's faces renumbered
Soup append(Soup a, const Soup& b)
{
  const std::size_t n = a.points.size();
  a.points.insert(a.points.end(), b.points.begin(), b.points.end());
  for(Polygon f : b.faces) {
    for(std::size_t& v : f) v += n;
    a.faces.push_back(f);
  }
  return a;
}

// --- facts about meshes, computed by the test -------------------------------------

SM mesh_of(const Soup& s)
{
  SM m;
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(s.points, s.faces, m);
  return m;
}

long long euler_characteristic(const SM& m)
{
  return (long long)num_vertices(m) - (long long)num_edges(m) + (long long)num_faces(m);
}

// the inner edges joining two border vertices, as (smaller, larger) vertex indices
std::set<std::pair<std::size_t, std::size_t> > chords(const SM& m)
{
  std::set<std::pair<std::size_t, std::size_t> > r;
  for(auto e : edges(m)) {
    const auto h = halfedge(e, m);
    const std::size_t a = source(h, m).idx(), b = target(h, m).idx();
    if(!is_border_edge(h, m) && CGAL::is_border(source(h, m), m) && CGAL::is_border(target(h, m), m))
      r.emplace(std::min(a, b), std::max(a, b));
  }
  return r;
}

// the triangles as sorted vertex triples; those of a mesh with vertex k named names[k]
std::multiset<Triple> vertex_sets(const Soup& s)
{
  std::multiset<Triple> r;
  for(const Polygon& f : s.faces) {
    Triple t = {f[0], f[1], f[2]};
    std::sort(t.begin(), t.end());
    r.insert(t);
  }
  return r;
}

std::multiset<Triple> vertex_sets(const SM& m, const std::vector<std::size_t>& names)
{
  Soup s = soup_of(m);
  for(Polygon& f : s.faces)
    for(std::size_t& v : f) v = names[v];
  return vertex_sets(s);
}

std::vector<std::size_t> identity(std::size_t n)
{
  std::vector<std::size_t> r(n);
  std::iota(r.begin(), r.end(), std::size_t(0));
  return r;
}

// --- running the preparation; what every result must satisfy -----------------------

struct Run
{
  HOT::Status r;
  SM out;
  HOT::Mesh_preparation prep;
  std::size_t V() const { return num_vertices(out); }
  std::size_t F() const { return num_faces(out); }
};

// A success gives a mesh that passes check_mesh() with prep.type, addressed as documented:
// output indices increasing; input vertices first, at their exact input position, mapped
// back by prepared_vertex; added vertices numbered n, n+1, ...; an input vertex merged into
// another is at its position. A failure leaves `out` empty.
void check_result(const Soup& s, const Run& x)
{
  const HOT::Mesh_preparation& prep = x.prep;
  if(!x.r) {
    CHECK_MSG(x.V() == 0 && x.F() == 0, "failure (" << x.r.message << ") left a mesh");
    return;
  }
  std::cout << "  " << prep.summary() << std::endl;
  const std::size_t n = s.points.size(), V = x.V();
  const HOT::Status c = HOT::check_mesh(x.out, prep.type);
  CHECK_MSG(c, "the prepared mesh fails check_mesh(): " << c.message);
  CHECK(prep.number_of_input_vertices == n && prep.number_of_input_faces == s.faces.size());
  CHECK(prep.prepared_vertex.size() == n && prep.output_index.size() == V);
  if(prep.prepared_vertex.size() != n || prep.output_index.size() != V) return;
  std::size_t next_added = n, bad = 0;
  for(std::size_t k = 0; k < V; ++k) {
    const std::size_t o = prep.output_index[k];
    bad += (k > 0 && o <= prep.output_index[k - 1]);
    bad += o < n ? x.out.point(SM::Vertex_index(k)) != s.points[o] || prep.prepared_vertex[o] != k : o != next_added++;
  }
  for(std::size_t i = 0; i < n; ++i) {
    const std::size_t p = prep.prepared_vertex[i];
    bad += p != npos && (p >= V || (prep.degenerate_faces_removed == 0 && x.out.point(SM::Vertex_index(p)) != s.points[i]));
  }
  CHECK_MSG(bad == 0, bad << " violations of the addressing");
  CHECK(prep.number_of_added_vertices() == next_added - n);
}

template <class NP = CGAL::parameters::Default_named_parameters>
Run prepare(const Soup& s, const NP& np = CGAL::parameters::default_values())
{
  Run x;
  x.out = mesh_of(Soup{{Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0)}, {{0, 1, 2}}}); // not empty before
  x.r = HOT::prepare_polygon_soup_for_embedding(s.points, s.faces, x.out, x.prep, np);
  check_result(s, x);
  return x;
}

#define CHECK_OK(x) CHECK_MSG((x).r, (x).r.message)
#define CHECK_CODE(x, c) CHECK_MSG((x).r.code == (c), "code " << (x).r.code << " expected " << (c) << ": " << (x).r.message)

} // namespace

// 1. a closed box of quads: every quad becomes 2 triangles, nothing else changes
TEST_CASE(quads)
{
  for(int n : {1, 3}) {
    const Soup s = quad_box(n);
    CHECK(s.points.size() == std::size_t(6 * n * n + 2) && s.faces.size() == std::size_t(6 * n * n));
    const Run x = prepare(s);
    CHECK_OK(x);
    CHECK(x.prep.type == HOT::Sphere_type && euler_characteristic(x.out) == 2 && CGAL::is_closed(x.out));
    CHECK(x.V() == s.points.size() && x.F() == 2 * s.faces.size());
    CHECK(x.prep.polygons_triangulated == s.faces.size() && x.prep.triangles_from_polygons == 2 * s.faces.size());
    CHECK(x.prep.prepared_vertex == identity(s.points.size()) && x.prep.output_index == identity(s.points.size()));
    for(std::size_t i = 0; i < s.points.size() && x.r; ++i) CHECK(x.out.point(SM::Vertex_index(i)) == s.points[i]);
    CHECK(x.prep.merged_duplicate_vertices + x.prep.isolated_vertices + x.prep.reoriented_faces == 0);
  }
}

// 2. an STL-like soup (every triangle with its own copies of its corners) is welded back
void check_unwelded(const Soup& s)
{
  const std::size_t V = std::set<Point>(s.points.begin(), s.points.end()).size(), F = s.faces.size();
  Soup u;
  std::map<Point, std::size_t> first_copy; // position -> index of its first copy in u
  std::vector<std::size_t> original;       // per copy: the vertex of s it copies
  for(const Polygon& f : s.faces) {
    u.faces.emplace_back();
    for(std::size_t v : f) {
      first_copy.emplace(s.points[v], u.points.size());
      u.faces.back().push_back(u.points.size());
      u.points.push_back(s.points[v]);
      original.push_back(v);
    }
  }
  const Run x = prepare(u);
  CHECK_OK(x);
  CHECK(x.V() == V && x.F() == F && x.prep.merged_duplicate_vertices == 3 * F - V);
  CHECK(HOT::check_mesh(x.out, HOT::Sphere_type));
  if(!x.r) return;
  std::size_t bad = 0;
  for(std::size_t c = 0; c < u.points.size(); ++c) {
    const std::size_t p = x.prep.prepared_vertex[c];
    bad += p == npos || x.prep.output_index[p] != first_copy[u.points[c]];
  }
  CHECK_MSG(bad == 0, bad << " copies not addressed to the vertex at their position");
  std::vector<std::size_t> names(x.V()); // the original's vertices: its faces come back
  for(std::size_t k = 0; k < names.size(); ++k) names[k] = original[x.prep.output_index[k]];
  CHECK(vertex_sets(x.out, names) == vertex_sets(s));
}

TEST_CASE(unwelded_soup)
{
  check_unwelded(icosphere(2));
  check_unwelded(demo_soup("bear"));
}

// 3. a known subset of faces reversed: the result is oriented consistently, i.e. agrees with
// the original orientation on every face or on none (orient_polygon_soup picks per component)
TEST_CASE(inconsistent_orientation)
{
  const Soup s = demo_soup("bear");
  Soup t = s;
  std::size_t reversed = 0;
  for(std::size_t f = 0; f < t.faces.size(); f += 3, ++reversed) std::reverse(t.faces[f].begin(), t.faces[f].end());
  const Run x = prepare(t);
  CHECK_OK(x);
  CHECK_MSG(x.prep.reoriented_faces == reversed || x.prep.reoriented_faces == s.faces.size() - reversed,
            x.prep.reoriented_faces << " reoriented, " << reversed << " reversed of " << s.faces.size());
  if(!x.r) return;
  CHECK(vertex_sets(x.out, x.prep.output_index) == vertex_sets(s));
  std::set<std::pair<std::size_t, std::size_t> > directed; // the original's directed edges
  for(const Polygon& f : s.faces)
    for(std::size_t k = 0; k < 3; ++k) directed.emplace(f[k], f[(k + 1) % 3]);
  std::size_t same = 0, total = 0;
  for(auto h : halfedges(x.out))
    if(!is_border(h, x.out)) {
      ++total;
      same += directed.count({x.prep.output_index[source(h, x.out).idx()], x.prep.output_index[target(h, x.out).idx()]});
    }
  CHECK_MSG(same == 0 || same == total, same << " of " << total << " halfedges keep the original direction");
}

// 4. isolated points (put first, so that every other index shifts), a repeated face, and a
// face with a repeated vertex
TEST_CASE(isolated_and_duplicate_faces)
{
  const Soup ico = icosphere(1);
  Soup s = append(Soup{{Point(5, 5, 5), Point(-5, 5, 5)}, {}}, ico);
  s.faces.push_back(s.faces[0]);
  s.faces.push_back({s.faces[1][0], s.faces[1][1], s.faces[1][0]});
  const Run x = prepare(s);
  CHECK_OK(x);
  CHECK(x.prep.isolated_vertices == 2 && x.prep.duplicate_faces_removed == 1 && x.prep.invalid_faces_removed == 1);
  CHECK(x.V() == ico.points.size() && x.F() == ico.faces.size());
  if(!x.r) return;
  CHECK(x.prep.prepared_vertex[0] == npos && x.prep.prepared_vertex[1] == npos);
  std::size_t bad = 0;
  for(std::size_t i = 2; i < s.points.size(); ++i)
    bad += x.prep.prepared_vertex[i] != i - 2 || x.prep.output_index[x.prep.prepared_vertex[i]] != i;
  CHECK_MSG(bad == 0, bad << " vertices not addressed by their input index");
  CHECK(vertex_sets(x.out, x.prep.output_index) == vertex_sets(append(Soup{{Point(), Point()}, {}}, ico)));
}

// 5. the one-ring faces of 3 far apart vertices removed: 3 holes, each a disk patch to fill
// (Euler: F = b - 2 + 2i for b border and i inner vertices), and 3 isolated vertices
TEST_CASE(holes)
{
  SM m;
  CHECK(hot_test::read_demo_mesh("bear", m));
  const std::vector<SM::Vertex_index> centres = hot_test::farthest_point_landmarks(m, 3);
  std::set<SM::Face_index> removed;
  std::map<std::size_t, std::size_t> centre_of; // ring vertex -> its centre
  for(SM::Vertex_index c : centres)
    for(auto h : CGAL::halfedges_around_target(c, m)) {
      removed.insert(face(h, m));
      centre_of[source(h, m).idx()] = c.idx();
    }
  const Soup s = soup_of(m);
  Soup t{s.points, {}};
  for(SM::Face_index f : faces(m))
    if(!removed.count(f)) t.faces.push_back(s.faces[f.idx()]);
  const Run x = prepare(t);
  CHECK_OK(x);
  CHECK(x.prep.type == HOT::Sphere_type && CGAL::is_closed(x.out) && euler_characteristic(x.out) == 2);
  CHECK(x.prep.isolated_vertices == 3 && x.prep.filled_holes.size() == 3);
  for(SM::Vertex_index c : centres) CHECK(x.prep.prepared_vertex[c.idx()] == npos);
  std::set<std::size_t> filled_centres;
  std::size_t faces_added = 0, vertices_added = 0;
  for(const HOT::Filled_hole& h : x.prep.filled_holes) {
    CHECK(h.faces_added + 2 == h.boundary_vertices + 2 * h.vertices_added);
    const auto it = centre_of.find(h.vertex);
    CHECK_MSG(it != centre_of.end(), "hole vertex " << h.vertex << " is on no removed one-ring");
    if(it == centre_of.end()) continue;
    filled_centres.insert(it->second);
    CHECK(h.boundary_vertices == degree(SM::Vertex_index(it->second), m));
    faces_added += h.faces_added;
    vertices_added += h.vertices_added;
  }
  CHECK(filled_centres.size() == 3);
  CHECK(x.V() == num_vertices(m) - 3 + vertices_added && x.F() == num_faces(m) - removed.size() + faces_added);
}

// the border loop of a disk: its vertex count and its length in bounding box diagonals
std::pair<std::size_t, double> border_loop(const SM& m)
{
  std::size_t n = 0;
  double length = 0;
  for(auto h : halfedges(m))
    if(is_border(h, m)) {
      for(auto g : CGAL::halfedges_around_face(h, m)) {
        ++n;
        length += std::sqrt(CGAL::squared_distance(m.point(source(g, m)), m.point(target(g, m))));
      }
      break;
    }
  const CGAL::Bbox_3 b = CGAL::bbox_3(m.points().begin(), m.points().end());
  const K::Vector_3 d(b.xmax() - b.xmin(), b.ymax() - b.ymin(), b.zmax() - b.zmin());
  return {n, length / std::sqrt(d.squared_length())};
}

// 6. mushroom.off is a disk whose loop is longer than half the diagonal: kept as a disk by
// default, refused as a sphere, filled when maximum_hole_length allows it
TEST_CASE(long_hole)
{
  SM m;
  CHECK(hot_test::read_demo_mesh("mushroom", m));
  CHECK(CGAL::Polygon_mesh_processing::number_of_borders(m) == 1 && euler_characteristic(m) == 1);
  const std::pair<std::size_t, double> loop = border_loop(m);
  CHECK_MSG(loop.second > 0.5, "the loop is " << loop.second << " diagonals long");
  const Soup s = soup_of(m);
  CHECK_CODE(prepare(s, HOT::parameters::orbifold_type(HOT::Sphere_type)), HOT::ERROR_WRONG_TOPOLOGY);
  const Run disk = prepare(s);
  CHECK_OK(disk);
  CHECK(disk.prep.type == HOT::Disk_type && disk.prep.filled_holes.empty() && disk.V() == num_vertices(m) + chords(m).size());
  const Run x = prepare(s, HOT::parameters::maximum_hole_length(loop.second * 1.01));
  CHECK_OK(x);
  CHECK(x.prep.type == HOT::Sphere_type && CGAL::is_closed(x.out) && euler_characteristic(x.out) == 2);
  CHECK(x.prep.filled_holes.size() == 1 && x.prep.split_chords.empty());
  if(x.prep.filled_holes.size() != 1) return;
  const HOT::Filled_hole& h = x.prep.filled_holes[0];
  CHECK(h.boundary_vertices == loop.first && h.faces_added + 2 == h.boundary_vertices + 2 * h.vertices_added);
  CHECK(x.F() == num_faces(m) + h.faces_added && x.V() == num_vertices(m) + h.vertices_added);
}

// 7. boundary chords (counted on the input): each split adds a vertex and two faces
void check_chords_split(const Soup& s)
{
  const SM m = mesh_of(s);
  const auto input_chords = chords(m);
  const Run x = prepare(s, HOT::parameters::orbifold_type(HOT::Disk_type));
  CHECK_OK(x);
  CHECK(x.prep.type == HOT::Disk_type && chords(x.out).empty());
  std::set<std::pair<std::size_t, std::size_t> > split; // output indices: the input's for input vertices
  for(auto c : x.prep.split_chords) split.emplace(std::min(c.first, c.second), std::max(c.first, c.second));
  CHECK_MSG(x.prep.split_chords.size() == input_chords.size() && split == input_chords,
            x.prep.split_chords.size() << " chords split, " << input_chords.size() << " in the input");
  CHECK(x.V() == num_vertices(m) + input_chords.size() && x.F() == num_faces(m) + 2 * input_chords.size());
  const Run y = prepare(s, HOT::parameters::split_boundary_chords(false));
  CHECK_OK(y);
  CHECK(y.prep.split_chords.empty() && chords(y.out) == input_chords);
}

TEST_CASE(boundary_chords)
{
  // a hexagonal fan (centre 0) with an ear on its side 1-2: edge 1-2 is the one chord
  Soup fan{{Point(0, 0, 0), Point(4, 0, 0), Point(2, 4, 0), Point(-2, 4, 0), Point(-4, 0, 0), Point(-2, -4, 0),
            Point(2, -4, 0), Point(6, 4, 0)}, {{1, 7, 2}}};
  for(std::size_t k = 1; k <= 6; ++k) fan.faces.push_back({0, k, k % 6 + 1});
  check_chords_split(fan);
  const Run x = prepare(fan);
  CHECK_OK(x);
  CHECK(x.prep.type == HOT::Disk_type && x.prep.split_chords.size() == 1 && x.V() == 9 && x.F() == 9);
  CHECK(x.prep.output_index.size() == 9 && x.prep.output_index.back() == 8);
  CHECK(x.r && x.out.point(SM::Vertex_index(8)) == Point(3, 2, 0)); // the midpoint of 1-2, exact
  const Soup devil = demo_soup("mannequin-devil");
  CHECK(!chords(mesh_of(devil)).empty());
  check_chords_split(devil);
}

// 8. two disjoint spheres, the smaller one first: refused, or the larger one kept
TEST_CASE(components)
{
  const Soup small = icosphere(0), large = icosphere(1, Point(5, 0, 0));
  const Soup s = append(small, large);
  CHECK_CODE(prepare(s), HOT::ERROR_SEVERAL_COMPONENTS);
  const Run x = prepare(s, HOT::parameters::keep_largest_component(true));
  CHECK_OK(x);
  CHECK(x.V() == large.points.size() && x.F() == large.faces.size());
  CHECK(x.prep.components_removed == 1 && x.prep.component_faces_removed == small.faces.size());
  const std::size_t n0 = small.points.size();
  std::size_t bad = 0;
  for(std::size_t i = 0; i < s.points.size() && x.r; ++i)
    bad += i < n0 ? x.prep.prepared_vertex[i] != npos : x.prep.prepared_vertex[i] != i - n0;
  CHECK_MSG(bad == 0, bad << " vertices wrongly addressed");
}

// 9. a strip of 2k triangles around a circle whose two ends meet at one vertex: split, it is
// the strip again, a disk with 2k+2 vertices whose 2k-1 inner edges all join border vertices
Soup pinched_strip(std::size_t k)
{
  Soup s; // inner row u_0 .. u_{k-1} (u_k is u_0), outer row t_0 .. t_k at indices k .. 2k
  const double pi = 3.14159265358979;
  for(std::size_t j = 0; j < k; ++j) s.points.emplace_back(std::cos(2 * pi * j / k), std::sin(2 * pi * j / k), 0);
  for(std::size_t j = 0; j <= k; ++j) s.points.emplace_back(2 * std::cos(1.8 * pi * j / k), 2 * std::sin(1.8 * pi * j / k), 0);
  for(std::size_t j = 0; j < k; ++j) {
    s.faces.push_back({j, (j + 1) % k, k + j + 1});
    s.faces.push_back({j, k + j + 1, k + j});
  }
  return s;
}

TEST_CASE(non_manifold_vertex)
{
  const std::size_t k = 8;
  const Soup s = pinched_strip(k);
  const Run x = prepare(s, HOT::parameters::split_boundary_chords(false));
  CHECK_OK(x);
  CHECK(x.prep.non_manifold_vertices_split == 1 && x.prep.type == HOT::Disk_type);
  CHECK(x.V() == 2 * k + 2 && x.F() == 2 * k && euler_characteristic(x.out) == 1);
  CHECK(x.prep.number_of_added_vertices() == 1 && x.r && x.out.point(SM::Vertex_index(2 * k + 1)) == s.points[0]);
  const Run y = prepare(s);
  CHECK_OK(y);
  CHECK(y.prep.split_chords.size() == 2 * k - 1);
  CHECK(y.V() == 2 * k + 2 + 2 * k - 1 && y.F() == 2 * k + 2 * (2 * k - 1));
}

// --- scans as they come: debris and openings, with the landmarks given -----------

// the faces of a prepared mesh as triples of output indices (rotated to start at the
// smallest): the filling ones (Mesh_preparation::filled_faces) or the others
std::set<Triple> output_faces(const Run& x, bool filled)
{
  std::set<std::size_t> fill(x.prep.filled_faces.begin(), x.prep.filled_faces.end());
  std::set<Triple> r;
  std::size_t j = 0;
  for(SM::Face_index f : faces(x.out)) {
    const bool is_filled = fill.count(j++) != 0;
    if(is_filled != filled) continue;
    Triple t;
    std::size_t k = 0;
    for(SM::Vertex_index v : vertices_around_face(halfedge(f, x.out), x.out)) t[k++] = x.prep.output_index[v.idx()];
    std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
    r.insert(t);
  }
  return r;
}

std::set<Triple> rotated_triples(const std::vector<Polygon>& faces)
{
  std::set<Triple> r;
  for(const Polygon& f : faces) {
    Triple t{{f[0], f[1], f[2]}};
    std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
    r.insert(t);
  }
  return r;
}

// 10. debris: a stray triangle (under 1% of the faces, no landmark) is dropped without being
// asked for; a component of 1.6% is not debris; landmarks choose the component kept and must
// all lie on one
TEST_CASE(debris)
{
  const Soup big = icosphere(3); // 1280 faces
  const Soup stray{{Point(5, 0, 0), Point(6, 0, 0), Point(5, 1, 0)}, {{0, 1, 2}}};
  const Soup s = append(stray, big);
  const Run x = prepare(s);
  CHECK_OK(x);
  CHECK(x.prep.components_removed == 1 && x.prep.debris_components_removed == 1 && x.prep.component_faces_removed == 1);
  CHECK(x.V() == big.points.size() && x.F() == big.faces.size());
  std::size_t bad = 0;
  for(std::size_t i = 0; i < s.points.size() && x.r; ++i)
    bad += i < 3 ? x.prep.prepared_vertex[i] != npos : x.prep.prepared_vertex[i] != i - 3;
  CHECK_MSG(bad == 0, bad << " vertices wrongly addressed");
  CHECK(x.prep.summary().find("debris") != std::string::npos);
  // a sphere of 20 faces beside 1280 is 1.5%: not debris, unless the fraction says so
  const Soup t = append(big, icosphere(0, Point(5, 0, 0)));
  const Run y = prepare(t);
  CHECK_CODE(y, HOT::ERROR_SEVERAL_COMPONENTS);
  CHECK_MSG(y.r.message.find("--largest-component") != std::string::npos && y.r.message.find(" 20") != std::string::npos, y.r.message);
  const Run z = prepare(t, HOT::parameters::maximum_debris_fraction(0.02));
  CHECK_OK(z);
  CHECK(z.prep.debris_components_removed == 1 && z.F() == big.faces.size());
  CHECK_CODE(prepare(t, HOT::parameters::maximum_debris_fraction(-0.5)), HOT::ERROR_WRONG_PARAMETER);
  // landmarks on the small sphere: it is the one kept (asked for), not the largest
  const std::size_t n = big.points.size();
  const std::vector<std::size_t> on_small{n, n + 3, n + 5, n + 7, n + 9};
  const Run w = prepare(t, HOT::parameters::input_landmarks(on_small, HOT::parameters::keep_largest_component(true)));
  CHECK_OK(w);
  CHECK(w.F() == 20 && w.prep.components_removed == 1 && w.prep.debris_components_removed == 0);
  for(std::size_t i : on_small) CHECK(w.r && w.prep.prepared_vertex[i] != npos);
  // without keep_largest_component the big sphere, without landmark, is not debris
  CHECK_CODE(prepare(t, HOT::parameters::input_landmarks(on_small)), HOT::ERROR_SEVERAL_COMPONENTS);
  // landmarks on the stray triangle and on the sphere: refused, naming them
  const std::vector<std::size_t> split{3, 1, 10, 20, 30};
  const Run u = prepare(s, HOT::parameters::input_landmarks(split, HOT::parameters::keep_largest_component(true)));
  CHECK_CODE(u, HOT::ERROR_SEVERAL_COMPONENTS);
  CHECK_MSG(u.r.message.find("landmark 1 on one of 1 faces") != std::string::npos, u.r.message);
  CHECK_CODE(prepare(s, HOT::parameters::input_landmarks(std::vector<std::size_t>{3, 4, 5, 6, s.points.size()})),
             HOT::ERROR_LANDMARK_OUT_OF_RANGE);
}

// 11. an opening much longer than maximum_hole_length (a cap of the sphere removed, its inner
// vertices left isolated): a disk without landmarks; landmarks inside the surface ask for the
// sphere type and it is closed, its new faces listed; landmarks all on its rim keep the disk
TEST_CASE(opening_under_landmarks)
{
  const Soup sphere = icosphere(3);
  Soup open = sphere;
  open.faces.clear();
  for(const Polygon& f : sphere.faces) {
    bool cap = false;
    for(std::size_t v : f) cap = cap || sphere.points[v].z() > 0.5;
    if(!cap) open.faces.push_back(f);
  }
  std::vector<std::size_t> inside, rim;
  {
    std::map<std::pair<std::size_t, std::size_t>, int> uses;
    for(const Polygon& f : open.faces)
      for(int i = 0; i < 3; ++i) ++uses[std::make_pair(std::min(f[i], f[(i + 1) % 3]), std::max(f[i], f[(i + 1) % 3]))];
    std::set<std::size_t> border;
    for(const auto& e : uses)
      if(e.second == 1) border.insert({e.first.first, e.first.second});
    for(std::size_t v : border) if(rim.size() < 6) rim.push_back(v);
    for(std::size_t v = 0; v < sphere.points.size() && inside.size() < 6; ++v)
      if(sphere.points[v].z() < -0.3) inside.push_back(v);
  }
  CHECK(rim.size() == 6 && inside.size() == 6 && open.faces.size() < sphere.faces.size());
  const Run disk = prepare(open);
  CHECK_OK(disk);
  CHECK(disk.prep.type == HOT::Disk_type && disk.prep.filled_holes.empty() && disk.prep.filled_faces.empty());
  const Run x = prepare(open, HOT::parameters::input_landmarks(inside));
  CHECK_OK(x);
  CHECK(x.prep.type == HOT::Sphere_type && x.prep.landmarks_decided && CGAL::is_closed(x.out) && euler_characteristic(x.out) == 2);
  CHECK(x.prep.filled_holes.size() == 1 && x.prep.filled_faces.size() == x.prep.faces_added_by_hole_filling());
  CHECK(x.prep.filled_faces.size() + open.faces.size() == x.F());
  // the faces not listed are exactly the input's, the listed ones all new
  CHECK(output_faces(x, false) == rotated_triples(open.faces));
  std::size_t touching_rim_only = 0;
  for(const Triple& t : output_faces(x, true)) {
    bool added = false;
    for(std::size_t v : t) added = added || v >= open.points.size();
    touching_rim_only += added ? 0 : 1; // a patch face on rim vertices only: possible, not an input face
  }
  CHECK(std::set<Triple>(output_faces(x, true)).size() == x.prep.filled_faces.size());
  CHECK_MSG(touching_rim_only < x.prep.filled_faces.size(), "the patch adds inner vertices");
  // a maximum given: a limit again
  CHECK_CODE(prepare(open, HOT::parameters::input_landmarks(inside, HOT::parameters::maximum_hole_length(0.5))),
             HOT::ERROR_WRONG_TOPOLOGY);
  // landmarks on the rim: the disk
  const Run y = prepare(open, HOT::parameters::input_landmarks(rim));
  CHECK_OK(y);
  CHECK(y.prep.type == HOT::Disk_type && y.prep.filled_faces.empty());
  // a second, small hole elsewhere: filled either way; with the landmarks on the rim the
  // disk stays and the hole's faces are listed
  Soup two = open;
  two.faces.clear();
  for(const Polygon& f : open.faces) {
    bool bottom = false;
    for(std::size_t v : f) bottom = bottom || sphere.points[v].z() < -0.97;
    if(!bottom) two.faces.push_back(f);
  }
  CHECK(two.faces.size() < open.faces.size());
  const Run z = prepare(two, HOT::parameters::input_landmarks(rim));
  CHECK_OK(z);
  CHECK(z.prep.type == HOT::Disk_type && z.prep.filled_holes.size() == 1 && !z.prep.filled_faces.empty());
  CHECK(output_faces(z, false) == rotated_triples(two.faces) || !z.prep.split_chords.empty());
  const Run both = prepare(two, HOT::parameters::input_landmarks(std::vector<std::size_t>{inside[0], inside[1], rim[0], rim[1], rim[2]}));
  CHECK_OK(both);
  CHECK(both.prep.type == HOT::Sphere_type && both.prep.filled_holes.size() == 2);
  CHECK(output_faces(both, false) == rotated_triples(two.faces));
}

// 12. handles (topological noise): with target_genus 0 the shortest non-separating loop is cut
// and both sides closed. On the torus the shortest such loops are the tube's circles and the
// inner equator, polygons of n chords of a unit circle: 2 n sin(pi / n)
TEST_CASE(handles_torus)
{
  const int n = 12;
  const Soup t = torus(n);
  const double pi = 3.14159265358979323846, shortest = 2 * n * std::sin(pi / n);
  const Run keep = prepare(t);
  CHECK_OK(keep);
  CHECK(keep.prep.cut_handles.empty() && euler_characteristic(keep.out) == 0);
  // the torus's bounding box is 6 x 6 x 2: the loop is 0.72 diagonals, over the default bound
  const Run refused = prepare(t, HOT::parameters::target_genus(0));
  CHECK_CODE(refused, HOT::ERROR_WRONG_TOPOLOGY);
  CHECK_MSG(refused.r.message.find("handle 1 of 1") != std::string::npos && refused.r.message.find("--max-handle") != std::string::npos,
            refused.r.message);
  const Run x = prepare(t, HOT::parameters::target_genus(0, HOT::parameters::maximum_handle_length(1.0)));
  CHECK_OK(x);
  CHECK(CGAL::is_closed(x.out) && euler_characteristic(x.out) == 2 && x.prep.type == HOT::Sphere_type);
  CHECK(x.prep.cut_handles.size() == 1 && x.prep.filled_holes.size() == 2);
  if(x.prep.cut_handles.size() != 1) return;
  const HOT::Cut_handle& h = x.prep.cut_handles[0];
  CHECK_MSG(std::abs(h.length - shortest) <= 1e-9 * shortest, "loop length " << h.length << ", shortest " << shortest);
  CHECK(h.vertices.size() == std::size_t(n));
  // n vertices copied (one side of the cut), the sides closed: the input's faces all kept
  CHECK(x.V() == t.points.size() + n + x.prep.filled_holes[0].vertices_added + x.prep.filled_holes[1].vertices_added);
  CHECK(x.F() == t.faces.size() + x.prep.filled_faces.size() && x.prep.filled_faces.size() == x.prep.faces_added_by_hole_filling());
  for(const HOT::Filled_hole& f : x.prep.filled_holes) CHECK(f.boundary_vertices == std::size_t(n));
}

// a sphere whose two antipodal faces (a, b, c) and (d, e, f) are joined by a tube of six
// triangles (fused limbs): genus 1; the handle is cut around the tube, through its six
// vertices only, no longer than the shorter of the two triangles' perimeters
TEST_CASE(handles_tube)
{
  Soup s = icosphere(3);
  std::size_t f1 = 0, f2 = 0;
  double lowest = HUGE_VAL;
  const Point top = CGAL::centroid(s.points[s.faces[0][0]], s.points[s.faces[0][1]], s.points[s.faces[0][2]]);
  for(std::size_t j = 0; j < s.faces.size(); ++j) { // the face opposite face 0
    const Point c = CGAL::centroid(s.points[s.faces[j][0]], s.points[s.faces[j][1]], s.points[s.faces[j][2]]);
    const double d = (c - CGAL::ORIGIN) * (top - CGAL::ORIGIN);
    if(d < lowest) { lowest = d; f2 = j; }
  }
  const Polygon A = s.faces[f1], B = s.faces[f2];
  const std::size_t a = A[0], b = A[1], c = A[2], d = B[0], e = B[1], f = B[2];
  auto perimeter = [&](const Polygon& q) {
    double l = 0;
    for(int i = 0; i < 3; ++i) l += std::sqrt(CGAL::squared_distance(s.points[q[i]], s.points[q[(i + 1) % 3]]));
    return l;
  };
  const double bound = std::min(perimeter(A), perimeter(B));
  s.faces.erase(s.faces.begin() + std::max(f1, f2));
  s.faces.erase(s.faces.begin() + std::min(f1, f2));
  // the tube: a <-> e, b <-> d, c <-> f, so that every new edge has its two sides opposite
  for(const Polygon& q : std::vector<Polygon>{{a, b, d}, {a, d, e}, {b, c, f}, {b, f, d}, {c, a, e}, {c, e, f}}) s.faces.push_back(q);
  CHECK(euler_characteristic(mesh_of(s)) == 0 && CGAL::is_closed(mesh_of(s)));
  const Run x = prepare(s, HOT::parameters::target_genus(0));
  CHECK_OK(x);
  CHECK(CGAL::is_closed(x.out) && euler_characteristic(x.out) == 2 && x.prep.cut_handles.size() == 1);
  if(x.prep.cut_handles.size() != 1) return;
  const HOT::Cut_handle& h = x.prep.cut_handles[0];
  CHECK_MSG(h.length <= bound * (1 + 1e-12), "loop " << h.length << ", the triangles' perimeters " << bound);
  const std::set<std::size_t> tube{a, b, c, d, e, f};
  for(std::size_t v : h.vertices) CHECK_MSG(tube.count(v) == 1, "loop vertex " << v << " is not on the tube");
  CHECK(x.prep.summary().find("cut handles: 1") != std::string::npos);
  // the same with an opening away from the tube, whose rim holds the landmarks: a disk of
  // genus 1, cut to a disk of genus 0 (one boundary loop, Euler characteristic 1), the loop
  // around the tube again, the opening kept
  const K::Vector_3 axis = CGAL::cross_product(top - CGAL::ORIGIN, K::Vector_3(0.3, 0.5, 0.8));
  const K::Vector_3 u = axis / std::sqrt(axis.squared_length());
  Soup opened = s;
  opened.faces.clear();
  for(const Polygon& q : s.faces) {
    const Point c = CGAL::centroid(s.points[q[0]], s.points[q[1]], s.points[q[2]]);
    if((c - CGAL::ORIGIN) * u < 0.8) opened.faces.push_back(q);
  }
  CHECK(opened.faces.size() + 4 < s.faces.size() && tube.count(a) == 1);
  std::vector<std::size_t> rim;
  {
    std::map<std::pair<std::size_t, std::size_t>, int> uses;
    for(const Polygon& q : opened.faces)
      for(int i = 0; i < 3; ++i) ++uses[std::make_pair(std::min(q[i], q[(i + 1) % 3]), std::max(q[i], q[(i + 1) % 3]))];
    std::set<std::size_t> border;
    for(const auto& e : uses)
      if(e.second == 1) border.insert({e.first.first, e.first.second});
    for(std::size_t v : border) if(rim.size() < 5) rim.push_back(v);
  }
  std::set<std::size_t> used;
  for(const Polygon& q : opened.faces) used.insert(q.begin(), q.end());
  CHECK(euler_characteristic(mesh_of(opened)) - static_cast<long long>(opened.points.size() - used.size()) == -1); // (isolated vertices apart)
  const Run y0 = prepare(opened, HOT::parameters::input_landmarks(rim, HOT::parameters::target_genus(0)));
  CHECK_OK(y0);
  CHECK(y0.prep.type == HOT::Disk_type && y0.prep.cut_handles.size() == 1 && euler_characteristic(y0.out) == 1);
  CHECK(CGAL::Polygon_mesh_processing::number_of_borders(y0.out) == 1);
  if(y0.prep.cut_handles.size() == 1) {
    CHECK_MSG(y0.prep.cut_handles[0].length <= bound * (1 + 1e-12), "loop " << y0.prep.cut_handles[0].length << ", bound " << bound);
    for(std::size_t v : y0.prep.cut_handles[0].vertices) CHECK_MSG(tube.count(v) == 1, "disk: loop vertex " << v << " is not on the tube");
  }
  // a disk's handles are cut without target_genus (a disk-type orbifold has genus 0): the
  // same mesh as with target_genus 0; genus 1 asked explicitly keeps the handle, which the
  // check then refuses (no disk-type orbifold of genus 1)
  const Run y1 = prepare(opened, HOT::parameters::input_landmarks(rim));
  CHECK_OK(y1);
  CHECK(y1.prep.type == HOT::Disk_type && y1.prep.cut_handles.size() == 1 && euler_characteristic(y1.out) == 1);
  CHECK(num_vertices(y1.out) == num_vertices(y0.out) && num_faces(y1.out) == num_faces(y0.out));
  const Run y2 = prepare(opened, HOT::parameters::input_landmarks(rim, HOT::parameters::target_genus(1)));
  CHECK_MSG(y2.r.code == HOT::ERROR_WRONG_TOPOLOGY && y2.prep.cut_handles.empty(), y2.r.message);
  // genus 0 asked of a sphere: nothing to do
  const Run y = prepare(icosphere(2), HOT::parameters::target_genus(0));
  CHECK_OK(y);
  CHECK(y.prep.cut_handles.empty() && !y.prep.changed());
}

// two closed meshes sharing vertex 0, either first: split into two components, the larger
// (the octahedron) kept; the shared vertex lies on it, so it stays addressed as vertex 0
TEST_CASE(shared_vertex)
{
  const Soup tetra{{Point(0, 0, 0), Point(-1, 0, 0), Point(0, -1, 0), Point(0, 0, -1)},
                   {{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 2}}};
  const Soup octa{{Point(0, 0, 0), Point(1, 0, 1), Point(1, 0, -1), Point(1, 1, 0), Point(1, -1, 0), Point(2, 0, 0)},
                  {{0, 3, 1}, {0, 2, 3}, {0, 4, 2}, {0, 1, 4}, {5, 1, 3}, {5, 3, 2}, {5, 2, 4}, {5, 4, 1}}};
  for(bool tetra_first : {true, false}) {
    const Soup& a = tetra_first ? tetra : octa;
    const Soup& b = tetra_first ? octa : tetra;
    Soup s = append(a, Soup{std::vector<Point>(b.points.begin() + 1, b.points.end()), {}});
    for(Polygon f : b.faces) {
      for(std::size_t& v : f) v = v == 0 ? 0 : v + a.points.size() - 1;
      s.faces.push_back(f);
    }
    const Run x = prepare(s, HOT::parameters::keep_largest_component(true));
    CHECK_OK(x);
    CHECK(x.prep.non_manifold_vertices_split == 1 && x.prep.components_removed == 1);
    CHECK(x.V() == 6 && x.F() == 8 && euler_characteristic(x.out) == 2);
    CHECK_MSG(x.prep.prepared_vertex[0] != npos && x.prep.number_of_added_vertices() == 0, "tetrahedron first: " << tetra_first);
  }
}

// 10. an octahedron on integer coordinates whose top vertex is moved exactly onto the
// midpoint of the opposite edge of one of its faces: that face is degenerate (collinear)
TEST_CASE(degenerate_face)
{
  const Soup s{{Point(2, 0, 0), Point(-2, 0, 0), Point(0, 2, 0), Point(0, -2, 0), Point(1, 1, 0), Point(0, 0, -2)},
               {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}}};
  CHECK(CGAL::collinear(s.points[0], s.points[2], s.points[4]));
  const Run x = prepare(s); // check_result(): a valid mesh, or a failure with `out` empty
  CHECK_MSG(x.r ? x.prep.degenerate_faces_removed >= 1 && x.prep.changed() : x.r.code != HOT::OK,
            "status " << x.r.code << ", " << x.prep.degenerate_faces_removed << " degenerate faces removed");
  if(x.r) CHECK(CGAL::is_closed(x.out) && euler_characteristic(x.out) == 2);
}

// 11. inputs no preparation can use: a specific code each time, `out` left empty (checked
// by check_result(), `out` being a triangle before the call)
TEST_CASE(bad_input)
{
  const Soup tetra{{Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0), Point(0, 0, 1)},
                   {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}}};
  Soup nan = tetra, inf = tetra, range = tetra;
  nan.points[2] = Point(0, std::numeric_limits<double>::quiet_NaN(), 0);
  inf.points[1] = Point(std::numeric_limits<double>::infinity(), 0, 0);
  range.faces[3][1] = 4;
  CHECK_CODE(prepare(nan), HOT::ERROR_NON_FINITE_COORDINATES);
  CHECK_CODE(prepare(inf), HOT::ERROR_NON_FINITE_COORDINATES);
  CHECK_CODE(prepare(range), HOT::ERROR_WRONG_PARAMETER);
  CHECK_CODE(prepare(Soup{tetra.points, {}}), HOT::ERROR_EMPTY_MESH);
  CHECK_CODE(prepare(Soup{tetra.points, {{0, 1, 0}, {2, 2, 2}}}), HOT::ERROR_EMPTY_MESH);
  { // a closed torus needs no preparation: kept as it is, of genus 1 (the closed type cuts it along a graph)
    const Run t = prepare(torus(12));
    CHECK_OK(t);
    CHECK(t.F() == torus(12).faces.size() &&
          static_cast<long long>(t.V()) - static_cast<long long>(num_edges(t.out)) + static_cast<long long>(t.F()) == 0);
  }
  CHECK_CODE(prepare(tetra, HOT::parameters::maximum_hole_length(-1.0)), HOT::ERROR_WRONG_PARAMETER);
  CHECK_CODE(prepare(tetra, HOT::parameters::orbifold_type(HOT::Disk_type)), HOT::ERROR_WRONG_TOPOLOGY);
}

// 11b. found by the fuzz target: two triangles on two distinct vertices at one position
// (1 and 2: on no border edge, so not merged) in a soup that is not a manifold mesh; PMP's
// merge_duplicate_polygons_in_polygon_soup() has the precondition that no polygon has two
// corners at one position (a CGAL assertion, or undefined behaviour without assertions).
// Those two are removed as invalid; 4 = (0, 1, -0) is merged into 3 = (0, 1, 0) (both on the
// border, -0 == 0), so the triangles 3 1 5 and 0 3 5 share the edge 3-5: a disk of 4
// vertices whose inner edge 3-5 joins two boundary vertices and is split (V 5, F 4); vertices
// 2 (only on removed faces) and 6 (on none) are isolated.
TEST_CASE(coincident_corners)
{
  const Soup s{{Point(1, 0, 0), Point(-1, 0, 0), Point(-1, 0, 0), Point(0, 1, 0), Point(0, 1, -0.0), Point(0, 0, 1),
                Point(0, 0, -1)},
               {{1, 2, 4}, {2, 1, 4}, {4, 1, 5}, {0, 3, 5}}};
  const Run a = prepare(s);
  CHECK_OK(a);
  CHECK(a.prep.invalid_faces_removed == 2 && a.prep.merged_duplicate_vertices == 1 && a.prep.isolated_vertices == 2);
  CHECK(a.prep.type == HOT::Disk_type && a.V() == 5 && a.F() == 4 && a.prep.split_chords.size() == 1);
  CHECK(a.prep.prepared_vertex[4] == a.prep.prepared_vertex[3] && a.prep.prepared_vertex[2] == npos &&
        a.prep.prepared_vertex[6] == npos);
  // also found by the fuzz target: a closed tetrahedron whose 4 vertices are at one position is
  // a manifold soup with every face degenerate; removing them leaves nothing (the addressing of
  // the collapsed vertices then looked for the nearest of no vertex)
  const Run b = prepare(Soup{std::vector<Point>(4, Point(0, 0, 0)), {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}}});
  CHECK_CODE(b, HOT::ERROR_DEGENERATE_FACE);
  // and (a hang, the soup of the fuzz input): a non-planar hexagon 2 0 3 1 5 4 among
  // triangles on its corners; after PMP::triangulate_faces() the halfedge structure was not
  // valid and the component search looped: now refused, in no time
  const Run c = prepare(Soup{{Point(1, 0, 0), Point(-1, 0, 0), Point(0, 0, 0), Point(0, -1, 0), Point(0, 0, 1), Point(0, 0, -1)},
                             {{0, 2, 4}, {2, 0, 3, 1, 5, 4}, {0, 2, 4}, {2, 1, 4}, {1, 3, 5}}});
  CHECK(!c.r);
}

// 11c. found by replaying the fuzz corpus in a release build: the pentagon a b c d e with
// a = (0,0,0), b = (20,1,0), c = (1,0,0), d = (0,-1,0), e = (1,0,-1) has the Newell normal
// (1, 0, -1) (by hand: the edges d-e and e-a give (1, 1, 1) and (0, -1, 0), a-b, b-c and c-d
// give (0, 0, -2)), and e - a = (1, 0, -1) is along it: a and e project onto one point of
// the polygon's plane. PMP::triangulate_faces() inserts both into a constrained Delaunay
// triangulation of that plane, whose precondition (distinct constraint ends) only assertions
// checked: a crash without them. Such a polygon is filled as a hole in 3D instead: a disk of
// three triangles on the five corners.
TEST_CASE(polygon_with_coincident_projections)
{
  const std::vector<Point> pts{Point(0, 0, 0), Point(20, 1, 0), Point(1, 0, 0), Point(0, -1, 0), Point(1, 0, -1)};
  namespace P = HOT::internal::preparation;
  P::Work_mesh pentagon, planar;
  std::vector<P::Work_vertex> vs, ws;
  for(const Point& p : pts) vs.push_back(pentagon.add_vertex(p));
  const P::Work_face f = pentagon.add_face(vs);
  CHECK(f != P::Work_face());
  CHECK(CGAL::Polygon_mesh_processing::compute_face_normal(f, pentagon) * K::Vector_3(0, 1, 0) == 0);
  CHECK(P::has_coincident_projections(pentagon, f));
  // a convex planar pentagon (the regular one): no two corners coincide in projection
  for(int i = 0; i < 5; ++i) ws.push_back(planar.add_vertex(Point(std::cos(1.2566370614359172 * i), std::sin(1.2566370614359172 * i), 0)));
  const P::Work_face g = planar.add_face(ws);
  CHECK(g != P::Work_face() && !P::has_coincident_projections(planar, g));
  const Run x = prepare(Soup{pts, {{0, 1, 2, 3, 4}}});
  CHECK_OK(x);
  CHECK(x.prep.polygons_triangulated == 1 && x.prep.triangles_from_polygons == 3);
  CHECK(x.prep.type == HOT::Disk_type && !CGAL::is_closed(x.out) && euler_characteristic(x.out) == 1);
}

// 12. the mesh interface (Polyhedron_3, Surface_mesh) gives the soup's result
struct Flat
{
  std::vector<Point> points;
  std::vector<Triple> faces; // cyclically rotated to start at the smallest index, sorted
  bool operator==(const Flat& o) const { return points == o.points && faces == o.faces; }
};

template <class TM>
Flat flat(const TM& m)
{
  Flat r;
  std::map<typename boost::graph_traits<TM>::vertex_descriptor, std::size_t> index;
  for(auto v : vertices(m)) {
    index[v] = r.points.size();
    r.points.push_back(get(CGAL::vertex_point, m, v));
  }
  for(auto f : faces(m)) {
    Triple t;
    std::size_t k = 0;
    for(auto v : vertices_around_face(halfedge(f, m), m)) t[k++] = index[v];
    std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
    r.faces.push_back(t);
  }
  std::sort(r.faces.begin(), r.faces.end());
  return r;
}

bool same_record(const HOT::Mesh_preparation& a, const HOT::Mesh_preparation& b)
{
  return a.prepared_vertex == b.prepared_vertex && a.output_index == b.output_index && a.summary() == b.summary() &&
         a.type == b.type && a.split_chords == b.split_chords;
}

TEST_CASE(mesh_interface)
{
  for(const char* name : {"pig", "cube_quad"}) {
    const Run soup = prepare(demo_soup(name));
    CHECK_OK(soup);
    std::ifstream in(hot_test::data_dir() + "/meshes/" + name + ".off");
    Poly poly;
    SM sm;
    CHECK(in >> poly && hot_test::read_demo_mesh(name, sm));
    for(int which = 0; which < 3; ++which) {
      HOT::Mesh_preparation prep;
      SM out;
      Poly pout;
      HOT::Status r = which == 0 ? HOT::prepare_mesh_for_embedding(poly, out, prep)
                    : which == 1 ? HOT::prepare_mesh_for_embedding(sm, out, prep)
                                 : HOT::prepare_mesh_for_embedding(poly, pout, prep);
      CHECK_MSG(r && same_record(prep, soup.prep), name << " " << which << ": " << r.message);
      CHECK_MSG((which == 2 ? flat(pout) : flat(out)) == flat(soup.out), name << " " << which);
    }
  }
}

// 13. a prepared mesh needs no preparation
TEST_CASE(idempotence)
{
  for(const char* name : {"pig", "mannequin-devil", "cube_quad"}) {
    const Run first = prepare(demo_soup(name));
    CHECK_OK(first);
    CHECK_MSG(first.prep.changed(), name);
    const Soup s = soup_of(first.out);
    const Run x = prepare(s);
    CHECK_OK(x);
    CHECK_MSG(!x.prep.changed() && x.prep.summary() == "no change", name << ": " << x.prep.summary());
    CHECK(x.V() == first.V() && x.F() == first.F() && flat(x.out) == flat(first.out));
    CHECK(x.prep.prepared_vertex == identity(s.points.size()) && x.prep.output_index == identity(s.points.size()));
  }
}

HOT_TEST_MAIN
