// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Orbifold tiles and their groups (paper section 3 and Appendix C; NOTES.md):
// Gauss-Bonnet areas, the golden ratio for k = 5, side pairings, cone stabilisers,
// the local tiling around every corner, and reduction of points to the tile.

#include "test_harness.h"

#include <CGAL/Hyperbolic_orbifold_Tutte/Orbifold_tile.h>

#include <CGAL/Random.h>

#include <algorithm>
#include <complex>
#include <vector>

namespace HOT = CGAL::Hyperbolic_orbifold_Tutte;
typedef HOT::Poincare_disk_traits_2<> Traits;
typedef HOT::Orbifold_tile<Traits> Tile;
typedef Traits::Point_2 Point;
typedef Traits::Isometry Isometry;
typedef Isometry::Complex C;

static CGAL::Random rng(4242);
static const Traits tr;

static C to_c(const Point& p) { return C(p.x(), p.y()); }
static Point to_p(const C& c) { return Point(c.real(), c.imag()); }
static double dist(const C& a, const C& b) { return tr.compute_hyperbolic_distance_2_object()(to_p(a), to_p(b)); }

static Tile make(HOT::Orbifold_type type, int k)
{
  Tile t;
  const HOT::Error_code ec = HOT::make_orbifold_tile(type, k, t);
  CHECK(ec == HOT::OK);
  return t;
}

static const HOT::Orbifold_type types[] = {HOT::Sphere_type, HOT::Disk_type};

TEST_CASE(not_hyperbolic_below_five_cones)
{
  for(HOT::Orbifold_type type : types) {
    for(int k : {-1, 0, 1, 2, 3, 4}) {
      Tile t;
      CHECK(HOT::make_orbifold_tile(type, k, t) == HOT::ERROR_NOT_HYPERBOLIC);
      CHECK(t.number_of_corners() == 0); // left unchanged
    }
    Tile t;
    CHECK(HOT::make_orbifold_tile(type, 5, t) == HOT::OK);
  }
  // 1 - k/4 < 0 (sphere) <=> k >= 5: the Euclidean case k = 4 has Euler characteristic 0
  CHECK(std::abs(HOT::Orbifold_signature::sphere(4).euler_characteristic()) < 1e-15);
  CHECK(!HOT::Orbifold_signature::sphere(4).is_hyperbolic());
  CHECK(HOT::Orbifold_signature::sphere(5).is_hyperbolic());
  CHECK(!HOT::Orbifold_signature::disk(4).is_hyperbolic());
  CHECK(HOT::Orbifold_signature::disk(5).is_hyperbolic());
  CHECK(std::string(HOT::error_message(HOT::ERROR_NOT_HYPERBOLIC)).find("hyperbolic") != std::string::npos);
  // a signature the package cannot tile yet is refused, not mis-built
  Tile t;
  CHECK(HOT::make_orbifold_tile(HOT::Orbifold_signature(HOT::Sphere_type, {3, 3, 3, 3}), t) != HOT::OK);
}

TEST_CASE(disk_tile_side_lengths)
{
  auto d = tr.compute_hyperbolic_distance_2_object();
  auto angle = tr.compute_hyperbolic_angle_2_object();
  // k = 5: cosh(side) is the golden ratio (NOTES.md)
  const Tile t5 = make(HOT::Disk_type, 5);
  const double golden = (1 + std::sqrt(5.0)) / 2;
  for(int i = 0; i < 5; ++i)
    CHECK_NEAR(std::cosh(d(t5.corner(i), t5.corner((i + 1) % 5))), golden, 1e-12);
  for(int k = 5; k <= 50; ++k) {
    const Tile t = make(HOT::Disk_type, k);
    CHECK(t.number_of_corners() == k);
    for(int i = 0; i < k; ++i) {
      const Point a = t.corner((i + k - 1) % k), b = t.corner(i), c = t.corner((i + 1) % k);
      // cosh(s/2) = cos(pi/k) / sin(pi/4); right angles at every corner
      CHECK_NEAR(std::cosh(d(b, c) / 2), std::cos(CGAL_PI / k) / std::sin(CGAL_PI / 4), 1e-11);
      CHECK_NEAR(angle(b, a, c), CGAL_PI / 2, 1e-11);
      CHECK_NEAR(t.corner_angle(i), CGAL_PI / 2, 0);
      CHECK(t.corner_cone(i) == i);
      CHECK(t.cone_corner(i) == i);
    }
  }
}

