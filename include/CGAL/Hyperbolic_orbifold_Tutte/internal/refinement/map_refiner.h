// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_REFINEMENT_MAP_REFINER_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_REFINEMENT_MAP_REFINER_H

// The refinement's driver (refine_orbifold_map() runs it; see arap_on_target.h for the
// subsystem): the state of one refinement (A's corners, the images of its vertices on B, their
// tangent bases) and its iterations. The certificate is a function given by the caller, so
// that this layer knows no public header but the vocabulary ones.

#include <CGAL/Hyperbolic_orbifold_Tutte/Map_refinement_statistics.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/error_code.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/core/dense_index.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/core/disk_models.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/refinement/arap_on_target.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/refinement/corner_moves.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/properties.h>
#include <CGAL/squared_distance_3.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#endif

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <complex>
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {
namespace internal {

// the points of B's face at location l
template <class Location, class Locator, class VertexPointMapB>
std::array<Eigen::Vector3d, 3> face_points(const Location& l, const Locator& locB, VertexPointMapB vpmB)
{
  std::array<Eigen::Vector3d, 3> P;
  for(int k = 0; k < 3; ++k) {
    const auto& p = get(vpmB, locB.vertex(locB.corner_vertex_index(l.face_index, k)));
    P[k] = Eigen::Vector3d(to_double(p.x()), to_double(p.y()), to_double(p.z()));
  }
  return P;
}

// the point of the disk, in the frame of the located corner, whose image on B's face
// `l.face_index` is y (affine coordinates there, extended outside the face, combined as the
// hyperboloid model does); none when the extension leaves the disk
template <class Location, class Locator, class VertexPointMapB>
std::optional<std::complex<double> > refinement_target(const Location& l, const Locator& locB, VertexPointMapB vpmB,
                                                        const Eigen::Vector3d& y)
{
  typedef std::complex<double> C;
  const std::array<Eigen::Vector3d, 3> P = face_points(l, locB, vpmB);
  C z[3];
  for(int k = 0; k < 3; ++k) {
    const auto c = locB.corner_point(l.face_index, k);
    z[k] = C(to_double(c.x()), to_double(c.y()));
  }
  Eigen::Matrix<double, 3, 2> E;
  E.col(0) = P[1] - P[0];
  E.col(1) = P[2] - P[0];
  const Eigen::Vector2d st = (E.transpose() * E).ldlt().solve(E.transpose() * (y - P[0]));
  const double bc[3] = {1 - st[0] - st[1], st[0], st[1]};
  C k(0, 0);
  double s = 0;
  for(int j = 0; j < 3; ++j) {
    const double mu = bc[j] / hyperboloid_weight(z[j]);
    k += mu * poincare_to_klein(z[j]);
    s += mu;
  }
  if(!(s > 0) || !(std::abs(k / s) < 1 - 1e-9))
    return std::nullopt;
  return l.element.inverse().apply(klein_to_poincare(k / s));
}

// an orthonormal basis of the plane of B's face at location l, its first vector `first`
// projected onto the plane (the face's first edge if the projection is short)
template <class Location, class Locator, class VertexPointMapB>
Eigen::Matrix<double, 3, 2> tangent_basis(const Location& l, const Locator& locB, VertexPointMapB vpmB, const Eigen::Vector3d& first)
{
  const std::array<Eigen::Vector3d, 3> P = face_points(l, locB, vpmB);
  const Eigen::Vector3d n = (P[1] - P[0]).cross(P[2] - P[0]).normalized();
  const Eigen::Vector3d projected = first - first.dot(n) * n;
  const Eigen::Vector3d t1 = projected.norm() > 0.5 ? projected.normalized() : Eigen::Vector3d((P[1] - P[0]).normalized());
  Eigen::Matrix<double, 3, 2> T;
  T.col(0) = t1;
  T.col(1) = n.cross(t1);
  return T;
}

// the disk point (located corner's frame) where the move m of image q (located at l) leads, m
// halved while its extension leaves the disk; false if none is found. The point q + m is taken
// into the disk by the chart of the face of B that holds the result: the chart of l's face
// first, then of the face where that point is located, until the face no longer changes (at
// most 4 times). One face's chart extended across its neighbours is wrong at first order (the
// Jacobian of B's embedding jumps from face to face), and the images then did not land where
// the tangent step said: on SHREC'07's humans the energy predicted along the step fell while the
// energy of the images increased, and the line search cut steps to 1/32 and less. `where` is
// z's location on B when the search found it (the last chart's face), else not successful.
template <class Location, class Locator, class VertexPointMapB>
bool refinement_move(const Location& l, const Locator& locB, VertexPointMapB vpmB, const Eigen::Vector3d& q, Eigen::Vector3d m,
                     std::complex<double>& z, Location& where)
{
  where.success = false;
  for(int halving = 0; halving < 30; ++halving, m *= 0.5)
    if(const auto t = refinement_target(l, locB, vpmB, q + m)) {
      z = *t;
      Location chart = l;
      for(int k = 0; k < 4; ++k) {
        const Location next = locB.locate_near(typename Locator::Point_2(z.real(), z.imag()), chart);
        if(!next.success || next.face_index == chart.face_index) {
          where = next;
          break;
        }
        const auto u = refinement_target(next, locB, vpmB, q + m);
        if(!u) {
          where = next; // (z unchanged)
          break;
        }
        z = *u;
        chart = next;
      }
      return true;
    }
  return false;
}

// One refinement of the map from A onto B (B's embedding searched by `Locator`): A's corners
// in `corners_`, the images `q_` of A's vertices (their primary corners located on B) and the
// iterations of refine_orbifold_map(). `certify(uv, why)` answers whether corners given as a
// halfedge property map are a certified embedding (OK), or the error and why.
template <class TriangleMeshA, class HalfedgeUVMapA, class TriangleMeshB, class Locator>
class Map_refiner
{
  typedef boost::graph_traits<TriangleMeshA> GT;
  typedef typename GT::vertex_descriptor vertex_descriptor;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  typedef typename boost::property_traits<HalfedgeUVMapA>::value_type UV_point;
  typedef std::complex<double> C;
  typedef typename Locator::Location Location;

public:
  typedef std::function<UV_point(halfedge_descriptor)> Corner_reader;
  typedef std::function<Error_code(const Corner_reader&, std::string&)> Certify;

  Map_refiner(const TriangleMeshA& A, const std::vector<vertex_descriptor>& landmarks, HalfedgeUVMapA uvA, const TriangleMeshB& B,
              const Locator& locB, Map_refinement_statistics& stats, const Certify& certify)
    : A_(A), landmarks_(landmarks), B_(B), locB_(locB), stats_(stats), certify_(certify), vidx_(vertices(A)), hidx_(halfedges(A)),
      corners_(hidx_.size(), C(0, 0)), fixed_(vidx_.size(), 0), q_(vidx_.size(), Eigen::Vector3d::Zero()), located_(vidx_.size(), C(2, 2)),
      T_(vidx_.size(), Eigen::Matrix<double, 3, 2>::Zero())
  {
    for(halfedge_descriptor h : halfedges(A))
      if(!is_border(h, A))
        corners_[hidx_(h)] = C(to_double(get(uvA, h).x()), to_double(get(uvA, h).y()));
  }

  // checks the embedding, reads A's faces and locates the images: OK, or the error (and
  // stats.message)
  template <class VertexPointMapA>
  Error_code prepare(VertexPointMapA vpmA)
  {
    std::string why;
    const Error_code ec = certified(why);
    if(ec != OK) {
      stats_.message = "the embedding to refine is not certified: " + why;
      return ec;
    }
    for(vertex_descriptor v : landmarks_)
      fixed_[vidx_(v)] = 1;
    moves_.reset(new Corner_moves<TriangleMeshA>(A_, vidx_, hidx_, corners_, fixed_));
    for(auto f : faces(A_)) {
      std::array<std::size_t, 3> c;
      std::array<Eigen::Vector3d, 3> p;
      int k = 0;
      for(vertex_descriptor v : vertices_around_face(halfedge(f, A_), A_)) {
        c[k] = vidx_(v);
        p[k++] = to_eigen(get(vpmA, v));
      }
      src_.add_face(c, p);
    }
    double area_B = 0;
    const auto vpmB = get(vertex_point, B_);
    for(auto f : faces(B_)) {
      const auto h = halfedge(f, B_);
      area_B += std::sqrt(to_double(squared_area(get(vpmB, source(h, B_)), get(vpmB, target(h, B_)), get(vpmB, target(next(h, B_), B_)))));
    }
    s_ = std::sqrt(area_B / src_.total_area);
    if(!locate()) {
      stats_.message = "a vertex of the source could not be located on the target";
      return ERROR_POINT_NOT_LOCATED;
    }
    stats_.energy_before = stats_.energy_after = src_.symmetric_dirichlet(q_, s_);
    stats_.tempered_energy_before = stats_.tempered_energy_after = tempered_ = src_.symmetric_dirichlet(q_, s_, cap_);
    for(char f : fixed_)
      stats_.free_vertices += f ? 0 : 1;
    sign_ = faces(A_).empty() ? POSITIVE : moves_->orientation(*faces(A_).begin(), corners_);
    step_.reset(new Arap_global_step(src_, fixed_));
    return OK;
  }

  // One iteration. The step, then a line search along it: halved until the energy decreases
  // and the iterate is certified (the moves that would turn a face over undone). When no step
  // lowers the energy, the step is solved again with the undone vertices held (the rest of it
  // is then a descent direction of the energy), and the last two rounds with the ARAP proxy,
  // whose weights do not blow up on nearly degenerate images. False when it stops (the last
  // certified iterate kept, stats.stop set).
  //
  // The vertices a step had to hold are held from the start of the next iterations (a pass that
  // fails is solved again free): on a squeezed protrusion the same few vertices are undone at
  // every iteration, and solving each step twice, the free one failing at every halving, made
  // most of the refinement's time (SHREC'07 hands: 0.35 s an iteration against 0.04 s held).
  // Every `free_period_` iterations a step is tried free again; the period doubles each time
  // that one still needs vertices held.
  bool iterate()
  {
    // the tangent bases at the images: the previous one projected onto the plane of the
    // image's face (a basis that turns little from one step to the next keeps the global
    // steps' matrices close, and the earlier factor a good preconditioner)
    for(std::size_t i = 0; i < vidx_.size(); ++i)
      if(!fixed_[i])
        T_[i] = tangent_basis(locs_[i], locB_, get(vertex_point, B_), T_[i].col(0));
    const std::vector<C> old = corners_, old_located = located_;
    const std::vector<Location> old_locs = locs_;
    const std::vector<Eigen::Vector3d> old_q = q_;
    const auto restore = [&]() {
      corners_ = old;
      locs_ = old_locs;
      located_ = old_located;
      q_ = old_q;
    };
    // the vertices of the faces whose density exceeds the tempering cap (no momentum there)
    std::vector<char> squeezed(vidx_.size(), 0);
    if(!last_move_.empty())
      for(std::size_t f = 0; f < src_.corners.size(); ++f)
        if(src_.areas[f] > 0 && !(Arap_source::density(src_.jacobian(f, q_), s_) <= cap_))
          for(std::size_t c : src_.corners[f])
            squeezed[c] = 1;
    const bool carried = !carried_.empty() && stats_.iterations < next_free_;
    const bool free_try = !carried_.empty() && !carried; // (a scheduled one)
    std::vector<char> held = carried ? carried_ : std::vector<char>(vidx_.size(), 0), solve_held;
    bool accepted = false, certificate_failed = false, solved = true;
    double e = tempered_;
    std::size_t undone = 0;
    for(int pass = carried ? 0 : 1; pass < 2 && !accepted; ++pass) {
      if(pass == 1 && carried) { // the held pass failed: the same iteration, free
        std::fill(held.begin(), held.end(), 0);
        restore();
      }
      for(int round = 0; round < 4 && !accepted; ++round) {
        if(round > 0) // (solved at the iterate, not at the last attempt's images)
          restore();
        std::vector<Eigen::Vector2d> d;
        solve_held = held;
        if(!step_->solve(q_, T_, s_, held, d, round < 2, cap_)) {
          solved = false; // (a round with the ARAP proxy may still solve)
          continue;
        }
        solved = true;
        if(round == 0) // (the heavy ball; see last_move_)
          for(std::size_t i = 0; i < last_move_.size(); ++i)
            if(!fixed_[i] && !held[i] && !squeezed[i])
              d[i] += momentum_ * (T_[i].transpose() * last_move_[i]);
        // each attempt's targets: the iterate's images moved by the step, scaled (not a point
        // on the disk's geodesic to the full step's target: B's charts differ from face to face)
        std::vector<C> to(vidx_.size());
        std::vector<Location> where(vidx_.size());
        std::vector<char> undone_flag(vidx_.size(), 0);
        for(int attempt = 0; attempt < 8 && !accepted; ++attempt) {
          restore();
          std::vector<char> moved(vidx_.size(), 0);
          for_each_vertex([&](std::size_t i) {
            if(fixed_[i] || held[i])
              return;
            const Eigen::Vector3d m = std::ldexp(1.0, -attempt) * (T_[i] * d[i]);
            moved[i] = refinement_move(old_locs[i], locB_, get(vertex_point, B_), old_q[i], m, to[i], where[i]);
          });
          undone = moves_->move(to, moved, old, corners_, sign_, undone_flag);
          // the moved images where refinement_move() located them (the others located again)
          for(std::size_t i = 0; i < vidx_.size(); ++i)
            if(moved[i] && where[i].success && corners_[hidx_(moves_->primary(i))] == to[i]) {
              locs_[i] = where[i];
              located_[i] = to[i];
              q_[i] = image(where[i]);
            }
          e = locate() ? src_.symmetric_dirichlet(q_, s_, cap_) : std::numeric_limits<double>::infinity();
          if(!(e < tempered_))
            continue;
          std::string why;
          if(certified(why) == OK)
            accepted = true;
          else {
            certificate_failed = true;
            stats_.message = why;
          }
        }
        for(std::size_t i = 0; i < held.size(); ++i)
          held[i] = held[i] || undone_flag[i];
      }
    }
    if(!accepted) {
      restore();
      stats_.stop = !solved ? Refinement_solver : certificate_failed ? Refinement_certificate : Refinement_converged;
      return false;
    }
    // converged after five iterations in a row that lower the energy by less than a relative
    // 1e-6 (one is not enough: a nearly degenerate image can make the first steps small
    // against a huge energy, and the later ones large)
    small_steps_ = e > tempered_ * (1 - 1e-6) ? small_steps_ + 1 : 0;
    // the accepted step's held vertices, if any (none: a free step, in its first round or with
    // the ARAP proxy)
    if(std::find(solve_held.begin(), solve_held.end(), 1) == solve_held.end())
      carried_.clear();
    else {
      carried_ = solve_held;
      if(!carried) { // a free step needed vertices held: held until the next free try
        if(free_try)
          free_period_ *= 2;
        next_free_ = stats_.iterations + 1 + free_period_;
      }
    }
    last_move_.resize(vidx_.size());
    for(std::size_t i = 0; i < vidx_.size(); ++i)
      last_move_[i] = q_[i] - old_q[i];
    tempered_ = stats_.tempered_energy_after = e;
    stats_.energy_after = src_.symmetric_dirichlet(q_, s_);
    stats_.undone_moves = undone;
    ++stats_.iterations;
    if(small_steps_ >= 5)
      stats_.stop = Refinement_converged;
    return small_steps_ < 5;
  }

  // writes the corners into `uv`
  void write(HalfedgeUVMapA uv) const
  {
    for(halfedge_descriptor h : halfedges(A_))
      if(!is_border(h, A_))
        put(uv, h, UV_point(corners_[hidx_(h)].real(), corners_[hidx_(h)].imag()));
  }

private:
  template <class P>
  static Eigen::Vector3d to_eigen(const P& p)
  {
    return Eigen::Vector3d(to_double(p.x()), to_double(p.y()), to_double(p.z()));
  }

  // the certificate of the current corners (its time counted)
  Error_code certified(std::string& why)
  {
    const auto t0 = std::chrono::steady_clock::now();
    const Error_code ec = certify_([this](halfedge_descriptor h) { return UV_point(corners_[hidx_(h)].real(), corners_[hidx_(h)].imag()); }, why);
    stats_.seconds_certificate += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return ec;
  }

  // locates the vertices whose primary corner moved (all of them the first time), each by a
  // walk from its previous location; false if one is not located
  bool locate()
  {
    if(locs_.empty())
      locs_.resize(vidx_.size());
    std::atomic<bool> ok(true);
    const auto run = [&](std::size_t i) {
      const halfedge_descriptor h = moves_->primary(i);
      if(h == GT::null_halfedge() || corners_[hidx_(h)] == located_[i])
        return;
      const typename Locator::Point_2 z(corners_[hidx_(h)].real(), corners_[hidx_(h)].imag());
      locs_[i] = located_[i] == C(2, 2) ? locB_.locate(z) : locB_.locate_near(z, locs_[i]);
      located_[i] = corners_[hidx_(h)];
      if(!locs_[i].success) {
        ok = false;
        return;
      }
      q_[i] = image(locs_[i]);
    };
    for_each_vertex(run);
    return ok.load();
  }

  // the point of B at location l (as surface_point())
  Eigen::Vector3d image(const Location& l) const
  {
    const std::array<Eigen::Vector3d, 3> P = face_points(l, locB_, get(vertex_point, B_));
    const std::array<double, 3>& b = l.barycentric;
    return (b[0] * P[0] + b[1] * P[1] + b[2] * P[2]) / (b[0] + b[1] + b[2]);
  }

  // run(i) for every vertex i, in parallel on large meshes (each i touches only its own data)
  template <class Run>
  void for_each_vertex(const Run& run) const
  {
#ifdef CGAL_LINKED_WITH_TBB
    if(vidx_.size() > 10000) {
      tbb::parallel_for(tbb::blocked_range<std::size_t>(0, vidx_.size(), 1024), [&](const tbb::blocked_range<std::size_t>& r) {
        for(std::size_t i = r.begin(); i != r.end(); ++i)
          run(i);
      });
      return;
    }
#endif
    for(std::size_t i = 0; i < vidx_.size(); ++i)
      run(i);
  }

  const TriangleMeshA& A_;
  const std::vector<vertex_descriptor>& landmarks_;
  const TriangleMeshB& B_;
  const Locator& locB_;
  Map_refinement_statistics& stats_;
  Certify certify_;
  const Dense_index<vertex_descriptor> vidx_;
  const Dense_index<halfedge_descriptor> hidx_;
  std::vector<C> corners_;
  std::vector<char> fixed_;
  std::unique_ptr<Corner_moves<TriangleMeshA> > moves_;
  Arap_source src_;
  double s_ = 1;
  std::vector<Location> locs_;
  std::vector<Eigen::Vector3d> q_;
  std::vector<C> located_; // per vertex: the primary corner's point when last located (2: never)
  std::vector<Eigen::Matrix<double, 3, 2> > T_;
  Sign sign_ = POSITIVE;
  std::unique_ptr<Arap_global_step> step_;
  // The iterations lower the energy tempered above a density of 100 (Arap_source::tempered()):
  // the faces squeezed more than about 10 times in one direction (a protrusion without a
  // landmark that B's embedding itself squeezes beyond what double resolves, a scan's thin
  // fingers) count logarithmically, so that their density (up to 1e16 and more on SHREC'07's
  // humans) neither dominates the sum, which the line search and the convergence test read, nor
  // stiffens the step; they still resist collapse (the logarithm's barrier, the certificate).
  static constexpr double cap_ = 100;
  double tempered_ = 0; // the tempered energy of the current iterate
  int small_steps_ = 0; // iterations in a row that lowered the energy by less than a relative 1e-6
  std::vector<char> carried_; // the vertices the last step held, when it needed them (else empty)
  int next_free_ = 0;         // the iteration of the next free try
  int free_period_ = 8;
  // Heavy-ball momentum (Polyak): the first solve of an iteration adds to each free image's
  // move `momentum_` times its last accepted move (in 3D, projected onto the current tangent
  // plane); the line search, the undoing and the certificate then treat the sum as the step.
  // Local-global steps crawl along the energy's flat valleys (a limb's twist about its axis
  // with 7 landmarks: the energy moves in its fourth digit while the map still moves), where
  // the last moves keep pointing the same way. Not on the vertices of faces squeezed beyond the
  // tempering cap: there the momentum sped up the tempered energy's decrease and slowed the
  // map's (test_refine's octopus with a free tentacle, mean error against the truth after 10,
  // 20, 30, 40 iterations: 3.60, 3.40, 3.29, 3.23% without momentum; 3.57, 3.48, 3.40, 3.42%
  // with it everywhere; 3.52, 3.39, 3.25, 3.17% with it but there). Measured on SHREC'07's
  // humans (12 ordered pairs, 7 landmarks): area under the transfer error curve 0.797 without
  // momentum, 0.800 with 0.8 (0.799 to 0.804 with 0.6 to 0.95 everywhere); at 60 iterations
  // 0.802 without, 0.805 with; 0.809 without at 120. Dropping the last moves after a step cut to
  // a quarter or less lost the gain. The retries of an iteration (held vertices, the ARAP proxy)
  // solve without it, so that they stay plain descent steps. (These figures are from before the
  // moves were taken through the chart of the face that holds them, see refinement_move().)
  static constexpr double momentum_ = 0.8;
  std::vector<Eigen::Vector3d> last_move_; // per vertex: its image's move in the last accepted iteration
};

} // namespace internal
} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_REFINEMENT_MAP_REFINER_H
