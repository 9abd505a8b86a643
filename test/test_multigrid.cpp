// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The algebraic multigrid of the large solves (internal/linear_algebra/smoothed_aggregation.h), against facts
// from outside it: a sparse LDL^T of the same matrix solves the same systems; the V-cycle is a
// Hermitian positive definite operator (conjugate gradients need that); a gauge transform
// D^* A D (D unit diagonal) of a real Laplacian is the same problem, so multigrid must see it
// as one (the phase transport of its tentative prolongator); multigrid's iterations do not
// grow with the size of a Poisson problem (Vanek, Mandel and Brezina 1996).

#include "test_harness.h"

#include <CGAL/Hyperbolic_orbifold_Tutte/internal/linear_algebra/smoothed_aggregation.h>

#include <Eigen/SparseCholesky>

#include <cmath>
#include <complex>
#include <random>
#include <string>
#include <type_traits>
#include <vector>

namespace HOTI = CGAL::Hyperbolic_orbifold_Tutte::internal;
typedef std::complex<double> Cd;

static std::mt19937_64 gen(20261203);
static double uniform(double a, double b) { return std::uniform_real_distribution<double>(a, b)(gen); }

// The weighted Laplacian of a side x side grid with its diagonals (a triangulated square), its
// border held fixed (Dirichlet: the border's weights stay on the diagonal), random weights in
// [0.2, 2]; edge transport `t(i, j, k, l)` (unit complex: entries -w t) from (i, j) to (k, l)
template <class Scalar, class Transport>
static Eigen::SparseMatrix<Scalar, Eigen::RowMajor> grid_laplacian(int side, const Transport& t)
{
  const int n = side * side;
  std::vector<Eigen::Triplet<Scalar> > trip;
  std::vector<double> diag(n, 0.0);
  auto id = [&](int i, int j) { return i * side + j; };
  for(int i = 0; i < side; ++i)
    for(int j = 0; j < side; ++j)
      for(const auto& d : {std::make_pair(1, 0), std::make_pair(0, 1), std::make_pair(1, 1)}) {
        const int k = i + d.first, l = j + d.second;
        const double w = uniform(0.2, 2.0);
        diag[id(i, j)] += w;
        if(k >= side || l >= side) // (a border edge: its other end is fixed)
          continue;
        diag[id(k, l)] += w;
        const Scalar v = -w * t(i, j, k, l);
        trip.emplace_back(id(i, j), id(k, l), v);
        trip.emplace_back(id(k, l), id(i, j), Eigen::numext::conj(v));
      }
  for(int i = 0; i < n; ++i)
    trip.emplace_back(i, i, Scalar(diag[i]));
  Eigen::SparseMatrix<Scalar, Eigen::RowMajor> A(n, n);
  A.setFromTriplets(trip.begin(), trip.end());
  return A;
}

template <class Scalar>
static Eigen::Matrix<Scalar, Eigen::Dynamic, 1> random_vector(Eigen::Index n)
{
  Eigen::Matrix<Scalar, Eigen::Dynamic, 1> v(n);
  for(Eigen::Index i = 0; i < n; ++i) {
    if constexpr(std::is_same<Scalar, double>::value)
      v[i] = uniform(-1, 1);
    else
      v[i] = Scalar(uniform(-1, 1), uniform(-1, 1));
  }
  return v;
}

// the solve by multigrid-preconditioned CG against a sparse LDL^T of the same matrix
template <class Scalar>
static int check_against_direct(const Eigen::SparseMatrix<Scalar, Eigen::RowMajor>& A, const std::string& what)
{
  typedef Eigen::Matrix<Scalar, Eigen::Dynamic, 1> V;
  HOTI::Smoothed_aggregation<Scalar> mg;
  CHECK_MSG(mg.compute(A), what << ": the hierarchy");
  const V b = random_vector<Scalar>(A.rows());
  V x;
  const int it = mg.solve(b, x, 1e-10, 200);
  CHECK_MSG(it > 0, what << ": conjugate gradients converged");
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<Scalar> > ldlt(A);
  CHECK(ldlt.info() == Eigen::Success);
  const V xd = ldlt.solve(b);
  const double err = (x - xd).norm() / xd.norm();
  std::cout << "  " << what << ": " << A.rows() << " rows, " << mg.number_of_levels() << " levels, operator complexity "
            << mg.operator_complexity() << ", " << it << " iterations, distance to LDL^T " << err << std::endl;
  // |x - xd| <= cond(A) |r| / |b|: with cond ~ side^2 ~ 1e4..1e5 and |r| <= 1e-10 |b|
  CHECK_MSG(err < 1e-5, what << ": " << err);
  // the residual itself, measured here
  V r(A.rows());
  r = b - A * x;
  CHECK_MSG(r.norm() <= 1e-10 * b.norm() * 1.0000001, what << ": residual " << r.norm() / b.norm());
  return it;
}

