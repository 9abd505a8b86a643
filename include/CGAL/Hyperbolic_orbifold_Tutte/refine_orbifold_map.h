// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_REFINE_ORBIFOLD_MAP_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_REFINE_ORBIFOLD_MAP_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Hyperbolic_orbifold_Tutte/genus.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/Map_refinement_statistics.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/certify_hyperbolic_orbifold_embedding.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/error_code.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/parameters.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/input/genus_cut.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/refinement/map_refiner.h>

#include <CGAL/boost/graph/named_params_helper.h>

#include <boost/property_map/function_property_map.hpp>

#include <chrono>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

/// \file refine_orbifold_map.h

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {

/*!
\ingroup PkgHyperbolicOrbifoldTutteHelperFunctions

whether `refine_orbifold_map()` can refine a map whose source is `A`, answered from the mesh
alone, so that a caller can ask before embedding: `OK`, or `ERROR_WRONG_PARAMETER` with the
reason when `A` is closed of genus 1 or more (the refinement moves corners in one disk
around the landmarks' orbifold). `refine_orbifold_map()` asks it first, then checks the
embedding itself (given without charts, certified).
\tparam TriangleMesh a model of `FaceGraph`
*/
template <class TriangleMesh>
Status check_refinable_source(const TriangleMesh& A)
{
  const long long genus = is_closed(A) ? closed_mesh_genus(A) : 0;
  if(genus > 0)
    return Status::failure(ERROR_WRONG_PARAMETER, "refine_orbifold_map() handles surfaces of genus 0; the source has genus " +
                                                    std::to_string(genus));
  return Status();
}

/*!
\ingroup PkgHyperbolicOrbifoldTutteHelperFunctions

refines the map \f$f_{AB}\f$ from `A` onto `B` through their common orbifold (the map of
`map_vertices()`) towards an isometry: moves `A`'s embedding `uvA` so that the map lowers its
as-rigid-as-possible (ARAP) energy
\f$ \sum_f |f| \, \| J_f - s R_f \|_F^2 / (s^2 |A|) \f$, with \f$J_f\f$ the Jacobian of the
map on face \f$f\f$ of `A` (its vertices' images on `B`, linear in between), \f$R_f\f$ the
closest rotation and \f$s^2\f$ the ratio of `B`'s area to `A`'s (0 for an isometry up to that
scale). Each iteration is a local-global step with the images moving in `B`'s tangent planes
(plus 0.8 times their last accepted moves, a heavy-ball momentum, except on faces squeezed
beyond the tempering cap below), turned into moves of `A`'s corners in the disk (each moved image
taken there by the chart of the face of `B` that holds it); copies of a vertex across the seams move by
the orbifold's side pairings, landmarks and border vertices stay, a move that would turn a
face of `A` over is undone (with its face's other moves), the step (in `B`'s tangent planes) is halved until the
iterate lowers the symmetric Dirichlet energy \f$ \sum_f |f| (\sigma_1^2 + \sigma_2^2 +
\sigma_1^{-2} + \sigma_2^{-2}) / |A| \f$ (singular values of \f$J_f / s\f$; 4 for an isometry
up to the scale \f$s\f$, infinite for a degenerate image), tempered: a face's density
\f$d > 100\f$ (a face squeezed about 10 times or more) counts as \f$100 (1 + \log(d / 100))\f$,
so that a few faces the target's embedding squeezes beyond what `double` resolves (a protrusion
without a landmark) neither dominate the sum nor stiffen the step, and still resist collapse
(`stats.tempered_energy_before`, `stats.tempered_energy_after`; the untempered energy, in
`stats.energy_before` and `stats.energy_after`, can rise where such faces dominate it); and the iterate is accepted only if
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
       `vertex_point_map` for `A` (`B`'s points are read with `get(vertex_point, B)`), and
       `progress` (a callable `void(const char* phase, double fraction)`, stored as a
       `std::function`): told, from the calling thread, the phase `"refinement"` with the
       fraction of the largest number of iterations done, 0 once the iterate is certified and
       the images located, then after every iteration, and 1 when the refinement ends (early
       when it converges or stops; not told when it refuses)

\return `OK` (read `stats.stop`), `ERROR_WRONG_PARAMETER` if `A` has genus 1 or more (`check_refinable_source()`) or its
embedding is given in charts (`chart_map`: refused), `ERROR_NO_1_TO_1_MAPPING` if `uvA` itself is not certified,
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
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const auto start = std::chrono::steady_clock::now();
  stats = Map_refinement_statistics();
  const int iterations = choose_parameter(get_parameter(np, internal_np::refine), 100);
  if(iterations < 0) {
    stats.message = "the number of refinement iterations must be at least 0";
    return ERROR_WRONG_PARAMETER;
  }
  typedef internal::Map_refiner<TriangleMeshA, HalfedgeUVMapA, TriangleMeshB, Locator> Refiner;
  internal::Corner_map_certifier<TriangleMeshA, NamedParameters> certifier(A, landmarks, np); // (the iterates keep the cut)
  const typename Refiner::Certify certify = [&](const typename Refiner::Corner_reader& corners, std::string& why) {
    Embedding_certificate cert;
    const Error_code ec = certifier(boost::make_function_property_map<
      typename boost::graph_traits<TriangleMeshA>::halfedge_descriptor>(corners), cert, why);
    if(ec == OK && !cert.is_bijective()) {
      std::ostringstream os;
      os << cert;
      why = os.str();
      return ERROR_NO_1_TO_1_MAPPING;
    }
    return ec;
  };
  if constexpr(!CGAL::parameters::is_default_parameter<NamedParameters, internal_np::chart_map_t>::value) {
    stats.message = "refine_orbifold_map() handles embeddings without charts around cone images";
    return ERROR_WRONG_PARAMETER;
  }
  if(const Status refusal = check_refinable_source(A); !refusal) {
    stats.message = refusal.message;
    return refusal.code;
  }
  Refiner refiner(A, landmarks, uvA, B, locB, stats, certify);
  const Error_code ec = refiner.prepare(choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point), get_const_property_map(vertex_point, A)));
  if(ec != OK)
    return ec;
  std::function<void(const char*, double)> progress; // (empty: no report)
  if constexpr(!CGAL::parameters::is_default_parameter<NamedParameters, internal_np::progress_t>::value)
    progress = get_parameter(np, internal_np::progress);
  const auto tell = [&progress](double fraction) {
    if(progress)
      progress("refinement", fraction);
  };
  tell(0.0);
  stats.stop = iterations == 0 ? Refinement_not_run : Refinement_iterations;
  for(int it = 0; it < iterations && refiner.iterate(); ++it)
    tell(static_cast<double>(it + 1) / iterations);
  refiner.write(uvA);
  tell(1.0);
  switch(stats.stop) {
  case Refinement_not_run: stats.message = "not refined (0 iterations asked)"; break;
  case Refinement_iterations: stats.message = "ran the " + std::to_string(iterations) + " iterations asked"; break;
  case Refinement_converged: stats.message = "converged: the energy no longer decreases (by a relative 1e-6 over five iterations, or at all)"; break;
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
