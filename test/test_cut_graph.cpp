// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers
//
// Test of include/CGAL/Hyperbolic_orbifold_Tutte/cut_through_landmarks.h and landmark_tour.h
//
// Usage: test_cut_graph [DATA_DIR]
//   DATA_DIR contains the `meshes/` folder of Debian's libcgal-demo data
//   (/usr/share/doc/libcgal-demo/data.tar.gz).  Without it, the checks on
//   file meshes are skipped (the generated meshes are always tested).
// Exit status: EXIT_SUCCESS iff every check passed.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/Seam_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>

#include <CGAL/Hyperbolic_orbifold_Tutte/cut_through_landmarks.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/landmark_tour.h>

#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <limits>
#include <map>
#include <queue>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <unordered_map>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3                                          Point;
typedef CGAL::Surface_mesh<Point>                           SM;
typedef CGAL::Polyhedron_3<K>                               Poly;

namespace HOT = CGAL::Hyperbolic_orbifold_Tutte;
namespace HI = CGAL::Hyperbolic_orbifold_Tutte::internal;
namespace PMP = CGAL::Polygon_mesh_processing;

// ---------------------------------------------------------------------------
// Minimal check machinery: one printed line per check, failures counted.
// ---------------------------------------------------------------------------
static int g_checks = 0;
static int g_failures = 0;

#define CHECK(cond, what)                                                     \
  do {                                                                        \
    ++g_checks;                                                               \
    const bool check_ok_ = static_cast<bool>(cond);                           \
    std::ostringstream check_os_;                                             \
    check_os_ << what;                                                        \
    std::cout << (check_ok_ ? "[PASS] " : "[FAIL] ") << check_os_.str()       \
              << std::endl;                                                   \
    if(!check_ok_) ++g_failures;                                              \
  } while(0)

// A check whose detail is an error string: empty means success.
#define CHECK_EMPTY(err, what)                                                \
  do {                                                                        \
    const std::string check_err_ = (err);                                     \
    CHECK(check_err_.empty(), what << (check_err_.empty() ? "" : " -- ")      \
                                   << check_err_);                            \
  } while(0)

static void info(const std::string& s) { std::cout << "[INFO] " << s << std::endl; }

// Deterministic pseudo-random numbers: std::mt19937 is fully specified by the
// standard, unlike the std::*_distribution classes.
struct Rng
{
  std::mt19937 gen;
  explicit Rng(unsigned int seed) : gen(seed) {}
  std::size_t below(std::size_t n) { return static_cast<std::size_t>(gen() % n); }
  double unit() { return static_cast<double>(gen()) / 4294967296.0; }
};

// ---------------------------------------------------------------------------
// Generated meshes (polygon soups)
// ---------------------------------------------------------------------------
typedef std::vector<Point>                      Points;
typedef std::vector<std::array<std::size_t, 3> > Triangles;

// Icosahedron subdivided `level` times (each triangle -> 4), projected on the
// unit sphere.  Vertices: 10*4^level + 2.
static void make_icosphere(int level, Points& pts, Triangles& tris)
{
  const double t = (1. + std::sqrt(5.)) / 2.;
  std::vector<std::array<double, 3> > P = {
    {{-1, t, 0}}, {{1, t, 0}}, {{-1, -t, 0}}, {{1, -t, 0}},
    {{0, -1, t}}, {{0, 1, t}}, {{0, -1, -t}}, {{0, 1, -t}},
    {{t, 0, -1}}, {{t, 0, 1}}, {{-t, 0, -1}}, {{-t, 0, 1}}};
  tris = {{{0, 11, 5}}, {{0, 5, 1}}, {{0, 1, 7}}, {{0, 7, 10}}, {{0, 10, 11}},
          {{1, 5, 9}}, {{5, 11, 4}}, {{11, 10, 2}}, {{10, 7, 6}}, {{7, 1, 8}},
          {{3, 9, 4}}, {{3, 4, 2}}, {{3, 2, 6}}, {{3, 6, 8}}, {{3, 8, 9}},
          {{4, 9, 5}}, {{2, 4, 11}}, {{6, 2, 10}}, {{8, 6, 7}}, {{9, 8, 1}}};
  auto normalize = [](std::array<double, 3> p) {
    const double l = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
    return std::array<double, 3>{{p[0] / l, p[1] / l, p[2] / l}};
  };
  for(auto& p : P) p = normalize(p);
  for(int it = 0; it < level; ++it) {
    std::map<std::pair<std::size_t, std::size_t>, std::size_t> mid;
    auto midpoint = [&](std::size_t a, std::size_t b) {
      const std::pair<std::size_t, std::size_t> key((std::min)(a, b), (std::max)(a, b));
      auto f = mid.find(key);
      if(f != mid.end()) return f->second;
      P.push_back(normalize({{(P[a][0] + P[b][0]) / 2, (P[a][1] + P[b][1]) / 2,
                              (P[a][2] + P[b][2]) / 2}}));
      mid[key] = P.size() - 1;
      return P.size() - 1;
    };
    Triangles next;
    for(const auto& f : tris) {
      const std::size_t a = midpoint(f[0], f[1]), b = midpoint(f[1], f[2]), c = midpoint(f[2], f[0]);
      next.push_back({{f[0], a, c}});
      next.push_back({{f[1], b, a}});
      next.push_back({{f[2], c, b}});
      next.push_back({{a, b, c}});
    }
    tris.swap(next);
  }
  pts.clear();
  for(const auto& p : P) pts.push_back(Point(p[0], p[1], p[2]));
}

// Torus grid (genus 1), to check that non-spheres are rejected.
static void make_torus(std::size_t nu, std::size_t nv, Points& pts, Triangles& tris)
{
  const double pi = std::acos(-1.);
  pts.clear();
  tris.clear();
  for(std::size_t i = 0; i < nu; ++i)
    for(std::size_t j = 0; j < nv; ++j) {
      const double u = 2 * pi * i / nu, v = 2 * pi * j / nv;
      pts.push_back(Point((2 + std::cos(v)) * std::cos(u), (2 + std::cos(v)) * std::sin(u), std::sin(v)));
    }
  auto id = [&](std::size_t i, std::size_t j) { return (i % nu) * nv + (j % nv); };
  for(std::size_t i = 0; i < nu; ++i)
    for(std::size_t j = 0; j < nv; ++j) {
      tris.push_back({{id(i, j), id(i + 1, j), id(i + 1, j + 1)}});
      tris.push_back({{id(i, j), id(i + 1, j + 1), id(i, j + 1)}});
    }
}

