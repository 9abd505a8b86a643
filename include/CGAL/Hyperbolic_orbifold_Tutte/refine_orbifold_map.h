// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_REFINE_ORBIFOLD_MAP_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_REFINE_ORBIFOLD_MAP_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Hyperbolic_orbifold_Tutte/certify_hyperbolic_orbifold_embedding.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/Map_refinement_statistics.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/error_code.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/parameters.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/surface_maps.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/refinement/arap_on_target.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/refinement/corner_moves.h>

#include <CGAL/boost/graph/named_params_helper.h>

#include <boost/property_map/function_property_map.hpp>

#include <atomic>
#include <chrono>
#include <cmath>
#include <complex>
#include <optional>
#include <string>
#include <vector>

/// \file refine_orbifold_map.h

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {

namespace internal {

// the point of the disk, in the frame of the located corner, whose image on B's face
// `l.face_index` is y (affine coordinates there, extended outside the face, combined as the
// hyperboloid model does); none when the extension leaves the disk
template <class Location, class Locator, class VertexPointMapB>
std::optional<std::complex<double> > refinement_target(const Location& l, const Locator& locB, VertexPointMapB vpmB,
                                                        const Eigen::Vector3d& y)
{
  typedef std::complex<double> C;
  Eigen::Vector3d P[3];
  C z[3];
  for(int k = 0; k < 3; ++k) {
    const auto& p = get(vpmB, locB.vertex(locB.corner_vertex_index(l.face_index, k)));
    P[k] = Eigen::Vector3d(to_double(p.x()), to_double(p.y()), to_double(p.z()));
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
  Eigen::Vector3d P[3];
  for(int k = 0; k < 3; ++k) {
    const auto& p = get(vpmB, locB.vertex(locB.corner_vertex_index(l.face_index, k)));
    P[k] = Eigen::Vector3d(to_double(p.x()), to_double(p.y()), to_double(p.z()));
  }
  const Eigen::Vector3d n = (P[1] - P[0]).cross(P[2] - P[0]).normalized();
  const Eigen::Vector3d projected = first - first.dot(n) * n;
  const Eigen::Vector3d t1 = projected.norm() > 0.5 ? projected.normalized() : Eigen::Vector3d((P[1] - P[0]).normalized());
  Eigen::Matrix<double, 3, 2> T;
  T.col(0) = t1;
  T.col(1) = n.cross(t1);
  return T;
}

// the disk point (located corner's frame) where the move m of image q leads, m halved while
// its extension leaves the disk; false if none is found
template <class Location, class Locator, class VertexPointMapB>
bool refinement_move(const Location& l, const Locator& locB, VertexPointMapB vpmB, const Eigen::Vector3d& q, Eigen::Vector3d m,
                     std::complex<double>& z)
{
  for(int halving = 0; halving < 30; ++halving, m *= 0.5)
    if(const auto t = refinement_target(l, locB, vpmB, q + m)) {
      z = *t;
      return true;
    }
  return false;
}

} // namespace internal

/*!
\ingroup PkgHyperbolicOrbifoldTutteHelperFunctions

refines the map \f$f_{AB}\f$ from `A` onto `B` through their common orbifold (the map of
`map_vertices()`) towards an isometry: moves `A`'s embedding `uvA` so that the map lowers its
as-rigid-as-possible (ARAP) energy
\f$ \sum_f |f| \, \| J_f - s R_f \|_F^2 / (s^2 |A|) \f$, with \f$J_f\f$ the Jacobian of the
map on face \f$f\f$ of `A` (its vertices' images on `B`, linear in between), \f$R_f\f$ the
closest rotation and \f$s^2\f$ the ratio of `B`'s area to `A`'s (0 for an isometry up to that
scale). Each iteration is a local-global step with the images moving in `B`'s tangent planes,
turned into moves of `A`'s corners in the disk; copies of a vertex across the seams move by
the orbifold's side pairings, landmarks and border vertices stay, a move that would turn a
face of `A` over is undone (with its face's other moves), the step is halved until the
iterate lowers the symmetric Dirichlet energy \f$ \sum_f |f| (\sigma_1^2 + \sigma_2^2 +
\sigma_1^{-2} + \sigma_2^{-2}) / |A| \f$ (singular values of \f$J_f / s\f$; 4 for an isometry
up to the scale \f$s\f$, infinite for a degenerate image), and the iterate is accepted only if
it passes `certify_hyperbolic_orbifold_embedding()` (exact). So the map
stays a bijection that interpolates the landmarks and is seamless through the orbifold, and
`uvA` always holds the last certified iterate.

\tparam TriangleMeshA, TriangleMeshB models of `FaceGraph`
\tparam HalfedgeUVMapA a model of `ReadWritePropertyMap` from `A`'s halfedges to a point type
        with `x()`, `y()` (the output format of `hyperbolic_orbifold_Tutte_embedding()`)
\tparam Locator the `Embedding_locator` of `B`'s embedding

\param A the source mesh, embedded by `uvA` (not in charts)
\param landmarks `A`'s landmarks in cone order (as for `certify_hyperbolic_orbifold_embedding()`)
\param uvA the embedding of `A` (certified), replaced by the refined one
\param B the target mesh
\param locB the locator of `B`'s embedding into the same orbifold
\param stats receives the energies, iterations, time and the reason of the stop
\param np optional named parameters: `refine` (an `int`, the largest number of iterations, default 100;
       0 leaves `uvA` as it is), those of `certify_hyperbolic_orbifold_embedding()`
       (`orbifold_type`, `frame`, `cone_orders`, `cut_graph`) describing `A`'s embedding, and
       `vertex_point_map` for `A` (`B`'s points are read with `get(vertex_point, B)`)

\return `OK` (read `stats.stop`), `ERROR_NO_1_TO_1_MAPPING` if `uvA` itself is not certified,
`ERROR_POINT_NOT_LOCATED` if a vertex of `A` cannot be located on `B`, or the certificate's
error; `uvA` is then unchanged.
*/
template <class TriangleMeshA, class HalfedgeUVMapA, class TriangleMeshB, class Locator,
          class NamedParameters = CGAL::parameters::Default_named_parameters>
Error_code refine_orbifold_map(const TriangleMeshA& A,
                               const std::vector<typename boost::graph_traits<TriangleMeshA>::vertex_descriptor>& landmarks,
                               HalfedgeUVMapA uvA, const TriangleMeshB& B, const Locator& locB,
                               Map_refinement_statistics& stats,
                               const NamedParameters& np = CGAL::parameters::default_values())
{
  typedef boost::graph_traits<TriangleMeshA> GT;
  typedef typename GT::vertex_descriptor vertex_descriptor;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  typedef typename boost::property_traits<HalfedgeUVMapA>::value_type UV_point;
  typedef std::complex<double> C;
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const auto start = std::chrono::steady_clock::now();
  stats = Map_refinement_statistics();
  const int iterations = choose_parameter(get_parameter(np, internal_np::refine), 100);
  if(iterations < 0) {
    stats.message = "the number of refinement iterations must be at least 0";
    return ERROR_WRONG_PARAMETER;
  }
  const auto vpmA = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point), get_const_property_map(vertex_point, A));
  const auto vpmB = get(vertex_point, B);
  const internal::Dense_index<vertex_descriptor> vidx(vertices(A));
  const internal::Dense_index<halfedge_descriptor> hidx(halfedges(A));
  std::vector<C> corners(hidx.size(), C(0, 0));
  for(halfedge_descriptor h : halfedges(A))
    if(!is_border(h, A))
      corners[hidx(h)] = C(to_double(get(uvA, h).x()), to_double(get(uvA, h).y()));
  const auto uv_of = boost::make_function_property_map<halfedge_descriptor>(
    [&corners, &hidx](halfedge_descriptor h) { return UV_point(corners[hidx(h)].real(), corners[hidx(h)].imag()); });
  // the certificate of the current corners
  const auto certified = [&](std::string& why) {
    const auto t0 = std::chrono::steady_clock::now();
    struct Clock_in { Map_refinement_statistics& st; std::chrono::steady_clock::time_point t;
      ~Clock_in() { st.seconds_certificate += std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count(); } } clock_in{stats, t0};
    Embedding_certificate cert;
    const Error_code ec = certify_hyperbolic_orbifold_embedding(A, landmarks, uv_of, cert, &why, np);
    if(ec != OK)
      return ec;
    if(!cert.is_bijective()) {
      std::ostringstream os;
      os << cert;
      why = os.str();
      return ERROR_NO_1_TO_1_MAPPING;
    }
    return OK;
  };
  {
    std::string why;
    const Error_code ec = certified(why);
    if(ec != OK) {
      stats.message = "the embedding to refine is not certified: " + why;
      return ec;
    }
  }
  std::vector<char> fixed(vidx.size(), 0);
  for(vertex_descriptor v : landmarks)
    fixed[vidx(v)] = 1;
  const internal::Corner_moves<TriangleMeshA> moves(A, vidx, hidx, corners, fixed);
  internal::Arap_source src;
  for(auto f : faces(A)) {
    std::array<std::size_t, 3> c;
    std::array<Eigen::Vector3d, 3> p;
    int k = 0;
    for(vertex_descriptor v : vertices_around_face(halfedge(f, A), A)) {
      const auto& pt = get(vpmA, v);
      c[k] = vidx(v);
      p[k++] = Eigen::Vector3d(to_double(pt.x()), to_double(pt.y()), to_double(pt.z()));
    }
    src.add_face(c, p);
  }
  double area_B = 0;
  for(auto f : faces(B)) {
    const auto h = halfedge(f, B);
    area_B += std::sqrt(to_double(squared_area(get(vpmB, source(h, B)), get(vpmB, target(h, B)), get(vpmB, target(next(h, B), B)))));
  }
  const double s = std::sqrt(area_B / src.total_area);
  // the images of the vertices (their primary corners located on B)
  std::vector<typename Locator::Location> locs;
  std::vector<Eigen::Vector3d> q(vidx.size(), Eigen::Vector3d::Zero());
  // the images of the vertices whose primary corner moved (all of them the first time), each
  // located by a walk from its previous location
  std::vector<C> located(vidx.size(), C(2, 2)); // (2: never located)
  const auto locate = [&]() {
    if(locs.empty())
      locs.resize(vidx.size());
    std::atomic<bool> ok(true);
    const auto run = [&](std::size_t i) {
      const halfedge_descriptor h = moves.primary(i);
      if(h == GT::null_halfedge() || corners[hidx(h)] == located[i])
        return;
      const typename Locator::Point_2 z(corners[hidx(h)].real(), corners[hidx(h)].imag());
      locs[i] = located[i] == C(2, 2) ? locB.locate(z) : locB.locate_near(z, locs[i]);
      located[i] = corners[hidx(h)];
      if(!locs[i].success) {
        ok = false;
        return;
      }
      const auto p = surface_point(locs[i], locB, vpmB);
      q[i] = Eigen::Vector3d(to_double(p.x()), to_double(p.y()), to_double(p.z()));
    };
#ifdef CGAL_LINKED_WITH_TBB
    if(vidx.size() > 10000) {
      tbb::parallel_for(tbb::blocked_range<std::size_t>(0, vidx.size(), 1024), [&](const tbb::blocked_range<std::size_t>& r) {
        for(std::size_t i = r.begin(); i != r.end(); ++i)
          run(i);
      });
      return ok.load();
    }
#endif
    for(std::size_t i = 0; i < vidx.size(); ++i)
      run(i);
    return ok.load();
  };
  if(!locate()) {
    stats.message = "a vertex of the source could not be located on the target";
    return ERROR_POINT_NOT_LOCATED;
  }
  stats.energy_before = stats.energy_after = src.symmetric_dirichlet(q, s);
  for(char f : fixed)
    stats.free_vertices += f ? 0 : 1;
  const Sign sign = faces(A).empty() ? POSITIVE : moves.orientation(*faces(A).begin(), corners);
  internal::Arap_global_step step(src, fixed);
  stats.stop = iterations == 0 ? Refinement_not_run : Refinement_iterations;
  // the tangent bases at the images: the previous one projected onto the plane of the image's
  // face (a basis that turns little from one step to the next keeps the global steps' matrices
  // close, and the earlier factor a good preconditioner)
  std::vector<Eigen::Matrix<double, 3, 2> > T(vidx.size(), Eigen::Matrix<double, 3, 2>::Zero());
  for(int it = 0; it < iterations; ++it) {
    for(std::size_t i = 0; i < vidx.size(); ++i)
      if(!fixed[i])
        T[i] = internal::tangent_basis(locs[i], locB, vpmB, T[i].col(0));
    // The step, then a line search along it: halved until the energy decreases and the
    // iterate is certified (the moves that would turn a face over undone). When no step
    // lowers the energy, the step is solved again with the undone vertices held (the rest of
    // it is then a descent direction of the energy), and the last two rounds with the ARAP
    // proxy, whose weights do not blow up on nearly degenerate images.
    const std::vector<C> old = corners;
    const std::vector<typename Locator::Location> old_locs = locs;
    const std::vector<C> old_located = located;
    const std::vector<Eigen::Vector3d> old_q = q;
    std::vector<char> held(vidx.size(), 0);
    bool accepted = false, certificate_failed = false, solved = true;
    double e = stats.energy_after;
    std::size_t undone = 0;
    for(int round = 0; round < 4 && !accepted; ++round) {
      std::vector<Eigen::Vector2d> d;
      if(!step.solve(q, T, s, held, d, round < 2)) {
        solved = false; // (a round with the ARAP proxy may still solve)
        continue;
      }
      solved = true;
      std::vector<C> from(vidx.size()), to(vidx.size());
      std::vector<double> alpha(vidx.size(), 0.0);
      for(std::size_t i = 0; i < vidx.size(); ++i)
        if(!fixed[i] && !held[i]) {
          from[i] = corners[hidx(moves.primary(i))];
          alpha[i] = internal::refinement_move(locs[i], locB, vpmB, q[i], T[i] * d[i], to[i]) ? 1.0 : 0.0;
        }
      std::vector<char> undone_flag(vidx.size(), 0);
      for(int attempt = 0; attempt < 8 && !accepted; ++attempt) {
        corners = old;
        std::vector<double> a = alpha;
        for(double& x : a)
          x = std::ldexp(x, -attempt);
        undone = moves.move(from, to, a, old, corners, sign, undone_flag);
        e = locate() ? src.symmetric_dirichlet(q, s) : std::numeric_limits<double>::infinity();
        if(!(e < stats.energy_after))
          continue;
        std::string why;
        if(certified(why) == OK)
          accepted = true;
        else {
          certificate_failed = true;
          stats.message = why;
        }
      }
      for(std::size_t i = 0; i < held.size(); ++i)
        held[i] = held[i] || undone_flag[i];
    }
    if(!accepted) {
      corners = old;
      locs = old_locs;
      located = old_located;
      q = old_q;
      stats.stop = !solved ? Refinement_solver : certificate_failed ? Refinement_certificate : Refinement_converged;
      break;
    }
    const bool small = e > stats.energy_after * (1 - 1e-6);
    stats.energy_after = e;
    stats.undone_moves = undone;
    ++stats.iterations;
    if(small) {
      stats.stop = Refinement_converged;
      break;
    }
  }
  for(halfedge_descriptor h : halfedges(A))
    if(!is_border(h, A))
      put(uvA, h, UV_point(corners[hidx(h)].real(), corners[hidx(h)].imag()));
  switch(stats.stop) {
  case Refinement_not_run: stats.message = "not refined (0 iterations asked)"; break;
  case Refinement_iterations: stats.message = "ran the " + std::to_string(iterations) + " iterations asked"; break;
  case Refinement_converged: stats.message = "converged: the energy no longer decreases by a relative 1e-6"; break;
  case Refinement_certificate:
    stats.message = "stopped at the last certified iterate: the next one failed the certificate (" + stats.message + ")";
    break;
  case Refinement_solver: stats.message = "stopped at the last iterate: the global step's linear system could not be solved"; break;
  }
  stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return OK;
}

} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_REFINE_ORBIFOLD_MAP_H
