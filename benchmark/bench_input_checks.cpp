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
// test_input_checks.large_meshes_are_built_and_checked (n = 200, k = 200K), without timings.
// Run by scripts/benchmark.sh.

#include "bench_common.h"

#include <CGAL/Hyperbolic_orbifold_Tutte/check_input.h>
#include <io/polygon_soup_to_mesh.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

namespace {

hot_tools::Polygon_soup cube_surface(int n)
{
  hot_tools::Polygon_soup soup;
  std::vector<int> id(std::size_t(n + 1) * (n + 1) * (n + 1), -1);
  auto vid = [&](int x, int y, int z) {
    int& i = id[(std::size_t(x) * (n + 1) + y) * (n + 1) + z];
    if(i < 0) {
      i = int(soup.points.size());
      soup.points.push_back({ { double(x), double(y), double(z) } });
    }
    return std::size_t(i);
  };
  for(int axis = 0; axis < 3; ++axis)
    for(int side = 0; side < 2; ++side)
      for(int i = 0; i < n; ++i)
        for(int j = 0; j < n; ++j) {
          auto pt = [&](int u, int v) {
            int c[3];
            c[axis] = side ? n : 0;
            c[(axis + 1) % 3] = u;
            c[(axis + 2) % 3] = v;
            return vid(c[0], c[1], c[2]);
          };
          const std::size_t a = pt(i, j), b = pt(i + 1, j), c = pt(i + 1, j + 1), d = pt(i, j + 1);
          const std::size_t t[2][3] = { { a, b, c }, { a, c, d } };
          for(auto& tri : t) {
            if(side)
              soup.face_vertices.insert(soup.face_vertices.end(), { tri[0], tri[1], tri[2] });
            else
              soup.face_vertices.insert(soup.face_vertices.end(), { tri[0], tri[2], tri[1] });
            soup.end_face();
          }
        }
  return soup;
}

hot_tools::Polygon_soup fan(std::size_t k)
{
  hot_tools::Polygon_soup f;
  f.points.push_back({ { 0, 0, 0 } });
  for(std::size_t i = 0; i <= k; ++i) {
    const double a = 3.0 * double(i) / double(k); // less than a full turn
    f.points.push_back({ { std::cos(a), std::sin(a), 0 } });
  }
  for(std::size_t i = 1; i <= k; ++i) {
    f.face_vertices.insert(f.face_vertices.end(), { 0, i, i + 1 });
    f.end_face();
  }
  return f;
}

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
    const hot_tools::Polygon_soup soup = cube_surface(n);
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
    const hot_tools::Polygon_soup f = fan(k);
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