template <class TM>
static bool mesh_from_soup(const Points& pts, const Triangles& tris, TM& tm)
{
  std::vector<std::vector<std::size_t> > polys;
  for(const auto& t : tris) polys.push_back(std::vector<std::size_t>(t.begin(), t.end()));
  PMP::polygon_soup_to_polygon_mesh(pts, polys, tm);
  return CGAL::is_valid_polygon_mesh(tm) && num_vertices(tm) == pts.size();
}

// ---------------------------------------------------------------------------
// Mesh helpers
// ---------------------------------------------------------------------------
template <class TM>
static std::vector<typename boost::graph_traits<TM>::vertex_descriptor> vertex_list(const TM& tm)
{
  std::vector<typename boost::graph_traits<TM>::vertex_descriptor> v;
  for(auto vd : vertices(tm)) v.push_back(vd);
  return v;
}

template <class TM>
static bool is_closed_genus0(const TM& tm)
{
  for(auto h : halfedges(tm))
    if(is_border(h, tm)) return false;
  const long long chi = static_cast<long long>(num_vertices(tm)) - static_cast<long long>(num_edges(tm))
                      + static_cast<long long>(num_faces(tm));
  return chi == 2 && CGAL::is_triangle_mesh(tm);
}

// k distinct random vertex indices in [0, n).
static std::vector<std::size_t> random_indices(std::size_t n, std::size_t k, Rng& rng)
{
  std::vector<std::size_t> out;
  std::set<std::size_t> used;
  while(out.size() < k) {
    const std::size_t i = rng.below(n);
    if(used.insert(i).second) out.push_back(i);
  }
  return out;
}

template <class TM>
static std::vector<typename boost::graph_traits<TM>::vertex_descriptor>
pick(const std::vector<typename boost::graph_traits<TM>::vertex_descriptor>& verts,
     const std::vector<std::size_t>& idx)
{
  std::vector<typename boost::graph_traits<TM>::vertex_descriptor> out;
  for(std::size_t i : idx) out.push_back(verts[i]);
  return out;
}

template <class TM>
static std::vector<typename boost::graph_traits<TM>::vertex_descriptor>
reorder(const std::vector<typename boost::graph_traits<TM>::vertex_descriptor>& L,
        const std::vector<std::size_t>& order)
{
  std::vector<typename boost::graph_traits<TM>::vertex_descriptor> out;
  for(std::size_t i : order) out.push_back(L[i]);
  return out;
}

// ---------------------------------------------------------------------------
// Independent verification of a cut
// ---------------------------------------------------------------------------
template <class TM>
static std::string verify_cut(const TM& tm,
                              const std::vector<typename boost::graph_traits<TM>::vertex_descriptor>& L,
                              const HOT::Cut_result<TM>& cut)
{
  typedef typename boost::graph_traits<TM>::vertex_descriptor vd;
  typedef typename boost::graph_traits<TM>::halfedge_descriptor hd;
  std::ostringstream err;
  if(!cut.ok) { err << "ok == false: " << cut.message; return err.str(); }
  const std::size_t k = L.size();
  if(cut.paths.size() + 1 != k) { err << cut.paths.size() << " paths for " << k << " landmarks"; return err.str(); }

  std::set<hd> all_halfedges;
  for(hd h : halfedges(tm)) all_halfedges.insert(h);

  // occurrences[v] = list of (path, position in that path's vertex list)
  std::map<vd, std::vector<std::pair<std::size_t, std::size_t> > > occurrences;
  std::vector<std::size_t> path_len(cut.paths.size());
  for(std::size_t i = 0; i < cut.paths.size(); ++i) {
    const auto& p = cut.paths[i];
    if(p.empty()) { err << "path " << i << " is empty"; return err.str(); }
    for(std::size_t j = 0; j < p.size(); ++j) {
      if(all_halfedges.count(p[j]) == 0) { err << "path " << i << " has an invalid halfedge"; return err.str(); }
      if(j + 1 < p.size() && target(p[j], tm) != source(p[j + 1], tm)) {
        err << "path " << i << " is not chained at position " << j; return err.str();
      }
    }
    if(source(p.front(), tm) != L[i]) { err << "path " << i << " does not start at landmark " << i; return err.str(); }
    if(target(p.back(), tm) != L[i + 1]) { err << "path " << i << " does not end at landmark " << i + 1; return err.str(); }
    std::vector<vd> pv;
    pv.push_back(source(p.front(), tm));
    for(hd h : p) pv.push_back(target(h, tm));
    path_len[i] = pv.size();
    std::set<vd> in_path(pv.begin(), pv.end());
    if(in_path.size() != pv.size()) { err << "path " << i << " is not simple"; return err.str(); }
    for(std::size_t j = 0; j < pv.size(); ++j) occurrences[pv[j]].push_back(std::make_pair(i, j));
  }
  std::map<vd, std::size_t> landmark_pos;
  for(std::size_t i = 0; i < k; ++i) landmark_pos[L[i]] = i;

  for(const auto& o : occurrences) {
    const auto lp = landmark_pos.find(o.first);
    if(lp == landmark_pos.end()) {
      if(o.second.size() != 1) { err << "a non-landmark vertex is on " << o.second.size() << " paths"; return err.str(); }
      continue;
    }
    // A landmark appears exactly as the endpoints of its (one or two) paths.
    const std::size_t li = lp->second;
    std::vector<std::pair<std::size_t, std::size_t> > expected;
    if(li > 0) expected.push_back(std::make_pair(li - 1, path_len[li - 1] - 1));
    if(li + 1 < k) expected.push_back(std::make_pair(li, std::size_t(0)));
    std::vector<std::pair<std::size_t, std::size_t> > got = o.second;
    std::sort(got.begin(), got.end());
    if(got != expected) { err << "landmark " << li << " appears elsewhere than as a path endpoint"; return err.str(); }
  }
  for(std::size_t i = 0; i < k; ++i)
    if(occurrences.count(L[i]) == 0) { err << "landmark " << i << " is not on the cut"; return err.str(); }
  return std::string();
}