// Area of the tile as a sum of geodesic triangles fanned from the origin (an interior point).
static double fan_area(const Tile& t)
{
  auto area = tr.compute_hyperbolic_triangle_area_2_object();
  double s = 0;
  for(int i = 0; i < t.number_of_sides(); ++i)
    s += area(Point(0, 0), t.corner(t.side_source(i)), t.corner(t.side_target(i)));
  return s;
}

TEST_CASE(tile_area_is_gauss_bonnet)
{
  auto angle = tr.compute_hyperbolic_angle_2_object();
  for(int k = 5; k <= 50; ++k) {
    const Tile s = make(HOT::Sphere_type, k), dk = make(HOT::Disk_type, k);
    CHECK_NEAR(fan_area(s), (k - 4) * CGAL_PI, 1e-9 * k);
    CHECK_NEAR(fan_area(dk), (k - 4) * CGAL_PI / 2, 1e-9 * k);
    CHECK_NEAR(s.area(), (k - 4) * CGAL_PI, 1e-12 * k);
    CHECK_NEAR(dk.area(), (k - 4) * CGAL_PI / 2, 1e-12 * k);
    // polygon: (n - 2) pi - sum of measured interior angles = area; the stored angles match
    for(const Tile* t : {&s, &dk}) {
      const int n = t->number_of_corners();
      double sum = 0;
      for(int i = 0; i < n; ++i) {
        const double a = angle(t->corner(i), t->corner((i + n - 1) % n), t->corner((i + 1) % n));
        CHECK_NEAR(a, t->corner_angle(i), 1e-9);
        sum += a;
      }
      CHECK_NEAR((n - 2) * CGAL_PI - sum, t->area(), 1e-8 * k);
    }
    // the sphere tile has 2k - 2 corners; every cone has total angle pi
    CHECK(s.number_of_corners() == 2 * k - 2);
    std::vector<double> cone_total(k, 0.0);
    for(int i = 0; i < s.number_of_corners(); ++i)
      cone_total[s.corner_cone(i)] += s.corner_angle(i);
    for(int c = 0; c < k; ++c)
      CHECK_NEAR(cone_total[c], CGAL_PI, 1e-12);
  }
}

TEST_CASE(sphere_tile_layout)
{
  for(int k = 5; k <= 20; ++k) {
    const Tile t = make(HOT::Sphere_type, k);
    // p_1 on the positive, p_k on the negative real axis, the origin their geodesic midpoint
    const Point p1 = t.cone_point(0), pk = t.cone_point(k - 1);
    CHECK(p1.y() == 0 && p1.x() > 0 && pk.y() == 0 && pk.x() < 0);
    CHECK_NEAR(p1.x(), -pk.x(), 1e-15);
    // p_2..p_{k-1} in the upper half disk, their mirror images q_j = conj(p_j) in the lower
    for(int c = 1; c < k - 1; ++c) {
      int copies = 0;
      for(int i = 0; i < t.number_of_corners(); ++i)
        if(t.corner_cone(i) == c) {
          ++copies;
          CHECK(t.corner(i).x() == t.cone_point(c).x());
          CHECK(std::abs(t.corner(i).y()) == std::abs(t.cone_point(c).y()));
        }
      CHECK(copies == 2);
      CHECK(t.cone_point(c).y() > 0);
    }
    // the corners are counterclockwise and the tile is convex (exact orientation)
    auto orient = tr.hyperbolic_orientation_2_object();
    const int n = t.number_of_corners();
    for(int i = 0; i < n; ++i) {
      const CGAL::Orientation o = orient(t.corner(i), t.corner((i + 1) % n), t.corner((i + 2) % n));
      // p_1 and p_k are straight corners (angle pi, collinear up to the rounding of the
      // corner coordinates); all others are strict left turns
      const int mid = (i + 1) % n;
      if(mid == 0 || mid == k - 1)
        CHECK_NEAR(tr.compute_hyperbolic_angle_2_object()(t.corner(mid), t.corner(i), t.corner((i + 2) % n)), CGAL_PI, 1e-12);
      else
        CHECK(o == CGAL::LEFT_TURN);
    }
    // the origin, geodesic midpoint of p_k p_1, is interior: that side is shared by the two halves
    CHECK(t.bounded_side(Point(0, 0)) == CGAL::ON_BOUNDED_SIDE);
  }
}

