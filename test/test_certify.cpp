// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// certify_corner_embedding(), the certificate that is independent of the solver, on a corpus
// of wrong embeddings built from good ones the package produces (libcgal-demo's bear, sphere
// type; mushroom and bear without a face, disk type): each wrong one must be rejected by the
// check that names its fault, each good one (the package's own, and maps that are bijective
// but not the package's: a vertex moved inside its one-ring's kernel, the tile's symmetries,
// a region moved to another fundamental domain, another frame) accepted. What makes each one
// right or wrong is known from its construction, not from the certificate.

#include "test_harness.h"
#include "test_common_meshes.h"

#include <CGAL/Hyperbolic_orbifold_Tutte/hyperbolic_orbifold_Tutte_embedding.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/certify_corner_embedding.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/Orbifold_tile.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/graph_traits_Polyhedron_3.h>
#include <CGAL/boost/graph/copy_face_graph.h>

#include "hot_app/io/embedding_obj.h"
#include "hot_app/io/embedding_obj_reader.h"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <limits>
#include <map>
#include <iterator>
#include <set>

namespace HOT = CGAL::Hyperbolic_orbifold_Tutte;
using namespace hot_test;
typedef std::complex<double> C;
typedef HOT::Hyperbolic_isometry_2<double> Isometry;
typedef HOT::Corner_embedding_certificate Cert;

namespace {

// a mesh, its landmarks as given, and the package's certified embedding of it
struct Embedded
{
  Mesh mesh;
  std::vector<vertex_descriptor> landmarks;
  HOT::Orbifold_type type = HOT::Sphere_type;
  HOT::Embedding_statistics stats;
  HOT::Corner_embedding E;
  bool ok = false;
};

void embed(Embedded& e, HOT::Landmark_order order)
{
  auto uv = e.mesh.add_property_map<halfedge_descriptor, K::Point_2>("h:uv").first;
  const HOT::Error_code ec = HOT::hyperbolic_orbifold_Tutte_embedding(
    e.mesh, e.landmarks, uv, HOT::parameters::landmark_order(order, HOT::parameters::embedding_statistics(&e.stats)));
  CHECK_MSG(ec == HOT::OK, e.stats.message);
  CHECK(HOT::make_corner_embedding(e.mesh, uv, e.E) == HOT::OK);
  e.ok = ec == HOT::OK && e.E.number_of_faces() == num_faces(e.mesh);
}

// bear.off with 7 landmarks spread by farthest-point sampling, cut along the paper's tour
const Embedded& bear()
{
  static Embedded e;
  if(!e.ok && num_faces(e.mesh) == 0) {
    CHECK(read_demo_mesh("bear", e.mesh));
    e.landmarks = farthest_point_landmarks(e.mesh, 7);
    embed(e, HOT::Tsp_order);
  }
  return e;
}

// mushroom.off (one boundary loop) with 6 corners spread along its boundary
const Embedded& mushroom()
{
  static Embedded e;
  if(!e.ok && num_faces(e.mesh) == 0) {
    CHECK(read_demo_mesh("mushroom", e.mesh));
    e.type = HOT::Disk_type;
    e.landmarks = boundary_landmarks(e.mesh, 6);
    embed(e, HOT::Given_order);
  }
  return e;
}

Cert certify(const Embedded& e, const HOT::Corner_embedding& E)
{
  Cert c;
  std::string message;
  const HOT::Error_code ec = HOT::certify_corner_embedding(e.mesh, e.landmarks, E, c, &message);
  CHECK_MSG(ec == HOT::OK, message);
  std::cout << "  " << message << std::endl;
  return c;
}

// rejected, and first by `check`
void expect_rejected(const Cert& c, HOT::Corner_embedding_check check)
{
  CHECK(!c.is_certified());
  CHECK_MSG(c.first_failed_check() == check, "first failed: " << c.first_failed_check() << " (" << c.summary()
                                             << "), expected " << HOT::check_name(check));
}

void expect_certified(const Cert& c)
{
  CHECK_MSG(c.is_certified(), c.summary());
  for(int i = 0; i < HOT::number_of_corner_embedding_checks; ++i)
    CHECK_MSG(c.checks[i].run && c.checks[i].failures == 0, HOT::check_name(HOT::Corner_embedding_check(i)));
}

C point(const HOT::Corner_embedding& E, std::size_t p) { return C(E.points[p][0], E.points[p][1]); }
void set_point(HOT::Corner_embedding& E, std::size_t p, const C& z) { E.points[p] = {{z.real(), z.imag()}}; }

// per vertex, the points of its corners (distinct: make_corner_embedding() shares equal ones)
std::vector<std::set<std::size_t> > points_of(const HOT::Corner_embedding& E, std::size_t V)
{
  std::vector<std::set<std::size_t> > r(V);
  for(std::size_t f = 0; f < E.number_of_faces(); ++f)
    for(int c = 0; c < 3; ++c)
      r[E.face_vertices[f][c]].insert(E.face_points[f][c]);
  return r;
}

std::vector<std::size_t> neighbours(const Mesh& m, std::size_t v)
{
  std::vector<std::size_t> r;
  for(vertex_descriptor w : vertices_around_target(halfedge(vertex_descriptor(static_cast<Mesh::size_type>(v)), m), m))
    r.push_back(w.idx());
  return r;
}

bool is_landmark(const Embedded& e, std::size_t v)
{
  for(vertex_descriptor l : e.landmarks)
    if(l.idx() == v)
      return true;
  return false;
}

// an interior vertex with one point, whose neighbours and theirs are too, and no landmark
// among them: far from the cut, the cones and the boundary (the first such vertex from `from`)
std::size_t plain_vertex(const Embedded& e, std::size_t from = 0)
{
  const std::vector<std::set<std::size_t> > pts = points_of(e.E, num_vertices(e.mesh));
  auto plain = [&](std::size_t v) {
    return pts[v].size() == 1 && !is_landmark(e, v) && !is_border(vertex_descriptor(static_cast<Mesh::size_type>(v)), e.mesh);
  };
  for(std::size_t v = from; v < num_vertices(e.mesh); ++v) {
    bool ok = plain(v);
    for(std::size_t w : neighbours(e.mesh, v))
      for(std::size_t x : neighbours(e.mesh, w))
        ok = ok && plain(w) && plain(x);
    if(ok)
      return v;
  }
  CHECK(false);
  return 0;
}

std::size_t point_of(const HOT::Corner_embedding& E, std::size_t v)
{
  for(std::size_t f = 0; f < E.number_of_faces(); ++f)
    for(int c = 0; c < 3; ++c)
      if(E.face_vertices[f][c] == v)
        return E.face_points[f][c];
  CHECK(false);
  return 0;
}

bool face_has(const HOT::Corner_embedding& E, std::size_t f, std::size_t v)
{
  return E.face_vertices[f][0] == v || E.face_vertices[f][1] == v || E.face_vertices[f][2] == v;
}

// the faces of E that are not positively oriented, by the traits' exact predicate: to check a
// test's premise ("every face positive")
std::size_t non_positive_faces(const HOT::Corner_embedding& E)
{
  HOT::Poincare_disk_traits_2<> tr;
  const auto orient = tr.hyperbolic_orientation_2_object();
  std::size_t n = 0;
  for(std::size_t f = 0; f < E.number_of_faces(); ++f) {
    const C a = point(E, E.face_points[f][0]), b = point(E, E.face_points[f][1]), c = point(E, E.face_points[f][2]);
    if(orient(K::Point_2(a.real(), a.imag()), K::Point_2(b.real(), b.imag()), K::Point_2(c.real(), c.imag())) != CGAL::POSITIVE)
      ++n;
  }
  return n;
}

template <class F>
HOT::Corner_embedding map_all_points(const HOT::Corner_embedding& E, const F& f)
{
  HOT::Corner_embedding R = E;
  for(std::size_t p = 0; p < R.points.size(); ++p)
    set_point(R, p, f(point(E, p)));
  return R;
}

// the point at fraction t of the geodesic from a to b
C along_geodesic(const C& a, const C& b, double t)
{
  const Isometry m = Isometry::translation_to_origin(a);
  return m.inverse().apply(t * m.apply(b));
}

// Moves the faces within `rings` rings of vertex v by the isometry g: vertices inside the
// region get their image in place, those on its rim a new point (the faces outside keep the old
// one), so the rim becomes a seam glued by g. Every face keeps its orientation.
HOT::Corner_embedding move_region(const Embedded& e, std::size_t v, int rings, const Isometry& g)
{
  const Mesh& m = e.mesh;
  std::set<std::size_t> region_vertices{v};
  for(int r = 0; r < rings; ++r) {
    std::set<std::size_t> next = region_vertices;
    for(std::size_t u : region_vertices)
      for(std::size_t w : neighbours(m, u))
        next.insert(w);
    region_vertices.swap(next);
  }
  HOT::Corner_embedding R = e.E;
  // the region: faces with all three vertices in it
  std::vector<char> in_region(R.number_of_faces(), 0);
  for(std::size_t f = 0; f < R.number_of_faces(); ++f)
    in_region[f] = region_vertices.count(R.face_vertices[f][0]) && region_vertices.count(R.face_vertices[f][1]) &&
                   region_vertices.count(R.face_vertices[f][2]);
  std::map<std::size_t, std::size_t> moved; // old point -> its image
  for(std::size_t f = 0; f < R.number_of_faces(); ++f) {
    if(!in_region[f])
      continue;
    for(int c = 0; c < 3; ++c) {
      const std::size_t p = e.E.face_points[f][c];
      auto it = moved.find(p);
      if(it == moved.end()) {
        R.points.push_back(R.points[p]);
        set_point(R, R.points.size() - 1, g.apply(point(e.E, p)));
        it = moved.emplace(p, R.points.size() - 1).first;
      }
      R.face_points[f][c] = it->second;
    }
  }
  return R;
}

// the tile of the embedding's orbifold (its definition: the paper's Appendix C)
HOT::Orbifold_tile<> tile_of(const Embedded& e)
{
  HOT::Orbifold_tile<> t;
  CHECK(HOT::make_orbifold_tile(e.type, static_cast<int>(e.landmarks.size()), t) == HOT::OK);
  return t;
}

C corner_point(const HOT::Orbifold_tile<>& t, int i) { return C(t.corner(i).x(), t.corner(i).y()); }

// the boundary vertices of the disk between two of its landmarks, and the landmarks
std::size_t border_vertex_between_landmarks(const Embedded& e)
{
  for(halfedge_descriptor h : halfedges(e.mesh))
    if(is_border(h, e.mesh)) {
      const std::size_t v = target(h, e.mesh).idx();
      const std::size_t a = source(h, e.mesh).idx(), b = target(next(h, e.mesh), e.mesh).idx();
      if(!is_landmark(e, v) && !is_landmark(e, a) && !is_landmark(e, b))
        return v;
    }
  CHECK(false);
  return 0;
}

// the shortest edge at vertex v in the embedding
double shortest_edge(const HOT::Corner_embedding& E, std::size_t v)
{
  double s = std::numeric_limits<double>::infinity();
  for(std::size_t f = 0; f < E.number_of_faces(); ++f)
    for(int c = 0; c < 3; ++c)
      if(E.face_vertices[f][c] == v)
        for(int d = 1; d < 3; ++d)
          s = std::min(s, std::abs(point(E, E.face_points[f][c]) - point(E, E.face_points[f][(c + d) % 3])));
  return s;
}

} // namespace

