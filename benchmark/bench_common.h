// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What the benchmark programs share: the kernel and mesh types, a steady clock, and
// the wall time and peak memory they print.

#ifndef HOT_BENCH_COMMON_H
#define HOT_BENCH_COMMON_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/hyperbolic_orbifold_Tutte.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>

#include <sys/resource.h>

#include <chrono>
#include <fstream>
#include <cmath>
#include <vector>
#include <string>

namespace HOT = CGAL::Hyperbolic_orbifold_Tutte;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> SM;
typedef boost::graph_traits<SM>::vertex_descriptor SM_vertex;
typedef boost::graph_traits<SM>::edge_descriptor SM_edge;
typedef boost::graph_traits<SM>::halfedge_descriptor SM_halfedge;
typedef boost::graph_traits<SM>::face_descriptor SM_face;
typedef std::chrono::steady_clock Clock;

/// wall time since `t`, in seconds
// the vertex indices of a landmark or rows file, whitespace-separated (no check: benchmark input)
inline std::vector<std::size_t> read_indices(const std::string& file)
{
  std::ifstream in(file);
  std::vector<std::size_t> out;
  std::size_t i;
  while(in >> i)
    out.push_back(i);
  return out;
}

inline double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

/// the diagonal of the bounding box of `m`
inline double diagonal(const SM& m)
{
  const CGAL::Bbox_3 b = CGAL::Polygon_mesh_processing::bbox(m);
  return std::sqrt(CGAL::square(b.xmax() - b.xmin()) + CGAL::square(b.ymax() - b.ymin()) + CGAL::square(b.zmax() - b.zmin()));
}

/// the process's peak resident memory so far, in MiB
inline double peak_rss_mb()
{
  rusage u;
  getrusage(RUSAGE_SELF, &u);
  return u.ru_maxrss / 1024.0;
}

#endif // HOT_BENCH_COMMON_H
