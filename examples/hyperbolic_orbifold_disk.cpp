// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A disk-type embedding: a mesh with one boundary loop, k landmarks on the boundary (in
// boundary order, either orientation) become the right-angled corners of a hyperbolic
// k-gon, the other boundary vertices slide along its sides.
//   hyperbolic_orbifold_disk [disk.off] [k]

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/hyperbolic_orbifold_Tutte.h>

#include <cmath>
#include <cstdlib>
#include <iostream>

namespace HOT = CGAL::Hyperbolic_orbifold_Tutte;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;

int main(int argc, char** argv)
{
  const char* path = argc > 1 ? argv[1] : "data/meshes/mushroom.off";
  const std::size_t k = argc > 2 ? std::strtoul(argv[2], nullptr, 10) : 6;
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(path, mesh)) {
    std::cerr << "cannot read " << path << std::endl;
    return EXIT_FAILURE;
  }
  // boundary vertices spread by arc length (select_landmarks does this for meshes with a border)
  const auto corners = HOT::select_landmarks(mesh, k);
  auto uv = mesh.add_property_map<Mesh::Halfedge_index, K::Point_2>("h:uv").first;
  HOT::Embedding_statistics stats;
  const HOT::Error_code ec = HOT::hyperbolic_orbifold_Tutte_embedding(
    mesh, corners, uv,
    HOT::parameters::orbifold_type(HOT::Disk_type, HOT::parameters::weight_type(HOT::Mean_value,
                                   HOT::parameters::embedding_statistics(&stats))));
  if(ec != HOT::OK) {
    std::cerr << HOT::error_message(ec) << ": " << stats.message << std::endl;
    return EXIT_FAILURE;
  }
  // Gauss-Bonnet: a disk with k corners of angle pi/2 and geodesic sides has hyperbolic area
  // (k - 4) pi/2; the triangles' areas add up to it to rounding (1e-6 k: the test suite's bound)
  const double expected = (k - 4) * CGAL_PI / 2;
  std::cout << "disk-type embedding, " << k << " corners of angle pi/2, area " << stats.certificate.total_area
            << " (expected (k-4) pi/2 = " << expected << "); " << stats.certificate << std::endl;
  if(std::abs(stats.certificate.total_area - expected) > 1e-6 * k) {
    std::cerr << "the area is not (k - 4) pi/2" << std::endl;
    return EXIT_FAILURE;
  }
  return stats.certificate.is_bijective() ? EXIT_SUCCESS : EXIT_FAILURE;
}