// ------------------------------------------------------------------------------------------
// good embeddings: accepted
// ------------------------------------------------------------------------------------------

TEST_CASE(sphere_package_embedding_accepted)
{
  const Embedded& e = bear();
  if(!e.ok)
    return;
  const Cert c = certify(e, e.E);
  expect_certified(c);
  const int k = 7;
  // the cone order found is the one the solver used: given landmark landmark_order[j] is cone j
  CHECK(e.stats.landmark_order.size() == std::size_t(k));
  for(int j = 0; j < k && j < int(e.stats.landmark_order.size()); ++j)
    CHECK(c.cone_order[e.stats.landmark_order[j]] == j);
  // the cut is a simple path through the cones: its inner vertices have two points, so the
  // seam edges number the points minus the vertices plus one
  CHECK(c.number_of_seam_edges == e.E.points.size() - num_vertices(e.mesh) + 1);
  // Gauss-Bonnet: a sphere with k cones of angle pi has area (k - 4) pi
  CHECK(c.area_lower <= (k - 4) * CGAL_PI && (k - 4) * CGAL_PI <= c.area_upper);
  CHECK(c.area_upper - c.area_lower < 1e-8);
  CHECK(c.max_angle_sum_deviation < 1e-9);
  CHECK(c.number_of_border_vertices == 0);
}

TEST_CASE(disk_package_embedding_accepted)
{
  const Embedded& e = mushroom();
  if(!e.ok)
    return;
  const Cert c = certify(e, e.E);
  expect_certified(c);
  const int k = 6;
  CHECK(c.number_of_seam_edges == 0);                // a disk is not cut
  CHECK(e.E.points.size() == num_vertices(e.mesh)); // one point per vertex
  std::size_t border = 0;
  for(halfedge_descriptor h : halfedges(e.mesh))
    border += is_border(h, e.mesh) ? 1 : 0;
  CHECK(c.number_of_border_vertices == border);
  CHECK(c.checks[HOT::Border_check].checked == border - k);
  // Gauss-Bonnet: a disk with k corners of angle pi/2 has area (k - 4) pi / 2
  CHECK(c.area_lower <= (k - 4) * CGAL_PI / 2 && (k - 4) * CGAL_PI / 2 <= c.area_upper);
  // the corners follow the tile's counterclockwise, as the solver placed them: the j-th
  // landmark of landmark_order at corner j, or at corner k - j when they were given clockwise
  for(int j = 0; j < k; ++j)
    CHECK(c.cone_order[e.stats.landmark_order[j]] == (e.stats.landmark_order_reversed ? (k - j) % k : j));
}

TEST_CASE(disk_from_sphere_without_a_face_accepted)
{
  // bear.off without the faces around its vertex of largest degree (a disk: a triangle's hole
  // would have 3 boundary vertices, and a disk-type orbifold needs 5 corners)
  Embedded e;
  CHECK(read_demo_mesh("bear", e.mesh));
  vertex_descriptor centre = *vertices(e.mesh).begin();
  for(vertex_descriptor v : vertices(e.mesh))
    if(degree(v, e.mesh) > degree(centre, e.mesh))
      centre = v;
  const std::size_t hole = degree(centre, e.mesh);
  CHECK(hole >= 5);
  // its star becomes one polygon, then a hole
  CGAL::Euler::remove_face(CGAL::Euler::remove_center_vertex(halfedge(centre, e.mesh), e.mesh), e.mesh);
  e.mesh.collect_garbage();
  e.type = HOT::Disk_type;
  e.landmarks = boundary_landmarks(e.mesh, 5);
  CHECK(e.landmarks.size() == 5);
  embed(e, HOT::Given_order);
  if(!e.ok)
    return;
  const Cert c = certify(e, e.E);
  expect_certified(c);
  CHECK(c.type == HOT::Disk_type && c.number_of_border_vertices == hole);
}

TEST_CASE(vertex_moved_inside_its_kernel_accepted)
{
  // still bijective, no longer harmonic: 5% of the way to a neighbour, the one-ring still
  // positive (premise checked with the exact predicate)
  for(const Embedded* e : {&bear(), &mushroom()}) {
    if(!e->ok)
      continue;
    const std::size_t v = plain_vertex(*e, 100), p = point_of(e->E, v);
    const std::size_t w = neighbours(e->mesh, v)[0];
    HOT::Corner_embedding E = e->E;
    set_point(E, p, along_geodesic(point(E, p), point(E, point_of(E, w)), 0.05));
    CHECK(non_positive_faces(E) == 0);
    expect_certified(certify(*e, E));
  }
}

