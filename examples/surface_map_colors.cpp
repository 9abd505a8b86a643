// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A map between two surfaces with colour transfer: a mesh A and a smoothly deformed copy B
// are embedded into one orbifold with the same landmarks; a colour field on A (stripes of
// its height) is transferred to B through the map, and both are drawn into an SVG picture
// (a small orthographic renderer: painter's algorithm with Lambert shading).
//   surface_map_colors [mesh.off] [picture.svg]

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>

#include <CGAL/hyperbolic_orbifold_Tutte.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>

namespace HOT = CGAL::Hyperbolic_orbifold_Tutte;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef Mesh::Vertex_index vertex_descriptor;
typedef Mesh::Halfedge_index halfedge_descriptor;
typedef Mesh::Property_map<halfedge_descriptor, K::Point_2> UV_map;

// draws `m` with per-vertex colours into the square [x0, x0 + size] of the SVG
static void draw(std::ostream& os, const Mesh& m, const std::vector<K::Vector_3>& colour, double x0, double size)
{
  const CGAL::Bbox_3 bb = CGAL::Polygon_mesh_processing::bbox(m);
  const double scale = 0.9 * size / std::max(bb.xmax() - bb.xmin(), bb.ymax() - bb.ymin());
  const double cx = (bb.xmin() + bb.xmax()) / 2, cy = (bb.ymin() + bb.ymax()) / 2;
  std::vector<std::pair<double, Mesh::Face_index> > order;
  for(auto f : faces(m)) {
    double z = 0;
    for(auto v : vertices_around_face(halfedge(f, m), m)) z += m.point(v).z();
    order.push_back(std::make_pair(z, f));
  }
  std::sort(order.begin(), order.end()); // far faces first (view along -z)
  const K::Vector_3 light(0.3, 0.4, 1.0);
  for(const auto& of : order) {
    std::vector<vertex_descriptor> vs;
    for(auto v : vertices_around_face(halfedge(of.second, m), m)) vs.push_back(v);
    K::Vector_3 n = CGAL::cross_product(m.point(vs[1]) - m.point(vs[0]), m.point(vs[2]) - m.point(vs[0]));
    const double len = std::sqrt(n.squared_length());
    const double shade = len > 0 ? 0.35 + 0.65 * std::abs(n * light) / (len * std::sqrt(light.squared_length())) : 0.5;
    const K::Vector_3 c = (colour[vs[0]] + colour[vs[1]] + colour[vs[2]]) / 3.0;
    char rgb[16];
    std::snprintf(rgb, sizeof(rgb), "#%02x%02x%02x", int(255 * std::min(1.0, shade * c.x())),
                  int(255 * std::min(1.0, shade * c.y())), int(255 * std::min(1.0, shade * c.z())));
    os << "<polygon fill=\"" << rgb << "\" stroke=\"" << rgb << "\" stroke-width=\"0.3\" points=\"";
    for(auto v : vs)
      os << x0 + size / 2 + scale * (m.point(v).x() - cx) << "," << size / 2 - scale * (m.point(v).y() - cy) << " ";
    os << "\"/>\n";
  }
}

