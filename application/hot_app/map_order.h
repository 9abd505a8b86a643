// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef HOT_APP_MAP_ORDER_H
#define HOT_APP_MAP_ORDER_H

// The landmark order of a map between two meshes: the orders to try, best first, and the
// embeddings of the two meshes in the first order both accept. The one choice of the command
// line's `map` (tools/jobs/map.h) and the Python module's map_meshes() (python/src/embedding.cpp):
// the same orders in the same turn, the same refusals, the same messages.
// (A collection ranks the tours of all its meshes: Orbifold_collection, and collection_order()
// of collection_job.h for its separate jobs.)

#include <CGAL/Hyperbolic_orbifold_Tutte/landmark_tour.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/Orbifold_tile.h> // Orbifold_type

#include "hot_app/job_support.h"

#include <cstddef>
#include <string>
#include <vector>

namespace hot_cli {

// The cone orders a map tries in turn, best first, each with the mesh whose tour it is (0 the
// source, 1 the target, npos the given order). `how`: "auto", "tsp" or "given". Sphere type of
// genus 0: with "auto" the source's and the target's tours ranked by HOT::rank_landmark_tours()
// (the longest, over the two meshes, of the cut's length in that order over the mesh's own
// tour's; the source's on ties), with "tsp" the source's tour alone, with "given" the given
// order alone. Disk type keeps the given order, genus g >= 1 takes any (the given one). `type`
// and `genus` are the source's (the target's are the same: checked before). Throws a Failure
// when a tour cannot be computed.
template <class Mesh, class Vertex>
std::vector<HOT::Landmark_order_candidate> map_landmark_orders(const std::string& how, HOT::Orbifold_type type, long long genus,
                                                               const Mesh& A, const std::vector<Vertex>& la, const Mesh& B,
                                                               const std::vector<Vertex>& lb)
{
  HOT::Landmark_order_candidate given;
  for(std::size_t i = 0; i < la.size(); ++i) given.order.push_back(i);
  given.mesh = std::size_t(-1);
  given.longest_ratio = 1;
  if(type != HOT::Sphere_type || genus != 0 || how == "given")
    return {given};
  std::vector<std::vector<std::vector<double> > > D(1, HOT::compute_landmark_distances(A, la, get(CGAL::vertex_point, A)));
  if(how != "tsp")
    D.push_back(HOT::compute_landmark_distances(B, lb, get(CGAL::vertex_point, B)));
  const std::vector<HOT::Landmark_order_candidate> r = HOT::rank_landmark_tours(D);
  if(r.empty())
    throw Failure{HOT::ERROR_CUT_FAILED, "the landmark tour could not be computed on the " + std::string(
                                           HOT::internal::is_finite_distance_matrix(D[0]) ? "target" : "source")};
  return r;
}

// "the source's tour", "the target's tour" or "the given order"
inline std::string order_origin(const HOT::Landmark_order_candidate& c)
{
  return c.mesh == 0 ? "the source's tour" : c.mesh == 1 ? "the target's tour" : "the given order";
}

// Embeds the source and the target of a map in the first order of `candidates` both accept:
// `embed_pair(candidate, target_first)` embeds both (with a choice, the mesh whose tour it is not
// first: the more likely to refuse it) and throws an `Error` (a `code`) when one refuses;
// `reason(error)` says which and why ("source: ..."). An order refused for a reason the order
// may cause (HOT::is_landmark_order_failure()) passes to the next one (`refusals` gets one line
// per order refused); any other failure, or the refusal of the only order, is rethrown. Returns
// the index of the order used, or npos when every order was refused: then `code` and `message`
// say which orders were tried and why each failed.
template <class Error, class EmbedPair, class Reason>
std::size_t embed_in_first_accepted_order(const std::vector<HOT::Landmark_order_candidate>& candidates, EmbedPair embed_pair,
                                          Reason reason, std::vector<std::string>& refusals, HOT::Error_code& code,
                                          std::string& message)
{
  for(std::size_t c = 0; c < candidates.size(); ++c) {
    try {
      embed_pair(candidates[c], candidates.size() > 1 && candidates[c].mesh == 0);
      return c;
    } catch(const Error& f) {
      if(candidates.size() == 1 || !HOT::is_landmark_order_failure(f.code))
        throw;
      std::string list;
      for(std::size_t i : candidates[c].order) list += (list.empty() ? "" : " ") + std::to_string(i);
      refusals.push_back(order_origin(candidates[c]) + " (" + list + ") was refused by the " + reason(f));
      if(c + 1 == candidates.size()) {
        std::string why;
        for(const std::string& r : refusals) why += (why.empty() ? "" : "; ") + r;
        code = f.code;
        message = "no landmark order works for both meshes (" + std::to_string(candidates.size()) + " tried): " + why;
      }
    }
  }
  return std::size_t(-1);
}

} // namespace hot_cli

#endif // HOT_APP_MAP_ORDER_H
