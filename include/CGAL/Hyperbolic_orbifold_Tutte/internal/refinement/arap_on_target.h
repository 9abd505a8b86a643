// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_REFINEMENT_ARAP_ON_TARGET_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_REFINEMENT_ARAP_ON_TARGET_H

// The refinement subsystem (refine_orbifold_map.h) owns the two halves of one iteration:
// this file, the as-rigid-as-possible (ARAP) energy of the map A -> B over A's faces and its
// local-global step, with the images moving in B's tangent planes; corner_moves.h, the step
// turned into A's corners in the disk (seam copies moved by their side pairings) and cut back
// where a face would turn over, so that every iterate is an embedding the exact certificate
// can accept. Nothing here knows the orbifold: the images are points of B with a tangent basis.

#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>

#include <CGAL/Hyperbolic_orbifold_Tutte/internal/linear_algebra/simplicial_float_factor.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#endif

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {
namespace internal {

// A's faces in their own planes: per face its three vertices (dense indices) and the gradients
// of the three hat functions in the face's 2D frame, and its area.
struct Arap_source
{
  std::vector<std::array<std::size_t, 3> > corners;
  std::vector<std::array<Eigen::Vector2d, 3> > gradients;
  std::vector<double> areas;
  double total_area = 0;

  void add_face(const std::array<std::size_t, 3>& c, const std::array<Eigen::Vector3d, 3>& p)
  {
    const Eigen::Vector3d a = p[1] - p[0], b = p[2] - p[0];
    const double la = a.norm();
    const double bx = a.dot(b) / la;
    const double by = std::sqrt((std::max)(0.0, b.squaredNorm() - bx * bx));
    Eigen::Matrix2d X;
    X << la, bx, 0, by;
    std::array<Eigen::Vector2d, 3> g;
    const double area = 0.5 * la * by;
    if(area > 0) {
      const Eigen::Matrix2d XiT = X.inverse().transpose();
      g[1] = XiT.col(0);
      g[2] = XiT.col(1);
      g[0] = -(g[1] + g[2]);
    } else
      g.fill(Eigen::Vector2d::Zero()); // a degenerate face of A carries no energy
    corners.push_back(c);
    gradients.push_back(g);
    areas.push_back(area);
    total_area += area;
  }

  // the map's Jacobian on face f (3x2, from A's face frame into space)
  Eigen::Matrix<double, 3, 2> jacobian(std::size_t f, const std::vector<Eigen::Vector3d>& q) const
  {
    Eigen::Matrix<double, 3, 2> J = Eigen::Matrix<double, 3, 2>::Zero();
    for(int j = 0; j < 3; ++j)
      J += q[corners[f][j]] * gradients[f][j].transpose();
    return J;
  }

  // the singular values (decreasing) and right singular vectors of J, from the 2x2 Gram matrix
  static void svd(const Eigen::Matrix<double, 3, 2>& J, Eigen::Vector2d& sigma, Eigen::Matrix2d& V)
  {
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> es;
    es.computeDirect(J.transpose() * J);
    const Eigen::Vector2d ev = es.eigenvalues(); // increasing
    sigma = Eigen::Vector2d(std::sqrt((std::max)(ev[1], 0.0)), std::sqrt((std::max)(ev[0], 0.0)));
    V.col(0) = es.eigenvectors().col(1);
    V.col(1) = es.eigenvectors().col(0);
  }

  // the closest scaled isometry s R to J (R: 3x2 with orthonormal columns, J V diag(1/sigma) V^T
  // when J has rank 2)
  static Eigen::Matrix<double, 3, 2> rotation(const Eigen::Matrix<double, 3, 2>& J, double s)
  {
    Eigen::Vector2d sigma;
    Eigen::Matrix2d V;
    svd(J, sigma, V);
    if(sigma[1] > 1e-12 * sigma[0])
      return s * J * V * sigma.cwiseInverse().asDiagonal() * V.transpose();
    Eigen::JacobiSVD<Eigen::Matrix<double, 3, 2> > full(J, Eigen::ComputeFullU | Eigen::ComputeFullV);
    return s * full.matrixU().leftCols<2>() * full.matrixV().transpose();
  }

  // the symmetric Dirichlet energy: the area-weighted mean over A's faces of
  // s1^2 + s2^2 + 1/s1^2 + 1/s2^2 (s1, s2 the singular values of J_f / s): 4 for an isometry up
  // to the scale s, infinite for a face whose image is degenerate. With the columns c0, c1 of
  // J / s: s1^2 + s2^2 = |c0|^2 + |c1|^2 and s1 s2 = |c0 x c1|, so the density is
  // (|c0|^2 + |c1|^2) (1 + 1 / |c0 x c1|^2), no SVD needed.
  double symmetric_dirichlet(const std::vector<Eigen::Vector3d>& q, double s, double cap = std::numeric_limits<double>::infinity()) const
  {
    double e = 0;
    for(std::size_t f = 0; f < corners.size(); ++f) {
      if(!(areas[f] > 0))
        continue;
      const double d = density(jacobian(f, q), s);
      if(!(d < std::numeric_limits<double>::infinity()))
        return d;
      e += areas[f] * tempered(d, cap);
    }
    return e / total_area;
  }

  // the energy density of face Jacobian J (infinite for a degenerate image)
  static double density(const Eigen::Matrix<double, 3, 2>& J0, double s)
  {
    const Eigen::Matrix<double, 3, 2> J = J0 / s;
    const double area2 = J.col(0).cross(J.col(1)).squaredNorm();
    if(!(area2 > 0))
      return std::numeric_limits<double>::infinity();
    return J.squaredNorm() * (1 + 1 / area2);
  }

  // The density of J / s, its gradient with respect to J's six entries (column-major: the
  // first column, then the second) and its Hessian projected onto the positive semidefinite
  // matrices; false for a degenerate image. The density is isotropic, a function of the
  // singular values of J / s, E = sum_k sigma_k^2 + sigma_k^-2, so its Hessian's eigensystem is
  // known in closed form (as for the planar isotropic energies; a 3 x 2 J adds two directions
  // out of the image's plane). With J / s = sigma_0 u_0 v_0^T + sigma_1 u_1 v_1^T, n = u_0 x u_1
  // and E_k = dE/dsigma_k = 2 sigma_k - 2 sigma_k^-3 (sigma_0 >= sigma_1), the six
  // eigenvectors (as 3 x 2 moves of J / s) and eigenvalues are:
  //   u_k v_k^T (k = 0, 1), stretching one singular value: d2E/dsigma_k^2 = 2 + 6 sigma_k^-4;
  //   (u_1 v_0^T - u_0 v_1^T) / sqrt 2, turning in the plane: (E_0 + E_1) / (sigma_0 + sigma_1)
  //     = 2 - 2 (sigma_0^2 - sigma_0 sigma_1 + sigma_1^2) / (sigma_0 sigma_1)^3;
  //   (u_1 v_0^T + u_0 v_1^T) / sqrt 2, shearing: (E_0 - E_1) / (sigma_0 - sigma_1)
  //     = 2 + 2 (sigma_0^2 + sigma_0 sigma_1 + sigma_1^2) / (sigma_0 sigma_1)^3 (no division:
  //     equal singular values need no special case);
  //   n v_k^T (k = 0, 1), tilting out of the plane: E_k / sigma_k = 2 - 2 sigma_k^-4.
  // The projection keeps the nonnegative ones. (Checked against finite differences of
  // density() in test_refine.)
  static bool density_derivatives(const Eigen::Matrix<double, 3, 2>& J, double s, double& value, Eigen::Matrix<double, 6, 1>& grad,
                                   Eigen::Matrix<double, 6, 6>& hess)
  {
    const Eigen::Matrix<double, 3, 2> M = J / s;
    Eigen::Vector2d sigma;
    Eigen::Matrix2d V;
    svd(M, sigma, V);
    if(!(sigma[1] > 0))
      return false;
    Eigen::Vector3d u[2];
    for(int k = 0; k < 2; ++k)
      u[k] = (M * V.col(k)) / sigma[k];
    const Eigen::Vector3d n = u[0].cross(u[1]).normalized();
    // the 6-vector of the move a b^T (a in space, b in the face's frame)
    const auto entries = [](const Eigen::Vector3d& a, const Eigen::Vector2d& b) {
      Eigen::Matrix<double, 6, 1> e;
      e << a * b[0], a * b[1];
      return e;
    };
    const double p = sigma[0] * sigma[1], p3 = p * p * p;
    const double s0 = sigma[0] * sigma[0], s1 = sigma[1] * sigma[1];
    value = s0 + s1 + 1 / s0 + 1 / s1;
    grad.setZero();
    for(int k = 0; k < 2; ++k)
      grad += (2 * sigma[k] - 2 / (sigma[k] * sigma[k] * sigma[k])) * entries(u[k], V.col(k));
    grad /= s;
    std::array<std::pair<double, Eigen::Matrix<double, 6, 1> >, 6> modes;
    modes[0] = {2 + 6 / (s0 * s0), entries(u[0], V.col(0))};
    modes[1] = {2 + 6 / (s1 * s1), entries(u[1], V.col(1))};
    modes[2] = {2 - 2 * (s0 - p + s1) / p3, (entries(u[1], V.col(0)) - entries(u[0], V.col(1))) / std::sqrt(2.0)};
    modes[3] = {2 + 2 * (s0 + p + s1) / p3, (entries(u[1], V.col(0)) + entries(u[0], V.col(1))) / std::sqrt(2.0)};
    modes[4] = {2 - 2 / (s0 * s0), entries(n, V.col(0))};
    modes[5] = {2 - 2 / (s1 * s1), entries(n, V.col(1))};
    hess.setZero();
    for(const auto& m : modes)
      if(m.first > 0)
        hess += m.first * m.second * m.second.transpose();
    hess /= s * s;
    return true;
  }

  // the density tempered above `cap`: itself below, cap (1 + log(d / cap)) above (C1)
  static double tempered(double d, double cap) { return d <= cap ? d : cap * (1 + std::log(d / cap)); }

};

// The global step: with the rotations of the current images q frozen, the moves d (2 per
// vertex, in the tangent bases T) minimising sum_f area_f |W_f (J_f(q + T d) - s R_f)|^2 with
// the vertices of `fixed` kept: W_f = I (ARAP), or the reweighting of the symmetric Dirichlet
// energy (see weights()). The sparsity pattern is analysed once.
class Arap_global_step
{
public:
  Arap_global_step(const Arap_source& src, const std::vector<char>& fixed) : src_(src), fixed_(fixed)
  {
    unknown_.assign(fixed.size(), npos);
    for(std::size_t i = 0; i < fixed.size(); ++i)
      if(!fixed[i])
        unknown_[i] = n_++;
  }

  std::size_t number_of_unknown_vertices() const { return n_; }

  // false when the factorisation fails (then d is zero); the vertices of `held` are tied to
  // d = 0 by a stiff spring (the pattern stays the one analysed)
  bool solve(const std::vector<Eigen::Vector3d>& q, const std::vector<Eigen::Matrix<double, 3, 2> >& T, double s,
             const std::vector<char>& held, std::vector<Eigen::Vector2d>& d, bool symmetric_dirichlet = true,
             double cap = std::numeric_limits<double>::infinity())
  {
    symmetric_dirichlet_ = symmetric_dirichlet;
    if(H_.rows() == 0)
      make_pattern();
    // the faces' blocks (in parallel), then summed in the faces' order (the same sums, to the
    // bit, whatever the number of threads)
    const std::size_t nf = src_.corners.size();
    blocks_.resize(nf);
    const auto block = [&](std::size_t f) {
      Face_block& b = blocks_[f];
      const auto& c = src_.corners[f];
      const auto& g = src_.gradients[f];
      double a = src_.areas[f];
      if(!(a > 0))
        return;
      const Eigen::Matrix<double, 3, 2> J = src_.jacobian(f, q);
      if(symmetric_dirichlet) {
        const double e = Arap_source::density(J, s); // (cheaper than the SVD of newton_block())
        if(e <= newton_density_ && newton_block(J, s, a, c, g, T, b))
          return;
        if(e > cap)
          a *= cap / e; // the tempered energy's gradient
      }
      const Eigen::Matrix<double, 3, 2> r = Arap_source::rotation(J, s) - J;
      const Eigen::Matrix3d M = weights(J, s);
      for(int i = 0; i < 3; ++i) {
        b.rhs[i] = a * T[c[i]].transpose() * M * r * g[i];
        for(int j = 0; j < 3; ++j)
          b.H[3 * i + j] = a * g[i].dot(g[j]) * T[c[i]].transpose() * M * T[c[j]];
      }
    };
#ifdef CGAL_LINKED_WITH_TBB
    if(nf > 10000)
      tbb::parallel_for(tbb::blocked_range<std::size_t>(0, nf, 1024), [&](const tbb::blocked_range<std::size_t>& r) {
        for(std::size_t f = r.begin(); f != r.end(); ++f)
          block(f);
      });
    else
#endif
      for(std::size_t f = 0; f < nf; ++f)
        block(f);
    double* value = H_.valuePtr();
    std::fill(value, value + H_.nonZeros(), 0.0);
    Eigen::VectorXd rhs = Eigen::VectorXd::Zero(2 * n_);
    for(std::size_t f = 0; f < nf; ++f) {
      if(!(src_.areas[f] > 0))
        continue;
      const Face_block& b = blocks_[f];
      const auto& c = src_.corners[f];
      for(int i = 0; i < 3; ++i) {
        const std::size_t ui = unknown_[c[i]];
        if(ui == npos)
          continue;
        rhs.segment<2>(2 * ui) += b.rhs[i];
        for(int j = 0; j < 3; ++j)
          if(unknown_[c[j]] != npos)
            for(int r0 = 0; r0 < 2; ++r0)
              for(int c0 = 0; c0 < 2; ++c0)
                value[slots_[36 * f + 12 * i + 4 * j + 2 * r0 + c0]] += b.H[3 * i + j](r0, c0);
      }
    }
    // a tiny Tikhonov term (a vertex whose faces are all degenerate stays put), the springs
    for(std::size_t i = 0; i < fixed_.size(); ++i)
      if(unknown_[i] != npos)
        for(int r0 = 0; r0 < 2; ++r0)
          value[diagonal_[2 * unknown_[i] + r0]] += (held[i] ? 1e8 : 1e-12) * src_.total_area;
    const Eigen::SparseMatrix<double>& H = H_;
    d.assign(fixed_.size(), Eigen::Vector2d::Zero());
    Eigen::VectorXd x;
    if(!(factored_ && !single_.empty() && preconditioned_solve(H, rhs, x))) {
      if(!factored_)
        ldlt_.analyzePattern(H);
      ldlt_.factorize(H);
      factored_ = ldlt_.info() == Eigen::Success;
      if(!factored_)
        return false;
      x = ldlt_.solve(rhs);
      // the next steps' preconditioner: the factor rounded to float (positive definite: D > 0)
      if((ldlt_.vectorD().array() > 0).all())
        single_.assign(ldlt_);
      else
        single_.clear();
    }
    if(!x.allFinite())
      return false;
    for(std::size_t i = 0; i < fixed_.size(); ++i)
      if(unknown_[i] != npos)
        d[i] = x.segment<2>(2 * unknown_[i]);
    return true;
  }

private:
  // the 2 x 2 blocks of a face's part of the system: H[3 i + j] couples its corners i and j
  struct Face_block
  {
    Eigen::Matrix2d H[9];
    Eigen::Vector2d rhs[3];
  };

  // Face block of Newton's step on a face whose density is at most newton_density_: the
  // energy's Hessian on the face, projected onto the positive semidefinite matrices, and its
  // gradient (density_derivatives()), carried to the corners' tangent moves by the hat
  // functions' gradients. Scaled by s^2/2 times the face's area, the proxy's scale (its
  // quadratic is |W (J - s R)|^2 with the energy's gradient at J up to that factor), so that the
  // two kinds of faces, the springs and the Tikhonov term weigh as before. Taken on the faces
  // whose density is at most newton_density_ (the caller tests it); false on a degenerate image.
  //
  // Why only there: on a squeezed face the energy's Hessian is far from its value a step away
  // (1/A varies fast), and Newton's step overshoots; the proxy's weights are bounded. On the
  // others Newton's step has the curvature the proxy lacks along the twists of limbs. Measured
  // with SHREC'07's humans (12 ordered pairs, 7 landmarks, 40 iterations): area under the
  // transfer error curve 0.804 with the proxy everywhere, 0.821 with Newton up to density 10;
  // on one pair the tempered energy after 40 iterations 4.1972 (proxy), 4.1887 (Newton up to
  // 10), 4.2051 (Newton everywhere).
  template <class Corners, class Gradients>
  bool newton_block(const Eigen::Matrix<double, 3, 2>& J, double s, double area, const Corners& c, const Gradients& g,
                    const std::vector<Eigen::Matrix<double, 3, 2> >& T, Face_block& b) const
  {
    double value;
    Eigen::Matrix<double, 6, 1> gJ;
    Eigen::Matrix<double, 6, 6> hJ;
    if(!Arap_source::density_derivatives(J, s, value, gJ, hJ))
      return false;
    // corner i's tangent move t changes J by (T_i t) g_i^T, its entries by U_i^T t with
    // U_i = [g_i[0] T_i^T, g_i[1] T_i^T] (2 x 6)
    const double k = 0.5 * s * s * area;
    Eigen::Matrix<double, 2, 6> U[3];
    Eigen::Matrix<double, 6, 2> HU[3];
    for(int i = 0; i < 3; ++i) {
      U[i] << g[i][0] * T[c[i]].transpose(), g[i][1] * T[c[i]].transpose();
      HU[i] = hJ * U[i].transpose();
      b.rhs[i] = -k * (U[i] * gJ);
    }
    for(int i = 0; i < 3; ++i)
      for(int j = i; j < 3; ++j) {
        b.H[3 * i + j] = k * (U[i] * HU[j]);
        if(j != i) // (a diagonal block is symmetric; assigning its own transpose would alias)
          b.H[3 * j + i] = b.H[3 * i + j].transpose();
      }
    return true;
  }

  // H_'s pattern (the blocks of the unknown vertices of a face, the diagonal) and where each
  // face's entries and the diagonal's are in its values
  void make_pattern()
  {
    typedef Eigen::Triplet<double> Tr;
    std::vector<Tr> trip;
    trip.reserve(src_.corners.size() * 36 + 2 * n_);
    for(const auto& c : src_.corners)
      for(int i = 0; i < 3; ++i)
        for(int j = 0; j < 3; ++j)
          if(unknown_[c[i]] != npos && unknown_[c[j]] != npos)
            for(int r0 = 0; r0 < 2; ++r0)
              for(int c0 = 0; c0 < 2; ++c0)
                trip.emplace_back(2 * unknown_[c[i]] + r0, 2 * unknown_[c[j]] + c0, 0.0);
    for(std::size_t k = 0; k < 2 * n_; ++k)
      trip.emplace_back(k, k, 0.0);
    H_.resize(2 * n_, 2 * n_);
    H_.setFromTriplets(trip.begin(), trip.end());
    H_.makeCompressed();
    const auto slot = [this](std::size_t row, std::size_t col) {
      const int* begin = H_.innerIndexPtr() + H_.outerIndexPtr()[col];
      const int* end = H_.innerIndexPtr() + H_.outerIndexPtr()[col + 1];
      return static_cast<std::size_t>(std::lower_bound(begin, end, static_cast<int>(row)) - H_.innerIndexPtr());
    };
    slots_.assign(36 * src_.corners.size(), 0);
    for(std::size_t f = 0; f < src_.corners.size(); ++f) {
      const auto& c = src_.corners[f];
      for(int i = 0; i < 3; ++i)
        for(int j = 0; j < 3; ++j)
          if(unknown_[c[i]] != npos && unknown_[c[j]] != npos)
            for(int r0 = 0; r0 < 2; ++r0)
              for(int c0 = 0; c0 < 2; ++c0)
                slots_[36 * f + 12 * i + 4 * j + 2 * r0 + c0] = slot(2 * unknown_[c[i]] + r0, 2 * unknown_[c[j]] + c0);
    }
    diagonal_.resize(2 * n_);
    for(std::size_t k = 0; k < 2 * n_; ++k)
      diagonal_[k] = slot(k, k);
  }

  // Conjugate gradients on H x = rhs preconditioned by the factor of an earlier matrix (the
  // matrices of successive steps differ little), its L rounded to float and solved on two
  // threads (simplicial_float_factor.h: a symmetric positive definite operator, the same bits
  // on any number of threads; Eigen's own solves made two thirds of the refinement's time on
  // 40K vertices): false when 20 iterations do not bring the residual below a tenth of the
  // right-hand side's, and the caller factors H itself. The iterations start from x = 0, so
  // that each iterate lowers the quadratic model below its value at 0
  // (x^T H x / 2 - rhs^T x < 0): rhs^T x > 0, a descent direction of the energy (rhs is minus
  // its gradient), however early the iterations stop. (Started from the preconditioned
  // right-hand side, unscaled, that was not so: with a goal of 1e-1 the refinement of
  // test_refine's bear stalled at an energy of 5.63, every step failing the line search; the
  // goal was 3e-2, which on one 40K-vertex pair took 484 iterations and 7 factorisations in
  // 30 steps, against 277 and 2 from zero to a tenth, both with the factor unrounded.)
  bool preconditioned_solve(const Eigen::SparseMatrix<double>& H, const Eigen::VectorXd& rhs, Eigen::VectorXd& x) const
  {
    const double goal = 1e-1 * rhs.norm();
    x = Eigen::VectorXd::Zero(rhs.size());
    Eigen::VectorXd r = rhs, z, p;
    single_.solve(r, z);
    p = z;
    double rz = r.dot(z);
    for(int k = 0; k < 20; ++k) {
      const Eigen::VectorXd Hp = H * p;
      const double pHp = p.dot(Hp);
      if(!(pHp > 0))
        return false;
      const double a = rz / pHp;
      x += a * p;
      r -= a * Hp;
      if(!(r.norm() > goal))
        return x.allFinite();
      single_.solve(r, z);
      const double rz2 = r.dot(z);
      p = z + (rz2 / rz) * p;
      rz = rz2;
    }
    return false;
  }

  // The proxy's metric on the residual J - s R: the identity for ARAP; for the symmetric
  // Dirichlet energy, the reweighting of scalable locally injective maps (Rabinovich et al.
  // 2017): along each singular direction u_k of J the weight w_k^2 = (t - t^-3) / (t - 1)
  // (t = s_k / s, 4 at t = 1), whose quadratic proxy has the energy's gradient at J; the
  // normal direction gets the mean weight.
  Eigen::Matrix3d weights(const Eigen::Matrix<double, 3, 2>& J, double s) const
  {
    if(!symmetric_dirichlet_)
      return Eigen::Matrix3d::Identity();
    Eigen::Vector2d sigma;
    Eigen::Matrix2d V;
    Arap_source::svd(J, sigma, V);
    const Eigen::Vector2d t = sigma / s;
    Eigen::Matrix3d M = Eigen::Matrix3d::Zero();
    Eigen::Vector3d u[3];
    for(int k = 0; k < 2; ++k)
      u[k] = sigma[k] > 0 ? Eigen::Vector3d(J * V.col(k) / sigma[k]) : Eigen::Vector3d::Zero();
    u[2] = u[0].cross(u[1]);
    double mean = 0;
    for(int k = 0; k < 2; ++k) {
      const double tk = (std::max)(t[k], 1e-8);
      // (capped: a nearly degenerate image would make the system too stiff to factor)
      const double w2 = (std::min)(std::abs(tk - 1) < 1e-6 ? 4.0 : (tk - std::pow(tk, -3)) / (tk - 1), 1e6);
      M += w2 * u[k] * u[k].transpose();
      mean += 0.5 * w2;
    }
    M += mean * u[2] * u[2].transpose();
    return M;
  }

  static constexpr std::size_t npos = static_cast<std::size_t>(-1);
  static constexpr double newton_density_ = 10; // (a tenth of the tempering cap, see newton_block())
  const Arap_source& src_;
  const std::vector<char>& fixed_;
  bool symmetric_dirichlet_ = true; // (the proxy of the current solve)
  std::vector<std::size_t> unknown_;
  std::size_t n_ = 0;
  Eigen::SparseMatrix<double> H_;    // the system, its pattern made once
  std::vector<std::size_t> slots_;    // per face, 36 places in H_'s values (see solve())
  std::vector<std::size_t> diagonal_; // per row, its diagonal's place
  std::vector<Face_block> blocks_;
  bool factored_ = false; // (ldlt_ holds the factor of an earlier step's matrix)
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double> > ldlt_;
  Simplicial_float_factor<double> single_; // ldlt_'s factor rounded to float (see preconditioned_solve())
};

} // namespace internal
} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_REFINEMENT_ARAP_ON_TARGET_H
