// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_ORBIFOLD_SOLVER_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_ORBIFOLD_SOLVER_H

#include <CGAL/Hyperbolic_orbifold_Tutte/internal/flat_problem.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/weight_type.h>

#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <unordered_map>
#include <vector>

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {


namespace internal {

// Edge weights from the 3D geometry, accumulated face by face on the cut mesh, so that
// the two copies of a seam edge together carry the base edge's weight (each base edge
// counts once in the energy). Cotangent sums are clamped below at epsilon per base edge.
template <class Point3>
void compute_edge_weights(Flat_problem& P, const std::vector<Point3>& base_points, Weight_type type, double epsilon)
{
  const std::size_t m = P.edges.size();
  P.edge_weight.assign(m, 0.0);
  std::unordered_map<long long, int> edge_id;
  edge_id.reserve(2 * m);
  auto key = [](int a, int b) { return (static_cast<long long>(std::min(a, b)) << 32) | static_cast<long long>(std::max(a, b)); };
  for(std::size_t e = 0; e < m; ++e)
    edge_id.emplace(key(P.edges[e][0], P.edges[e][1]), static_cast<int>(e));

  for(const auto& t : P.faces) {
    const Point3* p[3];
    for(int i = 0; i < 3; ++i)
      p[i] = &base_points[P.base[t[i]]];
    double len[3]; // len[i]: length of the edge opposite corner i
    double vec[3][3];
    for(int i = 0; i < 3; ++i) {
      const Point3& a = *p[(i + 1) % 3];
      const Point3& b = *p[(i + 2) % 3];
      vec[i][0] = CGAL::to_double(b.x()) - CGAL::to_double(a.x());
      vec[i][1] = CGAL::to_double(b.y()) - CGAL::to_double(a.y());
      vec[i][2] = CGAL::to_double(b.z()) - CGAL::to_double(a.z());
      len[i] = std::sqrt(vec[i][0] * vec[i][0] + vec[i][1] * vec[i][1] + vec[i][2] * vec[i][2]);
    }
    double angle[3];
    for(int i = 0; i < 3; ++i) {
      // angle at corner i between edges to i+1 and i+2
      const Point3& o = *p[i];
      const Point3& a = *p[(i + 1) % 3];
      const Point3& b = *p[(i + 2) % 3];
      const double u[3] = {CGAL::to_double(a.x()) - CGAL::to_double(o.x()), CGAL::to_double(a.y()) - CGAL::to_double(o.y()),
                           CGAL::to_double(a.z()) - CGAL::to_double(o.z())};
      const double v[3] = {CGAL::to_double(b.x()) - CGAL::to_double(o.x()), CGAL::to_double(b.y()) - CGAL::to_double(o.y()),
                           CGAL::to_double(b.z()) - CGAL::to_double(o.z())};
      const double dot = u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
      const double cx = u[1] * v[2] - u[2] * v[1], cy = u[2] * v[0] - u[0] * v[2], cz = u[0] * v[1] - u[1] * v[0];
      angle[i] = std::atan2(std::sqrt(cx * cx + cy * cy + cz * cz), dot);
    }
    for(int i = 0; i < 3; ++i) {
      // edge opposite corner i: vertices i+1, i+2
      const int a = t[(i + 1) % 3], b = t[(i + 2) % 3];
      double w = 0;
      switch(type) {
        case Cotangent: w = 0.5 / std::tan(angle[i]); break;
        case Uniform: w = 0.5; break;
        case Mean_value: {
          const double ta = std::tan(angle[(i + 1) % 3] / 2), tb = std::tan(angle[(i + 2) % 3] / 2);
          w = 0.5 * (ta + tb) / len[i];
          break;
        }
      }
      P.edge_weight[edge_id.at(key(a, b))] += w;
    }
  }
  // Per base edge: the total over its copies (two for a seam edge, one otherwise).
  std::unordered_map<long long, std::pair<double, int> > base_sum;
  base_sum.reserve(2 * m);
  for(std::size_t e = 0; e < m; ++e) {
    auto& s = base_sum[key(P.base[P.edges[e][0]], P.base[P.edges[e][1]])];
    s.first += P.edge_weight[e];
    s.second += 1;
  }
  for(std::size_t e = 0; e < m; ++e) {
    const auto& s = base_sum[key(P.base[P.edges[e][0]], P.base[P.edges[e][1]])];
    if(type == Uniform)
      P.edge_weight[e] = 1.0 / s.second;              // 1 per base edge
    else if(!(s.first >= epsilon))
      P.edge_weight[e] = epsilon / s.second;          // clamp (cotangent; degenerate geometry)
    else if(!(P.edge_weight[e] > 0))
      P.edge_weight[e] = s.first / s.second;          // a seam copy with a negative half: share the total
  }
  // keep the total of the copies of each base edge where a copy was rebalanced
  std::unordered_map<long long, double> total;
  total.reserve(2 * m);
  for(std::size_t e = 0; e < m; ++e)
    total[key(P.base[P.edges[e][0]], P.base[P.edges[e][1]])] += P.edge_weight[e];
  for(std::size_t e = 0; e < m; ++e) {
    const long long kk = key(P.base[P.edges[e][0]], P.base[P.edges[e][1]]);
    const auto& s = base_sum[kk];
    if(type != Uniform && s.first >= epsilon)
      P.edge_weight[e] *= s.first / total[kk];
  }
}

// Places the border: cone copies at their corners, other border vertices along their
// tile side at the fraction of the 3D arc length between the side's corners (sphere:
// p-side vertices on the side's geodesic, their twins follow by the pairing; disk: the
// parameter t of the Klein segment). Interior vertices: Euclidean Tutte embedding in the
// Klein model with the same weights (paper, section 5), mapped back to Poincare.
template <class Point3, class Tile>
Error_code initialize_embedding(const Flat_problem& P, const Tile& tile, const std::vector<Point3>& base_points,
                                std::vector<double>& x)
{
  typedef Complex<double> C;
  typedef Hyperbolic_isometry_2<double> Isometry;
  x.assign(P.n_vars, 0.0);
  const std::vector<int>& loop = P.border_loop;
  const int L = static_cast<int>(loop.size());
  auto dist3 = [&](int a, int b) {
    const Point3& p = base_points[P.base[a]];
    const Point3& q = base_points[P.base[b]];
    const double dx = CGAL::to_double(p.x()) - CGAL::to_double(q.x()), dy = CGAL::to_double(p.y()) - CGAL::to_double(q.y()),
                 dz = CGAL::to_double(p.z()) - CGAL::to_double(q.z());
    return std::sqrt(dx * dx + dy * dy + dz * dz);
  };
  // arc-length fraction along each side
  std::vector<double> frac(P.n, 0.0);
  {
    int i = 0;
    while(i < L) {
      int j = i + 1;
      while(j < L && P.corner[loop[j]] < 0)
        ++j;
      // corners at loop[i] and loop[j % L]
      std::vector<double> acc(1, 0.0);
      for(int q = i; q < j; ++q)
        acc.push_back(acc.back() + dist3(loop[q], loop[(q + 1) % L]));
      const double total = acc.back() > 0 ? acc.back() : 1.0;
      for(int q = i + 1; q < j; ++q)
        frac[loop[q]] = acc[q - i] / total;
      i = j;
    }
  }
  std::vector<C> z(P.n);
  std::vector<char> is_border(P.n, 0);
  for(int v : loop)
    is_border[v] = 1;
  for(int v : loop) {
    if(P.corner[v] >= 0) {
      z[v] = P.fixed[v];
    } else if(P.kind[v] == Free) { // sphere p-side: on the side's geodesic
      const int s = P.side[v];
      const auto& a = tile.corner(tile.side_source(s));
      const auto& b = tile.corner(tile.side_target(s));
      const C ca(CGAL::to_double(a.x()), CGAL::to_double(a.y())), cb(CGAL::to_double(b.x()), CGAL::to_double(b.y()));
      const Isometry to0 = Isometry::translation_to_origin(ca);
      const C b0 = to0.apply(cb);
      const double r = abs(b0);
      const double rr = std::tanh(frac[v] * std::atanh(r));
      z[v] = to0.inverse().apply(b0 * (rr / r));
      x[P.var[v]] = z[v].re;
      x[P.var[v] + 1] = z[v].im;
    } else if(P.kind[v] == On_line) {
      x[P.var[v]] = frac[v];
    }
  }
  for(int v : loop)
    if(P.kind[v] == Transformed || P.kind[v] == On_line)
      z[v] = position(P, x, v);

  // Tutte in Klein coordinates
  std::vector<int> interior_index(P.n, -1);
  int ni = 0;
  for(int v = 0; v < P.n; ++v)
    if(!is_border[v])
      interior_index[v] = ni++;
  if(ni > 0) {
    typedef Eigen::SparseMatrix<double> SpMat;
    std::vector<Eigen::Triplet<double> > trip;
    trip.reserve(4 * P.edges.size() + ni);
    Eigen::VectorXd bx = Eigen::VectorXd::Zero(ni), by = Eigen::VectorXd::Zero(ni);
    std::vector<double> diag(ni, 0.0);
    auto klein = [](const C& p) { return p * (2.0 / (1.0 + norm(p))); };
    for(std::size_t e = 0; e < P.edges.size(); ++e) {
      const int a = P.edges[e][0], b = P.edges[e][1];
      const double w = P.edge_weight[e];
      const int ia = interior_index[a], ib = interior_index[b];
      if(ia >= 0) diag[ia] += w;
      if(ib >= 0) diag[ib] += w;
      if(ia >= 0 && ib >= 0) {
        trip.emplace_back(ia, ib, -w);
        trip.emplace_back(ib, ia, -w);
      } else if(ia >= 0) {
        const C kb = klein(z[b]);
        bx[ia] += w * kb.re;
        by[ia] += w * kb.im;
      } else if(ib >= 0) {
        const C ka = klein(z[a]);
        bx[ib] += w * ka.re;
        by[ib] += w * ka.im;
      }
    }
    for(int i = 0; i < ni; ++i)
      trip.emplace_back(i, i, diag[i]);
    SpMat Lm(ni, ni);
    Lm.setFromTriplets(trip.begin(), trip.end());
    Eigen::SimplicialLDLT<SpMat> solver(Lm);
    if(solver.info() != Eigen::Success)
      return ERROR_CANNOT_SOLVE_LINEAR_SYSTEM;
    const Eigen::VectorXd kx = solver.solve(bx), ky = solver.solve(by);
    if(solver.info() != Eigen::Success)
      return ERROR_CANNOT_SOLVE_LINEAR_SYSTEM;
    for(int v = 0; v < P.n; ++v) {
      const int i = interior_index[v];
      if(i < 0)
        continue;
      const C k(kx[i], ky[i]);
      const double s = 1.0 - norm(k);
      if(!(s > 0) || !std::isfinite(k.re) || !std::isfinite(k.im))
        return ERROR_CANNOT_SOLVE_LINEAR_SYSTEM;
      const C p = k / (1.0 + std::sqrt(s));
      if(P.kind[v] == Free) {
        x[P.var[v]] = p.re;
        x[P.var[v] + 1] = p.im;
      }
    }
  }
  return OK;
}

struct Solver_options
{
  double gradient_tolerance = 1e-10; // force imbalance (relative hyperbolic gradient norm)
  int max_iterations = 200;
  bool verbose = false;
};

struct Solver_statistics
{
  int iterations = 0;
  double initial_energy = 0, energy = 0;
  double initial_gradient = 0, gradient = 0, relative_gradient = 0;
  double time_assemble = 0, time_factor = 0, time_line_search = 0;
  bool converged = false;
};

// Dirichlet energy (1/2) sum w d^2; gradient and projected Hessian if requested.
class Energy_evaluator
{
public:
  typedef Complex<double> C;
  explicit Energy_evaluator(const Flat_problem& P) : P_(P) {}

  // returns +infinity for infeasible x (a point on or outside the unit circle)
  double energy(const std::vector<double>& x) const
  {
    double E = 0;
    for(std::size_t e = 0; e < P_.edges.size(); ++e) {
      const C a = position(P_, x, P_.edges[e][0]), b = position(P_, x, P_.edges[e][1]);
      const double A = 1 - norm(a), B = 1 - norm(b);
      if(!(A > 0 && B > 0))
        return std::numeric_limits<double>::infinity();
      const double dx = a.re - b.re, dy = a.im - b.im;
      const double d = 2.0 * std::asinh(std::sqrt((dx * dx + dy * dy) / (A * B)));
      E += 0.5 * P_.edge_weight[e] * d * d;
    }
    return E;
  }

  bool feasible(const std::vector<double>& x) const
  {
    for(int v = 0; v < P_.n; ++v) {
      if(P_.kind[v] == Free) {
        if(!(x[P_.var[v]] * x[P_.var[v]] + x[P_.var[v] + 1] * x[P_.var[v] + 1] < 1.0))
          return false;
      } else if(P_.kind[v] == On_line) {
        const C k = P_.line_k0[v] + x[P_.var[v]] * P_.line_D[v];
        if(!(norm(k) < 1.0))
          return false;
      }
    }
    return true;
  }

  // gradient g (size n_vars) and, if H != nullptr, the Hessian with each edge's block
  // projected onto the positive semi-definite cone
  double evaluate(const std::vector<double>& x, std::vector<double>& g,
                  std::vector<Eigen::Triplet<double> >* H, bool project = true) const
  {
    g.assign(P_.n_vars, 0.0);
    g_abs_.assign(P_.n_vars, 0.0);
    if(H)
      H->clear();
    double E = 0;
    Position_jet ja, jb;
    Squared_distance_derivatives sd;
    for(std::size_t e = 0; e < P_.edges.size(); ++e) {
      const int a = P_.edges[e][0], b = P_.edges[e][1];
      position_jet(P_, x, a, ja);
      position_jet(P_, x, b, jb);
      const double hw = 0.5 * P_.edge_weight[e];
      if(ja.dim == 0 && jb.dim == 0) { // constant, but part of the energy that energy() returns
        squared_hyperbolic_distance(ja.z, jb.z, sd, false);
        E += hw * sd.f;
        continue;
      }
      squared_hyperbolic_distance(ja.z, jb.z, sd, H != nullptr);
      E += hw * sd.f;
      const int oa = variable_owner(P_, a), ob = variable_owner(P_, b);
      // local variables: first ja.dim of a, then jb.dim of b
      const int n = ja.dim + jb.dim;
      double lg[4];
      int gi[4];
      // dz_i as real 2-vectors, per local variable, with its offset in the 4-vector (0: z, 2: w)
      double J[4][2];
      int off[4];
      for(int i = 0; i < ja.dim; ++i) {
        J[i][0] = ja.dz[i].re; J[i][1] = ja.dz[i].im; off[i] = 0; gi[i] = oa + i;
      }
      for(int i = 0; i < jb.dim; ++i) {
        J[ja.dim + i][0] = jb.dz[i].re; J[ja.dim + i][1] = jb.dz[i].im; off[ja.dim + i] = 2; gi[ja.dim + i] = ob + i;
      }
      for(int i = 0; i < n; ++i) {
        lg[i] = hw * (sd.g[off[i]] * J[i][0] + sd.g[off[i] + 1] * J[i][1]);
        g[gi[i]] += lg[i];
        g_abs_[gi[i]] += std::abs(lg[i]);
      }
      if(!H)
        continue;
      Eigen::Matrix4d M = Eigen::Matrix4d::Zero();
      for(int i = 0; i < n; ++i)
        for(int j = i; j < n; ++j) {
          double h = 0;
          for(int p = 0; p < 2; ++p)
            for(int q = 0; q < 2; ++q)
              h += J[i][p] * sd.H[off[i] + p][off[j] + q] * J[j][q];
          // second derivatives of the position (same vertex only)
          if(off[i] == off[j]) {
            const Position_jet& jj = (off[i] == 0) ? ja : jb;
            const int ii = (off[i] == 0) ? i : i - ja.dim, kk = (off[j] == 0) ? j : j - ja.dim;
            h += sd.g[off[i]] * jj.ddz[ii][kk].re + sd.g[off[i] + 1] * jj.ddz[ii][kk].im;
          }
          M(i, j) = M(j, i) = hw * h;
        }
      if(project)
        project_psd(M, n);
      // every entry, zero or not: the sparsity pattern must not change between iterations,
      // since the symbolic factorisation is computed once
      for(int i = 0; i < n; ++i)
        for(int j = 0; j < n; ++j)
          H->emplace_back(gi[i], gi[j], M(i, j));
    }
    return E;
  }

  // hyperbolic (Riemannian) norm of the gradient: per vertex |grad| (1 - |z|^2) / 2,
  // per boundary parameter |dE/dt| / |dz/dt|_hyperbolic. With `relative`, divided by the
  // same norm of the sums of the absolute values of the edges' contributions (the
  // "forces" on each vertex, from the last call of evaluate() at x): the remaining
  // imbalance of the forces, a scale-free measure whose floor is the rounding error.
  double hyperbolic_gradient_norm(const std::vector<double>& x, const std::vector<double>& g, bool relative = false) const
  {
    double s = 0, sa = 0;
    Position_jet j;
    for(int v = 0; v < P_.n; ++v) {
      if(P_.kind[v] == Free) {
        const int i = P_.var[v];
        const double r = (1 - (x[i] * x[i] + x[i + 1] * x[i + 1])) / 2;
        s += (g[i] * g[i] + g[i + 1] * g[i + 1]) * r * r;
        sa += (g_abs_[i] * g_abs_[i] + g_abs_[i + 1] * g_abs_[i + 1]) * r * r;
      } else if(P_.kind[v] == On_line) {
        position_jet(P_, x, v, j);
        const double speed = abs(j.dz[0]) * 2 / (1 - norm(j.z));
        const double gt = g[P_.var[v]] / speed, ga = g_abs_[P_.var[v]] / speed;
        s += gt * gt;
        sa += ga * ga;
      }
    }
    if(!relative)
      return std::sqrt(s);
    return sa > 0 ? std::sqrt(s / sa) : 0.0;
  }

private:
  static void project_psd(Eigen::Matrix4d& M, int n)
  {
    if(n == 1) {
      if(M(0, 0) < 0) M(0, 0) = 0;
      return;
    }
    if(n == 2) {
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> es(M.topLeftCorner<2, 2>());
      if(es.eigenvalues().minCoeff() >= 0) return;
      Eigen::Vector2d l = es.eigenvalues().cwiseMax(0.0);
      M.topLeftCorner<2, 2>() = es.eigenvectors() * l.asDiagonal() * es.eigenvectors().transpose();
      return;
    }
    if(n == 3) {
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(M.topLeftCorner<3, 3>());
      if(es.eigenvalues().minCoeff() >= 0) return;
      Eigen::Vector3d l = es.eigenvalues().cwiseMax(0.0);
      M.topLeftCorner<3, 3>() = es.eigenvectors() * l.asDiagonal() * es.eigenvectors().transpose();
      return;
    }
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix4d> es(M);
    if(es.eigenvalues().minCoeff() >= 0) return;
    Eigen::Vector4d l = es.eigenvalues().cwiseMax(0.0);
    M = es.eigenvectors() * l.asDiagonal() * es.eigenvectors().transpose();
  }

  const Flat_problem& P_;
  mutable std::vector<double> g_abs_;
};

// Projected Newton with backtracking line search; the symbolic factorisation is computed once.
inline Error_code minimize_energy(const Flat_problem& P, std::vector<double>& x, const Solver_options& opt,
                                  Solver_statistics& st)
{
  typedef Eigen::SparseMatrix<double> SpMat;
  typedef std::chrono::steady_clock Clock;
  Energy_evaluator ev(P);
  st = Solver_statistics();
  if(P.n_vars == 0) {
    st.converged = true;
    return OK;
  }
  std::vector<double> g, xn(P.n_vars), gn;
  std::vector<Eigen::Triplet<double> > trip;
  Eigen::SimplicialLDLT<SpMat, Eigen::Lower, Eigen::AMDOrdering<int> > solver;
  bool analyzed = false;
  SpMat H(P.n_vars, P.n_vars);

  // Projected Newton far from the solution; the exact Hessian (quadratic convergence)
  // once the gradient is small, falling back to the projection if it is not definite.
  bool exact = false;
  auto t0 = Clock::now();
  double E = ev.evaluate(x, g, &trip, true);
  st.time_assemble += std::chrono::duration<double>(Clock::now() - t0).count();
  st.initial_energy = E;
  st.initial_gradient = ev.hyperbolic_gradient_norm(x, g);
  const double g0 = st.initial_gradient > 0 ? st.initial_gradient : 1.0;
  double gnorm = st.initial_gradient;
  double grel = ev.hyperbolic_gradient_norm(x, g, true);
  int stalls = 0;
  double best_grel = grel;
  int since_best = 0;
  for(int it = 0; it < opt.max_iterations; ++it) {
    if(grel <= opt.gradient_tolerance)
      break;
    // Newton with the exact Hessian halves the imbalance at least every few steps until
    // rounding stops it: ten steps without that mean the floor of double precision
    if(grel < 0.5 * best_grel || !exact) {
      best_grel = std::min(best_grel, grel);
      since_best = 0;
    } else if(++since_best > 10) {
      break;
    }
    auto t1 = Clock::now();
    H.setFromTriplets(trip.begin(), trip.end());
    double maxd = 0;
    for(int i = 0; i < P.n_vars; ++i)
      maxd = std::max(maxd, H.coeff(i, i));
    if(!exact) {
      // a tiny diagonal shift keeps the factorisation definite where a projected block is singular
      for(int i = 0; i < P.n_vars; ++i)
        H.coeffRef(i, i) += 1e-12 * maxd + 1e-300;
    }
    if(!analyzed) {
      solver.analyzePattern(H);
      analyzed = true;
    }
    solver.factorize(H);
    bool ok = solver.info() == Eigen::Success;
    if(ok && exact) // LDLT of an indefinite matrix "succeeds": check the pivots
      ok = (solver.vectorD().array() > 0).all();
    Eigen::Map<const Eigen::VectorXd> gv(g.data(), P.n_vars);
    Eigen::VectorXd p;
    if(ok) {
      p = solver.solve(-gv);
      if(exact && solver.info() == Eigen::Success) {
        // one step of iterative refinement: the exact Hessian can be badly conditioned
        const Eigen::VectorXd r = -gv - H * p;
        p += solver.solve(r);
      }
      ok = solver.info() == Eigen::Success && p.allFinite() && gv.dot(p) < 0;
    }
    st.time_factor += std::chrono::duration<double>(Clock::now() - t1).count();
    if(!ok) {
      if(exact) { // back to the projected Hessian
        exact = false;
        E = ev.evaluate(x, g, &trip, true);
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
      for(int i = 0; i < P.n_vars; ++i)
        xn[i] = x[i] + alpha * p[i];
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
    st.time_line_search += std::chrono::duration<double>(Clock::now() - t2).count();
    st.iterations = it + 1;
    if(!accepted) {
      if(++stalls > 2)
        break; // no progress possible at this precision: let the tolerance decide
      exact = !exact;
      E = ev.evaluate(x, g, &trip, !exact);
      continue;
    }
    stalls = 0;
    x.swap(xn);
    auto t3 = Clock::now();
    const double gprev = gnorm;
    E = ev.evaluate(x, g, nullptr);
    gnorm = ev.hyperbolic_gradient_norm(x, g);
    grel = ev.hyperbolic_gradient_norm(x, g, true);
    // switch to the exact Hessian near the solution
    if(!exact && gnorm / g0 < 1e-2 && alpha == 1.0)
      exact = true;
    E = ev.evaluate(x, g, &trip, !exact);
    st.time_assemble += std::chrono::duration<double>(Clock::now() - t3).count();
    (void)gprev;
    if(opt.verbose)
      std::cerr << "  newton " << it + 1 << (exact ? " (exact)" : " (projected)") << ": E = " << E
                << "  |grad|/|grad0| = " << gnorm / g0 << "  force imbalance " << grel << "  step " << alpha << std::endl;
  }
  st.energy = E;
  st.gradient = gnorm;
  st.relative_gradient = grel;
  st.converged = st.relative_gradient <= opt.gradient_tolerance;
  return st.converged ? OK : ERROR_NOT_CONVERGED;
}

// The paper's post-processing (section 5): every free vertex that is not inside the
// hyperbolic convex hull of its neighbours (detected by a non-positive incident face, exact
// test) is moved by a Mobius map to the origin with its one-ring, put at the Euclidean
// weighted centroid of its neighbours there, and moved back; repeated until no face is
// flipped or `max_sweeps` sweeps. Seam vertices see their neighbours across the seam
// through the side pairing. Returns the number of vertex moves.
inline int repair_one_rings(const Flat_problem& P, std::vector<double>& x, int max_sweeps = 100)
{
  typedef Complex<double> C;
  typedef Hyperbolic_isometry_2<double> Isometry;
  typedef Poincare_disk_traits_2<> Traits;
  const Traits::Hyperbolic_orientation_2 orient = Traits().hyperbolic_orientation_2_object();
  // neighbours of each free vertex, with the map bringing them into its frame
  struct Nb { int u; int via; double w; };  // via: the vertex of the edge standing for v (v or a twin copy)
  std::vector<std::vector<Nb> > nb(P.n);
  std::vector<std::vector<int> > vfaces(P.n);
  auto owner = [&](int v) { return P.kind[v] == Transformed ? P.twin[v] : v; };
  for(std::size_t e = 0; e < P.edges.size(); ++e) {
    const int a = P.edges[e][0], b = P.edges[e][1];
    if(P.kind[owner(a)] == Free) nb[owner(a)].push_back(Nb{b, a, P.edge_weight[e]});
    if(P.kind[owner(b)] == Free) nb[owner(b)].push_back(Nb{a, b, P.edge_weight[e]});
  }
  for(std::size_t f = 0; f < P.faces.size(); ++f)
    for(int i = 0; i < 3; ++i)
      vfaces[owner(P.faces[f][i])].push_back(static_cast<int>(f));
  auto face_ok = [&](int f) {
    const C a = position(P, x, P.faces[f][0]), b = position(P, x, P.faces[f][1]), c = position(P, x, P.faces[f][2]);
    return orient(Traits::Point_2(a.re, a.im), Traits::Point_2(b.re, b.im), Traits::Point_2(c.re, c.im)) == POSITIVE;
  };
  int moves = 0;
  for(int sweep = 0; sweep < max_sweeps; ++sweep) {
    int moved = 0;
    for(int v = 0; v < P.n; ++v) {
      if(P.kind[v] != Free)
        continue;
      bool bad = false;
      for(int f : vfaces[v])
        if(!face_ok(f)) { bad = true; break; }
      if(!bad)
        continue;
      const C z(x[P.var[v]], x[P.var[v] + 1]);
      const Isometry to0 = Isometry::translation_to_origin(z);
      C sum;
      double wsum = 0;
      for(const Nb& q : nb[v]) {
        C zu = position(P, x, q.u);
        if(q.via != v) // the edge is at a seam copy: bring the neighbour back through the pairing
          zu = P.transform[q.via].inverse().apply(zu);
        sum += q.w * to0.apply(zu);
        wsum += q.w;
      }
      if(!(wsum > 0))
        continue;
      const C c = to0.inverse().apply(sum / wsum);
      x[P.var[v]] = c.re;
      x[P.var[v] + 1] = c.im;
      ++moved;
    }
    moves += moved;
    if(moved == 0)
      break;
  }
  return moves;
}

} // namespace internal
} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_ORBIFOLD_SOLVER_H
