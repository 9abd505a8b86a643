// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// How well balanced each vertex of an embedding is (never run by ctest; a measurement for
// the manual's statement of what the solver guarantees per vertex):
//
//   vertex_balance [--k 12] [--seeds 1-10] [--weights cotan|uniform] mesh [mesh ...]
//
// embeds each closed genus-0 mesh with k random landmarks (std::mt19937_64 seeded with the
// seed; Tsp_order) and, at every vertex off the cut and not a landmark, measures the
// relative force residual r = |sum_j w_ij log_{z_i}(z_j)| / sum_j w_ij d_ij (the weighted
// hyperbolic centre-of-mass condition, computed with Mobius maps: independent of the
// solver's derivatives) and what double resolves there, rho = max_j 4e-16 / (A_ij d_ij)
// (A = the smaller 1 - |z|^2 of the edge's ends; the rounding of a coordinate moves a point
// by about 2e-16 / (1 - |z|^2) hyperbolic units, relative to the edge's length d).
// One line per run: the median and the largest r, the vertex of the largest (valence, |z|,
// rho, r / rho), how many vertices have r > 1e-8 and how many r > 1e-8 + 1000 rho.

#include "bench_common.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <set>
#include <string>
#include <vector>

typedef std::complex<double> C;
typedef HOT::Hyperbolic_isometry_2<double> Isometry;
typedef SM::Property_map<SM_halfedge, K::Point_2> UV_map;

int main(int argc, char** argv)
{
  int k = 12, s0 = 1, s1 = 10;
  HOT::Weight_type w = HOT::Cotangent;
  std::vector<std::string> meshes;
  for(int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if(a == "--k" && i + 1 < argc) k = std::atoi(argv[++i]);
    else if(a == "--seeds" && i + 1 < argc) {
      const std::string r = argv[++i];
      const std::size_t dash = r.find('-');
      s0 = std::atoi(r.substr(0, dash).c_str());
      s1 = dash == std::string::npos ? s0 : std::atoi(r.substr(dash + 1).c_str());
    } else if(a == "--weights" && i + 1 < argc) {
      const std::string v = argv[++i];
      w = v == "uniform" ? HOT::Uniform : HOT::Cotangent;
    } else
      meshes.push_back(a);
  }
  if(meshes.empty()) {
    std::fprintf(stderr, "usage: vertex_balance [--k K] [--seeds A-B] [--weights cotan|uniform] mesh...\n");
    return 2;
  }
  for(const std::string& path : meshes) {
    SM base;
    if(!CGAL::IO::read_polygon_mesh(path, base)) {
      std::fprintf(stderr, "cannot read %s\n", path.c_str());
      return 1;
    }
    for(int seed = s0; seed <= s1; ++seed) {
      SM m = base;
      std::mt19937_64 gen(seed);
      std::set<SM_vertex> chosen;
      std::vector<SM_vertex> lm;
      while(static_cast<int>(lm.size()) < k) {
        const SM_vertex v(static_cast<SM::size_type>(gen() % num_vertices(m)));
        if(chosen.insert(v).second) lm.push_back(v);
      }
      UV_map uv = m.add_property_map<SM_halfedge, K::Point_2>("h:uv").first;
      HOT::Embedding_statistics st;
      const HOT::Error_code ec = HOT::hyperbolic_orbifold_Tutte_embedding(
        m, lm, uv, HOT::parameters::weight_type(w, HOT::parameters::landmark_order(HOT::Tsp_order, HOT::parameters::embedding_statistics(&st))));
      if(ec != HOT::OK) {
        std::printf("%s k=%d seed=%d: %s (%s)\n", path.c_str(), k, seed, HOT::error_message(ec), st.message.c_str());
        continue;
      }
      std::vector<double> res;
      double worst = -1, worst_rho = 0, worst_z = 0;
      int worst_v = -1, worst_valence = 0, above = 0, above_rounding = 0;
      for(SM_vertex v : vertices(m)) {
        if(chosen.count(v)) continue;
        bool single = true, first = true;
        C z0;
        for(SM_halfedge h : halfedges_around_target(halfedge(v, m), m)) {
          const C z(get(uv, h).x(), get(uv, h).y());
          if(first) { z0 = z; first = false; }
          else if(std::abs(z - z0) > 1e-14) { single = false; break; }
        }
        if(!single) continue; // a cut vertex: its corners are in several places
        const Isometry to0 = Isometry::translation_to_origin(z0);
        C sum;
        double scale = 0, rho = 0;
        int valence = 0;
        for(SM_halfedge h : halfedges_around_target(halfedge(v, m), m)) {
          const SM_halfedge hp = prev(h, m);
          const C zj(get(uv, hp).x(), get(uv, hp).y());
          const C u = to0.apply(zj);
          const double r = std::abs(u), d = 2 * std::atanh(r);
          const double A = std::min(1 - std::norm(z0), 1 - std::norm(zj));
          rho = std::max(rho, 4e-16 / (A * d));
          double wij = 1;
          if(w == HOT::Cotangent) {
            auto cot = [&](SM_halfedge g) {
              const K::Point_3& a = m.point(source(g, m));
              const K::Point_3& b = m.point(target(g, m));
              const K::Point_3& c = m.point(target(next(g, m), m));
              const K::Vector_3 u1 = a - c, u2 = b - c;
              return (u1 * u2) / std::sqrt(CGAL::cross_product(u1, u2).squared_length());
            };
            wij = std::max(0.5 * (cot(h) + cot(opposite(h, m))), 1e-6);
          }
          sum += (wij * d / r) * u;
          scale += wij * d;
          ++valence;
        }
        const double rv = std::abs(sum) / scale;
        res.push_back(rv);
        above += rv > 1e-8;
        above_rounding += rv > 1e-8 + 1e3 * rho;
        if(rv > worst) {
          worst = rv;
          worst_v = static_cast<int>(v);
          worst_valence = valence;
          worst_rho = rho;
          worst_z = std::abs(z0);
        }
      }
      std::sort(res.begin(), res.end());
      std::printf("%s k=%d seed=%d: %zu vertices off the cut, residual median %.2g, largest %.2g at vertex %d "
                  "(valence %d, |z| = %.17g, rho %.2g, residual/rho %.3g); %d above 1e-8, %d above 1e-8 + 1000 rho; "
                  "relative gradient %.2g, floor %.2g%s, %d+%d iterations\n",
                  path.c_str(), k, seed, res.size(), res.empty() ? 0.0 : res[res.size() / 2], worst, worst_v, worst_valence,
                  worst_z, worst_rho, worst_rho > 0 ? worst / worst_rho : 0.0, above, above_rounding,
                  st.relative_gradient_norm, st.rounding_floor, st.converged_at_rounding_floor ? " (stopped there)" : "",
                  st.iterations, st.polishing_iterations);
      std::fflush(stdout);
    }
  }
  return 0;
}
