// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Stress test of the one-call embedding with random landmark sets (scripts/stress.sh runs
// it on the libcgal-demo meshes; never run by ctest).
//
//   stress_landmarks [options] mesh [mesh ...]
//     --ks 5,7,10,16,23,35,50  numbers of landmarks
//     --seeds 1-8              seeds: a list (1,4,9) or a range (1-8)
//     --max-vertices 60000     skip bigger meshes (0: no limit)
//     --time-budget SECONDS    stop starting runs once they would not fit (0: no limit)
//     --weights cotan          cotan, mvc or uniform (the embedding's weight_type)
//     --classify               only print, per mesh, "CLASS <mesh> <type> <vertices>" or
//                              "SKIP <mesh>: <reason>"
//
// Only closed genus-0 meshes (sphere type) and disks (one boundary loop, genus 0) are
// used; any other mesh is skipped with a line saying why. A landmark set is k distinct
// vertices drawn at random (a 64-bit Mersenne twister seeded from the seed, k and the
// mesh's file name, with its own bounded draw, so the sets are the same everywhere):
// any vertices for the sphere type; boundary vertices, sorted into boundary order, for
// the disk type (the corners of a disk-type orbifold must be boundary vertices in
// boundary order). Sphere type is embedded with Tsp_order, disk type with Given_order
// (as the command-line program does by default). The landmark indices printed are the
// 0-based vertex indices of the file, as the command-line program reads them:
//   hyperbolic_orbifold_tutte embed --mesh MESH --cones <file with the indices> --out x.obj
// reproduces a run (the order printed is the order given to the embedding).
//
// One line per run:
//   RUN <mesh> k=<k> seed=<s> <type> certified|REFUSED|FAILED <code> <seconds>s its=<n> ...
// "certified": OK and the statistics' certificate is bijective. "REFUSED": a clear error
// on input the method cannot take (ERROR_CUT_FAILED: the landmarks block every cut, e.g.
// a landmark surrounded by landmarks; ERROR_BOUNDARY_CHORD); the line says how many
// landmark pairs are mesh edges. "FAILED": anything else (solver, certificate,
// exception). REFUSED and FAILED lines carry the message, the certificate's counts and
// the landmarks. Then a table per mesh and one "SUMMARY" line per mesh.

#include "bench_common.h"

#include <CGAL/Hyperbolic_orbifold_Tutte/check_input.h>

#include <hot_app/io/read_and_check.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <iostream>
#include <map>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <vector>

static const char* error_code_name(HOT::Error_code ec)
{
  static const char* const names[] = {
    "OK", "ERROR_NOT_HYPERBOLIC", "ERROR_WRONG_PARAMETER", "ERROR_EMPTY_MESH", "ERROR_NON_TRIANGULAR_MESH",
    "ERROR_NON_MANIFOLD", "ERROR_SEVERAL_COMPONENTS", "ERROR_WRONG_TOPOLOGY", "ERROR_TOO_FEW_LANDMARKS",
    "ERROR_DUPLICATE_LANDMARK", "ERROR_LANDMARK_OUT_OF_RANGE", "ERROR_LANDMARK_NOT_ON_BORDER",
    "ERROR_DEGENERATE_FACE", "ERROR_NON_FINITE_COORDINATES", "ERROR_CUT_FAILED", "ERROR_CANNOT_SOLVE_LINEAR_SYSTEM",
    "ERROR_NOT_CONVERGED", "ERROR_NO_1_TO_1_MAPPING", "ERROR_POINT_NOT_LOCATED", "ERROR_READ_FAILED",
    "ERROR_WRITE_FAILED", "ERROR_BOUNDARY_CHORD", "ERROR_POLYGON_NOT_CONVEX", "ERROR_CORNERS_NOT_IN_BOUNDARY_ORDER"};
  static_assert(sizeof(names) / sizeof(names[0]) == HOT::number_of_error_codes, "one name per Error_code");
  const int i = static_cast<int>(ec);
  return (i >= 0 && i < HOT::number_of_error_codes) ? names[i] : "UNKNOWN_ERROR_CODE";
}