TEST_CASE(multigrid_solves_poisson_problems_in_a_bounded_number_of_iterations)
{
  auto one = [](int, int, int, int) { return 1.0; };
  std::vector<int> its;
  for(const int side : {60, 180, 360}) {
    const auto A = grid_laplacian<double>(side, one);
    its.push_back(check_against_direct(A, "Poisson " + std::to_string(side) + "^2"));
    HOTI::Smoothed_aggregation<double> mg;
    CHECK(mg.compute(A));
    // coarsening: about 9 nodes an aggregate on a triangulated grid, so few levels and little
    // more storage than the matrix (smoothed aggregation in 2D: 1.2 to 1.5)
    CHECK_MSG(mg.operator_complexity() < 1.6, mg.operator_complexity());
    CHECK(mg.rows(1) < A.rows() / 4);
    if(side == 360)
      CHECK(mg.number_of_levels() >= 3);
  }
  // the same handful of iterations at 36 times the size (a V-cycle's contraction does not
  // depend on the mesh size); a factorisation-free preconditioner that failed would need
  // O(side) iterations (Jacobi: hundreds)
  for(int it : its)
    CHECK_MSG(it <= 30, it);
  CHECK_MSG(its.back() <= its.front() + 6, its.front() << " -> " << its.back());
}

TEST_CASE(the_v_cycle_is_hermitian_positive_definite)
{
  // a connection Laplacian with smooth holonomy (a constant "magnetic field" b: the transport
  // exp(i b (x_a y_b - x_b y_a) / 2), curvature b per unit area) and one with random rotations
  for(const double field : {0.02, -1.0}) {
    auto t = [&](int i, int j, int k, int l) {
      return field < 0 ? std::polar(1.0, uniform(-3.0, 3.0)) : std::polar(1.0, field * (i * l - k * j) / 2.0);
    };
    const auto A = grid_laplacian<Cd>(120, t);
    HOTI::Smoothed_aggregation<Cd> mg;
    CHECK(mg.compute(A));
    for(int trial = 0; trial < 5; ++trial) {
      const Eigen::VectorXcd u = random_vector<Cd>(A.rows()), v = random_vector<Cd>(A.rows());
      Eigen::VectorXcd Mu, Mv;
      mg.apply(u, Mu);
      mg.apply(v, Mv);
      const Cd uMv = u.dot(Mv), vMu = v.dot(Mu); // (dot: conjugate-linear in its first argument)
      CHECK_MSG(std::abs(uMv - std::conj(vMu)) <= 1e-12 * std::abs(uMv), uMv << " vs " << std::conj(vMu));
      const Cd uMu = u.dot(Mu);
      CHECK(uMu.real() > 0);
      CHECK(std::abs(uMu.imag()) <= 1e-12 * uMu.real());
    }
    check_against_direct(A, field < 0 ? "random rotations" : "smooth holonomy");
  }
}

