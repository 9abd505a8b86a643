// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The parameterizer as a drop-in for CGAL's Euclidean orbifold code: the steps of CGAL 5.5's
// example Surface_mesh_parameterization/orbifold.cpp (Simple_cartesian<double>, a
// Seam_mesh cut along the seams of a .selection.txt, SMP::locate_cones' cone map, a vertex
// index map), with the three changes of examples/orbifold.cpp. The result is re-checked by
// the independent certifier on the corner map it defines, with the landmarks in the file's
// order: the cones must be at the tile's corners in that order (the order along the seam).

#include "test_harness.h"

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/Seam_mesh.h>
#include <CGAL/Surface_mesh_parameterization/Orbifold_Tutte_parameterizer_3.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/hyperbolic_orbifold_Tutte.h>

#include <cstdio>
#include <fstream>
#include <iterator>
#include <string>
#include <unordered_map>
#include <vector>

namespace {

typedef CGAL::Simple_cartesian<double> Kernel;
typedef Kernel::Point_2 Point_2;
typedef CGAL::Surface_mesh<Kernel::Point_3> SurfaceMesh;
typedef boost::graph_traits<SurfaceMesh>::vertex_descriptor SM_vertex_descriptor;
typedef boost::graph_traits<SurfaceMesh>::halfedge_descriptor SM_halfedge_descriptor;
typedef boost::graph_traits<SurfaceMesh>::edge_descriptor SM_edge_descriptor;
typedef SurfaceMesh::Property_map<SM_edge_descriptor, bool> Seam_edge_pmap;
typedef SurfaceMesh::Property_map<SM_vertex_descriptor, bool> Seam_vertex_pmap;
typedef CGAL::Seam_mesh<SurfaceMesh, Seam_edge_pmap, Seam_vertex_pmap> Mesh;
typedef boost::graph_traits<Mesh>::vertex_descriptor vertex_descriptor;
typedef boost::graph_traits<Mesh>::halfedge_descriptor halfedge_descriptor;
typedef SurfaceMesh::Property_map<SM_halfedge_descriptor, Point_2> UV_pmap;
namespace SMP = CGAL::Surface_mesh_parameterization;
namespace HOT = CGAL::Hyperbolic_orbifold_Tutte;
typedef HOT::Hyperbolic_orbifold_Tutte_parameterizer_3<Mesh> Parameterizer;

std::string source_data(const std::string& name) { return std::string(HOT_SOURCE_DIR) + "/examples/data/" + name; }

// What one run of the example's steps gives.
struct Run
{
  SMP::Error_code code = SMP::ERROR_WRONG_PARAMETER;
  HOT::Status status;
  HOT::Embedding_statistics stats;
  std::size_t cones_in_seam_mesh = 0;
  std::size_t seam_edges = 0;
  HOT::Embedding_certificate independent; // certify_hyperbolic_orbifold_embedding() of the corner map
  HOT::Error_code certify_code = HOT::ERROR_WRONG_PARAMETER;
  bool reversed_order_certifies = true; // the same map with the landmarks in the other order
  std::size_t points_outside_disk = 0;
};

// The example's steps (orbifold.cpp, lines 47-116 of CGAL 5.5), then the independent check.
Run run_example_steps(const std::string& filename, const std::string& cone_filename, SMP::Weight_type weights)
{
  Run run;
  SurfaceMesh sm;
  if(!CGAL::IO::read_polygon_mesh(filename, sm))
    return run;
  std::vector<SM_vertex_descriptor> cone_sm_vds;
  if(HOT::read_cones<SurfaceMesh>(sm, cone_filename.c_str(), std::back_inserter(cone_sm_vds)) != SMP::OK)
    return run;
  Seam_edge_pmap seam_edge_pm = sm.add_property_map<SM_edge_descriptor, bool>("e:on_seam", false).first;
  Seam_vertex_pmap seam_vertex_pm = sm.add_property_map<SM_vertex_descriptor, bool>("v:on_seam", false).first;
  Mesh mesh(sm, seam_edge_pm, seam_vertex_pm);
  mesh.add_seams(cone_filename.c_str());
  run.seam_edges = mesh.number_of_seam_edges();
  std::unordered_map<vertex_descriptor, int> indices;
  boost::associative_property_map<std::unordered_map<vertex_descriptor, int> > vimap(indices);
  int counter = 0;
  for(vertex_descriptor vd : vertices(mesh))
    put(vimap, vd, counter++);
  std::unordered_map<vertex_descriptor, SMP::Cone_type> cmap;
  SMP::locate_cones(mesh, cone_sm_vds.begin(), cone_sm_vds.end(), cmap);
  run.cones_in_seam_mesh = cmap.size();
  UV_pmap uvmap = sm.add_property_map<SM_halfedge_descriptor, Point_2>("h:uv").first;
  Parameterizer parameterizer(HOT::Sphere_type, weights);
  halfedge_descriptor bhd = CGAL::Polygon_mesh_processing::longest_border(mesh).first;
  run.code = parameterizer.parameterize(mesh, bhd, cmap, uvmap, vimap);
  run.status = parameterizer.last_status();
  run.stats = parameterizer.statistics();
  if(run.code != SMP::OK)
    return run;
  // the corner map: corner target(h) of face(h) is the seam-mesh vertex of h's target
  UV_pmap corners = sm.add_property_map<SM_halfedge_descriptor, Point_2>("h:corner_uv").first;
  for(auto f : faces(sm))
    for(SM_halfedge_descriptor h : halfedges_around_face(halfedge(f, sm), sm)) {
      const Point_2 p = get(uvmap, target(halfedge_descriptor(h, false), mesh));
      put(corners, h, p);
      run.points_outside_disk += (p.x() * p.x() + p.y() * p.y() < 1) ? 0 : 1;
    }
  run.certify_code = HOT::certify_hyperbolic_orbifold_embedding(sm, cone_sm_vds, corners, run.independent);
  HOT::Embedding_certificate reversed;
  const std::vector<SM_vertex_descriptor> backwards(cone_sm_vds.rbegin(), cone_sm_vds.rend());
  run.reversed_order_certifies = HOT::certify_hyperbolic_orbifold_embedding(sm, backwards, corners, reversed) == HOT::OK &&
                                 reversed.is_bijective();
  return run;
}

void check_certified(const Run& r, std::size_t k)
{
  CHECK_MSG(r.code == SMP::OK, r.status.message);
  CHECK(r.status.code == HOT::OK);
  CHECK(r.cones_in_seam_mesh == 2 + 2 * (k - 2)); // two ends once, the others on both sides of the seam
  CHECK(r.seam_edges > 0);
  CHECK(r.stats.certificate.is_bijective());
  CHECK(r.points_outside_disk == 0);
  CHECK(r.certify_code == HOT::OK);
  CHECK_MSG(r.independent.is_bijective(), "independent certificate of the file-order landmarks");
  CHECK(r.independent.cone_failures == 0);
  CHECK(r.independent.flipped_faces == 0);
  CHECK(!r.reversed_order_certifies); // the order matters: cone i of the file is at corner i
  // Gauss-Bonnet: the tile of k cones of angle pi has area (k - 4) pi
  CHECK_NEAR(r.independent.total_area, (static_cast<double>(k) - 4) * CGAL_PI, 1e-6);
}

} // namespace

