// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The paper's FAUST setting: a collection of N meshes (default 20) of about 7K vertices with
// 23 landmarks, embedded, then the maps between all N (N - 1) ordered pairs computed.
//   bench_collection [--meshes N] [--landmarks K] [--sequential] [base.off]
// The collection is N smooth, different deformations ("poses") of one base mesh (default:
// libcgal-demo's bull.off, 6.2K vertices) sharing its triangulation, as FAUST's meshes do;
// the landmarks are the same vertices on every pose. Prints timings, peak memory and the
// worst cycle-consistency error over sampled triples; asserts nothing (see test/).

#include "bench_common.h"

#include <CGAL/Polygon_mesh_processing/bbox.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <random>
#include <string>
#include <thread>
#include <vector>

// pose i: a bend about a random axis whose angle grows along the mesh, a twist, and a
// low-frequency wobble; smooth and orientation preserving, so the surfaces stay embedded
static SM pose(const SM& base, int i)
{
  SM m = base;
  if(i == 0) return m;
  std::mt19937 rng(1234 + i);
  std::uniform_real_distribution<double> U(-1, 1);
  const CGAL::Bbox_3 bb = CGAL::Polygon_mesh_processing::bbox(base);
  const double cx = (bb.xmin() + bb.xmax()) / 2, cy = (bb.ymin() + bb.ymax()) / 2, cz = (bb.zmin() + bb.zmax()) / 2;
  const double s = std::max({bb.xmax() - bb.xmin(), bb.ymax() - bb.ymin(), bb.zmax() - bb.zmin()});
  const double bend = 0.6 * U(rng), twist = 0.5 * U(rng), wob = 0.03 * s * U(rng), ph = 3 * U(rng);
  for(SM::Vertex_index v : vertices(m)) {
    const K::Point_3 p = base.point(v);
    double x = (p.x() - cx) / s, y = (p.y() - cy) / s, z = (p.z() - cz) / s;
    // bend in the x-y plane, angle proportional to x
    const double a = bend * x, ca = std::cos(a), sa = std::sin(a);
    double x1 = ca * x - sa * y, y1 = sa * x + ca * y;
    // twist about x, angle proportional to x
    const double t = twist * x1, ct = std::cos(t), st = std::sin(t);
    double y2 = ct * y1 - st * z, z2 = st * y1 + ct * z;
    m.point(v) = K::Point_3(cx + s * x1 + wob * std::sin(4 * y2 + ph), cy + s * y2, cz + s * z2 + wob * std::cos(3 * x1 + ph));
  }
  return m;
}

template <class Tag>
static int run(const SM& base, int N, std::size_t k)
{
  const auto landmarks = HOT::select_landmarks(base, k);
  HOT::Orbifold_collection<SM, Tag> c;
  const auto t0 = Clock::now();
  for(int i = 0; i < N; ++i)
    c.add_mesh(pose(base, i), landmarks);
  const double t_poses = seconds_since(t0);
  const auto t1 = Clock::now();
  const HOT::Error_code ec = c.embed();
  const double t_embed = seconds_since(t1);
  if(ec != HOT::OK) {
    std::printf("embedding failed: %s\n", c.message().c_str());
    return 1;
  }
  std::size_t certified = 0;
  int iterations = 0;
  for(int i = 0; i < N; ++i) {
    certified += c.statistics(i).certificate.is_bijective();
    iterations = std::max(iterations, c.statistics(i).iterations);
  }
  const auto t2 = Clock::now();
  c.compute_all_maps();
  const double t_maps = seconds_since(t2);
  std::size_t failed = 0;
  for(int a = 0; a < N; ++a)
    for(int b = 0; b < N; ++b)
      if(a != b)
        for(const auto& l : c.map(a, b)) failed += !l.success;
  // cycle consistency over a sample of triples
  double cycle = 0;
  std::mt19937 rng(7);
  for(int t = 0; t < 10 && N >= 3; ++t) {
    int a = rng() % N, b = rng() % N, d = rng() % N;
    if(a == b || b == d || a == d) continue;
    cycle = std::max(cycle, c.cycle_consistency_error(a, b, d));
  }
  std::printf("%-12s %6zu %4d %3zu %7s | %7.2f %7.3f | %8.2f %6d %9.3f | %5d %8zu | %8.1e | %7.0f | %8.2f %s\n", "collection",
              static_cast<std::size_t>(num_vertices(base)), N, k, std::is_same<Tag, CGAL::Parallel_tag>::value ? "TBB" : "serial",
              t_embed, t_embed / N, t_maps, N * (N - 1), t_maps / (N * (N - 1)), static_cast<int>(certified), failed, cycle,
              peak_rss_mb(), t_embed + t_maps, (t_embed + t_maps < 60 && failed == 0 && certified == std::size_t(N)) ? "target met (< 60 s)" : "TARGET MISSED");
  (void)t_poses;
  (void)iterations;
  return failed == 0 && certified == std::size_t(N) ? 0 : 1;
}

int main(int argc, char** argv)
{
  int N = 20;
  std::size_t k = 23;
  bool sequential = false;
  std::string file = "data/meshes/bull.off";
  for(int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if(a == "--meshes" && i + 1 < argc) N = std::atoi(argv[++i]);
    else if(a == "--landmarks" && i + 1 < argc) k = std::strtoul(argv[++i], nullptr, 10);
    else if(a == "--sequential") sequential = true;
    else file = a;
  }
  SM base;
  if(!CGAL::IO::read_polygon_mesh(file, base) || num_faces(base) == 0 || !CGAL::is_closed(base) || N < 2) {
    std::cerr << "usage: bench_collection [--meshes N >= 2] [--landmarks K] [--sequential] [closed genus-0 base.off]" << std::endl;
    return 2;
  }
  std::printf("%-12s %6s %4s %3s %7s | %7s %7s | %8s %6s %9s | %5s %8s | %8s | %7s | %8s\n", "", "verts", "N", "k", "threads",
              "embed", "per", "maps(s)", "pairs", "per map", "cert", "unmapped", "cycle", "RSS(MB)", "total(s)");
#ifdef CGAL_LINKED_WITH_TBB
  if(!sequential)
    return run<CGAL::Parallel_tag>(base, N, k);
#endif
  return run<CGAL::Sequential_tag>(base, N, k);
}