TEST_CASE(tile_symmetries_accepted_with_the_cone_order_found)
{
  // sphere type: the half turn z -> -z maps the tile onto itself, p_j to q_(k+1-j): cone j to
  // cone k-1-j (paper, Appendix C: the k-gon is symmetric about the imaginary axis, its mirror
  // image is the other half). The certificate must find the new order, not assume the old one.
  const Embedded& b = bear();
  if(b.ok) {
    const Cert c0 = certify(b, b.E);
    const Cert c = certify(b, map_all_points(b.E, [](const C& z) { return -z; }));
    expect_certified(c);
    for(int i = 0; i < 7; ++i)
      CHECK(c.cone_order[i] == 6 - c0.cone_order[i]);
  }
  // disk type: the rotation by 2 pi / k maps the regular k-gon's corner j to corner j + 1
  const Embedded& m = mushroom();
  if(m.ok) {
    const Cert c0 = certify(m, m.E);
    const C turn = std::polar(1.0, 2 * CGAL_PI / 6);
    const Cert c = certify(m, map_all_points(m.E, [&](const C& z) { return turn * z; }));
    expect_certified(c);
    for(int i = 0; i < 6; ++i)
      CHECK(c.cone_order[i] == (c0.cone_order[i] + 1) % 6);
  }
}

TEST_CASE(region_moved_to_another_tile_accepted)
{
  // a region moved by a side pairing: the same map onto the orbifold (the group does not change
  // it), now with a seam around the region glued by that side pairing; the certificate must read
  // the gluing from the coordinates, not from where the package cut
  const Embedded& e = bear();
  if(!e.ok)
    return;
  const HOT::Orbifold_tile<> t = tile_of(e);
  const std::size_t v = plain_vertex(e, 2000);
  for(int s : {0, 3, 7}) {
    const HOT::Corner_embedding R = move_region(e, v, 2, t.side_pairing(s));
    CHECK(non_positive_faces(R) == 0);
    const Cert c = certify(e, R);
    expect_certified(c);
    CHECK(c.number_of_seam_edges > certify(e, e.E).number_of_seam_edges);
    CHECK(c.seam_edges_per_side[s] + c.seam_edges_per_side[t.paired_side(s)] > 0);
  }
}

TEST_CASE(recentred_frame_accepted_with_the_frame)
{
  // a map into the tile moved by a Mobius map f (what a recentred embedding is): certified
  // with parameters::frame(f), and its cones are at no corner of the tile without it
  const Embedded& e = bear();
  if(!e.ok)
    return;
  const Isometry f = Isometry::translation_from_origin(C(0.3, -0.2)) * Isometry::rotation(0.7);
  const HOT::Corner_embedding R = map_all_points(e.E, [&](const C& z) { return f.apply(z); });
  Cert c;
  CHECK(HOT::certify_corner_embedding(e.mesh, e.landmarks, R, c, nullptr, HOT::parameters::frame(f)) == HOT::OK);
  expect_certified(c);
  expect_rejected(certify(e, R), HOT::Cone_check);
}

// ------------------------------------------------------------------------------------------
// cones of orders other than 2 (sphere type): the tile depends on the sequence of the orders
// along its boundary, which the certificate reads from the cones' points
// ------------------------------------------------------------------------------------------

namespace {

// bear.off with `orders.size()` landmarks (three given ones, or spread by farthest-point
// sampling), each of the given order, cut along the paper's tour
struct Ordered_bear
{
  Embedded e;
  std::vector<int> orders; // per landmark, as given
};

const Ordered_bear& ordered_bear(const std::vector<int>& orders)
{
  static std::map<std::vector<int>, Ordered_bear> cache;
  Ordered_bear& b = cache[orders];
  if(num_faces(b.e.mesh) > 0)
    return b;
  b.orders = orders;
  CHECK(read_demo_mesh("bear", b.e.mesh));
  if(orders.size() == 3) // (test_cli.sh, cone_orders)
    for(Mesh::size_type v : {8768u, 4116u, 9726u})
      b.e.landmarks.push_back(vertex_descriptor(v));
  else
    b.e.landmarks = farthest_point_landmarks(b.e.mesh, static_cast<int>(orders.size()));
  auto uv = b.e.mesh.add_property_map<halfedge_descriptor, K::Point_2>("h:uv").first;
  const HOT::Error_code ec = HOT::hyperbolic_orbifold_Tutte_embedding(
    b.e.mesh, b.e.landmarks, uv,
    HOT::parameters::cone_orders(orders, HOT::parameters::landmark_order(HOT::Tsp_order, HOT::parameters::embedding_statistics(&b.e.stats))));
  CHECK_MSG(ec == HOT::OK, b.e.stats.message);
  CHECK(HOT::make_corner_embedding(b.e.mesh, uv, b.e.E) == HOT::OK);
  b.e.ok = ec == HOT::OK && b.e.E.number_of_faces() == num_faces(b.e.mesh);
  return b;
}

Cert certify_with_orders(const Embedded& e, const HOT::Corner_embedding& E, const std::vector<int>& orders,
                         HOT::Error_code expected = HOT::OK, std::string* message = nullptr)
{
  Cert c;
  std::string m;
  const HOT::Error_code ec = HOT::certify_corner_embedding(e.mesh, e.landmarks, E, c, &m, HOT::parameters::cone_orders(orders));
  CHECK_MSG(ec == expected, m);
  std::cout << "  orders";
  for(int p : orders)
    std::cout << " " << p;
  std::cout << ": " << m << std::endl;
  if(message)
    *message = m;
  return c;
}

const std::vector<std::vector<int> >& mixed_orders()
{
  static const std::vector<std::vector<int> > o{{2, 3, 7}, {2, 2, 2, 3}, {2, 2, 3, 3, 4}};
  return o;
}

} // namespace

TEST_CASE(mixed_orders_accepted_with_the_orders_found)
{
  for(const std::vector<int>& orders : mixed_orders()) {
    const Ordered_bear& b = ordered_bear(orders);
    if(!b.e.ok)
      continue;
    const int k = static_cast<int>(orders.size());
    const Cert c = certify_with_orders(b.e, b.e.E, orders);
    expect_certified(c);
    // the cone order found is the cut's: landmark landmark_order[j] is tile cone j, of the
    // order the solver gave tile cone j (Embedding_statistics::cone_orders)
    for(int j = 0; j < k; ++j) {
      CHECK(c.cone_order[b.e.stats.landmark_order[j]] == j);
      CHECK(b.e.stats.cone_orders[j] == orders[b.e.stats.landmark_order[j]]);
    }
    CHECK(c.cone_orders == orders);
    double sum = 0;
    for(int i = 0; i < k; ++i) {
      CHECK_MSG(std::abs(c.measured_cone_orders[i] - orders[i]) < 1e-9, c.measured_cone_orders[i]);
      sum += 1.0 - 1.0 / orders[i];
    }
    // Gauss-Bonnet: 2 pi (sum (1 - 1/p) - 2)
    const double area = 2 * CGAL_PI * (sum - 2);
    CHECK_MSG(c.area_lower <= area && area <= c.area_upper, c.area_lower << " " << area << " " << c.area_upper);
    CHECK(std::abs(c.expected_area - area) < 1e-12);
    CHECK(c.max_angle_sum_deviation < 1e-9);
    CHECK(c.max_cone_distance < 1e-12);
    // the cut is a simple path through the cones
    CHECK(c.number_of_seam_edges == b.e.E.points.size() - num_vertices(b.e.mesh) + 1);
  }
}