TEST_CASE(side_pairings)
{
  for(HOT::Orbifold_type type : types) {
    for(int k = 5; k <= 12; ++k) {
      const Tile t = make(type, k);
      for(int i = 0; i < t.number_of_sides(); ++i) {
        const int j = t.paired_side(i);
        const Isometry& g = t.side_pairing(i);
        CHECK(t.paired_side(j) == i);
        CHECK((t.side_pairing(j) * g).is_identity(1e-9));
        CHECK(g.is_orientation_preserving() == (type == HOT::Sphere_type));
        const C a = to_c(t.corner(t.side_source(i))), b = to_c(t.corner(t.side_target(i)));
        const C a2 = to_c(t.corner(t.side_source(j))), b2 = to_c(t.corner(t.side_target(j)));
        // orientation-preserving gluing reverses the side's direction; reflections fix it
        const C ga = g.apply(a), gb = g.apply(b);
        if(type == HOT::Sphere_type) {
          CHECK(j != i);
          CHECK(dist(ga, b2) < 1e-9 && dist(gb, a2) < 1e-9);
          // glued corners are copies of the same cone
          CHECK(t.corner_cone(t.side_source(i)) == t.corner_cone(t.side_target(j)));
          CHECK(t.corner_cone(t.side_target(i)) == t.corner_cone(t.side_source(j)));
        } else {
          CHECK(j == i);
          CHECK(dist(ga, a) < 1e-9 && dist(gb, b) < 1e-9);
        }
        // the geodesic midpoint goes to the midpoint: the whole side is mapped onto the paired side
        const Point m = tr.construct_hyperbolic_midpoint_2_object()(to_p(a), to_p(b));
        const Point m2 = tr.construct_hyperbolic_midpoint_2_object()(to_p(a2), to_p(b2));
        CHECK(dist(g.apply(to_c(m)), to_c(m2)) < 1e-9);
        // an isometry: random distances preserved
        for(int r = 0; r < 10; ++r) {
          const C x(rng.get_double(-0.6, 0.6), rng.get_double(-0.6, 0.6)), y(rng.get_double(-0.6, 0.6), rng.get_double(-0.6, 0.6));
          CHECK_NEAR(dist(g.apply(x), g.apply(y)), dist(x, y), 1e-9);
        }
        // the neighbour across side i, side_pairing(i)^-1 (tile), lies on the other side of side i
        const C inner = g.inverse().apply(C(0.0, 0.0));
        CHECK(tr.side_of_oriented_hyperbolic_segment_2_object()(to_p(a), to_p(b), to_p(inner)) == CGAL::ON_NEGATIVE_SIDE);
      }
    }
  }
}

TEST_CASE(cone_stabilisers)
{
  for(HOT::Orbifold_type type : types) {
    for(int k = 5; k <= 9; ++k) {
      const Tile t = make(type, k);
      const std::vector<Isometry> group = t.group_elements(3);
      for(int i = 0; i < t.number_of_corners(); ++i) {
        const C v = to_c(t.corner(i));
        std::vector<Isometry> stab;
        for(const Isometry& g : group)
          if(!g.is_identity(1e-9) && dist(g.apply(v), v) < 1e-9)
            stab.push_back(g);
        if(type == HOT::Sphere_type) {
          // a cone of angle pi: its stabiliser is {id, half-turn}
          CHECK_MSG(stab.size() == 1, "corner " << i << " of k=" << k << ": " << stab.size() << " elements");
          for(const Isometry& g : stab) {
            CHECK(g.is_orientation_preserving());
            CHECK(std::abs(g.derivative(v).real() + 1) < 1e-9 && std::abs(g.derivative(v).imag()) < 1e-9);
            CHECK((g * g).is_identity(1e-9));
          }
        } else {
          // a corner of angle pi/2 of a reflection group: dihedral of order 4 (two reflections, one half-turn)
          CHECK_MSG(stab.size() == 3, "corner " << i << " of k=" << k << ": " << stab.size() << " elements");
          int reflections = 0, half_turns = 0;
          for(const Isometry& g : stab) {
            CHECK((g * g).is_identity(1e-9));
            if(g.is_orientation_preserving()) {
              ++half_turns;
              CHECK(std::abs(g.derivative(v).real() + 1) < 1e-9);
            } else {
              ++reflections;
            }
          }
          CHECK(reflections == 2 && half_turns == 1);
        }
      }
    }
  }
}