static std::string base_name(const std::string& path) { return path.substr(path.find_last_of('/') + 1); }

// FNV-1a: a stable hash of the mesh's file name, part of the seed
static std::uint64_t fnv1a(const std::string& s)
{
  std::uint64_t h = 1469598103934665603ULL;
  for(unsigned char c : s) {
    h ^= c;
    h *= 1099511628211ULL;
  }
  return h;
}

// k distinct values among 0..n-1 (partial Fisher-Yates), with a portable bounded draw
static std::vector<std::size_t> draw_distinct(std::size_t n, std::size_t k, std::mt19937_64& rng)
{
  std::vector<std::size_t> pool(n);
  for(std::size_t i = 0; i < n; ++i) pool[i] = i;
  for(std::size_t i = 0; i < k; ++i) {
    const std::uint64_t range = n - i, limit = UINT64_MAX - UINT64_MAX % range;
    std::uint64_t r;
    do r = rng(); while(r >= limit);
    std::swap(pool[i], pool[i + r % range]);
  }
  pool.resize(k);
  return pool;
}

static bool parse_list(const std::string& s, std::vector<std::size_t>& out)
{
  out.clear();
  std::stringstream ss(s);
  std::string item;
  while(std::getline(ss, item, ',')) {
    const std::size_t dash = item.find('-');
    char* end = nullptr;
    if(dash == std::string::npos) {
      const unsigned long v = std::strtoul(item.c_str(), &end, 10);
      if(item.empty() || *end) return false;
      out.push_back(v);
    } else {
      const std::string a = item.substr(0, dash), b = item.substr(dash + 1);
      const unsigned long lo = std::strtoul(a.c_str(), &end, 10);
      if(a.empty() || *end) return false;
      const unsigned long hi = std::strtoul(b.c_str(), &end, 10);
      if(b.empty() || *end || hi < lo || hi - lo > 100000) return false;
      for(unsigned long v = lo; v <= hi; ++v) out.push_back(v);
    }
  }
  return !out.empty();
}

struct Mesh_class
{
  bool usable = false;
  std::string reason; // why not usable
  HOT::Orbifold_type type = HOT::Sphere_type;
  std::size_t vertices = 0;
};

// reads and classifies a mesh: closed genus 0 (sphere type), disk (disk type) or neither
static Mesh_class classify(const std::string& path, SM& sm, std::size_t max_vertices)
{
  Mesh_class c;
  const HOT::Status rr = hot_tools::read_mesh(path, sm);
  if(!rr) {
    c.reason = std::string("cannot be read (") + error_code_name(rr.code) + ": " + rr.message + ")";
    return c;
  }
  c.vertices = num_vertices(sm);
  for(SM_face f : faces(sm))
    if(degree(f, sm) != 3) {
      c.reason = "not a triangle mesh (face " + std::to_string(f.idx()) + " has " + std::to_string(degree(f, sm)) +
                 " vertices)";
      return c;
    }
  if(!CGAL::is_valid_polygon_mesh(sm)) {
    c.reason = "not a valid 2-manifold polygon mesh";
    return c;
  }
  // connected components of the faces
  std::vector<int> comp(num_faces(sm), -1);
  int ncomp = 0;
  for(SM_face f : faces(sm)) {
    if(comp[f.idx()] >= 0) continue;
    std::vector<SM_face> stack(1, f);
    comp[f.idx()] = ncomp;
    while(!stack.empty()) {
      const SM_face g = stack.back();
      stack.pop_back();
      for(SM_halfedge h : halfedges_around_face(halfedge(g, sm), sm)) {
        const SM_face o = face(opposite(h, sm), sm);
        if(o != SM::null_face() && comp[o.idx()] < 0) {
          comp[o.idx()] = ncomp;
          stack.push_back(o);
        }
      }
    }
    ++ncomp;
  }
  const std::size_t loops = HOT::count_border_loops(sm);
  const long long chi = static_cast<long long>(num_vertices(sm)) - static_cast<long long>(num_edges(sm)) +
                        static_cast<long long>(num_faces(sm));
  std::ostringstream topo;
  topo << "V-E+F = " << chi << ", " << loops << " boundary loop" << (loops == 1 ? "" : "s");
  if(ncomp != 1) {
    c.reason = std::to_string(ncomp) + " connected components (" + topo.str() + ")";
    return c;
  }
  const long long genus2 = 2 - static_cast<long long>(loops) - chi; // twice the genus
  if(loops == 0 && chi == 2)
    c.type = HOT::Sphere_type;
  else if(loops == 1 && chi == 1)
    c.type = HOT::Disk_type;
  else {
    std::ostringstream os;
    os << "neither a closed genus-0 mesh nor a disk: genus " << genus2 / 2.0 << ", " << topo.str();
    c.reason = os.str();
    return c;
  }
  const HOT::Status r = HOT::check_mesh(sm, c.type);
  if(!r) {
    c.reason = std::string("the library refuses the mesh itself (") + error_code_name(r.code) + ": " + r.message + ")";
    return c;
  }
  if(max_vertices > 0 && c.vertices > max_vertices) {
    c.reason = std::to_string(c.vertices) + " vertices, more than --max-vertices " + std::to_string(max_vertices);
    return c;
  }
  c.usable = true;
  return c;
}

