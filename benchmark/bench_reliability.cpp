// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// map_reliability() against ground truth: pairs of meshes whose vertex i corresponds to
// vertex i (TOSCA's poses of one class, a mesh and a deformed copy), mapped A -> B with the
// same landmarks; per pair the vertices, the map's mean and largest error (percent of B's
// bounding-box diagonal), the vertices flagged unreliable (percent), and the fraction of the
// worst 1% of the vertices (by error) that are flagged.
//   bench_reliability [--noise S] [--split V F N] [--seed K] [--dump FILE] [--regions] [--scale-factor X]
//                     [--smoothing N] [--noise-multiple X] A.off CA B.off CB [A2.off CA2 B2.off CB2 ...]
// CA, CB: landmark files (one 0-based vertex per line, landmark j of CA corresponds to
// landmark j of CB). A and B must have the same number of vertices. Variants made in memory,
// both meshes alike (vertex numbers kept, the new vertices appended in the same order):
//   --noise S    Gaussian noise of standard deviation S x the diagonal on every coordinate,
//                independent on A and B (a scan's noise: slivers, folded triangles where the
//                triangles are small);
//   --split V F N  N rounds of splitting at their centroid (1 to 3) the triangles of A within
//                F x the diagonal of vertex V (B takes A's faces): a region of tiny triangles and
//                slivers, a scan's uneven resolution.
// Asserts nothing (test_maps checks the guarantees); prints one line per pair (--regions: and
// one per unresolved squeezed region, with the vertices its protrusion test flagged). --dump writes
// per vertex of the last pair: error (fraction of the diagonal), flagged, uncertainty.

#include "bench_common.h"

#include <CGAL/Polygon_mesh_processing/bbox.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <random>
#include <string>
#include <vector>

typedef K::Point_2 Point_2;
typedef SM::Property_map<SM_halfedge, Point_2> UV;
typedef HOT::Embedding_locator<SM, UV> Locator;

static bool read_indices(const std::string& file, std::vector<std::size_t>& out)
{
  std::ifstream in(file);
  std::size_t i;
  out.clear();
  while(in >> i)
    out.push_back(i);
  return !out.empty();
}

// both meshes as triangle lists over their points (B takes A's faces)
struct Soup
{
  std::vector<K::Point_3> a, b;
  std::vector<std::array<std::size_t, 3> > faces;
};

static SM to_mesh(const std::vector<K::Point_3>& points, const std::vector<std::array<std::size_t, 3> >& faces)
{
  SM m;
  for(const K::Point_3& p : points)
    m.add_vertex(p);
  for(const auto& f : faces)
    m.add_face(SM_vertex(static_cast<SM::size_type>(f[0])), SM_vertex(static_cast<SM::size_type>(f[1])),
               SM_vertex(static_cast<SM::size_type>(f[2])));
  return m;
}

static void split_near(Soup& s, std::size_t v, double radius, int rounds)
{
  const K::Point_3 c = s.a[v];
  for(int r = 0; r < rounds; ++r) {
    std::vector<std::array<std::size_t, 3> > out;
    for(const auto& f : s.faces) {
      double d = 1e300;
      for(std::size_t k : f)
        d = std::min(d, std::sqrt(CGAL::squared_distance(s.a[k], c)));
      if(d >= radius) {
        out.push_back(f);
        continue;
      }
      const std::size_t n = s.a.size();
      s.a.push_back(CGAL::centroid(s.a[f[0]], s.a[f[1]], s.a[f[2]]));
      s.b.push_back(CGAL::centroid(s.b[f[0]], s.b[f[1]], s.b[f[2]]));
      out.push_back({{f[0], f[1], n}});
      out.push_back({{f[1], f[2], n}});
      out.push_back({{f[2], f[0], n}});
    }
    s.faces.swap(out);
  }
}

static void add_noise(std::vector<K::Point_3>& p, double sigma, unsigned seed)
{
  std::mt19937 rng(seed);
  std::normal_distribution<double> N(0, sigma);
  for(K::Point_3& q : p) {
    const double x = N(rng), y = N(rng), z = N(rng);
    q = K::Point_3(q.x() + x, q.y() + y, q.z() + z);
  }
}

struct Embedded
{
  SM mesh;
  UV uv;
  HOT::Embedding_statistics st;
};

static bool embed(Embedded& e, const std::vector<SM_vertex>& lm, HOT::Landmark_order order)
{
  e.uv = e.mesh.add_property_map<SM_halfedge, Point_2>("h:uv", Point_2(2, 2)).first;
  const HOT::Error_code ec = HOT::hyperbolic_orbifold_Tutte_embedding(
    e.mesh, lm, e.uv, HOT::parameters::embedding_statistics(&e.st, HOT::parameters::landmark_order(order)));
  if(ec != HOT::OK)
    std::printf("    embedding failed: %s\n", e.st.message.c_str());
  return ec == HOT::OK;
}