TEST_CASE(mixed_orders_half_turn_and_frame_accepted)
{
  // z -> -z maps the tile of orders (p_1 .. p_k) onto the tile of (p_k .. p_1) (the k-gon
  // mirrored in the imaginary axis): the same map onto the orbifold, its cones in the reverse
  // sequence along the tile's boundary, which the certificate must read from the points
  for(const std::vector<int>& orders : mixed_orders()) {
    const Ordered_bear& b = ordered_bear(orders);
    if(!b.e.ok)
      continue;
    const int k = static_cast<int>(orders.size());
    const Cert c0 = certify_with_orders(b.e, b.e.E, orders);
    const Cert c = certify_with_orders(b.e, map_all_points(b.e.E, [](const C& z) { return -z; }), orders);
    expect_certified(c);
    for(int i = 0; i < k; ++i)
      CHECK(c.cone_order[i] == k - 1 - c0.cone_order[i]);
    // moved by a Mobius map: certified in that frame, not without it
    const Isometry f = Isometry::translation_from_origin(C(-0.25, 0.3)) * Isometry::rotation(2.1);
    const HOT::Corner_embedding R = map_all_points(b.e.E, [&](const C& z) { return f.apply(z); });
    Cert cf;
    CHECK(HOT::certify_corner_embedding(b.e.mesh, b.e.landmarks, R, cf, nullptr,
                                        HOT::parameters::cone_orders(orders, HOT::parameters::frame(f))) == HOT::OK);
    expect_certified(cf);
    CHECK(cf.cone_order == c0.cone_order);
    expect_rejected(certify_with_orders(b.e, R, orders), HOT::Cone_check);
  }
}

TEST_CASE(mixed_orders_wrong_orders_rejected)
{
  for(const std::vector<int>& orders : mixed_orders()) {
    const Ordered_bear& b = ordered_bear(orders);
    if(!b.e.ok)
      continue;
    const int k = static_cast<int>(orders.size());
    std::string msg;
    // the orders on other cones: every distinct permutation but the right one is rejected by
    // the cones check, the message naming a cone whose measured order is not the one given
    std::vector<int> p = orders;
    std::sort(p.begin(), p.end());
    int permutations = 0;
    do {
      if(p == orders)
        continue;
      ++permutations;
      const Cert c = certify_with_orders(b.e, b.e.E, p, HOT::OK, &msg);
      expect_rejected(c, HOT::Cone_check);
      CHECK_MSG(msg.find("the cones' points give other orders than those given") != std::string::npos ||
                  msg.find("but its given order is") != std::string::npos,
                msg);
    } while(std::next_permutation(p.begin(), p.end()));
    CHECK(permutations >= 2);
    // the largest order one more: no tile of those orders has the cones at its corners
    std::vector<int> more = orders;
    const std::size_t last = std::max_element(more.begin(), more.end()) - more.begin();
    ++more[last];
    const Cert c = certify_with_orders(b.e, b.e.E, more, HOT::OK, &msg);
    expect_rejected(c, HOT::Cone_check);
    CHECK_MSG(msg.find("at no corner of the tile") != std::string::npos, msg);
    CHECK_MSG(msg.find("has order " + std::to_string(orders[last]) + ".0000, not " + std::to_string(more[last])) != std::string::npos, msg);
    // all 2: too few cones for 3 or 4, the wrong tile for 5
    Cert c2;
    const HOT::Error_code ec2 = HOT::certify_corner_embedding(b.e.mesh, b.e.landmarks, b.e.E, c2, &msg);
    if(k < 5)
      CHECK(ec2 == HOT::ERROR_TOO_FEW_LANDMARKS);
    else {
      CHECK(ec2 == HOT::OK);
      expect_rejected(c2, HOT::Cone_check);
    }
  }
  // input errors: not hyperbolic, an order below 2, one order too few, a disk
  const Ordered_bear& b = ordered_bear({2, 3, 7});
  if(!b.e.ok)
    return;
  std::string msg;
  certify_with_orders(b.e, b.e.E, {2, 3, 6}, HOT::ERROR_NOT_HYPERBOLIC, &msg);
  CHECK_MSG(msg.find("not hyperbolic") != std::string::npos, msg);
  certify_with_orders(b.e, b.e.E, {1, 3, 7}, HOT::ERROR_WRONG_PARAMETER, &msg);
  certify_with_orders(b.e, b.e.E, {3, 7}, HOT::ERROR_WRONG_PARAMETER, &msg);
  const Embedded& m = mushroom();
  if(m.ok) {
    Cert c;
    CHECK(HOT::certify_corner_embedding(m.mesh, m.landmarks, m.E, c, &msg, HOT::parameters::cone_orders(std::vector<int>{2, 2, 2, 2, 2, 3})) ==
          HOT::ERROR_WRONG_PARAMETER);
    CHECK_MSG(msg.find("sphere-type") != std::string::npos, msg);
  }
}

TEST_CASE(mixed_orders_cone_moved_off_its_corner_rejected)
{
  // each cone's point moved by 1e-6 (far below its triangles, far above the tolerance): the
  // cones check names it, at no corner; the orders measured still round to the given ones
  const Ordered_bear& b = ordered_bear({2, 3, 7});
  if(!b.e.ok)
    return;
  const std::vector<std::set<std::size_t> > pts = points_of(b.e.E, num_vertices(b.e.mesh));
  for(std::size_t i = 0; i < 3; ++i) {
    HOT::Corner_embedding E = b.e.E;
    const std::size_t p = *pts[b.e.landmarks[i].idx()].begin();
    set_point(E, p, point(E, p) + C(1e-6, -1e-6));
    std::string msg;
    const Cert c = certify_with_orders(b.e, E, b.orders, HOT::OK, &msg);
    expect_rejected(c, HOT::Cone_check);
    CHECK_MSG(msg.find("cone " + std::to_string(i) + " (vertex " + std::to_string(b.e.landmarks[i].idx()) + ") is at") != std::string::npos &&
                msg.find("at no corner of the tile") != std::string::npos && msg.find("other orders") == std::string::npos,
              msg);
  }
}

TEST_CASE(orders_of_2_given_change_nothing)
{
  // cone_orders of 2 for every cone is the default: the same verdict and numbers; the orders
  // found and measured are 2
  const Embedded& e = bear();
  if(!e.ok)
    return;
  const Cert a = certify(e, e.E);
  const Cert b = certify_with_orders(e, e.E, std::vector<int>(7, 2));
  expect_certified(b);
  CHECK(a.summary() == b.summary() && a.cone_order == b.cone_order && a.area_lower == b.area_lower && a.area_upper == b.area_upper &&
        a.max_angle_sum_deviation == b.max_angle_sum_deviation && a.max_seam_mismatch == b.max_seam_mismatch);
  CHECK(b.cone_orders == std::vector<int>(7, 2));
  for(double m : b.measured_cone_orders)
    CHECK_MSG(std::abs(m - 2) < 1e-9, m);
  const Embedded& m = mushroom();
  if(m.ok) {
    const Cert d = certify(m, m.E);
    CHECK(d.cone_orders == std::vector<int>(6, 2));
    for(double x : d.measured_cone_orders)
      CHECK_MSG(std::abs(x - 2) < 1e-9, x);
  }
}

// ------------------------------------------------------------------------------------------
// wrong embeddings: rejected, by the right check
// ------------------------------------------------------------------------------------------

// The bear's embedding with the points nearest one of its cut's end cones written in a chart
// centred at the cone's tile corner, as embed writes a protrusion ending at a landmark
// (application/hot_app/io/embedding_obj.h): chart = translation_to_origin(corner), the cone at the origin
// exactly, each charted point's vt its chart point's tile point. It is the same map (moved by
// rounding), so it must stay certified; `cone_point` receives the cone's point.
HOT::Corner_embedding bear_in_a_chart(const Embedded& e, std::size_t& cone_point, int& corner, std::size_t& charted)
{
  HOT::Corner_embedding E = e.E;
  HOT::Orbifold_tile<HOT::Poincare_disk_traits_2<> > tile;
  CHECK(HOT::make_orbifold_tile(HOT::Sphere_type, static_cast<int>(e.landmarks.size()), tile) == HOT::OK);
  // the cut's first cone (an end of the cut: its seam is glued by the rotation by pi about it)
  const std::size_t v = e.landmarks[e.stats.landmark_order[0]].idx();
  const std::vector<std::set<std::size_t> > pts = points_of(E, num_vertices(e.mesh));
  CHECK(pts[v].size() == 1);
  cone_point = *pts[v].begin();
  const C z0 = point(E, cone_point);
  corner = 0;
  auto corner_point = [&](int i) { return C(CGAL::to_double(tile.corner(i).x()), CGAL::to_double(tile.corner(i).y())); };
  for(int i = 1; i < tile.number_of_corners(); ++i)
    if(std::abs(corner_point(i) - z0) < std::abs(corner_point(corner) - z0))
      corner = i;
  CHECK(std::abs(corner_point(corner) - z0) < 1e-9);
  const Isometry chart = Isometry::translation_to_origin(corner_point(corner));
  E.charts.push_back({{chart.a().real(), chart.a().imag(), chart.b().real(), chart.b().imag()}});
  E.chart_corners.push_back(corner);
  E.point_charts.assign(E.points.size(), -1);
  E.chart_points.assign(E.points.size(), {{0.0, 0.0}});
  // the 300 points nearest the corner
  std::vector<std::pair<double, std::size_t> > by_distance;
  for(std::size_t p = 0; p < E.points.size(); ++p)
    by_distance.emplace_back(std::abs(point(E, p) - corner_point(corner)), p);
  std::sort(by_distance.begin(), by_distance.end());
  charted = 300;
  for(std::size_t i = 0; i < charted; ++i) {
    const std::size_t p = by_distance[i].second;
    const C w = p == cone_point ? C(0, 0) : chart.apply(point(E, p));
    E.point_charts[p] = 0;
    E.chart_points[p] = {{w.real(), w.imag()}};
    set_point(E, p, chart.inverse().apply(w));
  }
  return E;
}

