// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Meshes and landmark sets for the tests: libcgal-demo meshes (read from the data
// directory the harness is given) and generated ones; deterministic landmark choices.

#ifndef HOT_TEST_COMMON_MESHES_H
#define HOT_TEST_COMMON_MESHES_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/Polygon_mesh_processing/border.h>

#include <fstream>
#include <queue>
#include <string>
#include <vector>

namespace hot_test {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef boost::graph_traits<Mesh>::vertex_descriptor vertex_descriptor;
typedef boost::graph_traits<Mesh>::halfedge_descriptor halfedge_descriptor;

inline bool read_demo_mesh(const std::string& name, Mesh& m)
{
  std::ifstream in(data_dir() + "/meshes/" + name + ".off");
  m.clear();
  return in && (in >> m) && num_faces(m) > 0;
}

// Dijkstra distances over edges weighted by length, from several sources.
inline std::vector<double> graph_distances(const Mesh& m, const std::vector<vertex_descriptor>& sources)
{
  std::vector<double> d(num_vertices(m), 1e300);
  typedef std::pair<double, int> Q;
  std::priority_queue<Q, std::vector<Q>, std::greater<Q> > q;
  for(vertex_descriptor s : sources) {
    d[s.idx()] = 0;
    q.push(Q(0, int(s.idx())));
  }
  while(!q.empty()) {
    const Q t = q.top();
    q.pop();
    if(t.first > d[t.second])
      continue;
    const vertex_descriptor v(t.second);
    for(halfedge_descriptor h : halfedges_around_target(halfedge(v, m), m)) {
      const vertex_descriptor u = source(h, m);
      const double nd = t.first + std::sqrt(CGAL::squared_distance(m.point(u), m.point(v)));
      if(nd < d[u.idx()]) {
        d[u.idx()] = nd;
        q.push(Q(nd, int(u.idx())));
      }
    }
  }
  return d;
}

// k landmarks by farthest-point sampling on graph distance, starting from `start`
inline std::vector<vertex_descriptor> farthest_point_landmarks(const Mesh& m, int k, int start = 0)
{
  std::vector<vertex_descriptor> lm;
  std::vector<vertex_descriptor> seed(1, vertex_descriptor(start));
  std::vector<double> d = graph_distances(m, seed);
  // first landmark: farthest from the start vertex
  int best = 0;
  for(std::size_t i = 0; i < d.size(); ++i)
    if(d[i] > d[best] && d[i] < 1e299) best = int(i);
  lm.push_back(vertex_descriptor(best));
  while(int(lm.size()) < k) {
    d = graph_distances(m, lm);
    best = 0;
    for(std::size_t i = 0; i < d.size(); ++i)
      if(d[i] > d[best] && d[i] < 1e299) best = int(i);
    lm.push_back(vertex_descriptor(best));
  }
  return lm;
}

// the boundary loop of a disk mesh (halfedge order), then k vertices spread by arc length
inline std::vector<vertex_descriptor> boundary_landmarks(const Mesh& m, int k, double phase = 0.0)
{
  halfedge_descriptor b;
  for(halfedge_descriptor h : halfedges(m))
    if(is_border(h, m)) { b = h; break; }
  std::vector<vertex_descriptor> loop;
  std::vector<double> acc(1, 0.0);
  halfedge_descriptor h = b;
  do {
    loop.push_back(target(h, m));
    acc.push_back(acc.back() + std::sqrt(CGAL::squared_distance(m.point(source(h, m)), m.point(target(h, m)))));
    h = next(h, m);
  } while(h != b);
  std::vector<vertex_descriptor> lm;
  std::size_t j = 0;
  for(int i = 0; i < k; ++i) {
    const double s = (i + phase) / k * acc.back();
    while(j + 1 < loop.size() && acc[j + 1] < s) ++j;
    if(lm.empty() || lm.back() != loop[j]) lm.push_back(loop[j]);
  }
  return lm;
}

} // namespace hot_test

#endif
