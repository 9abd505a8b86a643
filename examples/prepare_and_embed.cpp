// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A mesh as it comes (here pig.off: a closed shape with 7 holes, which check_mesh() refuses)
// is prepared for the embedding: its holes are filled, and the landmarks, given as vertex
// numbers of the file, are found in the prepared mesh through the preparation's addressing.
//   prepare_and_embed [mesh file] [k]

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/IO/polygon_soup_io.h>

#include <CGAL/hyperbolic_orbifold_Tutte.h>

#include <cstdlib>
#include <iostream>
#include <vector>

namespace HOT = CGAL::Hyperbolic_orbifold_Tutte;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef boost::graph_traits<Mesh>::vertex_descriptor vertex_descriptor;
typedef boost::graph_traits<Mesh>::halfedge_descriptor halfedge_descriptor;

int main(int argc, char** argv)
{
  const char* path = argc > 1 ? argv[1] : "data/meshes/pig.off";
  const std::size_t k = argc > 2 ? std::strtoul(argv[2], nullptr, 10) : 7;
  std::vector<K::Point_3> points;
  std::vector<std::vector<std::size_t> > polygons;
  if(!CGAL::IO::read_polygon_soup(path, points, polygons)) {
    std::cerr << "cannot read " << path << std::endl;
    return EXIT_FAILURE;
  }
  Mesh mesh;
  HOT::Mesh_preparation prep;
  const HOT::Status prepared = HOT::prepare_polygon_soup_for_embedding(points, polygons, mesh, prep);
  if(!prepared) {
    std::cerr << HOT::error_message(prepared.code) << ": " << prepared.message << std::endl;
    return EXIT_FAILURE;
  }
  std::cout << path << ": " << prep.summary() << std::endl;

  // A landmark file holds vertex numbers of the input file. Here they are picked on the
  // prepared mesh and said in the file's numbering (a vertex added inside a filled hole has a
  // number past the file's vertices: skipped), then read back as a landmark file is read.
  std::vector<std::size_t> file_vertices;
  for(vertex_descriptor v : HOT::select_landmarks(mesh, k + 3)) {
    const std::size_t i = prep.output_index[v.idx()];
    if(i < prep.number_of_input_vertices && file_vertices.size() < k)
      file_vertices.push_back(i);
  }
  const std::vector<vertex_descriptor> verts(vertices(mesh).begin(), vertices(mesh).end());
  std::vector<vertex_descriptor> landmarks;
  std::cout << "landmarks (file vertices):";
  for(std::size_t i : file_vertices) {
    std::cout << " " << i;
    landmarks.push_back(verts[prep.prepared_vertex[i]]); // npos only for a vertex on no face
  }
  std::cout << std::endl;

  auto uv = mesh.add_property_map<halfedge_descriptor, K::Point_2>("h:uv").first;
  HOT::Embedding_statistics stats;
  const HOT::Error_code ec = HOT::hyperbolic_orbifold_Tutte_embedding(
    mesh, landmarks, uv, HOT::parameters::orbifold_type(prep.type, HOT::parameters::embedding_statistics(&stats)));
  if(ec != HOT::OK) {
    std::cerr << HOT::error_message(ec) << ": " << stats.message << std::endl;
    return EXIT_FAILURE;
  }
  std::cout << num_vertices(mesh) << " vertices (" << prep.number_of_added_vertices() << " added) embedded; "
            << stats.certificate << std::endl;
  return stats.certificate.is_bijective() ? EXIT_SUCCESS : EXIT_FAILURE;
}
