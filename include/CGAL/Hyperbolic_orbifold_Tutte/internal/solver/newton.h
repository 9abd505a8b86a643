// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_SOLVER_NEWTON_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_SOLVER_NEWTON_H

#include <CGAL/disable_warnings.h>

/// \file newton.h
// The energy's minimisation: Riemannian Newton with a preconditioned conjugate gradient, the
// definition of minimize_energy() (declared, with its options, in solver_doors.h).

#include <CGAL/Hyperbolic_orbifold_Tutte/error_code.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/Embedding_statistics.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/solver/connection_preconditioner.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/solver/dirichlet_energy.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/solver/flat_problem.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/linear_algebra/interior_laplacian.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/linear_algebra/smoothed_aggregation.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/solver/solver_doors.h>

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

// y = H d for a symmetric H stored whole (column-major): column i's entries are row i's, so
// each y_i is one column's sum, in parallel over the columns; each sum is in the order of
// Eigen's own product (ascending rows), whatever the number of threads
inline void symmetric_product(const Eigen::SparseMatrix<double>& H, const Eigen::VectorXd& d, Eigen::VectorXd& y)
{
  sparse_outer_products(H.cols(), H.outerIndexPtr(), H.innerNonZeroPtr(), H.innerIndexPtr(), H.valuePtr(), d, y);
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
//
// The steps of minimize_energy(), one method each; x is moved in place.
class Newton_minimizer
{
public:
  static constexpr int max_cg_iterations = 400;        // per Newton step
  static constexpr int refactor_cg_iterations = 25;    // refactor the preconditioner after a Newton step that needed more
  // relative gradient norm below which a full step hands over to Newton with the exact Hessian
  static constexpr double newton_threshold = 1e-2;
  static constexpr int max_model_refactorizations = 8; // preconditioner refactorisations during the gradient steps

  Newton_minimizer(const Flat_problem& P, std::vector<double>& x, const Solver_options& opt, Solver_statistics& st)
    : P_(P), x_(x), opt_(opt), st_(st), nv_(P.n_vars), xn_(P.n_vars)
  {}

  // `interior`: see minimize_energy
  Error_code run(const Interior_laplacian* interior)
  {
    set_up_preconditioner(interior);
    // (the Hessian's pattern only now: a factor rounded to single precision has shrunk)
    ev_.emplace(P_);
    start();
    for(int it = 0; it < opt_.max_iterations; ++it) {
      if(stops_before_step(it))
        break;
      const Direction found = find_direction();
      if(found == Direction_retry)
        continue;
      if(found == Direction_failed)
        return ERROR_CANNOT_SOLVE_LINEAR_SYSTEM;
      double alpha = 1.0;
      const bool accepted = line_search(alpha);
      st_.iterations = it + 1;
      if(!accepted) {
        if(++stalls_ > 2) {
          stagnated_ = true;
          break; // no progress possible at this precision: let the tolerance decide
        }
        phase_ = phase_ == Projected ? Exact : Projected;
        E_ = assemble();
        continue;
      }
      take_step(it, alpha);
    }
    return finish();
  }

private:
  typedef std::complex<double> C;
  typedef Eigen::SparseMatrix<double> SpMat;
  typedef Eigen::Map<const Eigen::VectorXd> Gradient;
  typedef std::chrono::steady_clock Clock;
  enum Phase { Model, Projected, Exact };
  enum Direction { Direction_found, Direction_retry, Direction_failed };

  static double seconds(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }
  Energy_evaluator& ev() { return *ev_; }

  // the initialisation's preconditioner where it made one for this problem (shared, or
  // prefactored: see Interior_laplacian; factored again here only if the seam rotations have
  // changed since), else one of our own
  void set_up_preconditioner(const Interior_laplacian* interior)
  {
    pre_ = interior ? (interior->connection ? interior->connection.get() : interior->prefactored.get()) : nullptr;
    if(pre_ == nullptr || &pre_->problem() != &P_) {
      own_pre_.reset(new Connection_laplacian_preconditioner(P_, interior));
      // (the initialisation's choice where it is given: one threshold, Interior_laplacian's)
      if(interior && interior->index.size() == static_cast<std::size_t>(P_.n) ? interior->multigrid != nullptr
                                                                                : P_.n >= opt_.multigrid_from)
        own_pre_->use_multigrid();
      pre_ = own_pre_.get();
    }
    use_direct_ = opt_.direct_solver;
    auto t0 = Clock::now();
    if(!use_direct_ && !pre_->factored_at(x_) && !pre_->factor(x_))
      use_direct_ = true;
    pre_->solve_in_single_precision(opt_.single_precision_small_preconditioner);
    st_.time_factorization += seconds(t0);
  }

  // the first phase, and the energy and gradient at the start
  void start()
  {
    hw_.resize(nv_);
    p_.resize(nv_);
    r_.resize(nv_);
    zv_.resize(nv_);
    d_.resize(nv_);
    Hd_.resize(nv_);
    phase_ = use_direct_ ? Projected : (opt_.polish || !opt_.gradient_steps) ? Exact : Model;
    polishing_ = opt_.polish;
    tolerance_ = polishing_ ? 0.0 : opt_.gradient_tolerance;
    E_ = assemble();
    st_.initial_energy = E_;
    st_.initial_gradient_norm = ev().hyperbolic_gradient_norm(x_, g_);
    g0_ = st_.initial_gradient_norm > 0 ? st_.initial_gradient_norm : 1.0;
    gnorm_ = st_.initial_gradient_norm;
    grel_ = ev().hyperbolic_gradient_norm(x_, g_, true);
    best_grel_ = grel_;
    grel_start_ = grel_;
  }

  // Solver_options::progress: log(start/now) / log(start/tolerance), clamped to [0, 1], never
  // below what was told before (the imbalance need not fall at every step); not while polishing
  void tell_progress()
  {
    if(!opt_.progress || polishing_)
      return;
    double f = 1.0;
    if(grel_start_ > tolerance_ && tolerance_ > 0 && grel_ > tolerance_)
      f = grel_ < grel_start_ ? std::log(grel_start_ / grel_) / std::log(grel_start_ / tolerance_) : 0.0;
    f = std::min(1.0, std::max(f, progress_told_));
    if(!(f >= 0)) // (NaN)
      f = progress_told_;
    progress_told_ = f;
    opt_.progress(f);
  }

  // gradient, and the Hessian the phase needs
  double assemble()
  {
    auto t = Clock::now();
    const double e = ev().evaluate(x_, g_, phase_ == Model ? nullptr : &H_, phase_ == Projected);
    if(phase_ == Exact)
      subtract_christoffel_terms(P_, x_, g_, H_);
    st_.time_assembly += seconds(t);
    return e;
  }

  // per-variable weights of the hyperbolic norm of a gradient (or residual)
  void set_norm_weights()
  {
    Position_jet j;
    for(int v = 0; v < P_.n; ++v) {
      if(P_.kind[v] == Free) {
        const int i = P_.var[v];
        hw_[i] = hw_[i + 1] = (1 - (x_[i] * x_[i] + x_[i + 1] * x_[i + 1])) / 2;
      } else if(P_.kind[v] == On_line) {
        position_jet(P_, x_, v, j);
        hw_[P_.var[v]] = (1 - squared_modulus(j.z)) / (2 * std::abs(j.dz[0]));
      }
    }
  }

  // Converged, or stagnated: true to stop before step `it`. Polishing starts here.
  bool stops_before_step(int it)
  {
    if(grel_ <= tolerance_) {
      // converged as a whole; every vertex too? (a region squeezed to 1e-12 has forces too
      // small for the global imbalance to see): if not, Newton on, until it is or to the floor
      if(polishing_ || !(opt_.vertex_imbalance > 0) || ev().unbalanced_vertices(x_, g_, opt_.vertex_imbalance) == 0)
        return true;
      polishing_ = true;
      tolerance_ = 0.0;
      polish_start_ = it;
      best_grel_ = grel_;
      since_best_ = 0;
      if(phase_ != Exact) {
        phase_ = Exact;
        E_ = assemble();
      }
    } else if(polishing_ && opt_.vertex_imbalance > 0 && ev().unbalanced_vertices(x_, g_, opt_.vertex_imbalance) == 0) {
      return true; // every vertex balanced, or at its rounding floor
    }
    // Near the solution Newton with the exact Hessian halves the imbalance at least every
    // few steps until rounding stops it: ten steps without that mean the floor of double
    // precision (three when polishing: Newton starts there next to the solution)
    if(grel_ < 0.5 * best_grel_ || phase_ != Exact || grel_ > 1e-6) {
      best_grel_ = std::min(best_grel_, grel_);
      since_best_ = 0;
    } else if(++since_best_ > (polishing_ ? 3 : 10) ||
              (since_best_ >= 3 && grel_ <= 10 * ev().rounding_floor(x_))) { // (evaluates at x: g unchanged)
      stagnated_ = true;
      return true;
    }
    return false;
  }

  // the step p_ of the phase; a retry after a change of phase or of solver
  Direction find_direction()
  {
    auto t1 = Clock::now();
    const Gradient gv(g_.data(), nv_);
    bool ok = false;
    if(phase_ == Model) {
      pre_->set_scaling(x_);
      r_ = -gv;
      pre_->apply(r_, p_);
      ok = p_.allFinite() && gv.dot(p_) < 0;
    } else if(!use_direct_) {
      if(!iterative_direction(gv, t1, ok))
        return Direction_retry;
    }
    if(use_direct_ && phase_ != Model)
      ok = direct_direction(gv);
    st_.time_factorization += seconds(t1);
    if(!ok) {
      if(phase_ != Projected) { // to the projected Hessian
        phase_ = Projected;
        E_ = assemble();
        return Direction_retry;
      }
      return Direction_failed;
    }
    return Direction_found;
  }

  // Newton's step by preconditioned conjugate gradients (`ok`: a descent direction found);
  // false for a retry (the preconditioner not factored again: the direct solver; negative
  // curvature of the exact Hessian: the projected Hessian)
  bool iterative_direction(const Gradient& gv, Clock::time_point t1, bool& ok)
  {
    if(phase_ == Projected) {
      // a tiny diagonal shift keeps the system definite where a projected block is singular
      double maxd = 0;
      for(int i = 0; i < nv_; ++i)
        maxd = std::max(maxd, H_.coeff(i, i));
      for(int i = 0; i < nv_; ++i)
        H_.coeffRef(i, i) += 1e-12 * maxd + 1e-300;
    }
    if(last_cg_ > refactor_cg_iterations) { // the preconditioner has drifted away
      if(!pre_->factor(x_)) {
        use_direct_ = true;
        st_.time_factorization += seconds(t1);
        return false;
      }
      ++st_.preconditioner_factorizations;
    }
    bool negative_curvature = false, reached = false;
    const int k = conjugate_gradients(gv, negative_curvature, reached);
    st_.cg_iterations += k;
    last_cg_ = k;
    if(negative_curvature && phase_ == Exact) { // back to the projected Hessian
      st_.time_factorization += seconds(t1);
      phase_ = Projected;
      last_cg_ = 0;
      E_ = assemble();
      return false;
    }
    if(k == 0) // negative curvature along the first direction: the preconditioned gradient
      p_ = zv_;
    ok = p_.allFinite() && gv.dot(p_) < 0;
    if(!reached && !negative_curvature && ++st_.cg_failures > 2)
      use_direct_ = true; // the preconditioner does not fit this problem
    return true;
  }

  // preconditioned conjugate gradients on H p = -g, residual in the hyperbolic norm;
  // superlinear tolerance (sqrt), but no more accurate than the stopping test needs.
  // Returns the iterations.
  int conjugate_gradients(const Gradient& gv, bool& negative_curvature, bool& reached)
  {
    set_norm_weights();
    pre_->set_scaling(x_);
    const double eta = std::max(std::min(0.5, std::sqrt(grel_)), std::min(0.5, 0.25 * tolerance_ / grel_));
    const double target = eta * (gv.cwiseProduct(hw_)).norm();
    p_.setZero();
    r_ = -gv;
    pre_->apply(r_, zv_);
    d_ = zv_;
    double rz = r_.dot(zv_);
    int k = 0;
    for(; k < max_cg_iterations; ++k) {
      if(phase_ == Exact) // (symmetric to the last bit; the projected blocks are not quite)
        symmetric_product(H_, d_, Hd_);
      else
        Hd_.noalias() = H_ * d_;
      const double dHd = d_.dot(Hd_);
      if(!(dHd > 0)) {
        negative_curvature = true;
        break;
      }
      const double alpha = rz / dHd;
      p_ += alpha * d_;
      r_ -= alpha * Hd_;
      if(r_.cwiseProduct(hw_).norm() <= target) {
        reached = true;
        ++k;
        break;
      }
      pre_->apply(r_, zv_);
      const double rz_new = r_.dot(zv_);
      d_ = zv_ + (rz_new / rz) * d_;
      rz = rz_new;
    }
    return k;
  }

  // Newton's step with the Hessian factored (sparse LDL^T, symbolic analysis once)
  bool direct_direction(const Gradient& gv)
  {
    if(!direct_analyzed_) {
      direct_.analyzePattern(H_);
      direct_analyzed_ = true;
    }
    direct_.factorize(H_);
    bool ok = direct_.info() == Eigen::Success;
    if(ok && phase_ == Exact) // LDLT of an indefinite matrix "succeeds": check the pivots
      ok = (direct_.vectorD().array() > 0).all();
    if(ok) {
      p_ = direct_.solve(-gv);
      if(phase_ == Exact && direct_.info() == Eigen::Success) {
        // one step of iterative refinement: the exact Hessian can be badly conditioned
        const Eigen::VectorXd res = -gv - H_ * p_;
        p_ += direct_.solve(res);
      }
      ok = direct_.info() == Eigen::Success && p_.allFinite() && gv.dot(p_) < 0;
    }
    return ok;
  }

  // Backtracking along p_ from x_ into xn_: true if a step was accepted (its length `alpha`)
  bool line_search(double& alpha)
  {
    const double slope = Gradient(g_.data(), nv_).dot(p_);
    auto t2 = Clock::now();
    bool accepted = false;
    for(int ls = 0; ls < 60; ++ls) {
      for(int i = 0; i < nv_; ++i)
        xn_[i] = x_[i] + alpha * p_[i];
      if(phase_ != Projected)
        move_along_geodesics(alpha);
      if(ev().feasible(xn_)) {
        const double En = ev().energy(xn_);
        if(En <= E_ + 1e-4 * alpha * slope) {
          accepted = true;
          break;
        }
        // At the precision of the energy (about 1e-16 |E|) Armijo cannot see progress any
        // more; then a step is accepted when it reduces the gradient.
        if(std::abs(En - E_) <= 1e-12 * std::abs(E_)) {
          ev().evaluate(xn_, gn_, nullptr);
          if(ev().hyperbolic_gradient_norm(xn_, gn_) < gnorm_) {
            accepted = true;
            break;
          }
        }
      }
      alpha *= 0.5;
    }
    st_.time_line_search += seconds(t2);
    return accepted;
  }

  // Free vertices move along the geodesic of their step, by its hyperbolic length (the
  // exponential map): a long step near the circle then bends instead of leaving the disk,
  // and the line search need not shorten every vertex's step for it. Same first-order step,
  // so the Armijo test is unchanged; with the Riemannian Hessian this is Riemannian Newton,
  // whose steps stay long where straight ones must be cut to 1/128 (stiff cotangent weights
  // of 1e5 near the circle: 20 steps instead of 190). Not for the projected Hessian: it
  // models the energy along straight lines.
  void move_along_geodesics(double alpha)
  {
    for(int v = 0; v < P_.n; ++v) {
      if(P_.kind[v] != Free)
        continue;
      const int i = P_.var[v];
      const C z(x_[i], x_[i + 1]), d(alpha * p_[i], alpha * p_[i + 1]);
      const double len = std::abs(d);
      if(!(len > 0))
        continue;
      const double L = 2 * len / (1 - squared_modulus(z));
      const C w = d * (std::tanh(L / 2) / len);
      const C y = divide(w + z, C(1.0) + std::conj(z) * w);
      xn_[i] = y.real();
      xn_[i + 1] = y.imag();
    }
  }

  // the accepted step taken: the new energy and gradient, and the next phase
  void take_step(int it, double alpha)
  {
    stalls_ = 0;
    x_.swap(xn_);
    const double grel_prev = grel_;
    E_ = assemble();
    gnorm_ = ev().hyperbolic_gradient_norm(x_, g_);
    grel_ = ev().hyperbolic_gradient_norm(x_, g_, true);
    if(opt_.verbose)
      std::cerr << "  step " << it + 1 << (phase_ == Model ? " (preconditioned gradient)" : phase_ == Exact ? " (Newton)" : " (projected Newton)")
                << ": E = " << E_ << "  |grad|/|grad0| = " << gnorm_ / g0_ << "  force imbalance " << grel_ << "  step " << alpha
                << "  cg " << st_.cg_iterations << std::endl;
    tell_progress();
    // a gradient step the line search had to shorten: the embedding has moved far from where
    // the preconditioner was factored (seam rotations, long edges): factor it anew, at most
    // a few times; when gradient steps keep being slow, Newton takes over
    if(phase_ == Model && alpha < 0.3 && refactorings_ < max_model_refactorizations) {
      auto t4 = Clock::now();
      if(pre_->factor(x_)) {
        ++st_.preconditioner_factorizations;
        ++refactorings_;
      } else {
        use_direct_ = true;
        phase_ = Projected;
      }
      st_.time_factorization += seconds(t4);
    }
    if(phase_ == Model && (alpha < 1.0 || grel_ > 0.8 * grel_prev))
      ++slow_steps_;
    // to Newton with the exact Hessian near the solution
    if(phase_ != Exact && grel_ > tolerance_ &&
       ((gnorm_ / g0_ < newton_threshold && alpha == 1.0) || (phase_ == Model && slow_steps_ >= 3))) {
      phase_ = Exact;
      E_ = assemble();
    }
  }

  // the statistics at the end
  Error_code finish()
  {
    if(polishing_)
      st_.polishing_iterations = st_.iterations - polish_start_;
    st_.energy = E_;
    st_.gradient_norm = gnorm_;
    st_.relative_gradient_norm = grel_;
    st_.rounding_floor = ev().rounding_floor(x_);
    // Converged: the imbalance is below the tolerance or, where rounding makes that
    // impossible (Newton stagnates), within ten times what rounding the coordinates causes
    st_.converged_at_rounding_floor = stagnated_ && grel_ > opt_.gradient_tolerance && grel_ <= 10 * st_.rounding_floor;
    st_.converged = st_.relative_gradient_norm <= opt_.gradient_tolerance || st_.converged_at_rounding_floor;
    return st_.converged ? OK : ERROR_NOT_CONVERGED;
  }

  const Flat_problem& P_;
  std::vector<double>& x_;
  const Solver_options& opt_;
  Solver_statistics& st_;
  const int nv_;
  std::vector<double> g_, xn_, gn_;
  SpMat H_;
  Eigen::SimplicialLDLT<SpMat, Eigen::Lower, Eigen::AMDOrdering<int> > direct_;
  bool direct_analyzed_ = false;
  std::unique_ptr<Connection_laplacian_preconditioner> own_pre_;
  Connection_laplacian_preconditioner* pre_ = nullptr;
  bool use_direct_ = false;
  std::optional<Energy_evaluator> ev_;
  Eigen::VectorXd hw_, p_, r_, zv_, d_, Hd_;
  Phase phase_ = Exact;
  bool polishing_ = false, stagnated_ = false;
  double tolerance_ = 0, E_ = 0, g0_ = 1, gnorm_ = 0, grel_ = 0, best_grel_ = 0;
  double grel_start_ = 0, progress_told_ = 0; // (Solver_options::progress)
  int polish_start_ = 0, stalls_ = 0, last_cg_ = 0, slow_steps_ = 0, refactorings_ = 0, since_best_ = 0;
};

// Minimises the energy (see Newton_minimizer): the door declared in solver_doors.h.
template <int>
Error_code minimize_energy(const Flat_problem& P, std::vector<double>& x, const Solver_options& opt,
                           Solver_statistics& st, const Interior_laplacian* interior)
{
  st = Solver_statistics();
  if(P.n_vars == 0) {
    st.converged = true;
    return OK;
  }
  return Newton_minimizer(P, x, opt, st).run(interior);
}

} // namespace internal
} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_SOLVER_NEWTON_H