// Checks that the seam mesh obtained from the cut is a topological disk:
// V - E + F = 1, exactly one border cycle, of length 2 * (cut edges), and
// V = n + V_c - 2.  Also reports num_vertices(seam mesh) through *nv_api.
template <class TM, class SEM, class SVM>
static std::string check_seam_disk(const TM& tm, SEM sem, SVM svm, const HOT::Cut_result<TM>& cut,
                                   std::size_t* nv_api = nullptr)
{
  typedef CGAL::Seam_mesh<TM, SEM, SVM> Seam;
  std::ostringstream err;
  Seam seam(tm, sem, svm);
  if(!HOT::add_cut_to_seam_mesh(seam, tm, cut)) return "add_cut_to_seam_mesh returned false";

  const std::size_t cut_edges = cut.number_of_cut_edges();
  const std::size_t cut_vertices = cut_edges + 1;
  if(seam.number_of_seam_edges() != cut_edges) { err << "seam edge count " << seam.number_of_seam_edges(); return err.str(); }

  std::size_t V = 0, E = 0, F = 0;
  for(auto v : vertices(seam)) { (void)v; ++V; }
  for(auto e : edges(seam)) { (void)e; ++E; }
  for(auto f : faces(seam)) { (void)f; ++F; }
  const long long chi = static_cast<long long>(V) - static_cast<long long>(E) + static_cast<long long>(F);
  if(chi != 1) { err << "Euler characteristic of the seam mesh is " << chi; return err.str(); }
  if(V != num_vertices(tm) + cut_vertices - 2) {
    err << "seam mesh has " << V << " vertices, expected " << num_vertices(tm) + cut_vertices - 2;
    return err.str();
  }
  if(V != HOT::count_seam_mesh_vertices(seam)) return "count_seam_mesh_vertices disagrees with iteration";

  typedef typename boost::graph_traits<Seam>::halfedge_descriptor shd;
  std::size_t n_border = 0;
  shd first;
  bool have_first = false;
  for(shd h : halfedges(seam)) {
    if(is_border(h, seam)) {
      ++n_border;
      if(!have_first) { first = h; have_first = true; }
    }
  }
  if(!have_first) return "the seam mesh has no border";
  std::size_t cycle = 0;
  shd h = first;
  do {
    if(!is_border(h, seam)) return "walking the border left the border";
    h = next(h, seam);
    ++cycle;
  } while(h != first && cycle <= n_border);
  if(cycle != n_border) { err << "border has " << n_border << " halfedges but the first cycle has " << cycle; return err.str(); }
  if(cycle != 2 * cut_edges) { err << "border cycle length " << cycle << " != 2 * " << cut_edges; return err.str(); }

  const std::size_t nv = num_vertices(seam); // first call: cache computed now, after the seams
  if(nv_api) *nv_api = nv;
  if(nv != V) { err << "num_vertices(seam mesh) = " << nv << " but iteration gives " << V; return err.str(); }
  if(num_edges(seam) != E) { err << "num_edges(seam mesh) = " << num_edges(seam) << " but iteration gives " << E; return err.str(); }
  return std::string();
}

typedef SM::Property_map<SM::Edge_index, bool>   SM_seam_edge_map;
typedef SM::Property_map<SM::Vertex_index, bool> SM_seam_vertex_map;

static std::string check_seam_disk_sm(SM& sm, const HOT::Cut_result<SM>& cut)
{
  SM_seam_edge_map sem = sm.add_property_map<SM::Edge_index, bool>("e:test_on_seam", false).first;
  SM_seam_vertex_map svm = sm.add_property_map<SM::Vertex_index, bool>("v:test_on_seam", false).first;
  const std::string err = check_seam_disk(sm, sem, svm, cut);
  sm.remove_property_map(sem);
  sm.remove_property_map(svm);
  return err;
}

typedef boost::graph_traits<Poly>::edge_descriptor   Poly_edge;
typedef boost::graph_traits<Poly>::vertex_descriptor Poly_vertex;

static std::string check_seam_disk_poly(const Poly& p, const HOT::Cut_result<Poly>& cut)
{
  std::unordered_map<Poly_edge, bool> e_map;
  std::unordered_map<Poly_vertex, bool> v_map;
  boost::associative_property_map<std::unordered_map<Poly_edge, bool> > sem(e_map);
  boost::associative_property_map<std::unordered_map<Poly_vertex, bool> > svm(v_map);
  return check_seam_disk(p, sem, svm, cut);
}

// Chords counted independently: every edge of tm, not on the cut, with both
// endpoints on the cut.
template <class TM>
static std::size_t brute_force_chords(const TM& tm, const HOT::Cut_result<TM>& cut)
{
  typedef typename boost::graph_traits<TM>::vertex_descriptor vd;
  std::set<vd> cv;
  std::set<std::pair<vd, vd> > ce;
  for(const auto& p : cut.paths)
    for(auto h : p) {
      cv.insert(source(h, tm));
      cv.insert(target(h, tm));
      ce.insert(std::make_pair((std::min)(source(h, tm), target(h, tm)), (std::max)(source(h, tm), target(h, tm))));
    }
  std::size_t n = 0;
  for(auto e : edges(tm)) {
    const vd a = source(e, tm), b = target(e, tm);
    if(cv.count(a) && cv.count(b) && !ce.count(std::make_pair((std::min)(a, b), (std::max)(a, b)))) ++n;
  }
  return n;
}

// Cut as sequences of (source index, target index) in vertex iteration order,
// to compare cuts across mesh types.
template <class TM>
static std::vector<std::vector<std::pair<std::size_t, std::size_t> > >
cut_as_indices(const TM& tm, const HOT::Cut_result<TM>& cut)
{
  std::map<typename boost::graph_traits<TM>::vertex_descriptor, std::size_t> id;
  std::size_t i = 0;
  for(auto v : vertices(tm)) id[v] = i++;
  std::vector<std::vector<std::pair<std::size_t, std::size_t> > > out;
  for(const auto& p : cut.paths) {
    out.emplace_back();
    for(auto h : p) out.back().push_back(std::make_pair(id[source(h, tm)], id[target(h, tm)]));
  }
  return out;
}

template <class TM>
static double cut_length(const TM& tm, const HOT::Cut_result<TM>& cut)
{
  double l = 0.;
  auto vpm = get(CGAL::vertex_point, tm);
  for(const auto& p : cut.paths)
    for(auto h : p) l += std::sqrt(CGAL::squared_distance(get(vpm, source(h, tm)), get(vpm, target(h, tm))));
  return l;
}

static bool is_permutation_of_iota(const std::vector<std::size_t>& v, std::size_t k)
{
  if(v.size() != k) return false;
  std::vector<std::size_t> s = v;
  std::sort(s.begin(), s.end());
  for(std::size_t i = 0; i < k; ++i) if(s[i] != i) return false;
  return true;
}

// ---------------------------------------------------------------------------
// Tests
// ---------------------------------------------------------------------------

