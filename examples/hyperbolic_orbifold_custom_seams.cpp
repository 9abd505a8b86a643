// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The expert path: the user builds the CGAL::Seam_mesh and its seams (here: shortest paths
// p1 -> p2 -> ... -> pk along mesh edges, avoiding each other), then calls the
// parameterizer class, which writes one Poincare point per seam-mesh vertex.
//   hyperbolic_orbifold_custom_seams [mesh.off] [k]

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/Seam_mesh.h>
#include <CGAL/boost/graph/Dual.h>

#include <CGAL/hyperbolic_orbifold_Tutte.h>

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <queue>
#include <set>

namespace HOT = CGAL::Hyperbolic_orbifold_Tutte;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> SM;
typedef boost::graph_traits<SM>::vertex_descriptor SM_vertex;
typedef boost::graph_traits<SM>::edge_descriptor SM_edge;
typedef boost::graph_traits<SM>::halfedge_descriptor SM_halfedge;
typedef SM::Property_map<SM_edge, bool> Seam_edge_map;
typedef SM::Property_map<SM_vertex, bool> Seam_vertex_map;
typedef CGAL::Seam_mesh<SM, Seam_edge_map, Seam_vertex_map> Mesh;

// shortest path (edge count, breadth first) from s to t avoiding the vertices in `blocked`
static std::vector<SM_vertex> path(const SM& sm, SM_vertex s, SM_vertex t, const std::set<SM_vertex>& blocked)
{
  std::map<SM_vertex, SM_vertex> parent;
  std::queue<SM_vertex> q;
  q.push(s);
  parent[s] = s;
  while(!q.empty()) {
    const SM_vertex v = q.front();
    q.pop();
    if(v == t) break;
    for(SM_vertex w : vertices_around_target(halfedge(v, sm), sm))
      if(!parent.count(w) && (w == t || !blocked.count(w))) {
        parent[w] = v;
        q.push(w);
      }
  }
  std::vector<SM_vertex> p;
  if(!parent.count(t)) return p;
  for(SM_vertex v = t; v != s; v = parent[v]) p.push_back(v);
  p.push_back(s);
  std::reverse(p.begin(), p.end());
  return p;
}

int main(int argc, char** argv)
{
  const char* path_name = argc > 1 ? argv[1] : "data/meshes/hand.off";
  const std::size_t k = argc > 2 ? std::strtoul(argv[2], nullptr, 10) : 6;
  SM sm;
  if(!CGAL::IO::read_polygon_mesh(path_name, sm)) {
    std::cerr << "cannot read " << path_name << std::endl;
    return EXIT_FAILURE;
  }
  const std::vector<SM_vertex> landmarks = HOT::select_landmarks(sm, k);

  // the seams: one simple path through the landmarks in the given order
  Seam_edge_map sem = sm.add_property_map<SM_edge, bool>("e:on_seam", false).first;
  Seam_vertex_map svm = sm.add_property_map<SM_vertex, bool>("v:on_seam", false).first;
  Mesh mesh(sm, sem, svm);
  std::set<SM_vertex> used(landmarks.begin(), landmarks.end());
  for(std::size_t i = 0; i + 1 < landmarks.size(); ++i) {
    std::set<SM_vertex> blocked = used;
    blocked.erase(landmarks[i]);
    const std::vector<SM_vertex> p = path(sm, landmarks[i], landmarks[i + 1], blocked);
    if(p.empty()) {
      std::cerr << "no free path between landmarks " << i << " and " << i + 1 << std::endl;
      return EXIT_FAILURE;
    }
    for(std::size_t j = 0; j + 1 < p.size(); ++j) {
      mesh.add_seam(p[j], p[j + 1]);
      used.insert(p[j]);
    }
  }
  // a border halfedge of the seam mesh
  boost::graph_traits<Mesh>::halfedge_descriptor bhd;
  for(auto h : halfedges(mesh))
    if(is_border(h, mesh)) { bhd = h; break; }

  auto uv = sm.add_property_map<SM_halfedge, K::Point_2>("h:uv").first; // one point per seam-mesh vertex
  HOT::Hyperbolic_orbifold_Tutte_parameterizer_3<Mesh> parameterizer(HOT::Sphere_type, HOT::Cotangent);
  HOT::Embedding_statistics stats;
  const HOT::Error_code ec = parameterizer.parameterize(mesh, bhd, landmarks, uv, &stats);
  if(ec != HOT::OK) {
    std::cerr << HOT::error_message(ec) << ": " << stats.message << std::endl;
    return EXIT_FAILURE;
  }
  std::cout << stats.number_of_vertices << " seam-mesh vertices, " << mesh.number_of_seam_edges() << " seam edges, "
            << stats.iterations << " Newton iterations; " << stats.certificate << std::endl;
  // Gauss-Bonnet: k cones of angle pi on a sphere give the hyperbolic area (k - 4) pi
  const double expected = (static_cast<double>(k) - 4) * CGAL_PI;
  if(std::abs(stats.certificate.total_area - expected) > 1e-6 * k) {
    std::cerr << "area " << stats.certificate.total_area << ", not (k - 4) pi = " << expected << std::endl;
    return EXIT_FAILURE;
  }
  return stats.certificate.is_bijective() ? EXIT_SUCCESS : EXIT_FAILURE;
}
