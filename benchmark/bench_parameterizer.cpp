// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Times, on the same meshes: CGAL's Euclidean Orbifold_Tutte_parameterizer_3 (4 cones,
// parallelogram orbifold, cotangent weights), our hyperbolic embedding (cut, init, optimise,
// certify) and the "Cholesky floor" (one factorisation + solve of the cotangent Laplacian, the
// faster of Eigen's simplicial LDL^T and, where available, CHOLMOD's supernodal LL^T).
//   bench_parameterizer [--landmarks K] [--euclid-max N] [--no-map] [--no-floor] [--detail] [--verbose] [--repeat N] [--multigrid-from N] (mesh.off | generated:N) [...]
// generated:N is a genus-0 blob with protrusions of about N vertices (made here);
// mesh.off@cones.txt uses the landmarks listed in cones.txt instead of K farthest points.
// Prints one table row per mesh; nothing is asserted here (see test/ for correctness).

#include "bench_common.h"
#include "generated_blob.h"

#include <CGAL/boost/graph/Seam_mesh.h>
#include <CGAL/Surface_mesh_parameterization/Orbifold_Tutte_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/orbifold_shortest_path.h>

#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/boost/graph/generators.h>

#include <Eigen/SparseCholesky>
#ifdef CGAL_HOT_USE_CHOLMOD
#include <Eigen/CholmodSupport>
#endif

#include <chrono>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <list>
#include <map>
#include <random>
#include <string>
#include <unordered_map>
#include <vector>

namespace SMP = CGAL::Surface_mesh_parameterization;

// CGAL's Euclidean orbifold Tutte embedding with 4 cones (its own seam and cone setup)
static double euclidean_orbifold_time(SM& sm, const std::vector<SM_vertex>& cones4, bool& ok)
{
  typedef SM::Property_map<SM_edge, bool> SEM;
  typedef SM::Property_map<SM_vertex, bool> SVM;
  typedef CGAL::Seam_mesh<SM, SEM, SVM> Mesh;
  typedef boost::graph_traits<Mesh>::vertex_descriptor vertex_descriptor;
  typedef boost::graph_traits<Mesh>::halfedge_descriptor halfedge_descriptor;
  SEM sem = sm.add_property_map<SM_edge, bool>("e:bench_seam", false).first;
  SVM svm = sm.add_property_map<SM_vertex, bool>("v:bench_seam", false).first;
  Mesh mesh(sm, sem, svm);
  const auto cut = HOT::compute_cut_through_landmarks(sm, cones4, get(CGAL::vertex_point, sm));
  ok = cut.ok && HOT::add_cut_to_seam_mesh(mesh, sm, cut);
  std::unordered_map<vertex_descriptor, int> indices;
  int counter = 0;
  for(vertex_descriptor vd : vertices(mesh))
    indices[vd] = counter++;
  boost::associative_property_map<std::unordered_map<vertex_descriptor, int> > vimap(indices);
  std::unordered_map<vertex_descriptor, SMP::Cone_type> cmap;
  SMP::locate_cones(mesh, cones4.begin(), cones4.end(), cmap);
  auto uvmap = sm.add_property_map<SM_halfedge, K::Point_2>("h:bench_uv").first;
  halfedge_descriptor bhd;
  for(halfedge_descriptor h : halfedges(mesh))
    if(is_border(h, mesh)) { bhd = h; break; }
  SMP::Orbifold_Tutte_parameterizer_3<Mesh> parameterizer(SMP::Parallelogram, SMP::Cotangent);
  const auto t = Clock::now();
  const SMP::Error_code ec = parameterizer.parameterize(mesh, bhd, cmap, uvmap, vimap);
  const double time = seconds_since(t);
  ok = ok && ec == SMP::OK;
  sm.remove_property_map(uvmap);
  sm.remove_property_map(sem);
  sm.remove_property_map(svm);
  return time;
}

