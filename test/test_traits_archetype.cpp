// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Concept archetype: a traits class with only the documented requirements of
// HyperbolicOrbifoldTraits_2 (doc/.../Concepts) must be enough for the tile code and the
// parameterizer and the point locator: if the code starts using anything else, this stops compiling.
#include "test_harness.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/hyperbolic_orbifold_Tutte.h>
#include <CGAL/boost/graph/Seam_mesh.h>

#include <iostream>
namespace HOT = CGAL::Hyperbolic_orbifold_Tutte;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef HOT::Poincare_disk_traits_2<K> PT;

struct Arch {
  typedef K::FT FT;
  typedef K::Point_2 Point_2;
  typedef HOT::Hyperbolic_isometry_2<double> Isometry;
  struct Hyperbolic_orientation_2 {
    CGAL::Orientation operator()(const Point_2& p, const Point_2& q, const Point_2& r) const { return PT().hyperbolic_orientation_2_object()(p, q, r); }
  };
  struct Compute_hyperbolic_distance_2 {
    FT operator()(const Point_2& p, const Point_2& q) const { return PT().compute_hyperbolic_distance_2_object()(p, q); }
  };
  struct Compute_hyperbolic_angle_2 {
    FT operator()(const Point_2& p, const Point_2& q, const Point_2& r) const { return PT().compute_hyperbolic_angle_2_object()(p, q, r); }
  };
  struct Construct_Klein_point_2 {
    Point_2 operator()(const Point_2& p) const { return PT().construct_Klein_point_2_object()(p); }
  };
  struct Construct_hyperbolic_midpoint_2 {
    Point_2 operator()(const Point_2& p, const Point_2& q) const { return PT().construct_hyperbolic_midpoint_2_object()(p, q); }
  };
  Hyperbolic_orientation_2 hyperbolic_orientation_2_object() const { return {}; }
  Compute_hyperbolic_distance_2 compute_hyperbolic_distance_2_object() const { return {}; }
  Compute_hyperbolic_angle_2 compute_hyperbolic_angle_2_object() const { return {}; }
  Construct_Klein_point_2 construct_Klein_point_2_object() const { return {}; }
  Construct_hyperbolic_midpoint_2 construct_hyperbolic_midpoint_2_object() const { return {}; }
};

typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef boost::graph_traits<Mesh>::vertex_descriptor vd;
typedef boost::graph_traits<Mesh>::edge_descriptor ed;
typedef boost::graph_traits<Mesh>::halfedge_descriptor hd;
typedef std::unordered_map<ed, bool, boost::hash<ed>> EF;
typedef std::unordered_map<vd, bool, boost::hash<vd>> VF;
typedef CGAL::Seam_mesh<Mesh, boost::associative_property_map<EF>, boost::associative_property_map<VF>> SM;
typedef boost::graph_traits<SM>::halfedge_descriptor SM_hd;

// the point of a halfedge of the seam mesh: uv at its target's halfedge in the mesh
struct SM_uv {
  typedef SM_hd key_type;
  typedef K::Point_2 value_type;
  typedef K::Point_2 reference;
  typedef boost::readable_property_map_tag category;
  const Mesh::Property_map<hd, K::Point_2>* uv;
  const SM* sm;
  friend K::Point_2 get(const SM_uv& m, SM_hd h) { return get(*m.uv, hd(target(h, *m.sm))); }
};

TEST_CASE(archetype_is_enough)
{
  for(HOT::Orbifold_type t : {HOT::Sphere_type, HOT::Disk_type}) {
    HOT::Orbifold_tile<Arch> tile;
    CHECK(HOT::make_orbifold_tile(t, 7, tile) == HOT::OK);
    auto r = tile.reduce_to_tile(K::Point_2(0.999, 0.01));
    CHECK(tile.bounded_side(r.point) != CGAL::ON_UNBOUNDED_SIDE);
    CHECK(tile.group_elements(2).size() > 1);
  }
  // disk type: a fan-triangulated polygon with an inner ring (no boundary chords)
  Mesh m;
  const int n = 20;
  std::vector<vd> outer, inner;
  vd c = m.add_vertex(K::Point_3(0, 0, 0));
  for(int i = 0; i < n; ++i) outer.push_back(m.add_vertex(K::Point_3(std::cos(2*CGAL_PI*i/n), std::sin(2*CGAL_PI*i/n), 0)));
  for(int i = 0; i < n; ++i) inner.push_back(m.add_vertex(K::Point_3(0.6*std::cos(2*CGAL_PI*(i+0.5)/n), 0.6*std::sin(2*CGAL_PI*(i+0.5)/n), 0)));
  for(int i = 0; i < n; ++i) {
    int j = (i + 1) % n;
    m.add_face(outer[i], outer[j], inner[i]);
    m.add_face(inner[i], outer[j], inner[j]);
    m.add_face(c, inner[i], inner[j]);
  }
  EF ef; VF vf; for(auto e : edges(m)) ef[e] = false; for(auto v : vertices(m)) vf[v] = false;
  SM sm(m, boost::associative_property_map<EF>(ef), boost::associative_property_map<VF>(vf));
  boost::graph_traits<SM>::halfedge_descriptor bhd;
  for(auto h : halfedges(sm)) if(is_border(h, sm)) { bhd = h; break; }
  std::vector<vd> lm; for(int i = 0; i < n; i += 4) lm.push_back(outer[i]);
  auto uv = m.add_property_map<hd, K::Point_2>("h:uv").first;
  HOT::Hyperbolic_orbifold_Tutte_parameterizer_3<SM, Arch> p(HOT::Disk_type);
  HOT::Embedding_statistics st;
  HOT::Error_code ec = p.parameterize(sm, bhd, lm, uv, &st);
  CHECK_MSG(ec == HOT::OK, HOT::error_message(ec) << " " << st.message);
  CHECK_MSG(st.certificate.is_bijective(), st.certificate);
  // the point locator with the archetype traits: the centroid of every face is found
  HOT::Orbifold_tile<Arch> tile;
  CHECK(HOT::make_orbifold_tile(HOT::Disk_type, int(lm.size()), tile) == HOT::OK);
  const HOT::Embedding_locator<SM, SM_uv, Arch> locator(sm, SM_uv{&uv, &sm}, tile);
  CHECK_MSG(locator.is_valid(), locator.message());
  CHECK(locator.number_of_inverted_faces() == 0);
  for(std::size_t i = 0; i < locator.number_of_faces(); ++i) {
    const auto loc = locator.locate(locator.disk_point(i, {{1.0 / 3, 1.0 / 3, 1.0 / 3}}));
    CHECK(loc.success && loc.face_index == i);
  }
}

HOT_TEST_MAIN