static int run_pair(const std::string& fa, const std::string& ca, const std::string& fb, const std::string& cb, double noise,
                    long split_vertex, double split_fraction, int split_rounds, unsigned seed, const std::string& dump,
                    const HOT::Map_reliability_options& options, bool regions)
{
  SM ma, mb;
  std::vector<std::size_t> la, lb;
  if(!CGAL::IO::read_polygon_mesh(fa, ma) || !CGAL::IO::read_polygon_mesh(fb, mb) || !read_indices(ca, la) || !read_indices(cb, lb) ||
     la.size() != lb.size() || num_vertices(ma) != num_vertices(mb)) {
    std::printf("%s -> %s: cannot read, or not the same number of vertices or landmarks\n", fa.c_str(), fb.c_str());
    return 1;
  }
  Soup s;
  for(SM_vertex v : vertices(ma))
    s.a.push_back(ma.point(v));
  for(SM_vertex v : vertices(mb))
    s.b.push_back(mb.point(v));
  for(SM_face f : faces(ma)) {
    std::array<std::size_t, 3> t;
    int k = 0;
    for(SM_vertex v : vertices_around_face(halfedge(f, ma), ma))
      t[k++] = v.idx();
    s.faces.push_back(t);
  }
  const double da = diagonal(ma), db = diagonal(mb);
  if(split_vertex >= 0)
    split_near(s, static_cast<std::size_t>(split_vertex), split_fraction * da, split_rounds);
  if(noise > 0) {
    add_noise(s.a, noise * da, seed);
    add_noise(s.b, noise * db, seed + 1000);
  }
  Embedded A, B;
  A.mesh = to_mesh(s.a, s.faces);
  B.mesh = split_vertex >= 0 ? to_mesh(s.b, s.faces) : mb;
  if(split_vertex < 0 && noise > 0)
    for(SM_vertex v : vertices(B.mesh))
      B.mesh.point(v) = s.b[v.idx()];
  std::vector<SM_vertex> lma, lmb;
  for(std::size_t i = 0; i < la.size(); ++i) {
    lma.push_back(SM_vertex(static_cast<SM::size_type>(la[i])));
    lmb.push_back(SM_vertex(static_cast<SM::size_type>(lb[i])));
  }
  std::string name = fa.substr(fa.find_last_of('/') + 1) + " -> " + fb.substr(fb.find_last_of('/') + 1);
  if(noise > 0) name += " noise " + std::to_string(noise);
  if(split_vertex >= 0) name += " split " + std::to_string(split_rounds);
  const auto t0 = Clock::now();
  if(!embed(A, lma, HOT::Tsp_order)) {
    std::printf("%-44s: source refused\n", name.c_str());
    return 1;
  }
  std::vector<SM_vertex> lmb_ordered;
  for(std::size_t i : A.st.landmark_order)
    lmb_ordered.push_back(lmb[i]);
  if(!embed(B, lmb_ordered, HOT::Given_order)) {
    std::printf("%-44s: target refused\n", name.c_str());
    return 1;
  }
  const double t_embed = seconds_since(t0);
  const HOT::Orbifold_type type = CGAL::is_closed(B.mesh) ? HOT::Sphere_type : HOT::Disk_type;
  const Locator L(B.mesh, B.uv, type, static_cast<int>(la.size()), HOT::Hyperboloid_linear);
  const auto locs = HOT::map_vertices(A.mesh, A.uv, L);
  const auto t1 = Clock::now();
  const HOT::Map_reliability r = HOT::map_reliability(A.mesh, A.uv, B.mesh, B.uv, L, locs, options);
  const double t_check = seconds_since(t1);
  const std::size_t n = num_vertices(A.mesh);
  const double diag = diagonal(B.mesh);
  std::vector<double> error(n, std::numeric_limits<double>::infinity());
  const auto vpm = get(CGAL::vertex_point, B.mesh);
  for(std::size_t i = 0; i < n; ++i)
    if(locs[i].success)
      error[i] = std::sqrt(CGAL::squared_distance(HOT::surface_point(locs[i], L, vpm), B.mesh.point(SM_vertex(static_cast<SM::size_type>(i))))) / diag;
  std::vector<char> flagged(n, 0);
  for(std::size_t i : r.unreliable_vertices)
    flagged[i] = 1;
  double sum = 0, worst = 0;
  for(double e : error) {
    sum += e;
    worst = std::max(worst, e);
  }
  std::vector<std::size_t> order(n);
  for(std::size_t i = 0; i < n; ++i)
    order[i] = i;
  const std::size_t k = std::max<std::size_t>(1, n / 100);
  std::partial_sort(order.begin(), order.begin() + k, order.end(), [&](std::size_t x, std::size_t y) { return error[x] > error[y]; });
  std::size_t covered = 0;
  for(std::size_t j = 0; j < k; ++j)
    covered += flagged[order[j]];
  const double mean = sum / static_cast<double>(n), fraction = double(r.unreliable_vertices.size()) / double(n);
  std::printf("%-44s %8zu %7.3f %7.2f %8zu %7.2f %9.0f %6s | %6zu %6zu %6zu %6.3f | %6.2f %7.3f\n", name.c_str(), n, 100 * mean,
              100 * worst, r.unreliable_vertices.size(), 100 * fraction, 100.0 * double(covered) / double(k),
              mean < 0.01 ? (fraction <= 0.05 ? "yes" : "NO") : "-", r.scale_flagged, r.rounding_flagged, r.protrusion_flagged,
              r.scale_noise, t_embed, t_check);
  if(regions)
    for(const HOT::Squeezed_region& g : r.regions)
      if(g.unresolved) {
        std::printf("    unresolved region of %zu vertices, collapse vertex %zu: discrepancy %.3g (one-ring sizes %.3g, %.3g), "
                    "scale disagreement %.2f, %zu flagged\n", g.number_of_vertices, g.source_vertex, g.discrepancy, g.source_size,
                    g.target_size, g.scale_disagreement, g.unreliable_vertices);
      }
  if(!dump.empty()) {
    std::ofstream out(dump);
    out.precision(10);
    const HOT::internal::Embedding_scale<SM> ea(A.mesh, A.uv, get(CGAL::vertex_point, A.mesh), L, 1e-2);
    const HOT::internal::Embedding_scale<SM> eb(B.mesh, B.uv, get(CGAL::vertex_point, B.mesh), L, 1e-2);
    for(std::size_t i = 0; i < n; ++i) {
      double lb = 0;
      for(int j = 0; j < 3; ++j)
        lb += locs[i].barycentric[j] * std::log(eb.rho[L.corner_vertex_index(locs[i].face_index, j)]);
      const Point_2 z = L.disk_point(locs[i]);
      out << i << ' ' << error[i] << ' ' << int(flagged[i]) << ' ' << r.uncertainty[i] << ' ' << r.scale_disagreement[i] << ' ' << ea.rho[i] << ' ' << std::exp(lb)
          << ' ' << ea.size[i] << ' ' << std::sqrt(CGAL::square(z.x()) + CGAL::square(z.y())) << ' ' << A.mesh.point(SM_vertex(i)) << '\n';
    }
    std::ofstream raw(dump + ".raw");
    raw.precision(17);
    for(const Embedded* e : {&A, &B}) {
      raw << "M " << num_vertices(e->mesh) << ' ' << num_faces(e->mesh) << '\n';
      for(SM_vertex v : vertices(e->mesh))
        raw << e->mesh.point(v) << '\n';
      for(SM_face f : faces(e->mesh)) {
        for(SM_halfedge h : halfedges_around_face(halfedge(f, e->mesh), e->mesh))
          raw << target(h, e->mesh).idx() << ' ' << get(e->uv, h).x() << ' ' << get(e->uv, h).y() << ' ';
        raw << '\n';
      }
    }
    for(std::size_t i = 0; i < n; ++i)
      raw << locs[i].face_index << ' ' << L.corner_vertex_index(locs[i].face_index, 0) << ' ' << L.corner_vertex_index(locs[i].face_index, 1)
          << ' ' << L.corner_vertex_index(locs[i].face_index, 2) << ' ' << locs[i].barycentric[0] << ' ' << locs[i].barycentric[1] << ' '
          << locs[i].barycentric[2] << '\n';
  }
  return 0;
}

