// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// EXPLORATION for issue 39, not a product: farthest-point samples of A matched on B by their
// exact geodesic distances to the landmarks (CGAL's Surface_mesh_shortest_path), searched
// near the image a map file gives them. Built only with -DHOT_BUILD_EXPLORATION=ON.
//   signature_matching A.off B.off LA LB MAP K OUT
// LA, LB: landmark vertex lists (corresponding); MAP: a map file of A onto B (the CLI's
// format); K: samples; OUT: one line per sample, "a face_of_B x y z". Prints the samples'
// error (vertex i <-> vertex i) under the map and after matching.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_shortest_path.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <fstream>
#include <iostream>
#include <queue>
#include <set>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> SM;
typedef CGAL::Surface_mesh_shortest_path_traits<K, SM> Traits;
typedef CGAL::Surface_mesh_shortest_path<Traits> SP;
typedef SM::Vertex_index V;
typedef SM::Face_index F;

static std::vector<std::size_t> ids(const char* f) { std::ifstream in(f); std::vector<std::size_t> r; std::size_t i; while(in >> i) r.push_back(i); return r; }

int main(int argc, char** argv)
{
  SM A, B;
  std::ifstream(argv[1]) >> A;
  std::ifstream(argv[2]) >> B;
  const std::vector<std::size_t> la = ids(argv[3]), lb = ids(argv[4]);
  const int k = std::atoi(argv[6]);
  std::vector<std::pair<std::size_t, std::array<double, 3> > > map;
  { std::ifstream in(argv[5]); std::size_t f; double x, y, z; while(in >> f >> x >> y >> z) map.push_back({f, {{x, y, z}}}); }
  std::vector<std::array<std::size_t, 3> > faces_file;
  {
    std::ifstream in(argv[2]); std::string off; std::size_t nv, nf, ne; in >> off >> nv >> nf >> ne;
    double x; for(std::size_t i = 0; i < 3 * nv; ++i) in >> x;
    for(std::size_t j = 0; j < nf; ++j) { std::size_t c, a, b, d; in >> c >> a >> b >> d; faces_file.push_back({{a, b, d}}); }
  }
  const CGAL::Bbox_3 bb = CGAL::Polygon_mesh_processing::bbox(B);
  const double diag = std::sqrt(CGAL::square(bb.xmax() - bb.xmin()) + CGAL::square(bb.ymax() - bb.ymin()) + CGAL::square(bb.zmax() - bb.zmin()));
  const std::size_t L = la.size(), na = num_vertices(A);
  // distances on A from every landmark (exact, at vertices)
  std::vector<std::vector<double> > dA(L, std::vector<double>(na));
  std::vector<std::unique_ptr<SP> > spB;
  for(std::size_t i = 0; i < L; ++i) {
    SP sp(A);
    sp.add_source_point(V(static_cast<SM::size_type>(la[i])));
    sp.build_sequence_tree();
    for(V v : vertices(A)) dA[i][v.idx()] = sp.shortest_distance_to_source_points(v).first;
    spB.emplace_back(new SP(B));
    spB.back()->add_source_point(V(static_cast<SM::size_type>(lb[i])));
    spB.back()->build_sequence_tree();
  }
  // farthest points on A (geodesic to the landmarks and the samples so far: the samples' own
  // distance fields by exact geodesics too)
  std::vector<double> dmin(na, 1e300);
  for(std::size_t i = 0; i < L; ++i) for(std::size_t v = 0; v < na; ++v) dmin[v] = std::min(dmin[v], dA[i][v]);
  std::vector<std::size_t> samples;
  for(int s = 0; s < k; ++s) {
    const std::size_t best = std::max_element(dmin.begin(), dmin.end()) - dmin.begin();
    samples.push_back(best);
    SP sp(A);
    sp.add_source_point(V(static_cast<SM::size_type>(best)));
    sp.build_sequence_tree();
    for(V v : vertices(A)) dmin[v.idx()] = std::min(dmin[v.idx()], sp.shortest_distance_to_source_points(v).first);
  }
  std::ofstream out(argv[7]);
  out.precision(17);
  double sum = 0, worst = 0, sum0 = 0, worst0 = 0;
  for(std::size_t s : samples) {
    const auto cost = [&](F f, const std::array<double, 3>& b) {
      double c = 0;
      for(std::size_t i = 0; i < L; ++i) {
        const double d = spB[i]->shortest_distance_to_source_points(f, b).first;
        const double r = (d - dA[i][s]) / (dA[i][s] + 0.05 * diag);
        c += r * r;
      }
      return c;
    };
    // the faces within 3 rings of the map's image
    const F f0(static_cast<SM::size_type>(map[s].first));
    std::set<F> region{f0};
    for(int r = 0; r < 3; ++r) {
      std::set<F> more = region;
      for(F f : region)
        for(V v : vertices_around_face(halfedge(f, B), B))
          for(F g : faces_around_target(halfedge(v, B), B))
            if(g != SM::null_face()) more.insert(g);
      region.swap(more);
    }
    double bc = 1e300; F bf; std::array<double, 3> bb3{{1. / 3, 1. / 3, 1. / 3}};
    const int N = 6;
    for(F f : region)
      for(int i = 0; i <= N; ++i)
        for(int j = 0; j <= N - i; ++j) {
          const std::array<double, 3> b{{double(i) / N, double(j) / N, double(N - i - j) / N}};
          const double c = cost(f, b);
          if(c < bc) { bc = c; bf = f; bb3 = b; }
        }
    // refine around the best (its face and neighbours), finer steps
    for(double h = 0.5 / N; h > 1e-3; h *= 0.5) {
      bool moved = true;
      while(moved) {
        moved = false;
        for(int d = 0; d < 6; ++d) {
          std::array<double, 3> b = bb3;
          const int p = d / 2, q = (p + 1 + (d % 2)) % 3;
          b[p] += h; b[q] -= h;
          if(b[q] < 0 || b[p] > 1) continue;
          const double c = cost(bf, b);
          if(c < bc) { bc = c; bb3 = b; moved = true; }
        }
      }
    }
    SP& any = *spB[0];
    const K::Point_3 q = any.point(bf, bb3);
    const K::Point_3 t = B.point(V(static_cast<SM::size_type>(s)));
    const double e = std::sqrt(CGAL::squared_distance(q, t)) / diag;
    K::Vector_3 acc(0, 0, 0);
    for(int c = 0; c < 3; ++c) acc = acc + map[s].second[c] * (B.point(V(static_cast<SM::size_type>(faces_file[map[s].first][c]))) - CGAL::ORIGIN);
    const K::Point_3 q0 = CGAL::ORIGIN + acc;
    const double e0 = std::sqrt(CGAL::squared_distance(q0, t)) / diag;
    sum += e; worst = std::max(worst, e); sum0 += e0; worst0 = std::max(worst0, e0);
    out << s << " " << bf.idx() << " " << q.x() << " " << q.y() << " " << q.z() << "\n";
  }
  std::printf("samples %zu: map's image error mean %.3f%% max %.2f%%; matched mean %.3f%% max %.2f%%\n", samples.size(),
              100 * sum0 / samples.size(), 100 * worst0, 100 * sum / samples.size(), 100 * worst);
  return 0;
}
