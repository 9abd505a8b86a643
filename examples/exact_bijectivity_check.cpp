// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// An independent, exact re-check of a result: every face of the embedding is positively
// oriented in the hyperbolic plane, evaluated with an exact kernel (Epeck) on the double
// coordinates written by the embedding, and the package's certificate is recomputed from
// the per-corner map alone.
//   exact_bijectivity_check [mesh.off] [k]

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/hyperbolic_orbifold_Tutte.h>

#include <cstdlib>
#include <iostream>

namespace HOT = CGAL::Hyperbolic_orbifold_Tutte;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Exact_predicates_exact_constructions_kernel EK;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef boost::graph_traits<Mesh>::halfedge_descriptor halfedge_descriptor;

int main(int argc, char** argv)
{
  const char* path = argc > 1 ? argv[1] : "data/meshes/triceratops.off";
  const std::size_t k = argc > 2 ? std::strtoul(argv[2], nullptr, 10) : 8;
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(path, mesh)) {
    std::cerr << "cannot read " << path << std::endl;
    return EXIT_FAILURE;
  }
  const auto landmarks = HOT::select_landmarks(mesh, k);
  auto uv = mesh.add_property_map<halfedge_descriptor, K::Point_2>("h:uv").first;
  HOT::Embedding_statistics stats;
  if(HOT::hyperbolic_orbifold_Tutte_embedding(mesh, landmarks, uv,
       HOT::parameters::landmark_order(HOT::Tsp_order, HOT::parameters::embedding_statistics(&stats))) != HOT::OK) {
    std::cerr << stats.message << std::endl;
    return EXIT_FAILURE;
  }
  // 1. orientation of every face, in exact arithmetic (Epeck's lazy exact numbers)
  HOT::Poincare_disk_traits_2<EK> exact;
  std::size_t positive = 0, other = 0;
  for(auto f : faces(mesh)) {
    std::vector<EK::Point_2> p;
    for(halfedge_descriptor h : halfedges_around_face(halfedge(f, mesh), mesh))
      p.push_back(EK::Point_2(get(uv, h).x(), get(uv, h).y())); // doubles convert exactly
    (exact.hyperbolic_orientation_2_object()(p[0], p[1], p[2]) == CGAL::POSITIVE ? positive : other)++;
  }
  // 2. the certificate, recomputed from the corner map (cut recovered from the map itself)
  std::vector<Mesh::Vertex_index> ordered;
  for(std::size_t i : stats.landmark_order) ordered.push_back(landmarks[i]);
  HOT::Embedding_certificate certificate;
  std::string message;
  const HOT::Error_code ec = HOT::certify_hyperbolic_orbifold_embedding(mesh, ordered, uv, certificate, &message);
  std::cout << positive << " faces positively oriented and " << other << " not (exact); re-certified: " << certificate
            << std::endl;
  return (other == 0 && ec == HOT::OK && certificate.is_bijective()) ? EXIT_SUCCESS : EXIT_FAILURE;
}
