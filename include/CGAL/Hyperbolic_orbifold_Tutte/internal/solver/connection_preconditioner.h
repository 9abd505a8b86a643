// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_SOLVER_CONNECTION_PRECONDITIONER_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_SOLVER_CONNECTION_PRECONDITIONER_H

#include <CGAL/disable_warnings.h>

/// \file connection_preconditioner.h
// The preconditioner of the Newton systems: the connection Laplacian, factored.

#include <CGAL/Hyperbolic_orbifold_Tutte/internal/solver/flat_problem.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/linear_algebra/interior_laplacian.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/linear_algebra/laplacian_factorization.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/linear_algebra/smoothed_aggregation.h>

#include <Eigen/Dense>
#include <Eigen/Sparse>

#include <complex>
#include <cstddef>
#include <memory>
#include <vector>

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {
namespace internal {

// Preconditioner of the Newton systems: the Hessian of E = (1/2) sum w d^2 is, for short
// edges, close to the Hermitian form sum_e w |xi_a - xi_b|^2 of the tangent vectors
// xi = lambda(z) dz measured in the hyperbolic metric (lambda = 2 / (1 - |z|^2)); a seam
// copy z' = m(z) moves by m'(z) dz, i.e. by the same hyperbolic length turned by
// rho = m'/|m'|, and a disk-border vertex moves along its side, xi = lambda z'(t) dt.
// So H ~ S^T A S, with S the diagonal metric scaling and A the complex "connection
// Laplacian" (one complex unknown per vertex owning variables; entries -w conj(rho_a) rho_b).
// A is factored once (complex LDL^T, n x n: the size of the scalar Laplacian) and applied as
// S^-1 A^-1 S^-T, the scaling at the current iterate. A one-dimensional border variable
// takes the real part of its solution (the preconditioner stays symmetric positive definite).
class Connection_laplacian_preconditioner
{
public:
  typedef std::complex<double> Cd;
  typedef Eigen::SparseMatrix<Cd> CMat;

  // `interior`: the initialisation's factored interior Laplacian, used for the gauge (else
  // the preconditioner factors a real Laplacian of its own for it)
  //
  // `share_interior`: the vertices off the border loop are numbered first, the border's nodes
  // after them, and the factorisation keeps the first before the others (constrained AMD).
  // There is no rotation between two interior vertices, so the leading block is
  // the Laplacian of the interior with the border fixed, and its factor the leading block of
  // the factor: `solve_interior()` serves the initialisation and the gauge with no
  // factorisation of their own. Where that order cannot be kept or fills the factor too much
  // (a long cut, many landmarks: see Laplacian_factorization::analyze) the first `factor()`
  // returns false without factoring: the caller then factors the interior Laplacian itself.
  explicit Connection_laplacian_preconditioner(const Flat_problem& P, const Interior_laplacian* interior = nullptr,
                                               bool share_interior = false, double max_fill = 1.0)
    : P_(P), interior_(interior)
  {
    node_.assign(P.n, -1);
    copy_.assign(P.n, -1);
    std::vector<char> on_loop(P.n, 0);
    for(int v : P.border_loop)
      on_loop[v] = 1;
    for(int v = 0; v < P.n; ++v) {
      if(P.kind[v] == Transformed) {
        copy_[P.twin[v]] = v;
        has_seams_ = true;
      } else if(!on_loop[v] && P.kind[v] != Free) {
        share_interior = false; // (not met: the vertices off the loop are all free)
      }
    }
    if(share_interior) {
      for(int v = 0; v < P.n; ++v)
        if(!on_loop[v])
          node_[v] = n_interior_++;
      n_nodes_ = n_interior_;
      solver_.keep_leading_block(n_interior_, max_fill); // (ordered by constrained AMD there)
    }
    for(int v = 0; v < P.n; ++v)
      if((P.kind[v] == Free || P.kind[v] == On_line) && node_[v] < 0)
        node_[v] = n_nodes_++;
    owner_.assign(n_nodes_, -1);
    for(int v = 0; v < P.n; ++v)
      if(node_[v] >= 0)
        owner_[node_[v]] = v;
    shares_ = share_interior;
    if(interior_ && !usable(*interior_))
      interior_ = nullptr;
  }

  // Factored before the interior Laplacian is (at the same time, on another thread: see
  // initialize_embedding): no real Laplacian of its own for the gauge; attach_interior()
  // must give it the interior's once factored. Call before factor().
  void expect_interior() { interior_later_ = true; }
  // the interior Laplacian for the gauge, now factored: false (and the preconditioner not to
  // be used) if it cannot serve
  bool attach_interior(const Interior_laplacian* interior)
  {
    interior_later_ = false;
    interior_ = interior && usable(*interior) ? interior : nullptr;
    return interior_ != nullptr || !has_seams_;
  }

  // From now on A is not factored: its solves are one V-cycle of algebraic multigrid
  // (smoothed_aggregation.h), a Hermitian positive definite preconditioner whose set-up and
  // solves cost linear work. Call before the first factor(); the interior is not shared.
  void use_multigrid()
  {
    use_multigrid_ = true;
    shares_ = false;
  }

  const Flat_problem& problem() const { return P_; }

  // the first factor() kept the interior's block: solve_interior() works
  bool shares_interior() const { return shares_; }
  // position of v among the interior unknowns of solve_interior() (-1: border)
  int interior_index(int v) const { return shares_ && node_[v] >= 0 && node_[v] < n_interior_ ? node_[v] : -1; }
  int interior_size() const { return n_interior_; }

  // solves with the interior Laplacian (the border fixed), in interior_index() order
  bool solve_interior(const Eigen::VectorXcd& b, Eigen::VectorXcd& x) const
  {
    if(!shares_ || !factored_)
      return false;
    x = solver_.solve_leading(b);
    return x.size() == b.size() && x.allFinite();
  }

  // factored with the seam rotations at x (the matrix depends on x through them only)
  bool factored_at(const std::vector<double>& x) const
  {
    if(!factored_)
      return false;
    for(int v = 0; v < P_.n; ++v)
      if(P_.kind[v] == Transformed && !(rotation(v, x) == rho0_[v]))
        return false;
    return true;
  }

  // assembles A with the seam rotations at x and factors it (symbolic analysis once); after
  // use_multigrid(), sets its multigrid hierarchy up instead ("factored" then means that)
  bool factor(const std::vector<double>& x)
  {
    std::vector<Eigen::Triplet<Cd> > trip;
    trip.reserve(4 * P_.edges.size() + n_nodes_);
    std::vector<double> diag(n_nodes_, 0.0);
    for(std::size_t e = 0; e < P_.edges.size(); ++e) {
      const int a = P_.edges[e][0], b = P_.edges[e][1];
      const int na = node_of(a), nb = node_of(b);
      const double w = P_.edge_weight[e];
      const Cd ra = rotation(a, x), rb = rotation(b, x);
      if(na >= 0 && nb >= 0 && na == nb) {
        diag[na] += w * std::norm(ra - rb);
        continue;
      }
      if(na >= 0) diag[na] += w;
      if(nb >= 0) diag[nb] += w;
      if(na >= 0 && nb >= 0) {
        const Cd v = -w * std::conj(ra) * rb;
        trip.emplace_back(na, nb, v);
        trip.emplace_back(nb, na, std::conj(v));
      }
    }
    for(int i = 0; i < n_nodes_; ++i)
      trip.emplace_back(i, i, Cd(diag[i], 0.0));
    if(use_multigrid_) {
      typename Smoothed_aggregation<Cd>::Matrix Ar(n_nodes_, n_nodes_);
      Ar.setFromTriplets(trip.begin(), trip.end());
      std::vector<Eigen::Triplet<Cd> >().swap(trip);
      multigrid_.reset(new Smoothed_aggregation<Cd>());
      factored_ = multigrid_->compute(std::move(Ar));
      set_reference_rotations(x);
      return factored_;
    }
    CMat A(n_nodes_, n_nodes_);
    A.setFromTriplets(trip.begin(), trip.end());
    std::vector<Eigen::Triplet<Cd> >().swap(trip); // (freed before the factorisation: 0.3 GB at a million vertices)
    if(!analyzed_) {
      analyzed_ = true;
      if(!solver_.analyze(A) && shares_) {
        shares_ = false; // (only the initialisation asks to share: it factors its own Laplacian instead)
        return factored_ = false;
      }
    }
    if(has_seams_ && !interior_ && !shares_ && !gauge_factored_ && !interior_later_) {
      gauge_factored_ = true;
      factor_gauge_laplacian(A, x);
    }
    solver_.factorize(A);
    set_reference_rotations(x);
    factored_ = solver_.definite();
    if(factored_ && single_precision_)
      solver_.round_to_single_precision(simplicial_single_precision_);
    return factored_;
  }

  // From now on (and after every new factorisation) the solves use the factor rounded to
  // single precision (see Laplacian_factorization::round_to_single_precision): CHOLMOD's, and
  // Eigen's (simplicial) unless `simplicial` is false
  void solve_in_single_precision(bool simplicial = true)
  {
    single_precision_ = true;
    simplicial_single_precision_ = simplicial;
    if(factored_ && !use_multigrid_)
      solver_.round_to_single_precision(simplicial_single_precision_);
  }
  bool solves_in_single_precision() const { return solver_.single_precision(); }

  // the metric scaling at x
  void set_scaling(const std::vector<double>& x)
  {
    scale_.resize(n_nodes_);
    Position_jet j;
    for(int i = 0; i < n_nodes_; ++i) {
      const int v = owner_[i];
      if(P_.kind[v] == Free) {
        scale_[i] = Cd(conformal_factor(std::complex<double>(x[P_.var[v]], x[P_.var[v] + 1])), 0.0);
      } else {
        position_jet(P_, x, v, j);
        const double lambda = conformal_factor(j.z);
        scale_[i] = Cd(lambda * j.dz[0].real(), lambda * j.dz[0].imag());
      }
    }
    set_gauge(x);
  }

  // z = S^-1 A^-1 S^-T r
  void apply(const Eigen::VectorXd& r, Eigen::VectorXd& z) const
  {
    Eigen::VectorXcd& b = b_; // (kept: a fresh vector of this size costs its pages' first touch)
    Eigen::VectorXcd& xi = xi_;
    b.resize(n_nodes_);
    for_each_node([&](int i) {
      const int v = owner_[i], k = P_.var[v];
      if(P_.kind[v] == Free)
        b[i] = Cd(r[k], r[k + 1]) / scale_[i].real();
      else
        b[i] = scale_[i] * (r[k] / std::norm(scale_[i]));
      b[i] *= gauge_[i];
    });
    if(use_multigrid_)
      multigrid_->apply(b, xi);
    else
      xi = solver_.solve(b);
    z.resize(r.size());
    for_each_node([&](int i) {
      xi[i] *= std::conj(gauge_[i]);
      const int v = owner_[i], k = P_.var[v];
      if(P_.kind[v] == Free) {
        z[k] = xi[i].real() / scale_[i].real();
        z[k + 1] = xi[i].imag() / scale_[i].real();
      } else {
        z[k] = std::real(std::conj(scale_[i]) * xi[i]) / std::norm(scale_[i]);
      }
    });
  }

private:
  // f(i) for every node: in parallel on large meshes (each node's own entries)
  template <class F>
  void for_each_node(const F& f) const
  {
    if(n_nodes_ >= 65536)
      for_each_row(n_nodes_, [&](Eigen::Index i) { f(static_cast<int>(i)); });
    else
      for(int i = 0; i < n_nodes_; ++i)
        f(i);
  }

  // gauge: the seam rotations have turned by delta since the factorisation; spread the
  // turn smoothly over the mesh, so that psi jumps by delta across the seam
  void set_gauge(const std::vector<double>& x)
  {
    gauge_.assign(n_nodes_, Cd(1.0, 0.0));
    if(!has_seams_) return;
    std::vector<double> delta(P_.n, 0.0);
    bool any = false;
    for(int v = 0; v < P_.n; ++v)
      if(P_.kind[v] == Transformed) {
        delta[v] = std::arg(rotation(v, x) / rho0_[v]);
        any = any || delta[v] != 0;
      }
    if(!any) return;
    if(interior_ || shares_)
      harmonic_gauge(delta);
    else if(use_multigrid_)
      factor(x); // (no Laplacian for a gauge: the hierarchy anew, at these rotations)
    else
      least_squares_gauge(delta);
  }

  void set_reference_rotations(const std::vector<double>& x)
  {
    rho0_.assign(P_.n, Cd(1.0, 0.0));
    for(int v = 0; v < P_.n; ++v)
      if(P_.kind[v] == Transformed)
        rho0_[v] = rotation(v, x);
  }

  // harmonic in the interior, +delta/2 on a seam vertex's side, -delta/2 on its twin's
  // side (the interior Laplacian with the border fixed: the leading block of this
  // factorisation, or the initialisation's)
  void harmonic_gauge(const std::vector<double>& delta)
  {
    auto border_value = [&](int v) {
      if(P_.kind[v] == Transformed) return -delta[v] / 2;
      if(P_.kind[v] == Free && copy_[v] >= 0) return delta[copy_[v]] / 2;
      return 0.0;
    };
    auto index = [&](int v) { return shares_ ? interior_index(v) : interior_->index[v]; };
    Eigen::VectorXd rhs = Eigen::VectorXd::Zero(shares_ ? n_interior_ : interior_->size);
    for(std::size_t e = 0; e < P_.edges.size(); ++e) {
      const int a = P_.edges[e][0], b = P_.edges[e][1];
      const int ia = index(a), ib = index(b);
      if(ia >= 0 && ib < 0) rhs[ia] += P_.edge_weight[e] * border_value(b);
      else if(ib >= 0 && ia < 0) rhs[ib] += P_.edge_weight[e] * border_value(a);
    }
    Eigen::VectorXd psi;
    if(shares_) {
      Eigen::VectorXcd c;
      if(!solve_interior(rhs.cast<Cd>(), c))
        return; // (cannot happen once factored; no gauge is a valid, weaker, preconditioner)
      psi = c.real();
    } else if(interior_->multigrid) {
      // (from the last gauge: the rotations change little between two)
      if(!interior_->solve_by_multigrid(rhs.cast<Cd>(), psi_, gauge_tolerance))
        return; // (no gauge: a valid, weaker, preconditioner)
      psi = psi_.real();
    } else {
      psi = interior_->solver.solve(rhs);
    }
    for(int i = 0; i < n_nodes_; ++i) {
      const int v = owner_[i], ii = index(v);
      gauge_[i] = std::polar(1.0, ii >= 0 ? psi[ii] : border_value(v));
    }
  }

  // least squares over the edges: L psi = div delta
  void least_squares_gauge(const std::vector<double>& delta)
  {
    Eigen::VectorXd rhs = Eigen::VectorXd::Zero(n_nodes_);
    for(std::size_t e = 0; e < P_.edges.size(); ++e) {
      const int a = P_.edges[e][0], b = P_.edges[e][1];
      const int na = node_of(a), nb = node_of(b);
      if(na < 0 || nb < 0 || na == nb) continue;
      const double D = P_.edge_weight[e] * (delta[b] - delta[a]);
      rhs[nb] += D;
      rhs[na] -= D;
    }
    const Eigen::VectorXd psi = gauge_solver_.solve(rhs);
    for(int i = 0; i < n_nodes_; ++i)
      gauge_[i] = std::polar(1.0, psi[i]);
  }

  // the real Laplacian (no rotations) for the gauge, from A
  void factor_gauge_laplacian(const CMat& A, const std::vector<double>& x)
  {
    Eigen::SparseMatrix<double> L = A.real();
    for(std::size_t e = 0; e < P_.edges.size(); ++e) {
      const int a = P_.edges[e][0], b = P_.edges[e][1];
      const int na = node_of(a), nb = node_of(b);
      if(na >= 0 && na == nb) L.coeffRef(na, na) -= P_.edge_weight[e] * std::norm(rotation(a, x) - rotation(b, x));
      else if(na >= 0 && nb >= 0) L.coeffRef(na, nb) = L.coeffRef(nb, na) = 0.0;
    }
    for(std::size_t e = 0; e < P_.edges.size(); ++e) {
      const int na = node_of(P_.edges[e][0]), nb = node_of(P_.edges[e][1]);
      if(na >= 0 && nb >= 0 && na != nb) { L.coeffRef(na, nb) -= P_.edge_weight[e]; L.coeffRef(nb, na) -= P_.edge_weight[e]; }
    }
    gauge_solver_.compute(L);
  }

  // an interior Laplacian of this problem, factored or solved by multigrid
  bool usable(const Interior_laplacian& lap) const
  {
    return lap.index.size() == static_cast<std::size_t>(P_.n) && (lap.multigrid || (lap.own_factor && lap.solver.definite()));
  }

  int node_of(int v) const { return P_.kind[v] == Transformed ? node_[P_.twin[v]] : node_[v]; }

  // how a tangent vector of the owner turns on its way to this copy
  Cd rotation(int v, const std::vector<double>& x) const
  {
    if(P_.kind[v] != Transformed)
      return Cd(1.0, 0.0);
    Position_jet j;
    position_jet(P_, x, v, j);
    const double m = std::abs(j.dz[0]);
    return Cd(j.dz[0].real() / m, j.dz[0].imag() / m);
  }

  const Flat_problem& P_;
  std::vector<int> node_, owner_;
  int n_nodes_ = 0, n_interior_ = 0;
  const Interior_laplacian* interior_;
  bool shares_ = false, factored_ = false, single_precision_ = false, simplicial_single_precision_ = true;
  std::vector<int> copy_;      // the seam twin of a vertex, -1 if none
  bool has_seams_ = false, gauge_factored_ = false, interior_later_ = false;
  std::vector<Cd> scale_, gauge_, rho0_;
  Laplacian_factorization<double> gauge_solver_;
  Laplacian_factorization<Cd> solver_;
  bool analyzed_ = false;
  bool use_multigrid_ = false;
  std::unique_ptr<Smoothed_aggregation<Cd> > multigrid_;
  Eigen::VectorXcd psi_;                // the last gauge's harmonic function (multigrid; real)
  mutable Eigen::VectorXcd b_, xi_;     // apply()'s work vectors
  // the gauge's harmonic function by multigrid: only its smoothness matters
  static constexpr double gauge_tolerance = 1e-2;
};

} // namespace internal
} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_SOLVER_CONNECTION_PRECONDITIONER_H