TEST_CASE(region_around_a_cone_in_a_chart_accepted)
{
  const Embedded& e = bear();
  if(!e.ok)
    return;
  std::size_t cone_point = 0, charted = 0;
  int corner = 0;
  const HOT::Corner_embedding E = bear_in_a_chart(e, cone_point, corner, charted);
  const Cert c = certify(e, E);
  expect_certified(c);
  CHECK(c.number_of_charts == 1);
  CHECK(c.number_of_chart_points == charted);
  // every face with a charted corner is in the chart; those at the region's edge are mixed
  std::size_t with_charted_corner = 0, all_charted = 0;
  for(std::size_t f = 0; f < E.number_of_faces(); ++f) {
    int n = 0;
    for(int k = 0; k < 3; ++k)
      n += E.point_charts[E.face_points[f][k]] >= 0;
    with_charted_corner += n > 0;
    all_charted += n == 3;
  }
  CHECK_MSG(c.number_of_charted_faces == with_charted_corner, c.number_of_charted_faces << " " << with_charted_corner);
  CHECK(c.number_of_mixed_faces == with_charted_corner - all_charted);
  CHECK(c.number_of_mixed_faces > 0 && all_charted > 100);
  // the seam from the cone: both sides in the chart, glued by a rotation about its origin
  CHECK(c.number_of_chart_seam_edges > 0);
  CHECK(c.max_chart_seam_mismatch < 1e-13);
  CHECK(c.max_chart_origin_offset <= 64 * 1.1102230246251565e-16);
  CHECK(c.max_chart_point_offset <= 1);
  // the same with the package's own points: the counts of a map without charts
  const Cert plain = certify(e, e.E);
  CHECK(plain.number_of_charts == 0 && plain.number_of_charted_faces == 0 && plain.checks[HOT::Chart_check].run);
  CHECK(plain.number_of_seam_edges == c.number_of_seam_edges);
}

TEST_CASE(chart_table_and_chart_points_checked)
{
  const Embedded& e = bear();
  if(!e.ok)
    return;
  std::size_t cone_point = 0, charted = 0;
  int corner = 0;
  const HOT::Corner_embedding E0 = bear_in_a_chart(e, cone_point, corner, charted);
  {
    // centred at another corner
    HOT::Corner_embedding E = E0;
    HOT::Orbifold_tile<HOT::Poincare_disk_traits_2<> > tile;
    CHECK(HOT::make_orbifold_tile(HOT::Sphere_type, static_cast<int>(e.landmarks.size()), tile) == HOT::OK);
    E.chart_corners[0] = (corner + 1) % tile.number_of_corners();
    const Cert c = certify(e, E);
    expect_rejected(c, HOT::Chart_check);
    CHECK(c.result(HOT::Chart_check).element == Cert::Chart && c.result(HOT::Chart_check).first == 0);
  }
  {
    // b turned by 1e-12 radians (|b| kept: still normalized; its origin 3e-13 off the corner,
    // above 64 u)
    HOT::Corner_embedding E = E0;
    const C b = C(E.charts[0][2], E.charts[0][3]) * std::polar(1.0, 1e-12);
    E.charts[0][2] = b.real();
    E.charts[0][3] = b.imag();
    const Cert c = certify(e, E);
    expect_rejected(c, HOT::Chart_check);
    CHECK(c.result(HOT::Chart_check).message.find("origin") != std::string::npos);
    // b 1e-12 longer: not normalized
    E = E0;
    E.charts[0][2] *= 1 + 1e-12;
    E.charts[0][3] *= 1 + 1e-12;
    expect_rejected(certify(e, E), HOT::Chart_check);
    // and by 2 u: within the bound (the rounding of a chart)
    E = E0;
    E.charts[0][2] = std::nextafter(std::nextafter(E.charts[0][2], 2.0), 2.0);
    expect_certified(certify(e, E));
  }
  {
    // |a| < |b|: not an isometry of the disk
    HOT::Corner_embedding E = E0;
    std::swap(E.charts[0][0], E.charts[0][2]);
    std::swap(E.charts[0][1], E.charts[0][3]);
    const Cert c = certify(e, E);
    expect_rejected(c, HOT::Chart_check);
    CHECK(c.result(HOT::Chart_check).message.find("not an isometry of the disk") != std::string::npos);
  }
  {
    // the cone off its chart's origin, by far less than any edge
    HOT::Corner_embedding E = E0;
    E.chart_points[cone_point] = {{1e-30, 0.0}};
    expect_rejected(certify(e, E), HOT::Cone_check);
  }
  {
    // a chart point 1e-9 away from its vt's tile point
    HOT::Corner_embedding E = E0;
    std::size_t p = 0;
    while(!(E.point_charts[p] == 0 && p != cone_point))
      ++p;
    E.chart_points[p][0] += 1e-9;
    const Cert c = certify(e, E);
    expect_rejected(c, HOT::Chart_check);
    CHECK(c.result(HOT::Chart_check).element == Cert::Vertex);
  }
  {
    // a face with corners in two charts (a second chart, the same map)
    HOT::Corner_embedding E = E0;
    E.charts.push_back(E.charts[0]);
    E.chart_corners.push_back(E.chart_corners[0]);
    E.point_charts[cone_point] = 1;
    const Cert c = certify(e, E);
    expect_rejected(c, HOT::Chart_check);
    CHECK(c.result(HOT::Chart_check).element == Cert::Face);
  }
  {
    // arrays that do not match: an input error
    HOT::Corner_embedding E = E0;
    E.point_charts.pop_back();
    Cert c;
    CHECK(HOT::certify_corner_embedding(e.mesh, e.landmarks, E, c) == HOT::ERROR_WRONG_PARAMETER);
  }
}

TEST_CASE(neighbours_swapped)
{
  for(const Embedded* e : {&bear(), &mushroom()}) {
    if(!e->ok)
      continue;
    const std::size_t u = plain_vertex(*e, 500), w = neighbours(e->mesh, u)[0];
    HOT::Corner_embedding E = e->E;
    std::swap(E.points[point_of(E, u)], E.points[point_of(E, w)]);
    const Cert c = certify(*e, E);
    expect_rejected(c, HOT::Orientation_check);
    const Cert::Check_result& r = c.result(HOT::Orientation_check);
    CHECK(r.element == Cert::Face && (face_has(E, r.first, u) || face_has(E, r.first, w)));
  }
}

TEST_CASE(vertex_pushed_out_of_its_one_ring)
{
  for(const Embedded* e : {&bear(), &mushroom()}) {
    if(!e->ok)
      continue;
    // beyond a neighbour, on the geodesic from the vertex through it: outside the one-ring
    const std::size_t v = plain_vertex(*e, 700), w = neighbours(e->mesh, v)[0];
    HOT::Corner_embedding E = e->E;
    const std::size_t p = point_of(E, v);
    set_point(E, p, along_geodesic(point(E, p), point(E, point_of(E, w)), 2.5));
    const Cert c = certify(*e, E);
    expect_rejected(c, HOT::Orientation_check);
    CHECK(face_has(E, c.result(HOT::Orientation_check).first, v));
  }
}

