// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The fixed-boundary hyperbolic Tutte embedding (the paper's Theorem 1): a disk mesh onto a
// regular hyperbolic hexagon with right angles; six boundary vertices go to its corners,
// the other boundary vertices onto its sides, and the embedding is certified bijective.
//   fixed_boundary_hyperbolic_Tutte [disk.off]

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/hyperbolic_orbifold_Tutte.h>

#include <cmath>
#include <complex>
#include <cstdlib>
#include <iostream>
#include <vector>

namespace HOT = CGAL::Hyperbolic_orbifold_Tutte;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;

int main(int argc, char** argv)
{
  const char* path = argc > 1 ? argv[1] : "data/meshes/mushroom.off";
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(path, mesh)) {
    std::cerr << "cannot read " << path << std::endl;
    return EXIT_FAILURE;
  }
  // The regular hexagon with interior angles alpha, centred at the origin: split into six
  // isosceles triangles (apex angle 2 pi / 6, base angles alpha / 2), its corners are at
  // hyperbolic distance l from the origin, cosh(l) = cot(pi / 6) cot(alpha / 2), that is at
  // Euclidean radius tanh(l / 2) in the Poincare disk.
  const int n = 6;
  const double alpha = CGAL_PI / 2;
  const double l = std::acosh(1 / (std::tan(CGAL_PI / n) * std::tan(alpha / 2)));
  std::vector<K::Point_2> hexagon;
  for(int j = 0; j < n; ++j) {
    const std::complex<double> p = std::polar(std::tanh(l / 2), 2 * CGAL_PI * j / n);
    hexagon.push_back(K::Point_2(p.real(), p.imag()));
  }
  // six boundary vertices spread by arc length, in boundary order (in the direction of the
  // mesh's border halfedges: clockwise around the mesh, so the map onto the counterclockwise
  // hexagon reverses orientation, which the statistics report; either way it is a bijection)
  const auto corners = HOT::select_landmarks(mesh, n);

  auto uv = mesh.add_property_map<Mesh::Vertex_index, K::Point_2>("v:uv").first;
  HOT::Embedding_statistics stats;
  const HOT::Error_code ec =
    HOT::fixed_boundary_hyperbolic_Tutte_embedding(mesh, corners, hexagon, uv, HOT::parameters::embedding_statistics(&stats));
  if(ec != HOT::OK) {
    std::cerr << HOT::error_message(ec) << ": " << stats.message << std::endl;
    return EXIT_FAILURE;
  }
  // Gauss-Bonnet: a hexagon with six angles alpha has area 4 pi - 6 alpha (pi here)
  std::cout << num_vertices(mesh) << " vertices onto the regular right-angled hexagon in " << stats.iterations
            << " Newton iterations; area " << stats.certificate.total_area << " (expected " << 4 * CGAL_PI - n * alpha
            << ")" << (stats.orientation_reversed ? ", orientation reversed" : "") << std::endl;
  std::cout << "certified: " << (stats.certificate.is_bijective() ? "yes" : "no") << " -- " << stats.certificate << std::endl;
  return stats.certificate.is_bijective() ? EXIT_SUCCESS : EXIT_FAILURE;
}
