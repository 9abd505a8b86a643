// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Times the input path of the command-line program on large generated meshes: the polygon
// soup's validation and the mesh build (hot_tools::polygon_soup_to_mesh) and the checks
// (HOT::check_mesh, HOT::check_landmarks) at growing sizes, with the ratio of the times of
// consecutive sizes (linear time: the ratio of the sizes):
//   1. the surface of an n x n x n grid cube (6 n^2 + 2 vertices), n = 50, 100, 200, 400
//      (4x the size per step);
//   2. a fan of k triangles around one vertex (a disk), k = 50K to 400K (2x per step;
//      Euler::add_face would be quadratic there: 4).
// The sizes and the results' sanity (OK, vertex counts) are asserted by the test suite's
// test_input_checks.large_meshes_are_built_and_checked (n = 200, k = 200K), without timings,
// on the same generated meshes (test/generated_meshes.h).
// Run by scripts/benchmark.sh.

#include "bench_common.h"
#include "generated_meshes.h" // (generators/: the meshes the test suite checks)

#include <CGAL/Hyperbolic_orbifold_Tutte/check_input.h>
#include <hot_app/io/polygon_soup_to_mesh.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

namespace {

[[noreturn]] void fail(const char* what)
{
  std::fprintf(stderr, "bench_input_checks: %s failed\n", what);
  std::exit(EXIT_FAILURE);
}

} // namespace

int main()
{
  std::printf("%-26s %10s %10s %10s %10s %8s\n", "mesh", "vertices", "build_s", "check_s", "total_s", "ratio");
  double previous = 0;
  for(const int n : { 50, 100, 200, 400 }) {
    const hot_tools::Polygon_soup soup = hot_generated::cube_surface(n);
    SM sm;
    Clock::time_point t0 = Clock::now();
    if(!hot_tools::polygon_soup_to_mesh(soup, sm)) fail("building the cube");
    const double build = seconds_since(t0);
    t0 = Clock::now();
    HOT::Mesh_info info;
    if(!HOT::check_mesh(sm, HOT::Sphere_type, &info)) fail("checking the cube");
    const double check = seconds_since(t0), total = build + check;
    char name[64];
    std::snprintf(name, sizeof(name), "cube surface n=%d", n);
    std::printf("%-26s %10zu %10.3f %10.3f %10.3f %8s\n", name, info.number_of_vertices, build, check, total,
                previous > 0 ? std::to_string(total / previous).substr(0, 5).c_str() : "-");
    previous = total;
  }
  std::printf("(ratio: time over the previous size's; the size grows 4x per line, linear code gives about 4)\n");
  previous = 0;
  for(const std::size_t k : { 50000, 100000, 200000, 400000 }) {
    const hot_tools::Polygon_soup f = hot_generated::fan(k);
    SM sm;
    Clock::time_point t0 = Clock::now();
    if(!hot_tools::polygon_soup_to_mesh(f, sm)) fail("building the fan");
    const double build = seconds_since(t0);
    t0 = Clock::now();
    std::vector<SM::Vertex_index> lm;
    if(!HOT::check_mesh(sm, HOT::Disk_type) || !HOT::check_landmarks(sm, { 0, 1, 1000, k / 2, k + 1 }, HOT::Disk_type, lm))
      fail("checking the fan");
    const double check = seconds_since(t0), total = build + check;
    char name[64];
    std::snprintf(name, sizeof(name), "fan of %zu triangles", k);
    std::printf("%-26s %10zu %10.3f %10.3f %10.3f %8s\n", name, num_vertices(sm), build, check, total,
                previous > 0 ? std::to_string(total / previous).substr(0, 5).c_str() : "-");
    previous = total;
  }
  std::printf("(ratio: the size doubles per line, linear code gives about 2, quadratic 4)\n");
  std::printf("peak memory %.0f MiB\n", peak_rss_mb());
  return EXIT_SUCCESS;
}
