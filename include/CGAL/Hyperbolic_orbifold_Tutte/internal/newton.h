// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_NEWTON_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_NEWTON_H

#include <CGAL/disable_warnings.h>

/// \file newton.h
// The energy's minimisation: Riemannian Newton with a preconditioned conjugate gradient,
// on the whole problem or on a region of it.

#include <CGAL/Hyperbolic_orbifold_Tutte/error_code.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/connection_preconditioner.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/dirichlet_energy.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/flat_problem.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/interior_laplacian.h>

#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <memory>
#include <optional>
#include <vector>

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {
namespace internal {

struct Solver_options
{
  double gradient_tolerance = 1e-10; // force imbalance (relative hyperbolic gradient norm)
  int max_iterations = 200;
  int max_cg_iterations = 400;       // per Newton step
  int refactor_cg_iterations = 25;   // refactor the preconditioner after a Newton step that needed more
  // Preconditioned gradient steps before Newton (phase 1 of minimize_energy). Off: Newton
  // from the start is as fast with 7 landmarks and up to 1.8x faster with 50, where the
  // gradient steps' long moves need the preconditioner factored again two or three times.
  bool gradient_steps = false;
  double newton_threshold = 1e-2;    // with gradient steps: relative gradient norm below which Newton takes over
  int max_model_refactorizations = 8; // preconditioner refactorisations during the gradient steps
  bool geodesic_steps = true;        // move free vertices along geodesics (exponential map)
  bool direct_solver = false;        // factor every Newton system instead of conjugate gradients
  // Newton steps from the start, until rounding stops them (the tolerance is ignored): for a
  // converged embedding whose small regions need the last digits (see the parameterizer)
  bool polish = false;
  bool riemannian_hessian = true;    // Newton with the Riemannian Hessian (see minimize_energy)
  // the preconditioner's CHOLMOD factor rounded to float for its solves (single_precision_factor.h)
  bool single_precision_preconditioner = true;
  // converged also means: no vertex's own forces are out of balance by more than this
  // fraction of their sizes, unless rounding explains it (else Newton goes on to the floor)
  double vertex_imbalance = 1e-8;
  bool verbose = false;
};

struct Solver_statistics
{
  int iterations = 0;
  double initial_energy = 0, energy = 0;
  double initial_gradient = 0, gradient = 0, relative_gradient = 0;
  double time_assemble = 0, time_factor = 0, time_line_search = 0;
  int cg_iterations = 0, cg_failures = 0, preconditioner_factorizations = 0;
  double rounding_floor = 0;   // Energy_evaluator::rounding_floor() at the result
  int polishing_iterations = 0; // Newton steps to balance every vertex (after convergence)
  bool at_rounding_floor = false; // stopped by rounding (stagnation) within 10x that floor
  bool converged = false;
};

// The energy is geodesically convex, its Hessian in the disk's coordinates is not: this
// subtracts the Christoffel terms of the metric (2/(1-|z|^2))^2 |dz|^2 at each free vertex,
// Hess_ij = d_ij E - (s_i g_j + s_j g_i - delta_ij s.g), s = grad log(2/(1-|z|^2)) =
// 2z/(1-|z|^2), g the gradient: the Riemannian Hessian, positive semi-definite, equal to the
// exact one where g = 0 (Newton stays quadratic); v^T Hess v is the second derivative of E
// along the geodesics of initial velocities v. (Seam copies follow their twin through an
// isometry, so the twin's terms cover them; border parameters keep the coordinate Hessian.)
inline void subtract_christoffel_terms(const Flat_problem& P, const std::vector<double>& x, const std::vector<double>& g,
                                       Eigen::SparseMatrix<double>& H)
{
  for(int v = 0; v < P.n; ++v) {
    if(P.kind[v] != Free)
      continue;
    const int i = P.var[v];
    const double q = 2 / (1 - (x[i] * x[i] + x[i + 1] * x[i + 1]));
    const double s0 = q * x[i], s1 = q * x[i + 1], g0 = g[i], g1 = g[i + 1];
    const double sg = s0 * g0 + s1 * g1;
    H.coeffRef(i, i) -= 2 * s0 * g0 - sg;
    H.coeffRef(i + 1, i + 1) -= 2 * s1 * g1 - sg;
    H.coeffRef(i, i + 1) -= s0 * g1 + s1 * g0;
    H.coeffRef(i + 1, i) -= s0 * g1 + s1 * g0;
  }
}

// Minimises the energy with a backtracking (Armijo) line search, in up to two phases:
//  1. (only with Solver_options::gradient_steps) Preconditioned gradient steps
//     p = -M^-1 g with the connection Laplacian M at the current scaling: no Hessian, one
//     triangular solve per step. M is so close to the Hessian that these steps converge
//     fast while the energy is far from its minimum.
//  2. Riemannian Newton: the exact Riemannian Hessian (subtract_christoffel_terms), steps
//     along geodesics, the systems solved by conjugate gradients preconditioned by M,
//     refactored when it no longer fits (truncated Newton, relative tolerance
//     min(1/2, sqrt(force imbalance)): inexact far from the solution, superlinear near it).
// Where the Hessian is not definite after all (border parameters, rounding; negative
// curvature met by CG), the Hessian projected edge by edge onto the positive semi-definite
// cone is used instead. Should the iterative solves stall, or the connection Laplacian not
// factor, the Hessian is factored directly (sparse LDL^T, symbolic analysis once): the
// former, slower, solver. The solver stops at the tolerance, or at the rounding floor (see
// Energy_evaluator::rounding_floor) when Newton stagnates above the tolerance.
inline Error_code minimize_energy(const Flat_problem& P, std::vector<double>& x, const Solver_options& opt,
                                  Solver_statistics& st, const Interior_laplacian* interior = nullptr)
{
  typedef Complex<double> C;
  typedef Eigen::SparseMatrix<double> SpMat;
  typedef std::chrono::steady_clock Clock;
  auto seconds = [](Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); };
  st = Solver_statistics();
  if(P.n_vars == 0) {
    st.converged = true;
    return OK;
  }
  const int nv = P.n_vars;
  std::vector<double> g, xn(nv), gn;
  SpMat H;
  Eigen::SimplicialLDLT<SpMat, Eigen::Lower, Eigen::AMDOrdering<int> > direct;
  bool direct_analyzed = false;
  // the initialisation's preconditioner where it made one for this problem (it is factored
  // again here only if the seam rotations have changed since), else one of our own
  std::unique_ptr<Connection_laplacian_preconditioner> own_pre;
  Connection_laplacian_preconditioner* pre_ptr = interior ? interior->connection.get() : nullptr;
  if(pre_ptr == nullptr || &pre_ptr->problem() != &P) {
    own_pre.reset(new Connection_laplacian_preconditioner(P, interior));
    pre_ptr = own_pre.get();
  }
  Connection_laplacian_preconditioner& pre = *pre_ptr;
  bool use_direct = opt.direct_solver;
  auto t0 = Clock::now();
  if(!use_direct && !pre.factored_at(x) && !pre.factor(x))
    use_direct = true;
  if(opt.single_precision_preconditioner)
    pre.solve_in_single_precision();
  st.time_factor += seconds(t0);
  // (the Hessian's pattern only now: a factor rounded to single precision has shrunk)
  Energy_evaluator ev(P);

  // per-variable weights of the hyperbolic norm of a gradient (or residual)
  Eigen::VectorXd hw(nv);
  auto set_norm_weights = [&]() {
    Position_jet j;
    for(int v = 0; v < P.n; ++v) {
      if(P.kind[v] == Free) {
        const int i = P.var[v];
        hw[i] = hw[i + 1] = (1 - (x[i] * x[i] + x[i + 1] * x[i + 1])) / 2;
      } else if(P.kind[v] == On_line) {
        position_jet(P, x, v, j);
        hw[P.var[v]] = (1 - norm(j.z)) / (2 * abs(j.dz[0]));
      }
    }
  };

  enum Phase { Model, Projected, Exact };
  Phase phase = use_direct ? Projected : (opt.polish || !opt.gradient_steps) ? Exact : Model;
  bool polishing = opt.polish;
  double tolerance = polishing ? 0.0 : opt.gradient_tolerance;
  int polish_start = 0;
  auto assemble = [&]() { // gradient, and the Hessian the phase needs
    auto t = Clock::now();
    const double e = ev.evaluate(x, g, phase == Model ? nullptr : &H, phase == Projected);
    if(phase == Exact && opt.riemannian_hessian)
      subtract_christoffel_terms(P, x, g, H);
    st.time_assemble += seconds(t);
    return e;
  };
  double E = assemble();
  st.initial_energy = E;
  st.initial_gradient = ev.hyperbolic_gradient_norm(x, g);
  const double g0 = st.initial_gradient > 0 ? st.initial_gradient : 1.0;
  double gnorm = st.initial_gradient;
  double grel = ev.hyperbolic_gradient_norm(x, g, true);
  int stalls = 0, last_cg = 0, slow_steps = 0, refactorings = 0;
  bool stagnated = false;
  double best_grel = grel;
  int since_best = 0;
  Eigen::VectorXd p(nv), r(nv), zv(nv), d(nv), Hd(nv);
  for(int it = 0; it < opt.max_iterations; ++it) {
    if(grel <= tolerance) {
      // converged as a whole; every vertex too? (a region squeezed to 1e-12 has forces too
      // small for the global imbalance to see): if not, Newton on, until it is or to the floor
      if(polishing || !(opt.vertex_imbalance > 0) || ev.unbalanced_vertices(x, g, opt.vertex_imbalance) == 0)
        break;
      polishing = true;
      tolerance = 0.0;
      polish_start = it;
      best_grel = grel;
      since_best = 0;
      if(phase != Exact) {
        phase = Exact;
        E = assemble();
      }
    } else if(polishing && opt.vertex_imbalance > 0 && ev.unbalanced_vertices(x, g, opt.vertex_imbalance) == 0) {
      break; // every vertex balanced, or at its rounding floor
    }
    // Near the solution Newton with the exact Hessian halves the imbalance at least every
    // few steps until rounding stops it: ten steps without that mean the floor of double
    // precision (three when polishing: Newton starts there next to the solution)
    if(grel < 0.5 * best_grel || phase != Exact || grel > 1e-6) {
      best_grel = std::min(best_grel, grel);
      since_best = 0;
    } else if(++since_best > (polishing ? 3 : 10) ||
              (since_best >= 3 && grel <= 10 * ev.rounding_floor(x))) { // (evaluates at x: g unchanged)
      stagnated = true;
      break;
    }
    auto t1 = Clock::now();
    Eigen::Map<const Eigen::VectorXd> gv(g.data(), nv);
    bool ok = false;
    if(phase == Model) {
      pre.set_scaling(x);
      r = -gv;
      pre.apply(r, p);
      ok = p.allFinite() && gv.dot(p) < 0;
    } else if(!use_direct) {
      if(phase == Projected) {
        // a tiny diagonal shift keeps the system definite where a projected block is singular
        double maxd = 0;
        for(int i = 0; i < nv; ++i)
          maxd = std::max(maxd, H.coeff(i, i));
        for(int i = 0; i < nv; ++i)
          H.coeffRef(i, i) += 1e-12 * maxd + 1e-300;
      }
      if(last_cg > opt.refactor_cg_iterations) { // the preconditioner has drifted away
        if(!pre.factor(x)) {
          use_direct = true;
          st.time_factor += seconds(t1);
          continue;
        }
        ++st.preconditioner_factorizations;
      }
      // preconditioned conjugate gradients on H p = -g, residual in the hyperbolic norm;
      // superlinear tolerance (sqrt), but no more accurate than the stopping test needs
      set_norm_weights();
      pre.set_scaling(x);
      const double eta = std::max(std::min(0.5, std::sqrt(grel)), std::min(0.5, 0.25 * tolerance / grel));
      const double target = eta * (gv.cwiseProduct(hw)).norm();
      p.setZero();
      r = -gv;
      pre.apply(r, zv);
      d = zv;
      double rz = r.dot(zv);
      bool negative_curvature = false, reached = false;
      int k = 0;
      for(; k < opt.max_cg_iterations; ++k) {
        Hd.noalias() = H * d;
        const double dHd = d.dot(Hd);
        if(!(dHd > 0)) {
          negative_curvature = true;
          break;
        }
        const double alpha = rz / dHd;
        p += alpha * d;
        r -= alpha * Hd;
        if(r.cwiseProduct(hw).norm() <= target) {
          reached = true;
          ++k;
          break;
        }
        pre.apply(r, zv);
        const double rz_new = r.dot(zv);
        d = zv + (rz_new / rz) * d;
        rz = rz_new;
      }
      st.cg_iterations += k;
      last_cg = k;
      if(negative_curvature && phase == Exact) { // back to the projected Hessian
        st.time_factor += seconds(t1);
        phase = Projected;
        last_cg = 0;
        E = assemble();
        continue;
      }
      if(k == 0) // negative curvature along the first direction: the preconditioned gradient
        p = zv;
      ok = p.allFinite() && gv.dot(p) < 0;
      if(!reached && !negative_curvature && ++st.cg_failures > 2)
        use_direct = true; // the preconditioner does not fit this problem
    }
    if(use_direct && phase != Model) {
      if(!direct_analyzed) {
        direct.analyzePattern(H);
        direct_analyzed = true;
      }
      direct.factorize(H);
      ok = direct.info() == Eigen::Success;
      if(ok && phase == Exact) // LDLT of an indefinite matrix "succeeds": check the pivots
        ok = (direct.vectorD().array() > 0).all();
      if(ok) {
        p = direct.solve(-gv);
        if(phase == Exact && direct.info() == Eigen::Success) {
          // one step of iterative refinement: the exact Hessian can be badly conditioned
          const Eigen::VectorXd res = -gv - H * p;
          p += direct.solve(res);
        }
        ok = direct.info() == Eigen::Success && p.allFinite() && gv.dot(p) < 0;
      }
    }
    st.time_factor += seconds(t1);
    if(!ok) {
      if(phase != Projected) { // to the projected Hessian
        phase = Projected;
        E = assemble();
        continue;
      }
      return ERROR_CANNOT_SOLVE_LINEAR_SYSTEM;
    }
    const double slope = gv.dot(p);
    auto t2 = Clock::now();
    double alpha = 1.0, En = 0;
    bool accepted = false;
    double gnorm_new = gnorm;
    for(int ls = 0; ls < 60; ++ls) {
      for(int i = 0; i < nv; ++i)
        xn[i] = x[i] + alpha * p[i];
      if(opt.geodesic_steps && phase != Projected) {
        // free vertices move along the geodesic of their step, by its hyperbolic length
        // (the exponential map): a long step near the circle then bends instead of leaving
        // the disk, and the line search need not shorten every vertex's step for it. Same
        // first-order step, so the Armijo test is unchanged; with the Riemannian Hessian
        // this is Riemannian Newton, whose steps stay long where straight ones must be cut
        // to 1/128 (stiff cotangent weights of 1e5 near the circle: 20 steps instead of 190).
        // Not for the projected Hessian: it models the energy along straight lines.
        for(int v = 0; v < P.n; ++v) {
          if(P.kind[v] != Free)
            continue;
          const int i = P.var[v];
          const C z(x[i], x[i + 1]), d(alpha * p[i], alpha * p[i + 1]);
          const double len = abs(d);
          if(!(len > 0))
            continue;
          const double L = 2 * len / (1 - norm(z));
          const C w = d * (std::tanh(L / 2) / len);
          const C y = (w + z) / (C(1.0) + conj(z) * w);
          xn[i] = y.re;
          xn[i + 1] = y.im;
        }
      }
      if(ev.feasible(xn)) {
        En = ev.energy(xn);
        if(En <= E + 1e-4 * alpha * slope) {
          accepted = true;
          break;
        }
        // At the precision of the energy (about 1e-16 |E|) Armijo cannot see progress any
        // more; then a step is accepted when it reduces the gradient.
        if(std::abs(En - E) <= 1e-12 * std::abs(E)) {
          ev.evaluate(xn, gn, nullptr);
          gnorm_new = ev.hyperbolic_gradient_norm(xn, gn);
          if(gnorm_new < gnorm) {
            accepted = true;
            break;
          }
        }
      }
      alpha *= 0.5;
    }
    st.time_line_search += seconds(t2);
    st.iterations = it + 1;
    if(!accepted) {
      if(++stalls > 2) {
        stagnated = true;
        break; // no progress possible at this precision: let the tolerance decide
      }
      phase = phase == Projected ? Exact : Projected;
      E = assemble();
      continue;
    }
    stalls = 0;
    x.swap(xn);
    const double grel_prev = grel;
    E = assemble();
    gnorm = ev.hyperbolic_gradient_norm(x, g);
    grel = ev.hyperbolic_gradient_norm(x, g, true);
    if(opt.verbose)
      std::cerr << "  step " << it + 1 << (phase == Model ? " (preconditioned gradient)" : phase == Exact ? " (Newton)" : " (projected Newton)")
                << ": E = " << E << "  |grad|/|grad0| = " << gnorm / g0 << "  force imbalance " << grel << "  step " << alpha
                << "  cg " << st.cg_iterations << std::endl;
    // a gradient step the line search had to shorten: the embedding has moved far from where
    // the preconditioner was factored (seam rotations, long edges): factor it anew, at most
    // a few times; when gradient steps keep being slow, Newton takes over
    if(phase == Model && alpha < 0.3 && refactorings < opt.max_model_refactorizations) {
      auto t4 = Clock::now();
      if(pre.factor(x)) {
        ++st.preconditioner_factorizations;
        ++refactorings;
      } else {
        use_direct = true;
        phase = Projected;
      }
      st.time_factor += seconds(t4);
    }
    if(phase == Model && (alpha < 1.0 || grel > 0.8 * grel_prev))
      ++slow_steps;
    // to Newton with the exact Hessian near the solution
    if(phase != Exact && grel > tolerance &&
       ((gnorm / g0 < opt.newton_threshold && alpha == 1.0) || (phase == Model && slow_steps >= 3))) {
      phase = Exact;
      E = assemble();
    }
  }
  if(polishing)
    st.polishing_iterations = st.iterations - polish_start;
  st.energy = E;
  st.gradient = gnorm;
  st.relative_gradient = grel;
  st.rounding_floor = ev.rounding_floor(x);
  // Converged: the imbalance is below the tolerance or, where rounding makes that
  // impossible (Newton stagnates), within ten times what rounding the coordinates causes
  st.at_rounding_floor = stagnated && grel > opt.gradient_tolerance && grel <= 10 * st.rounding_floor;
  st.converged = st.relative_gradient <= opt.gradient_tolerance || st.at_rounding_floor;
  return st.converged ? OK : ERROR_NOT_CONVERGED;
}

// Newton on a region only: the vertices whose variables' owner is marked in `region`
// move, their neighbours stay where they are. The region's energy, gradient and linear
// solves are then at the region's own scale, which the whole problem's cannot see: a
// squeezed part of the embedding (a long protrusion without landmarks, 1e-20 across and
// shrinking along it) has forces 1e-20 times the largest ones, below the rounding of any
// global quantity. Returns the region's solver status.
inline Error_code minimize_energy_on_region(const Flat_problem& P, std::vector<double>& x, const std::vector<char>& region,
                                            const Solver_options& opt, Solver_statistics& st)
{
  auto moving = [&](int v) { return P.kind[v] != Fixed && region[owner_vertex(P, v)]; };
  // the region's vertices and their neighbours, in a problem of their own
  std::vector<int> local(P.n, -1), global;
  auto add = [&](int v) {
    if(local[v] < 0) {
      local[v] = static_cast<int>(global.size());
      global.push_back(v);
    }
  };
  Flat_problem Q;
  for(std::size_t e = 0; e < P.edges.size(); ++e) {
    const int a = P.edges[e][0], b = P.edges[e][1];
    if(!moving(a) && !moving(b))
      continue;
    add(a);
    add(b);
    if(P.kind[a] == Transformed) add(P.twin[a]);
    if(P.kind[b] == Transformed) add(P.twin[b]);
    Q.edges.push_back({a, b});
    Q.edge_weight.push_back(P.edge_weight[e]);
  }
  if(global.empty())
    return OK;
  for(auto& e : Q.edges)
    e = {local[e[0]], local[e[1]]};
  Q.type = P.type;
  Q.k = P.k;
  Q.n = static_cast<int>(global.size());
  Q.kind.assign(Q.n, Fixed);
  Q.var.assign(Q.n, -1);
  Q.twin.assign(Q.n, -1);
  Q.transform.assign(Q.n, Flat_problem::Isometry());
  Q.fixed.assign(Q.n, Flat_problem::C());
  Q.line_k0.assign(Q.n, Flat_problem::C());
  Q.line_D.assign(Q.n, Flat_problem::C());
  std::vector<double> xq;
  for(int i = 0; i < Q.n; ++i) { // variables of the owners first (a twin's index is needed below)
    const int v = global[i];
    if(!moving(v) || P.kind[v] == Transformed) {
      if(!moving(v))
        Q.fixed[i] = position(P, x, v);
      continue;
    }
    Q.kind[i] = P.kind[v];
    Q.var[i] = static_cast<int>(xq.size());
    xq.push_back(x[P.var[v]]);
    if(P.kind[v] == Free)
      xq.push_back(x[P.var[v] + 1]);
    else {
      Q.line_k0[i] = P.line_k0[v];
      Q.line_D[i] = P.line_D[v];
    }
  }
  for(int i = 0; i < Q.n; ++i) {
    const int v = global[i];
    if(moving(v) && P.kind[v] == Transformed) {
      Q.kind[i] = Transformed;
      Q.twin[i] = local[P.twin[v]];
      Q.transform[i] = P.transform[v];
    }
  }
  Q.n_vars = static_cast<int>(xq.size());
  const Error_code ec = minimize_energy(Q, xq, opt, st);
  for(int i = 0; i < Q.n; ++i) {
    const int v = global[i];
    if(Q.kind[i] == Free) {
      x[P.var[v]] = xq[Q.var[i]];
      x[P.var[v] + 1] = xq[Q.var[i] + 1];
    } else if(Q.kind[i] == On_line) {
      x[P.var[v]] = xq[Q.var[i]];
    }
  }
  return ec;
}

} // namespace internal
} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_NEWTON_H
