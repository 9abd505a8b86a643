// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Landmark transfer: how far a map A -> B sends the landmarks it was not given from their
// true place on B, as the correspondence benchmarks of scans measure it (geodesic error as a
// fraction of B's geodesic diameter; the fraction of points within 0.025; the area under the
// cumulative error curve over [0, 0.1], normalised to 1).
//   bench_transfer MAP.txt B.off LA LB ROWS [--label TEXT] [--errors FILE]
// MAP.txt: the `map --out` file (one line `face b0 b1 b2` per vertex of A); LA, LB: landmark
// files whose line j corresponds; ROWS: the 0-based rows of LA/LB the map was given (they are
// left out of the measure). Prints one line: label, held-out count, mean error, fraction within
// 0.025, AUC over [0, 0.1], worst. --errors FILE appends the held-out errors, one per line (for
// a summary over many pairs).
// Geodesic distances: CGAL's heat method on B's intrinsic Delaunay triangulation, from the
// true landmark's vertex, interpolated linearly at the image point; B's geodesic diameter by
// two sweeps (from vertex 0 to the farthest, from there to the farthest).
#include "bench_common.h"

#include <CGAL/Heat_method_3/Surface_mesh_geodesic_distances_3.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

typedef CGAL::Heat_method_3::Surface_mesh_geodesic_distances_3<SM, CGAL::Heat_method_3::Intrinsic_Delaunay> Heat;

int main(int argc, char** argv)
{
  if(argc < 6) {
    std::fprintf(stderr, "usage: bench_transfer MAP.txt B.off LA LB ROWS [--label TEXT] [--errors FILE]\n");
    return 2;
  }
  std::string label = argv[1], errors_file;
  for(int i = 6; i + 1 < argc; i += 2) {
    if(std::string(argv[i]) == "--label") label = argv[i + 1];
    else if(std::string(argv[i]) == "--errors") errors_file = argv[i + 1];
  }
  SM B;
  if(!CGAL::IO::read_polygon_mesh(argv[2], B) || !CGAL::is_triangle_mesh(B)) {
    std::fprintf(stderr, "bench_transfer: cannot read %s as a triangle mesh\n", argv[2]);
    return 1;
  }
  const std::vector<std::size_t> LA = read_indices(argv[3]), LB = read_indices(argv[4]), rows = read_indices(argv[5]);
  const std::set<std::size_t> given(rows.begin(), rows.end());
  // the map: face and barycentric coordinates per vertex of A
  std::vector<std::pair<long, std::array<double, 3> > > image;
  {
    std::ifstream in(argv[1]);
    std::string line;
    while(std::getline(in, line)) {
      std::istringstream s(line);
      long f;
      std::array<double, 3> b{};
      if(s >> f >> b[0] >> b[1] >> b[2]) image.push_back(std::make_pair(f, b));
    }
  }
  std::vector<SM_face> face_of(B.faces().begin(), B.faces().end());
  Heat heat(B);
  auto distances_from = [&](SM_vertex s) {
    SM::Property_map<SM_vertex, double> d = B.add_property_map<SM_vertex, double>("v:bench_distance", 0).first;
    heat.clear_sources();
    heat.add_source(s);
    heat.estimate_geodesic_distances(d);
    std::vector<double> out;
    for(SM_vertex v : vertices(B)) out.push_back(get(d, v));
    return out;
  };
  auto farthest = [&](const std::vector<double>& d) { return std::size_t(std::max_element(d.begin(), d.end()) - d.begin()); };
  const std::vector<double> d0 = distances_from(SM_vertex(0));
  const std::vector<double> d1 = distances_from(SM_vertex(SM::size_type(farthest(d0))));
  const std::vector<double> d2 = distances_from(SM_vertex(SM::size_type(farthest(d1))));
  const double diameter = (std::max)(*std::max_element(d1.begin(), d1.end()), *std::max_element(d2.begin(), d2.end()));

  std::vector<double> errors;
  for(std::size_t r = 0; r < LA.size() && r < LB.size(); ++r) {
    if(given.count(r) || LA[r] >= image.size() || image[LA[r]].first < 0 || std::size_t(image[LA[r]].first) >= face_of.size())
      continue;
    const std::vector<double> d = distances_from(SM_vertex(SM::size_type(LB[r])));
    const auto& im = image[LA[r]];
    double e = 0;
    int k = 0;
    for(SM_vertex v : vertices_around_face(halfedge(face_of[im.first], B), B)) e += im.second[k++] * d[v.idx()];
    errors.push_back((std::max)(0.0, e) / diameter);
  }
  if(errors.empty()) {
    std::fprintf(stderr, "bench_transfer: no held-out landmark\n");
    return 1;
  }
  double mean = 0, within = 0, auc = 0, worst = 0;
  for(double e : errors) {
    mean += e / errors.size();
    within += (e <= 0.025) / double(errors.size());
    auc += (std::max)(0.0, 0.1 - e) / 0.1 / errors.size(); // the integral of the cumulative curve over [0, 0.1], over 0.1
    worst = (std::max)(worst, e);
  }
  std::printf("%-28s held-out %3zu  mean %.4f  within 0.025 %5.1f%%  AUC[0,0.1] %.3f  worst %.3f\n", label.c_str(), errors.size(),
              mean, 100 * within, auc, worst);
  if(!errors_file.empty()) {
    std::ofstream out(errors_file, std::ios::app);
    for(double e : errors) out << e << "\n";
  }
  return 0;
}