// Cuts on a generated sphere, Surface_mesh vs Polyhedron_3, determinism.
static void test_icosphere_cuts()
{
  Points pts; Triangles tris;
  make_icosphere(3, pts, tris);
  SM sm; Poly poly;
  CHECK(mesh_from_soup(pts, tris, sm) && is_closed_genus0(sm), "icosphere(3) Surface_mesh is a valid closed genus-0 mesh (" << num_vertices(sm) << " vertices)");
  CHECK(mesh_from_soup(pts, tris, poly) && is_closed_genus0(poly), "icosphere(3) Polyhedron_3 is a valid closed genus-0 mesh");
  const auto vs = vertex_list(sm);
  const auto vp = vertex_list(poly);
  bool same_order = vs.size() == vp.size();
  for(std::size_t i = 0; same_order && i < vs.size(); ++i) same_order = (sm.point(vs[i]) == vp[i]->point());
  CHECK(same_order, "Surface_mesh and Polyhedron_3 enumerate the icosphere vertices in the same order");

  struct Case { unsigned seed; std::size_t k; bool tsp; };
  const std::vector<Case> cases = {{1, 3, false}, {2, 5, false}, {3, 8, false}, {4, 12, true}, {5, 25, true}, {6, 50, true}};
  for(const Case& c : cases) {
    Rng rng(c.seed);
    std::vector<std::size_t> idx = random_indices(vs.size(), c.k, rng);
    if(c.tsp) {
      const auto order = HOT::compute_landmark_tour(sm, pick<SM>(vs, idx), get(CGAL::vertex_point, sm));
      const auto order_p = HOT::compute_landmark_tour(poly, pick<Poly>(vp, idx), get(CGAL::vertex_point, poly));
      CHECK(is_permutation_of_iota(order, c.k) && order == order_p,
            "icosphere k=" << c.k << ": TSP order is a permutation and identical on Surface_mesh and Polyhedron_3");
      std::vector<std::size_t> tmp;
      for(std::size_t i : order) tmp.push_back(idx[i]);
      if(order.size() == c.k) idx = tmp;
    }
    const auto Ls = pick<SM>(vs, idx);
    const auto Lp = pick<Poly>(vp, idx);
    const auto cs = HOT::compute_cut_through_landmarks(sm, Ls, get(CGAL::vertex_point, sm));
    const auto cp = HOT::compute_cut_through_landmarks(poly, Lp, get(CGAL::vertex_point, poly));
    const std::string tag = "icosphere k=" + std::to_string(c.k) + (c.tsp ? " (TSP order)" : " (random order)");
    CHECK_EMPTY(verify_cut(sm, Ls, cs), tag << ": Surface_mesh cut is a valid simple path through the landmarks");
    CHECK_EMPTY(verify_cut(poly, Lp, cp), tag << ": Polyhedron_3 cut is a valid simple path through the landmarks");
    CHECK(cs.ok && cp.ok && cut_as_indices(sm, cs) == cut_as_indices(poly, cp),
          tag << ": Surface_mesh and Polyhedron_3 give the same cut");
    if(cs.ok) CHECK_EMPTY(check_seam_disk_sm(sm, cs), tag << ": Surface_mesh seam mesh is a disk with one border cycle of length 2*cut edges");
    if(cp.ok) CHECK_EMPTY(check_seam_disk_poly(poly, cp), tag << ": Polyhedron_3 seam mesh is a disk with one border cycle of length 2*cut edges");
    const auto cs2 = HOT::compute_cut_through_landmarks(sm, Ls, get(CGAL::vertex_point, sm));
    CHECK(cs2.ok && cut_as_indices(sm, cs2) == cut_as_indices(sm, cs), tag << ": a second call gives the same cut (deterministic)");
    if(cs.ok) {
      const std::size_t ch = HOT::count_cut_chords(sm, cs);
      CHECK(ch == brute_force_chords(sm, cs) && HOT::count_cut_chords(poly, cp) == ch,
            tag << ": count_cut_chords (" << ch << ") matches a brute-force edge scan on both mesh types");
    }
    // Plain shortest paths have more chords: a better test of the counter.
    HOT::Cut_options plain;
    plain.chord_penalty = 0.;
    const auto c0 = HOT::compute_cut_through_landmarks(sm, Ls, get(CGAL::vertex_point, sm), plain);
    CHECK_EMPTY(verify_cut(sm, Ls, c0), tag << ": cut with chord_penalty=0 is valid too");
    if(c0.ok) {
      const std::size_t ch0 = HOT::count_cut_chords(sm, c0);
      CHECK(ch0 == brute_force_chords(sm, c0), tag << ": count_cut_chords with chord_penalty=0 (" << ch0 << ") matches a brute-force edge scan");
    }
  }
}

// Bad inputs must give ok == false and a one-line message, never a crash.
static void test_bad_inputs()
{
  Points pts; Triangles tris;
  make_icosphere(2, pts, tris);
  SM sm;
  mesh_from_soup(pts, tris, sm);
  const auto vs = vertex_list(sm);
  const auto vpm = get(CGAL::vertex_point, sm);
  auto bad = [](const HOT::Cut_result<SM>& r) {
    return !r.ok && !r.message.empty() && r.message.find('\n') == std::string::npos && r.paths.empty();
  };

  auto r0 = HOT::compute_cut_through_landmarks(sm, std::vector<SM::Vertex_index>(), vpm);
  CHECK(bad(r0), "no landmark -> ok=false (" << r0.message << ")");
  auto r2 = HOT::compute_cut_through_landmarks(sm, std::vector<SM::Vertex_index>{vs[0], vs[5]}, vpm);
  CHECK(bad(r2), "2 landmarks -> ok=false (" << r2.message << ")");
  auto rd = HOT::compute_cut_through_landmarks(sm, std::vector<SM::Vertex_index>{vs[0], vs[5], vs[9], vs[5]}, vpm);
  CHECK(bad(rd) && rd.message.find("duplicate") != std::string::npos, "duplicate landmark -> ok=false (" << rd.message << ")");
  auto ro = HOT::compute_cut_through_landmarks(sm, std::vector<SM::Vertex_index>{vs[0], SM::Vertex_index(1000000), vs[9]}, vpm);
  CHECK(bad(ro), "out-of-range landmark -> ok=false (" << ro.message << ")");
  auto rn = HOT::compute_cut_through_landmarks(sm, std::vector<SM::Vertex_index>{vs[0], SM::null_vertex(), vs[9]}, vpm);
  CHECK(bad(rn), "null landmark -> ok=false (" << rn.message << ")");
  CHECK(HOT::compute_landmark_tour(sm, std::vector<SM::Vertex_index>{vs[0], vs[5], vs[0]}, vpm).empty(),
        "compute_landmark_tour returns an empty order for duplicate landmarks");

  // A sphere with one face missing: it has a border.
  Triangles open_tris(tris.begin() + 1, tris.end());
  SM open_sm;
  mesh_from_soup(pts, open_tris, open_sm);
  const auto vo = vertex_list(open_sm);
  auto rb = HOT::compute_cut_through_landmarks(open_sm, std::vector<SM::Vertex_index>{vo[20], vo[40], vo[60]}, get(CGAL::vertex_point, open_sm));
  CHECK(bad(rb), "mesh with a border -> ok=false (" << rb.message << ")");
  Poly open_poly;
  mesh_from_soup(pts, open_tris, open_poly);
  const auto vop = vertex_list(open_poly);
  auto rbp = HOT::compute_cut_through_landmarks(open_poly, std::vector<Poly_vertex>{vop[20], vop[40], vop[60]}, get(CGAL::vertex_point, open_poly));
  CHECK(!rbp.ok && !rbp.message.empty(), "Polyhedron_3 with a border -> ok=false (" << rbp.message << ")");

  // A closed torus: not genus 0.
  Points tp; Triangles tt;
  make_torus(16, 12, tp, tt);
  SM torus;
  mesh_from_soup(tp, tt, torus);
  const auto vt = vertex_list(torus);
  auto rt = HOT::compute_cut_through_landmarks(torus, std::vector<SM::Vertex_index>{vt[0], vt[50], vt[100]}, get(CGAL::vertex_point, torus));
  CHECK(bad(rt), "closed torus -> ok=false (" << rt.message << ")");

  // A landmark whose whole 1-ring is made of other landmarks cannot be
  // reached from a far landmark: impossible even with retries.
  const SM::Vertex_index v = vs[0];
  std::vector<SM::Vertex_index> ring;
  for(auto h : halfedges_around_target(v, sm)) ring.push_back(source(h, sm));
  std::reverse(ring.begin(), ring.end()); // any cyclic order will do
  std::vector<SM::Vertex_index> L = {vs[100], v};
  L.insert(L.end(), ring.begin(), ring.end());
  auto ri = HOT::compute_cut_through_landmarks(sm, L, vpm);
  CHECK(bad(ri) && ri.message.find("landmark #0") != std::string::npos && ri.message.find("landmark #1") != std::string::npos,
        "landmark walled in by other landmarks -> ok=false naming landmarks #0 and #1 (" << ri.message << ")");
}