TEST_CASE(cgal_orbifold_example_bear)
{
  const Run r = run_example_steps(hot_test::data_dir() + "/meshes/bear.off", source_data("bear.selection.txt"),
                                  SMP::Cotangent);
  check_certified(r, 7);
}

TEST_CASE(cgal_orbifold_example_armadillo)
{
  const Run r = run_example_steps(hot_test::data_dir() + "/meshes/armadillo.off",
                                  source_data("armadillo.selection.txt"), SMP::Cotangent);
  check_certified(r, 7);
}

TEST_CASE(cgal_orbifold_example_mean_value_weights)
{
  const Run r = run_example_steps(hot_test::data_dir() + "/meshes/bear.off", source_data("bear.selection.txt"),
                                  SMP::Mean_value);
  check_certified(r, 7);
}

// read_cones(): the first line only, any number of cones, clear refusals
TEST_CASE(read_cones_errors)
{
  SurfaceMesh sm;
  CHECK(CGAL::IO::read_polygon_mesh(hot_test::data_dir() + "/meshes/bear.off", sm));
  const std::string tmp = "test_cgal_drop_in_cones.selection.txt";
  auto read = [&](const std::string& content, std::vector<SM_vertex_descriptor>& out, HOT::Status& st) {
    std::ofstream(tmp) << content;
    return HOT::read_cones(sm, tmp, std::back_inserter(out), &st);
  };
  std::vector<SM_vertex_descriptor> out;
  HOT::Status st;
  CHECK(read("1 2 3 4 5 6 7 8 9\n\n10 11 12 13\n", out, st) == SMP::OK);
  CHECK(out.size() == 9 && st.code == HOT::OK); // the seam line is not read
  CHECK(out.size() == 9 && out[0] == SM_vertex_descriptor(1) && out[8] == SM_vertex_descriptor(9));
  const std::string too_far = std::to_string(num_vertices(sm));
  const std::vector<std::pair<std::string, HOT::Error_code> > bad = {
    {"1 2 3 3 4\n", HOT::ERROR_DUPLICATE_LANDMARK}, {"1 2 " + too_far + " 4 5\n", HOT::ERROR_LANDMARK_OUT_OF_RANGE},
    {"1 2 x 4 5\n", HOT::ERROR_READ_FAILED},         {"1 2 -3 4 5\n", HOT::ERROR_READ_FAILED},
    {"\n1 2 3 4 5\n", HOT::ERROR_TOO_FEW_LANDMARKS}};
  for(const auto& b : bad) {
    out.clear();
    CHECK_MSG(read(b.first, out, st) == SMP::ERROR_WRONG_PARAMETER, b.first);
    CHECK_MSG(out.empty() && st.code == b.second && !st.message.empty(), b.first + " -> " + st.message);
  }
  std::remove(tmp.c_str());
  out.clear();
  CHECK(HOT::read_cones(sm, "no/such/file.selection.txt", std::back_inserter(out), &st) == SMP::ERROR_WRONG_PARAMETER);
  CHECK(out.empty() && st.code == HOT::ERROR_READ_FAILED);
}

