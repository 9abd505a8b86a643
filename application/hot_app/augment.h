// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef HOT_APP_AUGMENT_H
#define HOT_APP_AUGMENT_H

// `map --augment` and Python's map_meshes(augment=True): the thin tips the landmarks leave out,
// matched across the two meshes (HOT::match_extremities()), appended to both meshes' landmarks.

#include "hot_app/job_input.h"

#include <CGAL/Hyperbolic_orbifold_Tutte/match_extremities.h>

#include <string>
#include <vector>

namespace hot_cli {

// Appends the matched pairs to `la` (on A) and `lb` (on B), and an order 2 per pair to `orders`
// when cone orders are given; returns the matching. Meshes that are not closed of genus 0, or a
// refusal of match_extremities(), fail (`who`, the option's name, begins the message).
inline HOT::Extremity_matching<SM_vertex> augment_landmarks(HOT::Orbifold_type type, long long genus_a, long long genus_b,
                                                            const Surface_mesh& A, std::vector<SM_vertex>& la,
                                                            const Surface_mesh& B, std::vector<SM_vertex>& lb,
                                                            std::vector<int>& orders, const std::string& who)
{
  if(type != HOT::Sphere_type || genus_a != 0 || genus_b != 0)
    throw Failure{HOT::ERROR_WRONG_PARAMETER, who + " adds landmarks inside closed meshes of genus 0 (sphere type); these meshes are not"};
  HOT::Extremity_matching<SM_vertex> xm;
  const HOT::Error_code ec = HOT::match_extremities(A, la, B, lb, xm);
  if(ec != HOT::OK)
    throw Failure{ec, who + ": " + xm.message};
  for(const std::pair<SM_vertex, SM_vertex>& p : xm.pairs) {
    la.push_back(p.first);
    lb.push_back(p.second);
    if(!orders.empty())
      orders.push_back(2);
  }
  return xm;
}

} // namespace hot_cli

#endif // HOT_APP_AUGMENT_H