// A configuration where computing the pieces in chain order fails: landmark
// #2 can only be entered through one vertex x, and the shortest path #0->#1
// goes through x.  The retry (computing piece 1 first) must succeed.
static void test_retry_order()
{
  Points pts; Triangles tris;
  make_icosphere(3, pts, tris);
  SM sm;
  mesh_from_soup(pts, tris, sm);
  const auto vpm = get(CGAL::vertex_point, sm);
  const auto vs = vertex_list(sm);

  const SM::Vertex_index v = vs[200];
  std::vector<SM::Vertex_index> ring;
  for(auto h : halfedges_around_target(v, sm)) ring.push_back(source(h, sm));
  const SM::Vertex_index x = ring[0];
  // Candidates for #0 and #1: vertices within 3 rings of x, off v's 1-ring.
  std::set<SM::Vertex_index> forbidden(ring.begin(), ring.end());
  forbidden.insert(v);
  std::set<SM::Vertex_index> near_x = {x};
  for(int r = 0; r < 3; ++r) {
    std::set<SM::Vertex_index> grown = near_x;
    for(auto u : near_x) for(auto h : halfedges_around_target(u, sm)) grown.insert(source(h, sm));
    near_x.swap(grown);
  }
  std::vector<SM::Vertex_index> cand;
  for(auto u : near_x) if(!forbidden.count(u)) cand.push_back(u);

  // Plain shortest paths: the chord penalty would steer piece #0 away from x
  // (x is next to landmarks) and hide the situation we want to provoke.
  HOT::Cut_options plain;
  plain.chord_penalty = 0.;
  HOT::Cut_options once = plain;
  once.max_attempts = 1;
  bool found = false;
  for(std::size_t a = 0; a < cand.size() && !found; ++a) {
    for(std::size_t b = 0; b < cand.size() && !found; ++b) {
      if(a == b) continue;
      std::vector<SM::Vertex_index> L = {cand[a], cand[b], v};
      L.insert(L.end(), ring.begin() + 1, ring.end());
      const auto r1 = HOT::compute_cut_through_landmarks(sm, L, vpm, once);
      if(r1.ok || r1.message.find("landmark #1") == std::string::npos || r1.message.find("landmark #2") == std::string::npos)
        continue;
      found = true;
      CHECK(!r1.ok && r1.number_of_attempts == 1, "retry scenario: with max_attempts=1 (no chord penalty) the chain order fails on piece #1->#2 (" << r1.message << ")");
      const auto r = HOT::compute_cut_through_landmarks(sm, L, vpm, plain);
      CHECK(r.ok && r.number_of_attempts >= 2, "retry scenario: default max_attempts succeeds after " << r.number_of_attempts << " attempts");
      CHECK_EMPTY(verify_cut(sm, L, r), "retry scenario: the cut is a valid simple path through the landmarks in the given order");
      if(r.ok) CHECK_EMPTY(check_seam_disk_sm(sm, r), "retry scenario: seam mesh is a disk");
    }
  }
  CHECK(found, "found a landmark configuration where chain order fails and reordering is needed");
}

