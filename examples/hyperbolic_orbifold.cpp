// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The simplest call: embed a closed genus-0 mesh into the hyperbolic sphere-type
// orbifold whose cones are 7 well-spread landmarks, and check the certificate.
//   hyperbolic_orbifold [mesh.off] [k]

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/hyperbolic_orbifold_Tutte.h>

#include <cstdlib>
#include <fstream>
#include <iostream>

namespace HOT = CGAL::Hyperbolic_orbifold_Tutte;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef boost::graph_traits<Mesh>::halfedge_descriptor halfedge_descriptor;

int main(int argc, char** argv)
{
  const char* path = argc > 1 ? argv[1] : "data/meshes/bear.off";
  const std::size_t k = argc > 2 ? std::strtoul(argv[2], nullptr, 10) : 7;
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(path, mesh)) {
    std::cerr << "cannot read " << path << std::endl;
    return EXIT_FAILURE;
  }
  const auto landmarks = HOT::select_landmarks(mesh, k);

  // Poincare-disk coordinates of every face corner
  auto uv = mesh.add_property_map<halfedge_descriptor, K::Point_2>("h:uv").first;
  HOT::Embedding_statistics stats;
  const HOT::Error_code ec = HOT::hyperbolic_orbifold_Tutte_embedding(
    mesh, landmarks, uv, HOT::parameters::landmark_order(HOT::Tsp_order, HOT::parameters::embedding_statistics(&stats)));
  if(ec != HOT::OK) {
    std::cerr << HOT::error_message(ec) << ": " << stats.message << std::endl;
    return EXIT_FAILURE;
  }
  std::cout << num_vertices(mesh) << " vertices embedded in " << stats.iterations << " Newton iterations; "
            << stats.certificate << std::endl;
  return stats.certificate.is_bijective() ? EXIT_SUCCESS : EXIT_FAILURE;
}