TEST_CASE(multigrid_sees_through_a_gauge_transform)
{
  // A' = D^* A D with D = diag(exp(i phi)), phi random: A' x' = D^* b has x' = D^* x. The
  // connection's near-kernel is D^* 1: a prolongator that ignored the transport would hold
  // the constant, far from it, and need many times the iterations.
  const int side = 200;
  std::vector<double> phi(side * side);
  for(double& p : phi)
    p = uniform(-3.1, 3.1);
  auto one = [](int, int, int, int) { return 1.0; };
  const std::mt19937_64 saved = gen;
  const auto A = grid_laplacian<double>(side, one);
  gen = saved; // (the same weights)
  auto t = [&](int i, int j, int k, int l) { return std::polar(1.0, phi[k * side + l] - phi[i * side + j]); };
  const auto Ag = grid_laplacian<Cd>(side, t);
  // entries of Ag are conj(D_a) A_ab D_b: check the construction itself
  CHECK_NEAR(std::abs(Ag.coeff(0, 1) - std::polar(1.0, phi[1] - phi[0]) * A.coeff(0, 1)), 0.0, 1e-14);
  HOTI::Smoothed_aggregation<double> real;
  HOTI::Smoothed_aggregation<Cd> complex;
  CHECK(real.compute(A));
  CHECK(complex.compute(Ag));
  const Eigen::VectorXd b = random_vector<double>(A.rows());
  Eigen::VectorXcd bg(A.rows());
  for(Eigen::Index i = 0; i < A.rows(); ++i)
    bg[i] = std::polar(1.0, -phi[i]) * b[i];
  Eigen::VectorXd x;
  Eigen::VectorXcd xg;
  const int it = real.solve(b, x, 1e-10, 200), itg = complex.solve(bg, xg, 1e-10, 200);
  std::cout << "  real: " << it << " iterations, gauge-transformed: " << itg << std::endl;
  CHECK(it > 0 && itg > 0);
  CHECK_MSG(std::abs(itg - it) <= 1, it << " vs " << itg);
  double worst = 0;
  for(Eigen::Index i = 0; i < A.rows(); ++i)
    worst = std::max(worst, std::abs(xg[i] - std::polar(1.0, -phi[i]) * x[i]));
  CHECK_MSG(worst <= 1e-6 * x.cwiseAbs().maxCoeff(), worst);
}

TEST_CASE(a_real_hierarchy_solves_two_real_systems_as_one_complex)
{
  auto one = [](int, int, int, int) { return 1.0; };
  const auto A = grid_laplacian<double>(150, one);
  HOTI::Smoothed_aggregation<double> real;
  HOTI::Smoothed_aggregation<double, Cd> pair;
  CHECK(real.compute(A));
  CHECK(pair.compute(A));
  const Eigen::VectorXd b1 = random_vector<double>(A.rows()), b2 = random_vector<double>(A.rows());
  Eigen::VectorXd x1, x2;
  Eigen::VectorXcd x;
  CHECK(real.solve(b1, x1, 1e-10, 200) > 0);
  CHECK(real.solve(b2, x2, 1e-10, 200) > 0);
  CHECK(pair.solve(b1.cast<Cd>() + Cd(0, 1) * b2.cast<Cd>(), x, 1e-10, 200) > 0);
  CHECK_MSG((x.real() - x1).norm() <= 1e-7 * x1.norm(), (x.real() - x1).norm() / x1.norm());
  CHECK_MSG((x.imag() - x2).norm() <= 1e-7 * x2.norm(), (x.imag() - x2).norm() / x2.norm());
  // warm start: from the solution, no iteration
  Eigen::VectorXd y = x1;
  CHECK(real.solve(b1, y, 1e-9, 200) == 0);
}

TEST_CASE(small_and_degenerate_systems)
{
  // below the coarsest size: one level, factored; CG converges at once
  auto one = [](int, int, int, int) { return 1.0; };
  const auto A = grid_laplacian<double>(20, one);
  HOTI::Smoothed_aggregation<double> mg;
  CHECK(mg.compute(A));
  CHECK(mg.number_of_levels() == 1);
  const Eigen::VectorXd b = random_vector<double>(A.rows());
  Eigen::VectorXd x;
  CHECK(mg.solve(b, x, 1e-12, 10) == 1);
  CHECK((A * x - b).norm() <= 1e-12 * b.norm());
  // zero right-hand side: zero, at once
  Eigen::VectorXd z;
  CHECK(mg.solve(Eigen::VectorXd::Zero(A.rows()), z, 1e-12, 10) == 0);
  CHECK(z.size() == A.rows() && z.norm() == 0);
  // not definite (the sign of a Laplacian turned): refused at the coarsest level
  HOTI::Smoothed_aggregation<double> neg;
  CHECK(!neg.compute(Eigen::SparseMatrix<double, Eigen::RowMajor>(-A)));
  const auto big = grid_laplacian<double>(100, one);
  CHECK(!neg.compute(Eigen::SparseMatrix<double, Eigen::RowMajor>(-big)));
}

HOT_TEST_MAIN