// one factorisation + solve of the n x n cotangent Laplacian (one vertex pinned)
static double cholesky_floor_time(const SM& sm)
{
  const int n = static_cast<int>(num_vertices(sm));
  std::vector<Eigen::Triplet<double> > trip;
  std::vector<double> diag(n, 0.0);
  for(SM_halfedge h : halfedges(sm)) {
    if(is_border(h, sm)) continue;
    const K::Point_3& a = sm.point(source(h, sm));
    const K::Point_3& b = sm.point(target(h, sm));
    const K::Point_3& c = sm.point(target(next(h, sm), sm));
    const K::Vector_3 u = a - c, v = b - c;
    const double w = std::max(1e-6, 0.5 * (u * v) / std::sqrt(CGAL::cross_product(u, v).squared_length()));
    const int i = static_cast<int>(source(h, sm).idx()), j = static_cast<int>(target(h, sm).idx());
    if(i > 0 && j > 0) { trip.emplace_back(i - 1, j - 1, -w); trip.emplace_back(j - 1, i - 1, -w); }
    diag[i] += w;
    diag[j] += w;
  }
  for(int i = 1; i < n; ++i) trip.emplace_back(i - 1, i - 1, diag[i]);
  Eigen::SparseMatrix<double> L(n - 1, n - 1);
  L.setFromTriplets(trip.begin(), trip.end());
  auto t = Clock::now();
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double> > chol(L);
  const Eigen::VectorXd x = chol.solve(Eigen::VectorXd::Ones(n - 1));
  double time = seconds_since(t);
  if(!x.allFinite()) return -1;
#ifdef CGAL_HOT_USE_CHOLMOD
  // the faster of Eigen's simplicial and CHOLMOD's supernodal factorisation
  t = Clock::now();
  Eigen::CholmodSupernodalLLT<Eigen::SparseMatrix<double> > sn(L);
  const Eigen::VectorXd y = sn.solve(Eigen::VectorXd::Ones(n - 1));
  if(y.allFinite()) time = std::min(time, seconds_since(t));
#endif
  return time;
}