TEST_CASE(vertex_collapsed_onto_a_neighbour)
{
  for(const Embedded* e : {&bear(), &mushroom()}) {
    if(!e->ok)
      continue;
    const std::size_t v = plain_vertex(*e, 900), w = neighbours(e->mesh, v)[0];
    HOT::Corner_embedding E = e->E;
    E.points[point_of(E, v)] = E.points[point_of(E, w)];
    const Cert c = certify(*e, E);
    expect_rejected(c, HOT::Degenerate_face_check);
    const std::size_t f = c.result(HOT::Degenerate_face_check).first;
    CHECK(face_has(E, f, v) && face_has(E, f, w));
  }
}

TEST_CASE(squared_coordinates_wind_twice)
{
  // z -> m(z)^2, m moving a vertex v0 to the origin: conformal and locally injective except at
  // v0, whose star winds twice around the origin. Its faces stay positive when its angles are
  // below pi/2 (they double): v0 is the first vertex far from the cut for which every face of
  // the squared map is positive (the premise, checked with the exact predicate).
  for(const Embedded* e : {&bear(), &mushroom()}) {
    if(!e->ok)
      continue;
    std::size_t v0 = 300;
    HOT::Corner_embedding E;
    for(int tries = 0; tries < 100; ++tries, ++v0) {
      v0 = plain_vertex(*e, v0);
      const Isometry m = Isometry::translation_to_origin(point(e->E, point_of(e->E, v0)));
      E = map_all_points(e->E, [&](const C& z) {
        const C w = m.apply(z);
        return w * w;
      });
      if(non_positive_faces(E) == 0)
        break;
    }
    CHECK(non_positive_faces(E) == 0);
    const Cert c = certify(*e, E);
    // the cones moved off the tile's corners; and the angle sum at v0 is 4 pi
    expect_rejected(c, HOT::Cone_check);
    const Cert::Check_result& a = c.result(HOT::Angle_sum_check);
    CHECK_MSG(a.run && a.failures == 1 && a.element == Cert::Vertex && a.first == v0, a.failures << " " << a.message);
    CHECK(a.message.find("wind") != std::string::npos);
  }
}

TEST_CASE(one_side_of_a_seam_moved_slightly)
{
  const Embedded& e = bear();
  if(!e.ok)
    return;
  // a cut vertex (two points) that is not a cone: one of its points moved by 1e-8, ten times
  // the documented position tolerance (1e-9), far below its edges' lengths
  const std::vector<std::set<std::size_t> > pts = points_of(e.E, num_vertices(e.mesh));
  std::size_t v = 0;
  while(!(pts[v].size() == 2 && !is_landmark(e, v)))
    ++v;
  const std::size_t p = *pts[v].rbegin();
  for(double d : {1e-8, 1e-6}) {
    HOT::Corner_embedding E = e.E;
    set_point(E, p, point(E, p) + C(d, 0));
    CHECK(non_positive_faces(E) == 0);
    const Cert c = certify(e, E);
    expect_rejected(c, HOT::Seam_check);
    CHECK(c.result(HOT::Angle_sum_check).failures == 0);
    const Cert::Check_result& r = c.result(HOT::Seam_check);
    CHECK(r.element == Cert::Edge && (r.first == v || r.second == v));
  }
  // within rounding of the tolerance's scale (1e-11): still accepted
  HOT::Corner_embedding E = e.E;
  set_point(E, p, point(E, p) + C(1e-11, 0));
  expect_certified(certify(e, E));
}

TEST_CASE(region_glued_by_no_side_pairing)
{
  // independence from the cut: a region rotated about the origin (an isometry fixing no
  // cone's point is in no orbifold group) keeps every face positive and every angle sum, but
  // its rim is a seam glued by no side pairing; only the gluing check can see it
  const Embedded& e = bear();
  if(!e.ok)
    return;
  const HOT::Corner_embedding R = move_region(e, plain_vertex(e, 2000), 2, Isometry::rotation(0.3));
  CHECK(non_positive_faces(R) == 0);
  const Cert c = certify(e, R);
  expect_rejected(c, HOT::Seam_check);
  for(HOT::Corner_embedding_check k : {HOT::Cone_check, HOT::Orientation_check, HOT::Degenerate_face_check, HOT::Angle_sum_check})
    CHECK(c.result(k).run && c.result(k).failures == 0);
  // a side pairing composed with a small rotation: a wrong generator
  const HOT::Orbifold_tile<> t = tile_of(e);
  const HOT::Corner_embedding W = move_region(e, plain_vertex(e, 2000), 2, t.side_pairing(2) * Isometry::rotation(1e-4));
  CHECK(non_positive_faces(W) == 0);
  expect_rejected(certify(e, W), HOT::Seam_check);
  // a disk has no seams at all: its group's side pairings are reflections
  const Embedded& m = mushroom();
  if(m.ok) {
    const HOT::Corner_embedding D = move_region(m, plain_vertex(m, 300), 2, Isometry::rotation(0.3));
    CHECK(non_positive_faces(D) == 0);
    expect_rejected(certify(m, D), HOT::Seam_check);
  }
}

TEST_CASE(everything_shrunk_towards_the_origin)
{
  for(const Embedded* e : {&bear(), &mushroom()}) {
    if(!e->ok)
      continue;
    const HOT::Corner_embedding E = map_all_points(e->E, [](const C& z) { return 0.9 * z; });
    CHECK(non_positive_faces(E) == 0);
    const Cert c = certify(*e, E);
    expect_rejected(c, HOT::Cone_check);
    CHECK(c.result(HOT::Cone_check).failures == e->landmarks.size()); // every cone left its corner
  }
}

TEST_CASE(mirror_image)
{
  // complex conjugation reverses orientation. The sphere-type tile is symmetric about the real
  // axis with p_j and q_j copies of one cone (paper, Appendix C), so the cones stay at corners
  // of their own cones and every face is flipped; the disk's regular k-gon (corner i at angle
  // 2 pi (i + 1) / k) goes to itself with corner i at corner k - 2 - i: the corners now run
  // clockwise along the boundary
  const Embedded& b = bear();
  if(b.ok) {
    const Cert c = certify(b, map_all_points(b.E, [](const C& z) { return std::conj(z); }));
    expect_rejected(c, HOT::Orientation_check);
    CHECK(c.result(HOT::Orientation_check).failures == num_faces(b.mesh));
  }
  const Embedded& m = mushroom();
  if(m.ok) {
    const Cert c = certify(m, map_all_points(m.E, [](const C& z) { return std::conj(z); }));
    expect_rejected(c, HOT::Cone_check);
    CHECK(c.result(HOT::Cone_check).message.find("counterclockwise") != std::string::npos);
  }
}

TEST_CASE(nan_and_infinite_coordinates)
{
  const Embedded& e = bear();
  if(!e.ok)
    return;
  const std::size_t v = plain_vertex(e, 1000);
  for(double bad : {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()}) {
    HOT::Corner_embedding E = e.E;
    E.points[point_of(E, v)][1] = bad;
    const Cert c = certify(e, E);
    expect_rejected(c, HOT::Finite_coordinates_check);
    CHECK(c.result(HOT::Finite_coordinates_check).element == Cert::Vertex && c.result(HOT::Finite_coordinates_check).first == v);
  }
}

TEST_CASE(point_outside_the_disk)
{
  const Embedded& e = bear();
  if(!e.ok)
    return;
  const std::size_t v = plain_vertex(e, 1000);
  const C z = point(e.E, point_of(e.E, v));
  // on the unit circle exactly (1 + 0i), and just outside it
  for(const C& bad : {C(1, 0), z / std::abs(z) * 1.001}) {
    HOT::Corner_embedding E = e.E;
    set_point(E, point_of(E, v), bad);
    const Cert c = certify(e, E);
    expect_rejected(c, HOT::Inside_disk_check);
    CHECK(c.result(HOT::Inside_disk_check).first == v);
  }
}

