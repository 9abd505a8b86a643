// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_PIPELINE_EMBEDDING_PIPELINE_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_PIPELINE_EMBEDDING_PIPELINE_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Hyperbolic_orbifold_Tutte/Embedding_statistics.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/error_code.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/weight_type.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/pipeline/certify_and_repair.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/core/compiled_once.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/pipeline/cone_chart_solve.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/solver/cut_graph_problem.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/solver/flat_problem.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/solver/orbifold_solver.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/pipeline/recentring.h>

#include <CGAL/boost/graph/properties.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <sstream>
#include <string>
#include <unordered_map>
#include <vector>

// The embedding of a cut (seam) mesh, the pipeline's solve stage, in one place: the flat
// problem and its weights, the Euclidean Tutte initialisation, Newton, the certificate, and
// the mends when it fails (Newton to the floor of double, recentring, one-ring repairs).
// Hyperbolic_orbifold_Tutte_parameterizer_3 runs it; the one-call function, the collection
// and the command line reach it through the parameterizer.

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {
namespace internal {

// What the solve stage needs besides the mesh and the tile.
template <class TM_edge_descriptor>
struct Embedding_settings
{
  Weight_type weights = Cotangent;
  double epsilon = 1e-6;            // the lower clamp of cotangent weights
  Solver_options solver;
  bool recentring = false;
  bool charts = false;              // a part converging onto cone images may be written in charts
  std::pair<int, int> cut_graph_start{-1, -1}; // genus g >= 1: the cut graph's first edge (base indices), or none
  std::function<double(const TM_edge_descriptor&)> user_weights; // empty: `weights`
  // told the progress of the phases "initialization", "optimization" and "certificate" (see
  // Hyperbolic_orbifold_Tutte_parameterizer_3::set_progress()); empty: none
  std::function<void(const char*, double)> progress;
};

template <class SeamMesh, class Tile>
class Seam_mesh_embedding
{
public:
  typedef typename SeamMesh::TriangleMesh Triangle_mesh;
  typedef typename boost::graph_traits<SeamMesh>::halfedge_descriptor halfedge_descriptor;
  typedef typename boost::graph_traits<SeamMesh>::vertex_descriptor vertex_descriptor;
  typedef typename boost::graph_traits<Triangle_mesh>::vertex_descriptor TM_vertex_descriptor;
  typedef typename boost::graph_traits<Triangle_mesh>::edge_descriptor TM_edge_descriptor;
  typedef Embedding_settings<TM_edge_descriptor> Settings;
  typedef std::complex<double> C;

  Seam_mesh_embedding(const SeamMesh& mesh, halfedge_descriptor bhd, const std::vector<TM_vertex_descriptor>& landmarks,
                      const Tile& tile, const Settings& settings, Embedding_statistics& st)
    : mesh_(mesh), bhd_(bhd), landmarks_(landmarks), tile_(tile), settings_(settings), st_(st)
  {}

  // Runs the stage; on `OK`, `uv()[v]` is the certified position of `cut_vertices()[v]`
  // (in the frame `st.frame`). On failure `st.message` says why.
  Error_code run()
  {
    tell("initialization", 0.0);
    const auto t0 = Clock::now();
    Error_code ec = set_up();
    if(ec != OK)
      return ec;
    st_.time_setup = seconds_since(t0);
    const auto t1 = Clock::now();
    interior_.multigrid_from = settings_.solver.multigrid_from;
    ec = initialize_embedding(P_, tile_, base_points_, x_, &interior_); // factors what the solver reuses
    st_.time_initialization = seconds_since(t1);
    st_.shared_factorization = interior_.connection != nullptr;
    if(ec != OK)
      return fail(ec, "the Euclidean Tutte initialisation failed");
    tell("initialization", 1.0);
    tell("optimization", 0.0);
    const auto t2 = Clock::now();
    Solver_options solver = settings_.solver;
    if(settings_.progress)
      solver.progress = [this](double f) { tell("optimization", f); };
    ec = minimize_energy(P_, x_, solver, st_, &interior_); // (its part of the statistics)
    st_.time_optimization = seconds_since(t2);
    tell("optimization", 1.0);
    tell("certificate", 0.0);
    const bool recentring_tried = certify_and_mend(ec == OK);
    tell("certificate", 1.0);
    return verdict(ec, recentring_tried);
  }

  const std::vector<C>& uv() const { return uv_; }
  const std::vector<vertex_descriptor>& cut_vertices() const { return cut_vertices_; }
  const Flat_problem& flat_problem() const { return P_; }
  // the charts around cone images, where `uv()` is not the embedding (see cone_charts.h)
  const Cone_charts& charts() const { return charts_; }
  // the chart of cut vertex v (-1: none) and its position there
  std::pair<int, C> chart_point(std::size_t v) const
  {
    const int q = charts_.empty() ? -1 : charts_.region_q[v];
    return q < 0 ? std::make_pair(-1, C()) : std::make_pair(charts_.q_chart[q], charts_.q_position[q]);
  }

private:
  typedef std::chrono::steady_clock Clock;

  static double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

  void tell(const char* phase, double fraction) const
  {
    if(settings_.progress)
      settings_.progress(phase, fraction);
  }

  Error_code fail(Error_code ec, const std::string& msg)
  {
    st_.message = msg.empty() ? std::string(error_message(ec)) : msg;
    return ec;
  }

  // the flat problem of the cut mesh and its edge weights
  Error_code set_up()
  {
    std::string msg;
    const Error_code ec = tile_.signature().genus() > 0 // (a surface of genus g >= 1 cut along a graph)
                            ? build_cut_graph_topology(mesh_, bhd_, landmarks_, settings_.cut_graph_start, tile_, P_, base_vertex_, cut_vertices_, msg)
                            : build_flat_topology(mesh_, bhd_, landmarks_, tile_, P_, base_vertex_, cut_vertices_, msg);
    if(ec != OK) {
      st_.problem_vertices.assign(P_.problem_vertices.begin(), P_.problem_vertices.end());
      return fail(ec, msg);
    }
    st_.number_of_vertices = P_.n;
    st_.number_of_variables = P_.n_vars;
    st_.landmark_order_reversed = P_.landmark_order_reversed;
    const Triangle_mesh& tm = mesh_.mesh();
    const auto vpm = get(vertex_point, tm);
    base_points_.resize(P_.n_base);
    for(int i = 0; i < P_.n_base; ++i)
      base_points_[i] = get(vpm, base_vertex_[i]);
    if(settings_.user_weights)
      return set_user_weights(tm);
    compute_edge_weights(P_, base_points_, settings_.weights, settings_.epsilon);
    return OK;
  }

  // each base edge once in total: its copies (two along a seam) share the user's weight
  Error_code set_user_weights(const Triangle_mesh& tm)
  {
    std::unordered_map<long long, int> copies;
    auto key = [](int a, int b) { return (static_cast<long long>(std::min(a, b)) << 32) | std::max(a, b); };
    for(const auto& e : P_.edges)
      ++copies[key(P_.base[e[0]], P_.base[e[1]])];
    P_.edge_weight.resize(P_.edges.size());
    for(std::size_t i = 0; i < P_.edges.size(); ++i) {
      const int a = P_.base[P_.edges[i][0]], b = P_.base[P_.edges[i][1]];
      const auto e = edge(base_vertex_[a], base_vertex_[b], tm);
      const double w = e.second ? settings_.user_weights(e.first) : 0.0;
      if(!(w > 0) || !std::isfinite(w))
        return fail(ERROR_WRONG_PARAMETER, "the user weight of the edge between mesh vertices " + std::to_string(a) +
                                             " and " + std::to_string(b) + " is not a positive finite number");
      P_.edge_weight[i] = w / copies[key(a, b)];
    }
    return OK;
  }

  // The certificate, and the mends where it fails: a region too small for the stopping test
  // to see gets Newton to the floor of double; triangles below what double resolves get
  // recentring (when allowed); flipped faces the one-ring repairs. Returns whether
  // recentring was tried. The time of the mends that solve counts as optimisation.
  bool certify_and_mend(bool solved)
  {
    uv_.assign(P_.n, C());
    auto t3 = Clock::now();
    certify(P_, tile_, x_, uv_, st_);
    if(solved && flipped_only(st_)) {
      const auto t4 = Clock::now();
      polish_to_floor();
      const auto dt = Clock::now() - t4; // solver time, not certificate time
      st_.time_optimization += std::chrono::duration<double>(dt).count();
      t3 += dt;
      certify(P_, tile_, x_, uv_, st_);
    }
    tiny_ = unresolved_faces(P_, uv_, tile_.traits(), false);
    // (triangles below what double resolves have unreliable angles too: angle-sum failures)
    const Embedding_certificate& c = st_.certificate;
    const bool local_failure = !c.is_bijective() && c.points_outside_disk == 0 && c.twin_failures == 0 &&
                               c.cone_failures == 0 && c.border_failures == 0;
    const bool genus_zero = tile_.signature().genus() == 0; // (charts and recentring: genus 0 only)
    if(solved && local_failure && tiny_.count > 0 && genus_zero) {
      double radius = 0;
      Cone_charts probe;
      onto_cones_ = choose_cone_charts(P_, tile_, uv_, tiny_.flag, radius, probe);
    }
    if(onto_cones_ && settings_.charts && solve_in_charts()) {
      st_.time_certificate = seconds_since(t3);
      return false;
    }
    const bool recentring_tried = solved && local_failure && tiny_.count > 0 && settings_.recentring && genus_zero;
    if(recentring_tried) {
      const auto t4 = Clock::now();
      recentre(mesh_, bhd_, landmarks_, cut_vertices_, tile_, P_, settings_.solver, uv_, st_);
      const auto dt = Clock::now() - t4;
      st_.time_optimization += std::chrono::duration<double>(dt).count();
      t3 += dt;
    } else {
      repair(P_, tile_, x_, uv_, st_);
    }
    st_.time_certificate = seconds_since(t3);
    return recentring_tried;
  }

  // The faces below what double resolves converge onto cone images (a long protrusion ending
  // at a landmark): solved again in charts centred at them; true when certified so
  bool solve_in_charts()
  {
    const auto t = Clock::now();
    std::vector<C> uv = uv_;
    Embedding_statistics st = st_;
    bool ok = solve_in_cone_charts(P_, tile_, uv, settings_.solver, charts_, st);
    if(ok) {
      st.certificate = certify_flat(P_, tile_, uv, 1e-6, &charts_);
      ok = st.certificate.is_bijective();
    }
    st_.time_optimization += seconds_since(t);
    if(!ok) {
      charts_ = Cone_charts();
      return false;
    }
    st.time_optimization = st_.time_optimization;
    st_ = st;
    st_.charted_faces = charts_.Q.faces.size();
    st_.charts = charts_.chart;
    st_.chart_corners = charts_.chart_corner;
    uv_.swap(uv);
    return true;
  }

  // Newton until rounding stops it, with every vertex's forces balanced to the floor
  void polish_to_floor()
  {
    Solver_options polish = settings_.solver;
    polish.polish = true;
    polish.vertex_imbalance = 0;
    Solver_statistics ps;
    minimize_energy(P_, x_, polish, ps, &interior_); // only accepted (descent) steps change x
    st_.polishing_iterations += ps.iterations;
    st_.cg_iterations += ps.cg_iterations;
    st_.energy = ps.energy;
    st_.gradient_norm = ps.gradient_norm;
    st_.relative_gradient_norm = ps.relative_gradient_norm;
  }

  // the solver's failure, or the certificate's, with what to do about it
  Error_code verdict(Error_code ec, bool recentring_tried)
  {
    if(ec != OK) {
      std::ostringstream os;
      os << "the solver stopped at relative gradient norm " << st_.relative_gradient_norm << " after "
         << st_.iterations << " iterations (tolerance " << settings_.solver.gradient_tolerance
         << ", rounding floor " << st_.rounding_floor << ")";
      return fail(ec, os.str());
    }
    if(st_.certificate.is_bijective())
      return OK;
    std::ostringstream os;
    os << "the embedding failed the certificate: " << st_.certificate;
    // triangles double cannot resolve: their edges within a few hundred units in the last
    // place of their coordinates (a protrusion without landmarks shrinks exponentially
    // along its length, by e per radius for a tube: about 33 radii exhaust double)
    if(tiny_.count > 0 && onto_cones_) {
      // a protrusion ending at a landmark: it converges onto the landmark's cone image
      os << "; " << tiny_.count << " triangles are below what double resolves in the tile (smallest edge "
         << tiny_.smallest << "): they converge onto cone images (a long protrusion ending at a landmark)";
      if(settings_.charts)
        os << ", and solving them again in charts centred at the cone images did not suffice";
      else
        os << "; allow charts centred at the cone images (a chart map: parameters::chart_map())";
    } else if(tiny_.count > 0) {
      os << "; " << tiny_.count << " triangles are below what double resolves (smallest edge " << tiny_.smallest
         << "): a part of the mesh far from every landmark (a long protrusion) shrinks exponentially"
            " in the embedding; put a landmark on it";
      if(recentring_tried)
        os << " (solving it again with its deepest point at the origin did not suffice)";
      else if(!settings_.recentring)
        os << ", or allow recentring (parameters::recentring(true); command line: --recentre)";
    }
    return fail(ERROR_NO_1_TO_1_MAPPING, os.str());
  }

  const SeamMesh& mesh_;
  halfedge_descriptor bhd_;
  const std::vector<TM_vertex_descriptor>& landmarks_;
  const Tile& tile_;
  const Settings& settings_;
  Embedding_statistics& st_;

  Flat_problem P_;
  std::vector<TM_vertex_descriptor> base_vertex_;
  std::vector<vertex_descriptor> cut_vertices_;
  std::vector<typename boost::property_traits<typename boost::property_map<
    Triangle_mesh, boost::vertex_point_t>::const_type>::value_type> base_points_;
  std::vector<double> x_;
  Interior_laplacian interior_; // factored by the initialisation, reused by the solver
  std::vector<C> uv_;
  Cone_charts charts_; // empty unless a region converging onto cone images needed them
  bool onto_cones_ = false; // the faces double cannot resolve converge onto cone images
  Unresolved_faces tiny_;
};

// Runs the solve stage (a door compiled once in the project's own builds for the seam mesh of
// a CGAL::Surface_mesh over Epick's points and the default tile: internal/core/compiled_once.h).
template <class SeamMesh, class Tile>
Error_code run_embedding_stage(Seam_mesh_embedding<SeamMesh, Tile>& job)
{
  return job.run();
}

} // namespace internal
} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