int main(int argc, char** argv)
{
  std::size_t k = 7;
  std::size_t euclid_max = 500000; // CGAL's Euclidean solve takes minutes and > 4 GB beyond
  bool with_map = true, with_floor = true, detail = false, verbose = false;
  std::size_t multigrid_from = HOT::internal::default_multigrid_from; // (--multigrid-from N)
  int repeat = 1; // our embedding and the floor: the fastest of this many runs (timings vary on shared machines)
  std::vector<std::string> files;
  for(int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if(a == "--landmarks" && i + 1 < argc) k = std::strtoul(argv[++i], nullptr, 10);
    else if(a == "--euclid-max" && i + 1 < argc) euclid_max = std::strtoul(argv[++i], nullptr, 10);
    else if(a == "--no-map") with_map = false;
    else if(a == "--no-floor") with_floor = false; // peak memory of the embedding alone
    else if(a == "--detail") detail = true; // the optimisation's parts, on a second line
    else if(a == "--verbose") verbose = true; // the solver's steps on stderr
    else if(a == "--repeat" && i + 1 < argc) repeat = std::max(1, std::atoi(argv[++i]));
    else if(a == "--multigrid-from" && i + 1 < argc) multigrid_from = std::strtoul(argv[++i], nullptr, 10);
    else files.push_back(a);
  }
  if(files.empty()) {
    std::cerr << "usage: bench_parameterizer [--landmarks K] [--euclid-max N] [--no-map] [--no-floor] [--detail] [--verbose] [--repeat N] [--multigrid-from N] (mesh.off | generated:N) [...]" << std::endl;
    return 1;
  }
  std::printf("%-24s %8s %3s | %9s | %7s %7s %7s %7s %8s | %10s %9s | %7s %9s %7s | %7s | %7s %s\n", "mesh", "vertices", "k",
              "Euclid(s)", "cut", "init", "optim", "cert", "total(s)", "its/cg/rf", "imbalance", "ratio", "chol(s)", "x chol",
              "map(s)", "RSS(MB)", "certificate");
  for(std::string f : files) {
    SM sm;
    std::string name, cones_file;
    if(f.find('@') != std::string::npos) { // mesh.off@cones.txt: the landmarks given, one vertex index per line
      cones_file = f.substr(f.find('@') + 1);
      f = f.substr(0, f.find('@'));
    }
    if(f.rfind("generated:", 0) == 0) { // generated:N, a blob of about N vertices
      sm = hot_bench::generated_blob(std::strtoul(f.c_str() + 10, nullptr, 10));
      name = "blob_" + std::to_string(num_vertices(sm) / 1000) + "k";
    } else {
      if(!CGAL::IO::read_polygon_mesh(f, sm) || num_faces(sm) == 0) {
        std::printf("%-24s cannot read\n", f.c_str());
        continue;
      }
      name = f.substr(f.find_last_of('/') + 1);
      name = name.substr(0, name.find_last_of('.'));
    }
    std::vector<SM_vertex> landmarks;
    if(!cones_file.empty()) {
      std::ifstream in(cones_file);
      std::size_t i;
      while(in >> i)
        if(i < num_vertices(sm)) landmarks.push_back(SM_vertex(static_cast<SM::size_type>(i)));
      std::string c = cones_file.substr(cones_file.find_last_of('/') + 1);
      if(c.rfind(name + ".", 0) == 0) c = c.substr(name.size() + 1);
      if(c.size() > 4 && c.substr(c.size() - 4) == ".txt") c = c.substr(0, c.size() - 4);
      name += "@" + c;
    } else {
      landmarks = HOT::select_landmarks(sm, k);
    }
    bool eok = false;
    double te = -1;
    if(CGAL::is_closed(sm) && num_vertices(sm) <= euclid_max) {
      std::vector<SM_vertex> cones4(landmarks.begin(), landmarks.begin() + std::min<std::size_t>(4, landmarks.size()));
      te = euclidean_orbifold_time(sm, cones4, eok);
    }
    auto uv = sm.add_property_map<SM_halfedge, K::Point_2>("h:uv").first;
    HOT::Embedding_statistics st;
    HOT::Error_code ec = HOT::OK;
    double total = -1;
    for(int r = 0; r < repeat; ++r) { // (the fastest run's phases)
      HOT::Embedding_statistics str;
      const auto t = Clock::now();
      const HOT::Error_code ecr = HOT::hyperbolic_orbifold_Tutte_embedding(
        sm, landmarks, uv, HOT::parameters::landmark_order(HOT::Tsp_order, HOT::parameters::multigrid_threshold(multigrid_from, HOT::parameters::embedding_statistics(&str).verbose(verbose))));
      const double tr = seconds_since(t);
      if(r == 0 || tr < total) {
        total = tr;
        st = str;
        ec = ecr;
      }
      if(ecr != HOT::OK) break;
    }
    // mapping: every vertex of a smooth deformation of the mesh (embedded with the same
    // landmarks, in the same order) located on the mesh's embedding
    double tmap = -1;
    if(ec == HOT::OK && with_map) {
      SM def = sm;
      const CGAL::Bbox_3 bb = CGAL::Polygon_mesh_processing::bbox(sm);
      const double s = bb.xmax() - bb.xmin() + bb.ymax() - bb.ymin();
      for(SM_vertex v : vertices(def)) {
        const K::Point_3 p = def.point(v);
        def.point(v) = K::Point_3(p.x() + 0.05 * s * std::sin(3 * p.y() / s), p.y(), p.z() * 1.1);
      }
      std::vector<SM_vertex> ordered;
      for(std::size_t i : st.landmark_order) ordered.push_back(landmarks[i]);
      auto uvd = def.add_property_map<SM_halfedge, K::Point_2>("h:uvd").first;
      if(HOT::hyperbolic_orbifold_Tutte_embedding(def, ordered, uvd) == HOT::OK) {
        const auto tm0 = Clock::now();
        const HOT::Embedding_locator<SM, decltype(uv)> loc(sm, uv, CGAL::is_closed(sm) ? HOT::Sphere_type : HOT::Disk_type,
                                                           static_cast<int>(landmarks.size()));
        const auto f = HOT::map_vertices(def, uvd, loc);
        tmap = seconds_since(tm0);
        for(const auto& l : f)
          if(!l.success) tmap = -2;
      }
    }
    sm.remove_property_map(uv);
    double tc = -1.0;
    for(int r = 0; with_floor && r < repeat; ++r) {
      const double tr = cholesky_floor_time(sm);
      if(tr > 0 && (tc < 0 || tr < tc)) tc = tr;
    }
    std::printf("%-24s %8zu %3zu | %9.3f | %7.3f %7.3f %7.3f %7.3f %8.3f | %3d/%3d/%2d %9.1e | %7.2f %9.3f %7.1f | %7.3f | %7.0f %s\n",
                name.c_str(), static_cast<std::size_t>(num_vertices(sm)), landmarks.size(), eok ? te : -1.0,
                st.time_setup, st.time_initialization, st.time_optimization, st.time_certificate, total, st.iterations,
                st.cg_iterations, st.preconditioner_factorizations, st.relative_gradient_norm, (eok && te > 0) ? total / te : -1.0, tc, tc > 0 ? total / tc : -1.0, tmap, peak_rss_mb(),
                ec == HOT::OK && st.certificate.is_bijective() ? "bijective" : HOT::error_message(ec));
    if(detail)
      std::printf("  optimisation: assembly %.3f s, factorisations and solves %.3f s, line search %.3f s, other %.3f s\n",
                  st.time_assembly, st.time_factorization, st.time_line_search,
                  st.time_optimization - st.time_assembly - st.time_factorization - st.time_line_search);
    std::fflush(stdout);
  }
  return 0;
}