TEST_CASE(repeated_and_foreign_faces)
{
  const Embedded& e = bear();
  if(!e.ok)
    return;
  {
    // face 10 replaced by a copy of face 9
    HOT::Corner_embedding E = e.E;
    E.face_vertices[10] = E.face_vertices[9];
    E.face_points[10] = E.face_points[9];
    const Cert c = certify(e, E);
    expect_rejected(c, HOT::Repeated_face_check);
    CHECK(c.result(HOT::Repeated_face_check).element == Cert::Face && c.result(HOT::Repeated_face_check).first == 10);
  }
  {
    // a copy of face 0, rotated to start at another corner, appended
    HOT::Corner_embedding E = e.E;
    E.face_vertices.push_back({{E.face_vertices[0][1], E.face_vertices[0][2], E.face_vertices[0][0]}});
    E.face_points.push_back({{E.face_points[0][1], E.face_points[0][2], E.face_points[0][0]}});
    const Cert c = certify(e, E);
    expect_rejected(c, HOT::Repeated_face_check);
    CHECK(c.result(HOT::Repeated_face_check).first == E.number_of_faces() - 1);
  }
  {
    // a face reversed
    HOT::Corner_embedding E = e.E;
    std::swap(E.face_vertices[5][1], E.face_vertices[5][2]);
    std::swap(E.face_points[5][1], E.face_points[5][2]);
    const Cert c = certify(e, E);
    expect_rejected(c, HOT::Mesh_face_check);
    CHECK(c.result(HOT::Mesh_face_check).first == 5);
    CHECK(c.result(HOT::Mesh_face_check).message.find("opposite orientation") != std::string::npos);
  }
  {
    // a face missing
    HOT::Corner_embedding E = e.E;
    E.face_vertices.pop_back();
    E.face_points.pop_back();
    const Cert c = certify(e, E);
    expect_rejected(c, HOT::Mesh_face_check);
    CHECK(c.result(HOT::Mesh_face_check).element == Cert::Mesh_face);
    CHECK(c.result(HOT::Mesh_face_check).first == num_faces(e.mesh) - 1);
  }
}

TEST_CASE(disk_border_vertex_off_its_side)
{
  const Embedded& e = mushroom();
  if(!e.ok)
    return;
  const std::size_t v = border_vertex_between_landmarks(e), p = point_of(e.E, v);
  // towards the origin (inwards: the tile is convex around it), by a thousandth of its
  // shortest edge: every face stays positive
  HOT::Corner_embedding E = e.E;
  const C z = point(E, p);
  set_point(E, p, z - z / std::abs(z) * (1e-3 * shortest_edge(E, v)));
  CHECK(non_positive_faces(E) == 0);
  const Cert c = certify(e, E);
  expect_rejected(c, HOT::Border_check);
  CHECK(c.result(HOT::Border_check).first == v);
  CHECK(c.result(HOT::Border_check).message.find("off its tile side") != std::string::npos);
}

TEST_CASE(disk_border_vertex_beyond_its_segment)
{
  // on the geodesic line of its side, past the side's end corner: the line alone does not see it
  const Embedded& e = mushroom();
  if(!e.ok)
    return;
  const Cert c0 = certify(e, e.E);
  const HOT::Orbifold_tile<> t = tile_of(e);
  const std::size_t v = border_vertex_between_landmarks(e), p = point_of(e.E, v);
  const C z = point(e.E, p);
  // its side: the tile side whose geodesic passes nearest to it (it is on one, within rounding)
  int side = 0;
  double best = 1;
  for(int s = 0; s < t.number_of_sides(); ++s) {
    const C c0p = corner_point(t, t.side_source(s)), c1p = corner_point(t, t.side_target(s));
    const Isometry m = Isometry::translation_to_origin(c0p);
    const C a = m.apply(c1p), b = m.apply(z); // the geodesic is the diameter through a
    const double off = std::abs(a.real() * b.imag() - a.imag() * b.real()) / std::abs(a);
    if(off < best) { best = off; side = s; }
  }
  CHECK(best < 1e-12);
  // 0.05 past the side's end corner, on its geodesic
  const C c0p = corner_point(t, t.side_source(side)), c1p = corner_point(t, t.side_target(side));
  const C beyond = along_geodesic(c0p, c1p, 1.05);
  HOT::Corner_embedding E = e.E;
  set_point(E, p, beyond);
  const Cert c = certify(e, E);
  expect_rejected(c, HOT::Border_check);
  CHECK(c.result(HOT::Border_check).first == v);
  CHECK(c.result(HOT::Border_check).message.find("beyond the side's segment") != std::string::npos);
  (void)c0;
}

TEST_CASE(polyhedron_mesh)
{
  // any FaceGraph: the bear's embedding certified on a Polyhedron_3 copy of the mesh (its
  // vertex indices renumbered to the copy's order of vertices()), and a reversed face found there
  const Embedded& e = bear();
  if(!e.ok)
    return;
  typedef CGAL::Polyhedron_3<K> Polyhedron;
  typedef boost::graph_traits<Polyhedron>::vertex_descriptor P_vertex;
  Polyhedron P;
  std::map<vertex_descriptor, P_vertex> v2v;
  CGAL::copy_face_graph(e.mesh, P, CGAL::parameters::vertex_to_vertex_output_iterator(std::inserter(v2v, v2v.end())));
  std::map<P_vertex, std::size_t> position;
  for(P_vertex v : vertices(P))
    position.emplace(v, position.size());
  HOT::Corner_embedding E = e.E;
  for(auto& t : E.face_vertices)
    for(std::size_t& v : t)
      v = position[v2v[vertex_descriptor(static_cast<Mesh::size_type>(v))]];
  std::vector<P_vertex> cones;
  for(vertex_descriptor v : e.landmarks)
    cones.push_back(v2v[v]);
  Cert c;
  CHECK(HOT::certify_corner_embedding(P, cones, E, c) == HOT::OK);
  expect_certified(c);
  CHECK(c.number_of_seam_edges == certify(e, e.E).number_of_seam_edges);
  std::swap(E.face_points[7][0], E.face_points[7][1]);
  std::swap(E.face_vertices[7][0], E.face_vertices[7][1]);
  CHECK(HOT::certify_corner_embedding(P, cones, E, c) == HOT::OK);
  expect_rejected(c, HOT::Mesh_face_check);
}

// ------------------------------------------------------------------------------------------
// inputs the certificate refuses to look at, and the OBJ file
// ------------------------------------------------------------------------------------------

TEST_CASE(input_errors)
{
  const Embedded& e = bear();
  if(!e.ok)
    return;
  Cert c;
  std::string msg;
  std::vector<vertex_descriptor> few(e.landmarks.begin(), e.landmarks.begin() + 4);
  CHECK(HOT::certify_corner_embedding(e.mesh, few, e.E, c, &msg) == HOT::ERROR_TOO_FEW_LANDMARKS);
  std::vector<vertex_descriptor> twice = e.landmarks;
  twice[1] = twice[0];
  CHECK(HOT::certify_corner_embedding(e.mesh, twice, e.E, c, &msg) == HOT::ERROR_DUPLICATE_LANDMARK);
  CHECK(HOT::certify_corner_embedding(e.mesh, e.landmarks, e.E, c, &msg, HOT::parameters::orbifold_type(HOT::Disk_type)) ==
        HOT::ERROR_WRONG_TOPOLOGY);
  HOT::Corner_embedding E = e.E;
  E.face_points[3][1] = E.points.size();
  CHECK(HOT::certify_corner_embedding(e.mesh, e.landmarks, E, c, &msg) == HOT::ERROR_WRONG_PARAMETER);
  CHECK(msg.find("face 3") != std::string::npos);
  // a mesh of two components, and a torus-like topology, are neither a sphere nor a disk
  Mesh two = e.mesh;
  CGAL::copy_face_graph(e.mesh, two);
  CHECK(HOT::certify_corner_embedding(two, e.landmarks, e.E, c, &msg) == HOT::ERROR_SEVERAL_COMPONENTS);
  const Embedded& m = mushroom();
  if(m.ok) {
    std::vector<vertex_descriptor> inner = m.landmarks;
    inner[0] = vertex_descriptor(static_cast<Mesh::size_type>(plain_vertex(m, 0)));
    CHECK(HOT::certify_corner_embedding(m.mesh, inner, m.E, c, &msg) == HOT::ERROR_LANDMARK_NOT_ON_BORDER);
  }
}