int main(int argc, char** argv)
{
  const char* path = argc > 1 ? argv[1] : "data/meshes/hand.off";
  const char* picture = argc > 2 ? argv[2] : "surface_map_colors.svg";
  Mesh A;
  if(!CGAL::IO::read_polygon_mesh(path, A)) {
    std::cerr << "cannot read " << path << std::endl;
    return EXIT_FAILURE;
  }
  // B: a smooth deformation of A (a bend), same triangulation and landmarks
  Mesh B = A;
  const CGAL::Bbox_3 bb = CGAL::Polygon_mesh_processing::bbox(A);
  const double h = bb.ymax() - bb.ymin();
  for(vertex_descriptor v : vertices(B)) {
    const K::Point_3 p = B.point(v);
    const double t = (p.y() - bb.ymin()) / h;
    B.point(v) = K::Point_3(p.x() + 0.35 * h * t * t, p.y(), p.z());
  }
  std::vector<vertex_descriptor> landmarks = HOT::select_landmarks(A, 9);
  // one cone order for both meshes: the tour on A. The results (Orbifold_embedding) hold the
  // corner coordinates with what is needed to read them (the orbifold, the landmark order, ...)
  HOT::Orbifold_embedding<Mesh, UV_map> embA(A, A.add_property_map<halfedge_descriptor, K::Point_2>("h:uv").first);
  HOT::Orbifold_embedding<Mesh, UV_map> embB(B, B.add_property_map<halfedge_descriptor, K::Point_2>("h:uv").first);
  HOT::Embedding_statistics sa, sb;
  if(HOT::hyperbolic_orbifold_Tutte_embedding(A, landmarks, embA,
       HOT::parameters::landmark_order(HOT::Tsp_order, HOT::parameters::embedding_statistics(&sa))) != HOT::OK) {
    std::cerr << sa.message << std::endl;
    return EXIT_FAILURE;
  }
  if(HOT::hyperbolic_orbifold_Tutte_embedding(B, embA.ordered_landmarks(), embB, HOT::parameters::embedding_statistics(&sb)) != HOT::OK) {
    std::cerr << sb.message << std::endl;
    return EXIT_FAILURE;
  }
  // colours of A: stripes of the height, plus a gradient
  auto colourA = A.add_property_map<vertex_descriptor, K::Vector_3>("v:colour").first;
  for(vertex_descriptor v : vertices(A)) {
    const double t = (A.point(v).y() - bb.ymin()) / h;
    const double s = 0.5 + 0.5 * std::sin(40 * t);
    put(colourA, v, K::Vector_3(0.2 + 0.8 * s, 0.3 + 0.5 * t, 1.0 - 0.8 * s));
  }
  // B's vertices located on A's embedding; A's colours interpolated there
  const HOT::Embedding_locator<Mesh, UV_map> locA(embA);
  const auto f = HOT::map_vertices(embB, locA);
  auto colourB = B.add_property_map<vertex_descriptor, K::Vector_3>("v:colour").first;
  const std::size_t written = HOT::transfer_vertex_property(B, f, locA, colourA, colourB);
  // the map's accuracy: B is A bent, so a vertex should land near itself. Two bounds known
  // without the code: the landmarks land on the landmarks (the orbifold's cones; to rounding),
  // and no vertex lands further from itself than the bend moves any vertex (0.35 of the
  // height, at the top), which the identity map would do if the map were no better than that
  double worst = 0, worst_landmark = 0;
  std::size_t i = 0;
  for(vertex_descriptor v : vertices(B)) {
    const K::Point_3 p = HOT::surface_point(f[i++], locA, get(CGAL::vertex_point, A));
    const double d = std::sqrt(CGAL::squared_distance(p, A.point(v))) / h;
    worst = std::max(worst, d);
    if(std::find(landmarks.begin(), landmarks.end(), v) != landmarks.end())
      worst_landmark = std::max(worst_landmark, d);
  }
  std::vector<K::Vector_3> ca, cb;
  for(vertex_descriptor v : vertices(A)) ca.push_back(get(colourA, v));
  for(vertex_descriptor v : vertices(B)) cb.push_back(get(colourB, v));
  std::ofstream svg(picture);
  svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"1000\" height=\"540\" viewBox=\"0 0 1000 540\">\n"
      << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  draw(svg, A, ca, 0, 500);
  draw(svg, B, cb, 500, 500);
  svg << "<text x=\"250\" y=\"525\" font-family=\"sans-serif\" font-size=\"16\" text-anchor=\"middle\">A: colour field</text>\n"
      << "<text x=\"750\" y=\"525\" font-family=\"sans-serif\" font-size=\"16\" text-anchor=\"middle\">B (bent A): colours carried by the map</text>\n</svg>\n";
  std::cout << written << " vertices of B coloured through the map; largest distance of a mapped vertex from its "
            << "original: " << worst << " of the height (landmarks: " << worst_landmark << "); wrote " << picture << std::endl;
  if(worst_landmark > 1e-9 || !(worst < 0.35)) {
    std::cerr << "the map is wrong: landmarks " << worst_landmark << " off (bound 1e-9), vertices " << worst
              << " off (bound: the bend's largest displacement, 0.35 of the height)" << std::endl;
    return EXIT_FAILURE;
  }
  return written == num_vertices(B) ? EXIT_SUCCESS : EXIT_FAILURE;
}
