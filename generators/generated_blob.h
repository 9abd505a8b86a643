// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The benchmarks' generated meshes ("generated:N" of bench_parameterizer, bench_io --write-blob).

#ifndef HOT_BENCH_GENERATED_BLOB_H
#define HOT_BENCH_GENERATED_BLOB_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/generators.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <random>
#include <vector>

namespace hot_bench {

typedef CGAL::Exact_predicates_inexact_constructions_kernel Blob_kernel;
typedef CGAL::Surface_mesh<Blob_kernel::Point_3> Blob_mesh;

// A generated genus-0 test surface of about n vertices: the frequency-f geodesic sphere
// (10 f^2 + 2 vertices), made a blob with long smooth protrusions by a radial function (so
// it stays embedded), plus a little noise along the radius.
inline Blob_mesh generated_blob(std::size_t n, unsigned seed = 5)
{
  const int f = std::max(1, static_cast<int>(std::lround(std::sqrt((static_cast<double>(n) - 2) / 10))));
  Blob_mesh icosa;
  CGAL::make_icosahedron(icosa, Blob_kernel::Point_3(0, 0, 0), 1.0);
  Blob_mesh sm;
  std::map<std::array<long long, 3>, Blob_mesh::Vertex_index> index;
  auto vertex_at = [&](const Blob_kernel::Vector_3& p) {
    const Blob_kernel::Vector_3 u = p / std::sqrt(p.squared_length());
    const std::array<long long, 3> key{{std::llround(u.x() * 1e9), std::llround(u.y() * 1e9), std::llround(u.z() * 1e9)}};
    auto it = index.find(key);
    if(it == index.end()) it = index.emplace(key, sm.add_vertex(Blob_kernel::Point_3(u.x(), u.y(), u.z()))).first;
    return it->second;
  };
  for(auto fc : faces(icosa)) {
    std::array<Blob_kernel::Vector_3, 3> c;
    int i = 0;
    for(auto v : vertices_around_face(halfedge(fc, icosa), icosa)) c[i++] = icosa.point(v) - CGAL::ORIGIN;
    std::vector<std::vector<Blob_mesh::Vertex_index> > row(f + 1);
    for(int a = 0; a <= f; ++a)
      for(int b = 0; b <= f - a; ++b)
        row[a].push_back(vertex_at(c[0] + (c[1] - c[0]) * (double(a) / f) + (c[2] - c[0]) * (double(b) / f)));
    for(int a = 0; a < f; ++a)
      for(int b = 0; b < f - a; ++b) {
        sm.add_face(row[a][b], row[a + 1][b], row[a][b + 1]);
        if(b + 1 < f - a) sm.add_face(row[a + 1][b], row[a + 1][b + 1], row[a][b + 1]);
      }
  }
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> U(-1, 1);
  std::vector<Blob_kernel::Vector_3> centre;
  std::vector<double> height, width;
  for(int j = 0; j < 9; ++j) {
    Blob_kernel::Vector_3 c(U(rng), U(rng), U(rng));
    centre.push_back(c / std::sqrt(c.squared_length()));
    height.push_back(j < 4 ? 1.5 + U(rng) * 0.5 : 0.3 * U(rng)); // four long protrusions, bumps and dents
    width.push_back(j < 4 ? 0.04 : 0.2);
  }
  const double noise = 0.1 * 2.0 / f; // a tenth of an edge
  for(Blob_mesh::Vertex_index v : vertices(sm)) {
    const Blob_kernel::Vector_3 u = sm.point(v) - CGAL::ORIGIN;
    double r = 1;
    for(std::size_t j = 0; j < centre.size(); ++j) r += height[j] * std::exp(-(1 - u * centre[j]) / width[j]);
    r += noise * U(rng);
    sm.point(v) = CGAL::ORIGIN + u * r;
  }
  return sm;
}

} // namespace hot_bench

#endif // HOT_BENCH_GENERATED_BLOB_H