TEST_CASE(tiling_around_every_corner)
{
  auto angle = tr.compute_hyperbolic_angle_2_object();
  for(HOT::Orbifold_type type : types) {
    for(int k = 5; k <= 9; ++k) {
      const Tile t = make(type, k);
      const int n = t.number_of_corners();
      const std::vector<Isometry> group = t.group_elements(4);
      for(int i = 0; i < n; ++i) {
        const C v = to_c(t.corner(i));
        // the sectors at v of all tile images g(T) having a corner at v
        std::vector<std::pair<double, double> > sectors; // (start direction, angle)
        for(const Isometry& g : group) {
          for(int j = 0; j < n; ++j) {
            if(dist(g.apply(to_c(t.corner(j))), v) > 1e-8)
              continue;
            const C prev = g.apply(to_c(t.corner((j + n - 1) % n)));
            const C next = g.apply(to_c(t.corner((j + 1) % n)));
            // interior angle at the corner, measured on the image
            const double a = angle(to_p(v), to_p(next), to_p(prev));
            CHECK_NEAR(a, t.corner_angle(j), 1e-8);
            // counterclockwise tile images: the interior goes from the direction of next to that of prev
            // (for a reflected copy the order flips)
            const Isometry to0 = Isometry::translation_to_origin(v);
            const C dn = to0.apply(next), dp = to0.apply(prev);
            const double start = g.is_orientation_preserving() ? std::atan2(dn.imag(), dn.real()) : std::atan2(dp.imag(), dp.real());
            sectors.push_back(std::make_pair(start, a));
          }
        }
        double total = 0;
        for(auto& s : sectors)
          total += s.second;
        CHECK_MSG(std::abs(total - 2 * CGAL_PI) < 1e-7,
                  (type == HOT::Sphere_type ? "sphere" : "disk") << " k=" << k << " corner " << i << ": total " << total
                                                                 << " from " << sectors.size() << " tiles");
        // no overlap: sorted by start, each sector ends where the next begins
        std::sort(sectors.begin(), sectors.end());
        for(std::size_t s = 0; s < sectors.size(); ++s) {
          const double end = sectors[s].first + sectors[s].second;
          const double next_start = (s + 1 < sectors.size()) ? sectors[s + 1].first : sectors[0].first + 2 * CGAL_PI;
          CHECK_NEAR(end, next_start, 1e-7);
        }
      }
    }
  }
}

// a random point well inside the tile: a convex combination in a fan triangle, away from its sides
static Point random_interior_point(const Tile& t)
{
  const int i = rng.get_int(0, t.number_of_sides());
  const Point a = tr.construct_Klein_point_2_object()(t.corner(t.side_source(i)));
  const Point b = tr.construct_Klein_point_2_object()(t.corner(t.side_target(i)));
  double w1 = rng.get_double(0.05, 1), w2 = rng.get_double(0.05, 1), w0 = rng.get_double(0.05, 1);
  const double s = w0 + w1 + w2;
  w0 /= s; w1 /= s; w2 /= s;
  return tr.construct_Poincare_point_2_object()(Point(w1 * a.x() + w2 * b.x(), w1 * a.y() + w2 * b.y()));
}

// hyperbolic distance from p to the tile (0 when inside), through the sides' geodesics
static double distance_outside(const Tile& t, const Point& p)
{
  double worst = 0;
  for(int i = 0; i < t.number_of_sides(); ++i) {
    const C a = to_c(t.corner(t.side_source(i))), b = to_c(t.corner(t.side_target(i)));
    const Isometry to0 = Isometry::translation_to_origin(a);
    const C b0 = to0.apply(b);
    const Isometry align = Isometry::rotation(-std::arg(b0)) * to0; // side on the real axis, tile above
    const C w = align.apply(to_c(p));
    if(w.imag() < 0)
      worst = std::max(worst, std::asinh(2 * -w.imag() / (1 - HOT::internal::squared_modulus(w))));
  }
  return worst;
}

