// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Times the kernel pieces that later stages call per vertex: the exact orientation
// predicate (filtered) and reduce_to_tile for points spread up to |z| = 1 - 1e-9.

#include <CGAL/hyperbolic_orbifold_Tutte.h>
#include <CGAL/Random.h>

#include <chrono>
#include <cstdio>
#include <vector>

namespace HOT = CGAL::Hyperbolic_orbifold_Tutte;
typedef HOT::Poincare_disk_traits_2<> Traits;
typedef Traits::Point_2 Point;

int main()
{
  CGAL::Random rng(1);
  const int n = 1000000;
  std::vector<Point> pts;
  for(int i = 0; i < n; ++i) {
    const double r = 1 - std::pow(10.0, -rng.get_double(0, 9)), t = rng.get_double(0, 6.283185307179586);
    pts.push_back(Point(r * std::cos(t), r * std::sin(t)));
  }
  Traits tr;
  auto orient = tr.hyperbolic_orientation_2_object();
  auto t0 = std::chrono::steady_clock::now();
  long s = 0;
  for(int i = 0; i + 2 < n; ++i)
    s += orient(pts[i], pts[i + 1], pts[i + 2]);
  auto t1 = std::chrono::steady_clock::now();
  std::printf("orientation predicate: %.1f ns per call (checksum %ld)\n",
              std::chrono::duration<double, std::nano>(t1 - t0).count() / (n - 2), s);
  for(HOT::Orbifold_type type : {HOT::Sphere_type, HOT::Disk_type})
    for(int k : {5, 7, 23, 50}) {
      HOT::Orbifold_tile<Traits> tile;
      HOT::make_orbifold_tile(type, k, tile);
      const int m = 200000;
      std::size_t steps = 0, max_steps = 0;
      t0 = std::chrono::steady_clock::now();
      for(int i = 0; i < m; ++i) {
        const auto r = tile.reduce_to_tile(pts[i]);
        steps += r.steps;
        max_steps = std::max(max_steps, r.steps);
      }
      t1 = std::chrono::steady_clock::now();
      std::printf("reduce_to_tile %-6s k=%-2d: %.2f us per point, %.1f steps on average, %zu at most\n",
                  type == HOT::Sphere_type ? "sphere" : "disk", k,
                  std::chrono::duration<double, std::micro>(t1 - t0).count() / m, double(steps) / m, max_steps);
    }
  return 0;
}