// ------------------------------------------------------------------------------------------
// closed meshes of genus g >= 1: certified without a tile (issue 22)
// ------------------------------------------------------------------------------------------

// a closed mesh of genus g >= 1 with `k` landmarks (farthest-point sampling), embedded in the
// polygon of its cut graph
const Embedded& closed_genus(const std::string& name, int k)
{
  static std::map<std::string, Embedded> cache;
  Embedded& e = cache[name];
  if(!e.ok && num_faces(e.mesh) == 0) {
    CHECK(read_demo_mesh(name, e.mesh));
    if(k > 0)
      e.landmarks = farthest_point_landmarks(e.mesh, k);
    auto uv = e.mesh.add_property_map<halfedge_descriptor, K::Point_2>("h:uv").first;
    const HOT::Error_code ec =
      HOT::hyperbolic_orbifold_Tutte_embedding(e.mesh, e.landmarks, uv, HOT::parameters::embedding_statistics(&e.stats));
    CHECK_MSG(ec == HOT::OK, name << ": " << e.stats.message);
    CHECK(HOT::make_corner_embedding(e.mesh, uv, e.E) == HOT::OK);
    e.ok = ec == HOT::OK && e.E.number_of_faces() == num_faces(e.mesh);
  }
  return e;
}

TEST_CASE(closed_genus_package_embeddings_accepted)
{
  // eight (genus 2, no cone), elk (genus 1, one cone), helmet (genus 3, one cone)
  const struct { const char* name; int genus, cones; } cases[] = {{"eight", 2, 0}, {"elk", 1, 1}, {"helmet", 3, 1}};
  for(const auto& t : cases) {
    const Embedded& e = closed_genus(t.name, t.cones);
    if(!e.ok)
      continue;
    const Cert c = certify(e, e.E);
    expect_certified(c);
    CHECK(c.genus == t.genus);
    // Gauss-Bonnet: 2 pi (2g - 2 + k / 2)
    const double area = 2 * CGAL_PI * (2 * t.genus - 2 + 0.5 * t.cones);
    CHECK_MSG(c.area_lower <= area && area <= c.area_upper, t.name << ": area [" << c.area_lower << ", " << c.area_upper << "]");
    CHECK(std::abs(c.expected_area - area) < 1e-12);
    CHECK(c.max_angle_sum_deviation < 1e-9);
    CHECK(c.angle_sum_tolerance > 0);
    CHECK(c.number_of_seam_edges > 0 && c.number_of_seam_isometries > 0 && c.number_of_seam_consistency_checks > 0);
    CHECK(c.max_seam_mismatch < 1e-12);
    for(int o : c.cone_orders)
      CHECK(o == 2);
  }
}

TEST_CASE(closed_genus_tampered_rejected)
{
  const Embedded& e = closed_genus("elk", 1);
  if(!e.ok)
    return;
  const std::size_t V = num_vertices(e.mesh);
  const std::vector<std::set<std::size_t> > pts = points_of(e.E, V);
  const std::size_t cone = e.landmarks[0].idx();
  // an interior vertex (one point, its neighbours too) moved across a neighbour: flipped faces
  for(std::size_t v = 0; v < V; ++v) {
    const std::vector<std::size_t> nb = neighbours(e.mesh, v);
    bool interior = pts[v].size() == 1;
    for(std::size_t w : nb)
      interior = interior && pts[w].size() == 1;
    if(!interior)
      continue;
    HOT::Corner_embedding E = e.E;
    const C z = point(E, *pts[v].begin()), n = point(E, *pts[nb[0]].begin());
    set_point(E, *pts[v].begin(), 2.0 * n - z);
    expect_rejected(certify(e, E), HOT::Orientation_check);
    break;
  }
  // one copy of a seam vertex (not the cone) moved by 1e-6: its seams' isometries break
  for(std::size_t v = 0; v < V; ++v) {
    if(pts[v].size() < 2 || v == cone)
      continue;
    HOT::Corner_embedding E = e.E;
    set_point(E, *pts[v].begin(), point(E, *pts[v].begin()) + C(1e-6, 0));
    const Cert c = certify(e, E);
    CHECK(!c.is_certified());
    CHECK_MSG(c.checks[HOT::Seam_check].failures > 0, c.summary());
    break;
  }
  // a cone claimed at one more vertex: its angle sum is 2 pi, not pi
  {
    Cert c;
    std::string msg;
    std::vector<vertex_descriptor> more = e.landmarks;
    more.push_back(vertex_descriptor(static_cast<Mesh::size_type>(cone == 0 ? 1 : 0)));
    CHECK(HOT::certify_corner_embedding(e.mesh, more, e.E, c, &msg) == HOT::OK);
    expect_rejected(c, HOT::Angle_sum_check);
    // and the wrong order: 3
    CHECK(HOT::certify_corner_embedding(e.mesh, e.landmarks, e.E, c, &msg, HOT::parameters::cone_orders(std::vector<int>{3})) == HOT::OK);
    expect_rejected(c, HOT::Angle_sum_check);
    // the cone dropped: a torus without cone is not hyperbolic
    CHECK(HOT::certify_corner_embedding(e.mesh, std::vector<vertex_descriptor>(), e.E, c, &msg) == HOT::ERROR_NOT_HYPERBOLIC);
  }
  // another mesh's embedding (eight's): not its faces
  const Embedded& other = closed_genus("eight", 0);
  if(other.ok) {
    Cert c;
    std::string msg;
    CHECK(HOT::certify_corner_embedding(e.mesh, e.landmarks, other.E, c, &msg) == HOT::OK);
    CHECK(!c.is_certified());
    CHECK(c.checks[HOT::Mesh_face_check].failures > 0);
  }
}

TEST_CASE(obj_file_round_trip)
{
  // the OBJ file embed writes (faces from another corner, vt shared per vertex), read back
  const Embedded& e = bear();
  if(!e.ok)
    return;
  auto uv = e.mesh.property_map<halfedge_descriptor, K::Point_2>("h:uv").first;
  const std::string path = "test_certify_round_trip.obj";
  {
    std::ofstream out(path);
    hot_tools::write_embedding_obj(out, e.mesh, uv);
  }
  HOT::Corner_embedding E;
  std::size_t nv = 0;
  const HOT::Status r = hot_tools::read_embedding_obj(path, E, nv);
  CHECK_MSG(r, r.message);
  CHECK(nv == num_vertices(e.mesh));
  CHECK(E.number_of_faces() == num_faces(e.mesh));
  CHECK(E.points.size() == e.E.points.size());
  const Cert a = certify(e, e.E), b = certify(e, E);
  expect_certified(b);
  CHECK(a.number_of_seam_edges == b.number_of_seam_edges && a.cone_order == b.cone_order);
  // corners without a point index, and a quad, are read errors naming the line
  {
    std::ofstream out(path);
    out << "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 0.1 0\nvt 0 0.1\nf 1/1 2/2 3\n";
  }
  const HOT::Status r2 = hot_tools::read_embedding_obj(path, E, nv);
  CHECK(!r2 && r2.message.find("line 7") != std::string::npos && r2.message.find("no point (vt) index") != std::string::npos);
  {
    std::ofstream out(path);
    out << "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nvt 0 0\nf 1/1 2/1 3/1 4/1\n";
  }
  const HOT::Status r3 = hot_tools::read_embedding_obj(path, E, nv);
  CHECK(!r3 && r3.message.find("triangles") != std::string::npos);
  {
    std::ofstream out(path);
    out << "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt nan 0\nvt 0.1 0\nvt 0 0.1\nf 1/1 2/2 3/4\n";
  }
  const HOT::Status r4 = hot_tools::read_embedding_obj(path, E, nv);
  CHECK(!r4 && r4.message.find("point index 4") != std::string::npos);
  std::remove(path.c_str());
}

HOT_TEST_MAIN