TEST_CASE(reduce_to_tile)
{
  for(HOT::Orbifold_type type : types) {
    for(int k : {5, 6, 7, 11, 23, 50}) {
      const Tile t = make(type, k);
      std::size_t max_steps = 0;
      for(int trial = 0; trial < 400; ++trial) {
        // radius up to 1 - 1e-9
        const double r = 1 - std::pow(10.0, -rng.get_double(0, 9));
        const double th = rng.get_double(0, 2 * CGAL_PI);
        const Point p(r * std::cos(th), r * std::sin(th));
        const Tile::Reduction red = t.reduce_to_tile(p);
        max_steps = std::max(max_steps, red.steps);
        CHECK_MSG(t.bounded_side(red.point) != CGAL::ON_UNBOUNDED_SIDE || distance_outside(t, red.point) < 1e-9,
                  "k=" << k << " r=1-" << 1 - r << " lands outside by " << distance_outside(t, red.point));
        // the returned element maps the input onto the returned point
        // (evaluating the composed element at a point near the circle cancels about
        // 1 / (1 - |p|^2) digits of its rounded coefficients, hence the tolerance)
        const C img = red.element.apply(to_c(p));
        const double tol = 1e-7 + 1e-12 / (1 - r * r);
        CHECK_MSG(dist(img, to_c(red.point)) < tol, "k=" << k << " r=1-" << 1-r << " steps " << red.steps << " element image off by " << dist(img, to_c(red.point)));
        // idempotent
        const Tile::Reduction again = t.reduce_to_tile(red.point);
        CHECK(dist(to_c(again.point), to_c(red.point)) < 1e-9);
        CHECK(again.element.is_identity(1e-6));
      }
      CHECK(max_steps < 1000);
      // known answer: an interior point moved by a random word of the group comes back, with the inverse word
      for(int trial = 0; trial < 200; ++trial) {
        const Point x = random_interior_point(t);
        // the word is applied in long double so that the test's own rounding stays far below the tolerance
        typedef HOT::Hyperbolic_isometry_2<long double> IL;
        Isometry g;
        const int len = rng.get_int(1, 25);
        IL::Complex zl(x.x(), x.y());
        for(int l = 0; l < len; ++l) {
          const Isometry& s = t.side_pairing(rng.get_int(0, t.number_of_sides()));
          const IL sl(s);
          // Stay where the answer is unique to 1e-6: the greedy reduction may return through
          // another word equal to g^-1 in the group (e.g. a half-turn instead of its inverse);
          // with rounded generators such relations hold to about 1e-16 |a|^2 and the defect
          // grows like 1 / (1 - |z|^2) with the distance (measured: 2e-6 at 1e-8 for k = 50).
          if(1 - HOT::internal::squared_modulus(sl.apply(zl)) < 1e-6)
            break;
          g = s * g;
          zl = sl.apply(zl);
        }
        const C z(static_cast<double>(zl.real()), static_cast<double>(zl.imag()));
        const Tile::Reduction red = t.reduce_to_tile(to_p(z));
        CHECK_MSG(dist(to_c(red.point), to_c(x)) < 1e-6, "k=" << k << " type " << type << " 1-|z|^2=" << 1 - HOT::internal::squared_modulus(z) << " steps " << red.steps << " back off by " << dist(to_c(red.point), to_c(x)) << " x=" << x);
        CHECK(red.element.is_close(g.inverse(), 1e-6));
      }
    }
  }
}

TEST_CASE(tile_images_do_not_overlap)
{
  for(HOT::Orbifold_type type : types) {
    for(int k : {5, 7}) {
      const Tile t = make(type, k);
      const std::vector<Isometry> group = t.group_elements(3);
      std::vector<Isometry> inverses;
      for(const Isometry& g : group)
        inverses.push_back(g.inverse());
      for(int trial = 0; trial < 300; ++trial) {
        const C z(rng.get_double(-0.3, 0.3), rng.get_double(-0.3, 0.3));
        int count = 0, boundary = 0;
        for(const Isometry& gi : inverses) {
          const CGAL::Bounded_side s = t.bounded_side(to_p(gi.apply(z)));
          count += (s == CGAL::ON_BOUNDED_SIDE);
          boundary += (s == CGAL::ON_BOUNDARY);
        }
        // every point near the origin is in exactly one tile image (or on shared sides)
        CHECK_MSG(count == 1 || (count == 0 && boundary >= 2), "count " << count << " boundary " << boundary);
      }
    }
  }
}

HOT_TEST_MAIN