// Seam_mesh caches num_vertices(): check what happens and that the documented
// recovery (new Seam_mesh on the filled maps + set_seam_edges_number) works.
static void test_seam_mesh_vertex_cache()
{
  Points pts; Triangles tris;
  make_icosphere(3, pts, tris);
  SM sm;
  mesh_from_soup(pts, tris, sm);
  const auto vs = vertex_list(sm);
  Rng rng(77);
  const auto L = pick<SM>(vs, random_indices(vs.size(), 6, rng));
  const auto cut = HOT::compute_cut_through_landmarks(sm, L, get(CGAL::vertex_point, sm));
  CHECK(cut.ok, "seam cache test: cut computed");
  if(!cut.ok) return;
  const std::size_t expected = num_vertices(sm) + cut.number_of_cut_vertices() - 2;

  typedef CGAL::Seam_mesh<SM, SM_seam_edge_map, SM_seam_vertex_map> Seam;
  SM_seam_edge_map sem = sm.add_property_map<SM::Edge_index, bool>("e:cache_seam", false).first;
  SM_seam_vertex_map svm = sm.add_property_map<SM::Vertex_index, bool>("v:cache_seam", false).first;
  {
    Seam primed(sm, sem, svm);
    const std::size_t before = num_vertices(primed); // fills the cache too early
    HOT::add_cut_to_seam_mesh(primed, sm, cut);
    const std::size_t after = num_vertices(primed);
    const std::size_t counted = HOT::count_seam_mesh_vertices(primed);
    CHECK(before == num_vertices(sm) && counted == expected,
          "seam cache: before the cut num_vertices = n = " << before << ", after it iteration counts n + V_c - 2 = " << counted);
    info("seam cache: Seam_mesh whose num_vertices() was called before add_seam reports " + std::to_string(after) +
         " after the cut while iteration gives " + std::to_string(counted) +
         (after == counted ? " (cache consistent)" : " (stale cache: CGAL 5.5 never invalidates it)"));

    // Recovery: a new Seam_mesh on the same, already filled, seam maps.
    Seam fresh(sm, sem, svm);
    fresh.set_seam_edges_number(cut.number_of_cut_edges());
    std::size_t E = 0;
    for(auto e : edges(fresh)) { (void)e; ++E; }
    CHECK(num_vertices(fresh) == expected && num_edges(fresh) == E &&
          static_cast<long long>(num_vertices(fresh)) - static_cast<long long>(E) + static_cast<long long>(num_faces(fresh)) == 1,
          "seam cache: a new Seam_mesh on the filled maps + set_seam_edges_number() reports consistent counts (V=" << num_vertices(fresh) << ")");
  }
  sm.remove_property_map(sem);
  sm.remove_property_map(svm);

  // A fresh Seam_mesh that receives the cut before any num_vertices() call.
  std::size_t nv = 0;
  SM_seam_edge_map sem2 = sm.add_property_map<SM::Edge_index, bool>("e:cache_seam2", false).first;
  SM_seam_vertex_map svm2 = sm.add_property_map<SM::Vertex_index, bool>("v:cache_seam2", false).first;
  const std::string err = check_seam_disk(sm, sem2, svm2, cut, &nv);
  CHECK(err.empty() && nv == expected, "seam cache: after add_cut_to_seam_mesh on a fresh Seam_mesh, num_vertices = iteration count = " << nv << (err.empty() ? "" : " -- " + err));
  // Adding the same cut again must report failure (edges already seams).
  {
    Seam again(sm, sem2, svm2);
    CHECK(!HOT::add_cut_to_seam_mesh(again, sm, cut), "add_cut_to_seam_mesh returns false when the edges are already seams");
  }
  sm.remove_property_map(sem2);
  sm.remove_property_map(svm2);
}

// TSP: matrix-level algorithms.
static void test_tsp_matrix()
{
  // Held-Karp vs brute force on random Euclidean points.
  bool all_agree = true, all_perm = true, heuristic_not_better = true;
  std::ostringstream detail;
  for(std::size_t k = 4; k <= 8; ++k) {
    for(unsigned seed = 1; seed <= 4; ++seed) {
      Rng rng(1000 * static_cast<unsigned>(k) + seed);
      std::vector<std::array<double, 3> > p(k);
      for(auto& q : p) q = {{rng.unit(), rng.unit(), rng.unit()}};
      std::vector<std::vector<double> > D(k, std::vector<double>(k));
      for(std::size_t i = 0; i < k; ++i)
        for(std::size_t j = 0; j < k; ++j)
          D[i][j] = std::sqrt((p[i][0] - p[j][0]) * (p[i][0] - p[j][0]) + (p[i][1] - p[j][1]) * (p[i][1] - p[j][1]) +
                              (p[i][2] - p[j][2]) * (p[i][2] - p[j][2]));
      std::vector<std::size_t> perm(k);
      for(std::size_t i = 0; i < k; ++i) perm[i] = i;
      double brute = std::numeric_limits<double>::infinity();
      do { brute = (std::min)(brute, HI::tour_length(D, perm)); } while(std::next_permutation(perm.begin() + 1, perm.end()));
      const auto hk = HI::shortest_tour_held_karp(D);
      const auto he = HI::shortest_tour_heuristic(D);
      if(!is_permutation_of_iota(hk, k) || !is_permutation_of_iota(he, k)) all_perm = false;
      const double lhk = HI::tour_length(D, hk), lhe = HI::tour_length(D, he);
      if(std::abs(lhk - brute) > 1e-9 * brute) { all_agree = false; detail << " k=" << k << " seed=" << seed << " HK=" << lhk << " brute=" << brute; }
      if(lhe < brute - 1e-9 * brute) heuristic_not_better = false;
    }
  }
  CHECK(all_perm, "Held-Karp and heuristic tours are permutations (k=4..8, 20 random point sets)");
  CHECK(all_agree, "Held-Karp tour length equals brute force on k=4..8 (20 random point sets)" << detail.str());
  CHECK(heuristic_not_better, "heuristic tour is never shorter than the optimum");

  // Points in convex position in the plane: the optimal tour is the hull
  // order, and a 2-opt local optimum has no crossing, hence is the hull order.
  {
    const std::size_t k = 24;
    const double pi = std::acos(-1.);
    Rng rng(5);
    std::vector<double> angle(k);
    for(std::size_t i = 0; i < k; ++i) angle[i] = 2 * pi * rng.unit();
    std::vector<std::vector<double> > D(k, std::vector<double>(k));
    for(std::size_t i = 0; i < k; ++i)
      for(std::size_t j = 0; j < k; ++j)
        D[i][j] = std::hypot(std::cos(angle[i]) - std::cos(angle[j]), 2 * (std::sin(angle[i]) - std::sin(angle[j])));
    std::vector<std::size_t> hull(k);
    for(std::size_t i = 0; i < k; ++i) hull[i] = i;
    std::sort(hull.begin(), hull.end(), [&](std::size_t a, std::size_t b) { return angle[a] < angle[b]; });
    const auto he = HI::shortest_tour(D);
    CHECK(std::abs(HI::tour_length(D, he) - HI::tour_length(D, hull)) < 1e-9,
          "k=24 points on an ellipse: heuristic tour (NN + 2-opt) has the hull-order length");
  }

  // open_tour_at_longest_edge: canonical w.r.t. rotation and reversal of the
  // tour, removes a longest edge, starts at its smaller endpoint.
  {
    bool ok = true;
    for(unsigned seed = 1; seed <= 10 && ok; ++seed) {
      Rng rng(seed);
      const std::size_t k = 3 + rng.below(10);
      std::vector<std::vector<double> > D(k, std::vector<double>(k, 0.));
      for(std::size_t i = 0; i < k; ++i)
        for(std::size_t j = i + 1; j < k; ++j) D[i][j] = D[j][i] = 1. + rng.below(5); // many ties on purpose
      std::vector<std::size_t> tour(k);
      for(std::size_t i = 0; i < k; ++i) tour[i] = i;
      for(std::size_t i = k - 1; i > 0; --i) std::swap(tour[i], tour[rng.below(i + 1)]);
      const auto ref = HI::open_tour_at_longest_edge(D, tour);
      double longest = 0.;
      for(std::size_t i = 0; i < k; ++i) longest = (std::max)(longest, D[tour[i]][tour[(i + 1) % k]]);
      ok = is_permutation_of_iota(ref, k) && D[ref.front()][ref.back()] == longest && ref.front() < ref.back();
      for(std::size_t r = 0; r < k && ok; ++r) {
        std::vector<std::size_t> t2 = tour;
        std::rotate(t2.begin(), t2.begin() + r, t2.end());
        ok = HI::open_tour_at_longest_edge(D, t2) == ref;
        std::reverse(t2.begin(), t2.end());
        ok = ok && HI::open_tour_at_longest_edge(D, t2) == ref;
      }
    }
    CHECK(ok, "open_tour_at_longest_edge: removes a longest edge, starts at its smaller endpoint, independent of tour rotation/orientation");
  }
}