enum Outcome { CERTIFIED, REFUSED, FAILED, NOT_RUN };

struct Run
{
  std::size_t k = 0, seed = 0;
  Outcome outcome = NOT_RUN;
  double seconds = 0;
  int iterations = 0;
};

int main(int argc, char** argv)
{
  std::vector<std::size_t> ks = {5, 7, 10, 16, 23, 35, 50}, seeds = {1, 2, 3, 4, 5, 6, 7, 8};
  std::size_t max_vertices = 60000;
  double budget = 0;
  bool only_classify = false;
  HOT::Weight_type weights = HOT::Cotangent;
  std::vector<std::string> files;
  auto usage = [] {
    std::cerr << "usage: stress_landmarks [--ks 5,7,10] [--seeds 1-8] [--max-vertices N] [--time-budget S] "
                 "[--weights cotan|mvc|uniform] [--classify] mesh [mesh ...]"
              << std::endl;
    return 2;
  };
  for(int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    const bool has_value = i + 1 < argc;
    if(a == "--ks" && has_value) {
      if(!parse_list(argv[++i], ks)) return usage();
    } else if(a == "--seeds" && has_value) {
      if(!parse_list(argv[++i], seeds)) return usage();
    } else if(a == "--max-vertices" && has_value) {
      max_vertices = std::strtoul(argv[++i], nullptr, 10);
    } else if(a == "--time-budget" && has_value) {
      budget = std::strtod(argv[++i], nullptr);
    } else if(a == "--weights" && has_value) {
      const std::string w = argv[++i];
      if(w == "cotan") weights = HOT::Cotangent;
      else if(w == "mvc") weights = HOT::Mean_value;
      else if(w == "uniform") weights = HOT::Uniform;
      else return usage();
    } else if(a == "--classify") {
      only_classify = true;
    } else if(!a.empty() && a[0] == '-') {
      return usage();
    } else {
      files.push_back(a);
    }
  }
  if(files.empty()) return usage();

  const auto start = Clock::now();
  auto elapsed = [&] { return seconds_since(start); };

  for(const std::string& path : files) {
    const std::string name = base_name(path);
    SM sm;
    const Mesh_class mc = classify(path, sm, max_vertices);
    if(!mc.usable) {
      std::printf("SKIP %s: %s\n", name.c_str(), mc.reason.c_str());
      std::fflush(stdout);
      continue;
    }
    const char* type_name = mc.type == HOT::Sphere_type ? "sphere" : "disk";
    if(only_classify) {
      std::printf("CLASS %s %s %zu\n", name.c_str(), type_name, mc.vertices);
      std::fflush(stdout);
      continue;
    }

    std::vector<SM_vertex> verts(vertices(sm).begin(), vertices(sm).end());
    // candidates: every vertex (sphere), or the boundary loop in order (disk)
    std::vector<std::size_t> candidates;
    if(mc.type == HOT::Sphere_type) {
      for(std::size_t i = 0; i < verts.size(); ++i) candidates.push_back(i);
    } else {
      SM_halfedge b = SM::null_halfedge();
      for(SM_halfedge h : halfedges(sm))
        if(is_border(h, sm)) { b = h; break; }
      for(SM_halfedge h : halfedges_around_face(b, sm)) candidates.push_back(target(h, sm).idx());
    }

    std::vector<Run> runs;
    std::map<std::size_t, double> last_time_for_k;
    double last_time = 0, mesh_start = elapsed();
    bool out_of_time = false;
    auto uv = sm.add_property_map<SM_halfedge, K::Point_2>("h:uv").first;
    for(std::size_t seed : seeds)
      for(std::size_t k : ks) {
        Run run;
        run.k = k;
        run.seed = seed;
        if(k > candidates.size()) {
          std::printf("RUN %s k=%zu seed=%zu %s skipped: only %zu %s\n", name.c_str(), k, seed, type_name,
                      candidates.size(), mc.type == HOT::Sphere_type ? "vertices" : "boundary vertices");
          continue;
        }
        const double predicted = last_time_for_k.count(k) ? last_time_for_k[k] : last_time;
        const double used = elapsed() - mesh_start;
        if(!out_of_time && budget > 0 && !runs.empty() && used + predicted > budget) out_of_time = true;
        if(out_of_time) {
          runs.push_back(run);
          continue;
        }
        std::mt19937_64 rng(fnv1a(name) ^ (0x9e3779b97f4a7c15ULL * (seed + 1)) ^ (0xbf58476d1ce4e5b9ULL * k));
        std::vector<std::size_t> chosen = draw_distinct(candidates.size(), k, rng);
        if(mc.type == HOT::Disk_type) std::sort(chosen.begin(), chosen.end()); // boundary order
        std::vector<std::size_t> idx;
        std::vector<SM_vertex> landmarks;
        for(std::size_t c : chosen) {
          idx.push_back(candidates[c]);
          landmarks.push_back(verts[candidates[c]]);
        }
        std::ostringstream lm;
        for(std::size_t i = 0; i < idx.size(); ++i) lm << (i ? "," : "") << idx[i];
        std::fprintf(stderr, "START %s k=%zu seed=%zu landmarks=%s\n", name.c_str(), k, seed, lm.str().c_str());
        std::fflush(stderr);

        HOT::Embedding_statistics st;
        HOT::Error_code ec = HOT::OK;
        std::string exception_text;
        const auto t = Clock::now();
        try {
          ec = HOT::hyperbolic_orbifold_Tutte_embedding(
            sm, landmarks, uv,
            HOT::parameters::landmark_order(mc.type == HOT::Sphere_type ? HOT::Tsp_order : HOT::Given_order,
                                            HOT::parameters::embedding_statistics(&st, HOT::parameters::weight_type(weights))));
        } catch(const std::exception& e) {
          exception_text = e.what();
        } catch(...) {
          exception_text = "unknown exception";
        }
        run.seconds = seconds_since(t);
        run.iterations = st.iterations;
        last_time = last_time_for_k[k] = run.seconds;

        const bool certified = exception_text.empty() && ec == HOT::OK && st.certificate.is_bijective();
        const bool refused = exception_text.empty() && (ec == HOT::ERROR_CUT_FAILED || ec == HOT::ERROR_BOUNDARY_CHORD);
        run.outcome = certified ? CERTIFIED : refused ? REFUSED : FAILED;
        runs.push_back(run);

        std::ostringstream line;
        line << "RUN " << name << " k=" << k << " seed=" << seed << " " << type_name << " ";
        line.setf(std::ios::fixed);
        line.precision(3);
        if(certified) {
          line << "certified " << run.seconds << "s its=" << st.iterations << " repaired=" << st.repaired_vertices;
        } else {
          // landmarks joined by a mesh edge (a reason for the cut to be impossible)
          const std::set<std::size_t> lmset(idx.begin(), idx.end());
          std::size_t adjacent = 0;
          for(std::size_t i : idx)
            for(SM_vertex w : vertices_around_target(halfedge(verts[i], sm), sm))
              if(w.idx() > i && lmset.count(w.idx())) ++adjacent;
          line << (refused ? "REFUSED " : "FAILED ")
               << (exception_text.empty() ? error_code_name(ec) : "EXCEPTION") << " " << run.seconds
               << "s its=" << st.iterations;
          line.precision(2);
          line.unsetf(std::ios::fixed);
          line << " rel_gradient=" << st.relative_gradient_norm << " adjacent_landmark_pairs=" << adjacent
               << " message=\"" << (exception_text.empty() ? st.message : exception_text) << "\"";
          line.precision(6);
          if(st.certificate.number_of_faces > 0 && ec != HOT::ERROR_NO_1_TO_1_MAPPING) // else in the message
            line << " certificate=\"" << st.certificate << "\"";
          if(!st.problem_vertices.empty()) {
            line << " problem_vertices=";
            for(std::size_t i = 0; i < st.problem_vertices.size(); ++i)
              line << (i ? "," : "") << st.problem_vertices[i];
          }
          if(!st.landmark_order.empty() && mc.type == HOT::Sphere_type) {
            line << " tsp_order=";
            for(std::size_t i = 0; i < st.landmark_order.size(); ++i) line << (i ? "," : "") << st.landmark_order[i];
          }
          line << " landmarks=" << lm.str();
        }
        std::printf("%s\n", line.str().c_str());
        std::fflush(stdout);
      }
    sm.remove_property_map(uv);

    // the table of this mesh, one row per k
    std::printf("TABLE %s (%s, %zu vertices)\n", name.c_str(), type_name, mc.vertices);
    std::printf("  %4s %5s %9s %7s %6s %7s %9s %9s %8s\n", "k", "runs", "certified", "refused", "failed", "not_run",
                "mean(s)", "max(s)", "max_its");
    std::size_t tot[4] = {0, 0, 0, 0};
    double total_time = 0;
    for(std::size_t k : ks) {
      std::size_t c[4] = {0, 0, 0, 0};
      double sum = 0, mx = 0;
      int its = 0;
      std::size_t ran = 0;
      for(const Run& r : runs) {
        if(r.k != k) continue;
        ++c[r.outcome];
        ++tot[r.outcome];
        if(r.outcome != NOT_RUN) {
          ++ran;
          sum += r.seconds;
          mx = std::max(mx, r.seconds);
          its = std::max(its, r.iterations);
        }
      }
      total_time += sum;
      if(ran == 0 && c[NOT_RUN] == 0) continue; // more landmarks than candidate vertices
      std::printf("  %4zu %5zu %9zu %7zu %6zu %7zu %9.3f %9.3f %8d\n", k, ran, c[CERTIFIED], c[REFUSED], c[FAILED],
                  c[NOT_RUN], ran ? sum / ran : 0.0, mx, its);
    }
    std::printf("SUMMARY %s type=%s vertices=%zu runs=%zu certified=%zu refused=%zu failed=%zu not_run=%zu seconds=%.1f\n",
                name.c_str(), type_name, mc.vertices, tot[CERTIFIED] + tot[REFUSED] + tot[FAILED], tot[CERTIFIED],
                tot[REFUSED], tot[FAILED], tot[NOT_RUN], total_time);
    std::fflush(stdout);
  }
  return 0;
}