// (declared where the unit included CGAL/Surface_mesh.h before: a program embedding a
// Surface_mesh through a Seam_mesh must include it before CGAL/boost/graph/Seam_mesh.h)
#if defined(CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_EXTERN_INSTANCES) && defined(CGAL_TOP_LEVEL_SURFACE_MESH_H) && \
    defined(CGAL_EXACT_PREDICATES_INEXACT_CONSTRUCTIONS_KERNEL_H)
#include <CGAL/Hyperbolic_orbifold_Tutte/Orbifold_tile.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/core/seam_mesh_storage.h>

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {
namespace internal {

typedef Seam_mesh_storage<CGAL::Surface_mesh<CGAL::Epick::Point_3> >::Mesh Instance_seam_mesh;

#define CGAL_HOT_RUN_EMBEDDING_STAGE_DOOR                                                                 \
  Error_code run_embedding_stage<Instance_seam_mesh, Orbifold_tile<> >(                                \
    Seam_mesh_embedding<Instance_seam_mesh, Orbifold_tile<> >&)
CGAL_HOT_INSTANCE(extern, CGAL_HOT_RUN_EMBEDDING_STAGE_DOOR)

} // namespace internal
} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL
#endif

#include <CGAL/enable_warnings.h>

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_PIPELINE_EMBEDDING_PIPELINE_H