// The landmark distance matrix against a Dijkstra search written here (a binary heap over
// the mesh's edges, Euclidean lengths), for every pair: 50 landmarks on icospheres of 2562
// vertices (below the library's parallel threshold of about 200000 vertex visits) and 10242
// (above it: one search per task).
static void test_landmark_distance_matrix()
{
  for(int level : {4, 5}) {
    Points pts; Triangles tris;
    make_icosphere(level, pts, tris);
    SM sm;
    mesh_from_soup(pts, tris, sm);
    const auto vs = vertex_list(sm);
    const auto vpm = get(CGAL::vertex_point, sm);
    const std::size_t k = 50;
    Rng rng(static_cast<unsigned>(31 * level));
    const auto L = pick<SM>(vs, random_indices(vs.size(), k, rng));
    const auto D = HI::compute_landmark_distance_matrix(sm, L, vpm);
    bool shape = D.size() == k, symmetric = true, agree = true;
    for(const auto& row : D) shape = shape && row.size() == k;
    std::ostringstream detail;
    for(std::size_t i = 0; shape && i < k; ++i) {
      std::vector<double> dist(num_vertices(sm), std::numeric_limits<double>::infinity());
      typedef std::pair<double, SM::Vertex_index> Item;
      std::priority_queue<Item, std::vector<Item>, std::greater<Item> > heap;
      dist[L[i]] = 0.;
      heap.push(Item(0., L[i]));
      while(!heap.empty()) {
        const Item top = heap.top();
        heap.pop();
        if(top.first > dist[top.second]) continue;
        for(auto h : CGAL::halfedges_around_target(halfedge(top.second, sm), sm)) {
          const auto v = source(h, sm);
          const double d = top.first + std::sqrt(CGAL::squared_distance(get(vpm, top.second), get(vpm, v)));
          if(d < dist[v]) { dist[v] = d; heap.push(Item(d, v)); }
        }
      }
      for(std::size_t j = 0; j < k; ++j) {
        if(D[i][j] != D[j][i]) symmetric = false;
        const double ref = dist[L[j]];
        if(!(std::abs(D[i][j] - ref) <= 1e-12 * (1. + ref))) {
          if(agree) detail << " first: " << i << "-" << j << " " << D[i][j] << " vs " << ref;
          agree = false;
        }
      }
    }
    const std::string tag = "landmark distances, " + std::to_string(vs.size()) + " vertices, k=50";
    CHECK(shape, tag << ": a " << k << " x " << k << " matrix");
    CHECK(symmetric, tag << ": symmetric");
    CHECK(agree, tag << ": every pair equals an independent Dijkstra search's distance" << detail.str());
  }
}

// TSP on a mesh with a known answer: landmarks along a great circle of an
// icosphere, in shuffled order, with one clearly longest gap.
static void test_tsp_great_circle(std::size_t k)
{
  Points pts; Triangles tris;
  make_icosphere(4, pts, tris);
  SM sm;
  mesh_from_soup(pts, tris, sm);
  const auto vs = vertex_list(sm);
  const double pi = std::acos(-1.);
  // Orthonormal basis (u, w) of a generic plane through the origin.
  const K::Vector_3 n0(0.3, 0.2, 1.0);
  const K::Vector_3 n = n0 / std::sqrt(n0.squared_length());
  K::Vector_3 u = CGAL::cross_product(n, K::Vector_3(1, 0, 0));
  u = u / std::sqrt(u.squared_length());
  const K::Vector_3 w = CGAL::cross_product(n, u);

  // Angles: gaps of (300/(k-1)) degrees +-20%, one gap of 60 degrees
  // (between angular positions 2 and 3), scaled to sum to 360.
  Rng rng(static_cast<unsigned>(k));
  std::vector<double> gaps(k);
  for(std::size_t i = 0; i < k; ++i) gaps[i] = (300. / (k - 1)) * (0.8 + 0.4 * rng.unit());
  gaps[2] = 60.;
  double total = 0.;
  for(double g : gaps) total += g;
  std::vector<double> angle(k);
  double a = 0.;
  for(std::size_t i = 0; i < k; ++i) { angle[i] = a * 2 * pi / total; a += gaps[i] * 360. / total; }

  // Landmark at angular position i = nearest mesh vertex to the circle point.
  std::vector<SM::Vertex_index> by_angle;
  for(std::size_t i = 0; i < k; ++i) {
    const Point target = CGAL::ORIGIN + std::cos(angle[i]) * u + std::sin(angle[i]) * w;
    SM::Vertex_index best = vs[0];
    for(auto v : vs) if(CGAL::squared_distance(sm.point(v), target) < CGAL::squared_distance(sm.point(best), target)) best = v;
    by_angle.push_back(best);
  }
  // Shuffle: landmark list position pos[i] holds angular position i.
  std::vector<std::size_t> pos(k);
  for(std::size_t i = 0; i < k; ++i) pos[i] = i;
  for(std::size_t i = k - 1; i > 0; --i) std::swap(pos[i], pos[rng.below(i + 1)]);
  std::vector<SM::Vertex_index> L(k);
  for(std::size_t i = 0; i < k; ++i) L[pos[i]] = by_angle[i];

  // Expected: circular order cut at the gap between angular positions 2 and
  // 3, starting at whichever of the two has the smaller landmark index, then
  // going away from the other one.
  std::vector<std::size_t> expected;
  if(pos[2] < pos[3]) { for(std::size_t i = 0; i < k; ++i) expected.push_back(pos[(2 + k - i) % k]); }
  else                { for(std::size_t i = 0; i < k; ++i) expected.push_back(pos[(3 + i) % k]); }

  const auto order = HOT::compute_landmark_tour(sm, L, get(CGAL::vertex_point, sm));
  std::ostringstream got;
  for(std::size_t i : order) got << i << ' ';
  CHECK(order == expected, "great circle k=" << k << (k <= 12 ? " (Held-Karp)" : " (NN + 2-opt)")
                           << ": TSP order is the circular order opened at the longest gap; got " << got.str());

  // The cut through the landmarks in that order is valid too.
  const auto cut = HOT::compute_cut_through_landmarks(sm, reorder<SM>(L, order), get(CGAL::vertex_point, sm));
  CHECK_EMPTY(verify_cut(sm, reorder<SM>(L, order), cut), "great circle k=" << k << ": cut in TSP order is valid");
}