int main(int argc, char** argv)
{
  double noise = 0, split_fraction = 0;
  long split_vertex = -1;
  int split_rounds = 0;
  unsigned seed = 1;
  std::string dump;
  bool regions = false;
  std::vector<std::string> files;
  HOT::Map_reliability_options options;
  for(int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if(a == "--noise" && i + 1 < argc) noise = std::atof(argv[++i]);
    else if(a == "--split" && i + 3 < argc) {
      split_vertex = std::atol(argv[++i]);
      split_fraction = std::atof(argv[++i]);
      split_rounds = std::atoi(argv[++i]);
    } else if(a == "--seed" && i + 1 < argc) seed = static_cast<unsigned>(std::atoi(argv[++i]));
    else if(a == "--dump" && i + 1 < argc) dump = argv[++i];
    else if(a == "--regions") regions = true;
    else if(a == "--scale-factor" && i + 1 < argc) options.scale_factor = std::atof(argv[++i]);
    else if(a == "--smoothing" && i + 1 < argc) options.smoothing_rounds = std::atoi(argv[++i]);
    else if(a == "--noise-multiple" && i + 1 < argc) options.noise_multiple = std::atof(argv[++i]);
    else files.push_back(a);
  }
  if(files.empty() || files.size() % 4 != 0) {
    std::cerr << "usage: bench_reliability [--noise S] [--split V F N] [--seed K] [--dump FILE] [--regions] A.off CA B.off CB [...]" << std::endl;
    return 2;
  }
  std::printf("%-44s %8s %7s %7s %8s %7s %9s %6s | %6s %6s %6s %6s | %6s %7s\n", "pair (ground truth: vertex i <-> vertex i)",
              "vertices", "mean%", "max%", "flagged", "flag%", "worst1%in", "<=5%?", "scale", "round", "protr", "noise", "embed", "check");
  int rc = 0;
  for(std::size_t i = 0; i < files.size(); i += 4)
    rc |= run_pair(files[i], files[i + 1], files[i + 2], files[i + 3], noise, split_vertex, split_fraction, split_rounds, seed, dump, options, regions);
  return rc;
}
