// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The same one-call embedding on a CGAL::Polyhedron_3, with the corner map held in a
// std::unordered_map (Polyhedron_3 has no property maps of its own).
//   hyperbolic_orbifold_polyhedron [mesh.off] [k]

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/boost/graph/graph_traits_Polyhedron_3.h>

#include <CGAL/hyperbolic_orbifold_Tutte.h>

#include <boost/property_map/property_map.hpp>

#include <cstdlib>
#include <fstream>
#include <iostream>
#include <unordered_map>

namespace HOT = CGAL::Hyperbolic_orbifold_Tutte;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Polyhedron_3<K> Polyhedron;
typedef boost::graph_traits<Polyhedron>::halfedge_descriptor halfedge_descriptor;

int main(int argc, char** argv)
{
  const char* path = argc > 1 ? argv[1] : "data/meshes/hand.off";
  const std::size_t k = argc > 2 ? std::strtoul(argv[2], nullptr, 10) : 7;
  Polyhedron poly;
  std::ifstream in(path);
  if(!(in >> poly) || poly.empty()) {
    std::cerr << "cannot read " << path << std::endl;
    return EXIT_FAILURE;
  }
  std::unordered_map<halfedge_descriptor, K::Point_2> corners;
  HOT::Embedding_statistics stats;
  const HOT::Error_code ec = HOT::hyperbolic_orbifold_Tutte_embedding(
    poly, HOT::select_landmarks(poly, k), boost::make_assoc_property_map(corners),
    HOT::parameters::landmark_order(HOT::Tsp_order, HOT::parameters::embedding_statistics(&stats)));
  if(ec != HOT::OK) {
    std::cerr << HOT::error_message(ec) << ": " << stats.message << std::endl;
    return EXIT_FAILURE;
  }
  std::cout << corners.size() << " face corners embedded; " << stats.certificate << std::endl;
  return stats.certificate.is_bijective() ? EXIT_SUCCESS : EXIT_FAILURE;
}