// Closed genus-0 meshes from the CGAL demo data.
static void test_file_meshes(const std::string& dir, double& total_chords_default, double& total_chords_plain)
{
  const std::vector<std::string> names = {"bear.off", "homer.off", "camel.off", "hand.off", "bunny00.off",
                                          "armadillo.off", "diplodocus.off", "triceratops.off",
                                          "mannequin-devil.off", "cow.off"};
  std::size_t used = 0;
  bool poly_compared = false;
  for(std::size_t m = 0; m < names.size(); ++m) {
    const std::string file = dir + "/meshes/" + names[m];
    SM sm;
    if(!std::ifstream(file) || !CGAL::IO::read_polygon_mesh(file, sm) || !CGAL::is_valid_polygon_mesh(sm)) {
      info("skip " + names[m] + ": cannot be read");
      continue;
    }
    if(!is_closed_genus0(sm)) {
      info("skip " + names[m] + ": not a closed genus-0 triangle mesh");
      continue;
    }
    ++used;
    const auto vs = vertex_list(sm);
    const auto vpm = get(CGAL::vertex_point, sm);
    struct Case { std::size_t k; bool tsp; };
    const std::vector<Case> cases = {{5, false}, {8, false}, {12, true}, {25, true}, {50, true}};
    for(const Case& c : cases) {
      Rng rng(static_cast<unsigned>(97 * m + c.k));
      auto L = pick<SM>(vs, random_indices(vs.size(), c.k, rng));
      if(c.tsp) {
        const auto order = HOT::compute_landmark_tour(sm, L, vpm);
        CHECK(is_permutation_of_iota(order, c.k), names[m] << " k=" << c.k << ": TSP order is a permutation of the landmarks");
        if(order.size() == c.k) L = reorder<SM>(L, order);
      }
      const auto t0 = std::chrono::steady_clock::now();
      const auto cut = HOT::compute_cut_through_landmarks(sm, L, vpm);
      const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
      const std::string tag = names[m] + " (" + std::to_string(vs.size()) + " v) k=" + std::to_string(c.k) +
                              (c.tsp ? " TSP order" : " random order");
      CHECK_EMPTY(verify_cut(sm, L, cut), tag << ": valid cut (attempts " << cut.number_of_attempts << ")");
      if(!cut.ok) continue;
      CHECK_EMPTY(check_seam_disk_sm(sm, cut), tag << ": seam mesh is a disk, one border cycle of length 2*" << cut.number_of_cut_edges());
      const std::size_t ch = HOT::count_cut_chords(sm, cut);
      if(c.tsp) {
        HOT::Cut_options plain;
        plain.chord_penalty = 0.;
        const auto cut0 = HOT::compute_cut_through_landmarks(sm, L, vpm, plain);
        if(cut0.ok) {
          total_chords_default += static_cast<double>(ch);
          total_chords_plain += static_cast<double>(HOT::count_cut_chords(sm, cut0));
          std::ostringstream os;
          os << tag << ": " << cut.number_of_cut_edges() << " cut edges, length " << cut_length(sm, cut)
             << ", chords " << ch << " (plain shortest paths: length " << cut_length(sm, cut0) << ", chords "
             << HOT::count_cut_chords(sm, cut0) << "), " << ms << " ms";
          info(os.str());
        }
      }
    }

    if(!poly_compared) {
      // Same file read as a Polyhedron_3 must give the same cut.
      Poly poly;
      if(CGAL::IO::read_polygon_mesh(file, poly) && num_vertices(poly) == vs.size()) {
        poly_compared = true;
        const auto vp = vertex_list(poly);
        Rng rng(4242);
        const auto idx = random_indices(vs.size(), 10, rng);
        const auto order = HOT::compute_landmark_tour(sm, pick<SM>(vs, idx), vpm);
        const auto order_p = HOT::compute_landmark_tour(poly, pick<Poly>(vp, idx), get(CGAL::vertex_point, poly));
        CHECK(order.size() == 10 && order == order_p, names[m] << ": TSP order identical for Surface_mesh and Polyhedron_3");
        std::vector<std::size_t> oidx;
        for(std::size_t i : order) oidx.push_back(idx[i]);
        const auto cs = HOT::compute_cut_through_landmarks(sm, pick<SM>(vs, oidx), vpm);
        const auto cp = HOT::compute_cut_through_landmarks(poly, pick<Poly>(vp, oidx), get(CGAL::vertex_point, poly));
        CHECK(cs.ok && cp.ok && cut_as_indices(sm, cs) == cut_as_indices(poly, cp),
              names[m] << ": Surface_mesh and Polyhedron_3 give the same cut (k=10)");
        if(cp.ok) CHECK_EMPTY(check_seam_disk_poly(poly, cp), names[m] << ": Polyhedron_3 seam mesh is a disk");
      }
    }
  }
  CHECK(used >= 3, "at least 3 closed genus-0 meshes found in " << dir << "/meshes (" << used << ")");
}

int main(int argc, char** argv)
{
  const auto t0 = std::chrono::steady_clock::now();
  std::cout << std::setprecision(6);

  test_icosphere_cuts();
  test_bad_inputs();
  test_retry_order();
  test_seam_mesh_vertex_cache();
  test_tsp_matrix();
  test_landmark_distance_matrix();
  test_tsp_great_circle(7);
  test_tsp_great_circle(16);

  double chords_default = 0., chords_plain = 0.;
  if(argc > 1) {
    test_file_meshes(argv[1], chords_default, chords_plain);
    CHECK(chords_default <= chords_plain,
          "chord penalty: total chords over the TSP-ordered file cuts " << chords_default << " <= plain shortest paths " << chords_plain);
  } else {
    info("no data directory given: file mesh checks skipped");
  }

  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::cout << (g_failures == 0 ? "ALL PASSED: " : "FAILURES: ") << g_failures << " failed out of " << g_checks
            << " checks, " << s << " s" << std::endl;
  return g_failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