// too few cones, and a cone map that does not tag the seam's ends: SMP error codes, the
// specific reason in last_status(), the uv map untouched
TEST_CASE(cgal_interface_refusals)
{
  SurfaceMesh sm;
  CHECK(CGAL::IO::read_polygon_mesh(hot_test::data_dir() + "/meshes/bear.off", sm));
  Seam_edge_pmap sep = sm.add_property_map<SM_edge_descriptor, bool>("e:on_seam", false).first;
  Seam_vertex_pmap svp = sm.add_property_map<SM_vertex_descriptor, bool>("v:on_seam", false).first;
  Mesh mesh(sm, sep, svp);
  std::vector<SM_vertex_descriptor> cones;
  HOT::read_cones(sm, source_data("bear.selection.txt"), std::back_inserter(cones));
  mesh.add_seams(source_data("bear.selection.txt").c_str());
  UV_pmap uvmap = sm.add_property_map<SM_halfedge_descriptor, Point_2>("h:uv", Point_2(7, 7)).first;
  std::unordered_map<vertex_descriptor, int> indices;
  boost::associative_property_map<std::unordered_map<vertex_descriptor, int> > vimap(indices);
  halfedge_descriptor bhd = CGAL::Polygon_mesh_processing::longest_border(mesh).first;
  Parameterizer parameterizer(HOT::Sphere_type, SMP::Cotangent);
  std::unordered_map<vertex_descriptor, SMP::Cone_type> cmap;
  SMP::locate_cones(mesh, cones.begin(), cones.end(), cmap);
  // every cone tagged duplicated: the seam's ends are unknown
  std::unordered_map<vertex_descriptor, SMP::Cone_type> untagged = cmap;
  for(auto& c : untagged)
    c.second = SMP::Duplicated_cone;
  CHECK(parameterizer.parameterize(mesh, bhd, untagged, uvmap, vimap) == SMP::ERROR_WRONG_PARAMETER);
  CHECK(parameterizer.last_status().code == HOT::ERROR_WRONG_PARAMETER);
  CHECK(parameterizer.last_status().message.find("First_unique_cone") != std::string::npos);
  // a cone map of only the two ends and one cone: 3 landmarks
  std::unordered_map<vertex_descriptor, SMP::Cone_type> three;
  for(const auto& c : cmap)
    if(c.second != SMP::Duplicated_cone || three.size() < 3)
      three.insert(c);
  CHECK(parameterizer.parameterize(mesh, bhd, three, uvmap, vimap) != SMP::OK);
  CHECK(parameterizer.last_status().code == HOT::ERROR_TOO_FEW_LANDMARKS ||
        parameterizer.last_status().code == HOT::ERROR_WRONG_PARAMETER);
  CHECK(!parameterizer.last_status().message.empty());
  std::size_t untouched = 0;
  for(auto h : halfedges(sm))
    untouched += get(uvmap, h) == Point_2(7, 7) ? 1 : 0;
  CHECK(untouched == num_halfedges(sm));
}

HOT_TEST_MAIN
