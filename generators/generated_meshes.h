// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Large generated polygon soups, shared by the test suite (test_input_checks: the results
// checked) and the benchmark (bench_input_checks: the times measured) so that both run on
// the same meshes. Not installed: the package does not need it.

#ifndef HOT_TEST_GENERATED_MESHES_H
#define HOT_TEST_GENERATED_MESHES_H

#include <hot_app/io/polygon_soup.h>

#include <cmath>
#include <cstddef>
#include <vector>

namespace hot_generated {

// the surface of an n x n x n grid cube, outward triangles: a closed genus-0 mesh of
// 6 n^2 + 2 vertices and 12 n^2 triangles (Euler: V - E + F = 2 with E = 3F/2)
inline hot_tools::Polygon_soup cube_surface(int n)
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

// a fan of k triangles around one vertex, less than a full turn: a disk of k + 2 vertices
// (Euler::add_face would be quadratic here, polygon_soup_to_mesh is not)
inline hot_tools::Polygon_soup fan(std::size_t k)
{
  hot_tools::Polygon_soup f;
  f.points.push_back({ { 0, 0, 0 } });
  for(std::size_t i = 0; i <= k; ++i) {
    const double a = 3.0 * double(i) / double(k);
    f.points.push_back({ { std::cos(a), std::sin(a), 0 } });
  }
  for(std::size_t i = 1; i <= k; ++i) {
    f.face_vertices.insert(f.face_vertices.end(), { 0, i, i + 1 });
    f.end_face();
  }
  return f;
}

} // namespace hot_generated

#endif // HOT_TEST_GENERATED_MESHES_H
