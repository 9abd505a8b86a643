// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef HOT_TOOLS_JOBS_LANDMARKS_H
#define HOT_TOOLS_JOBS_LANDMARKS_H

// The `landmarks` command: landmarks chosen far apart (select_landmarks()), as a landmark file.

#include "jobs/common.h"

#include <CGAL/Hyperbolic_orbifold_Tutte/select_landmarks.h>

#include <algorithm>
#include <iostream>
#include <set>
#include <string>
#include <vector>

namespace hot_cli {

// With --repair the landmarks are vertices of the input file: a landmark that falls on a vertex
// the repair added (inside a filled hole, or a copy of a split non-manifold vertex) moves to the
// nearest input vertex, ring by ring along the edges, that is not a landmark yet and is on the
// boundary if the landmark was.
inline std::vector<SM_vertex> input_vertices_only(const Surface_mesh& m, const hot_tools::Input_mesh& in, std::vector<SM_vertex> lm)
{
  const std::size_t n = in.prep.number_of_input_vertices;
  auto on_border = [&](SM_vertex v) { return bool(CGAL::is_border(v, m)); };
  std::set<SM_vertex> taken(lm.begin(), lm.end());
  for(SM_vertex& v : lm) {
    if(hot_tools::output_vertex(v, &in) < n) continue;
    // breadth-first over the one-rings, nearest first within a ring
    std::vector<SM_vertex> ring(1, v);
    std::set<SM_vertex> seen(ring.begin(), ring.end());
    SM_vertex found = v;
    while(found == v && !ring.empty()) {
      std::vector<SM_vertex> next;
      for(SM_vertex u : ring)
        for(SM_vertex w : vertices_around_target(halfedge(u, m), m))
          if(seen.insert(w).second) next.push_back(w);
      std::sort(next.begin(), next.end(), [&](SM_vertex a, SM_vertex b) {
        return CGAL::squared_distance(m.point(a), m.point(v)) < CGAL::squared_distance(m.point(b), m.point(v));
      });
      for(SM_vertex w : next)
        if(found == v && hot_tools::output_vertex(w, &in) < n && !taken.count(w) && on_border(w) == on_border(v)) found = w;
      ring.swap(next);
    }
    taken.erase(v);
    taken.insert(found);
    v = found;
  }
  return lm;
}

inline int run_landmarks(int argc, char** argv)
{
  const Options opt(argc, argv, 2, {"mesh", "count", "out", "max-hole", "target-genus", "max-handle"}, with_progress_flag(repair_flags()));
  const std::string mesh_path = opt.get("mesh"), out = opt.get("out");
  const long k = opt.get_int("count", 1, 100000);
  const hot_tools::Repair_options repair = parse_repair_options(opt);
  Progress_line progress("landmarks", opt.has("progress"));
  Surface_mesh m;
  Input in;
  progress.step("read");
  require(hot_tools::read_input_mesh(mesh_path, std::nullopt, repair, m, in.file));
  progress.done("read");
  if(in.file.repaired)
    progress.clear(); // (a terminal's line, before stdout)
  print_repair(mesh_path, in);
  if(static_cast<std::size_t>(k) > num_vertices(m))
    throw Usage_error{"--count is larger than the number of vertices (" + std::to_string(num_vertices(m)) + ")"};
  progress.step("select");
  std::vector<SM_vertex> lm = HOT::select_landmarks(m, static_cast<std::size_t>(k));
  if(lm.size() != static_cast<std::size_t>(k))
    throw Failure{HOT::ERROR_WRONG_PARAMETER, "the boundary has fewer than " + std::to_string(k) + " vertices"};
  if(in.file.repaired)
    lm = input_vertices_only(m, in.file, lm);
  progress.done("select");
  progress.step("write");
  write_file_atomically(out, [&](std::ostream& os) {
    for(std::size_t i : file_indices(lm, in.file))
      os << i << "\n";
  });
  progress.done("write");
  progress.clear();
  std::cout << "wrote " << k << " landmarks of " << mesh_path << " to " << out << std::endl;
  return EXIT_SUCCESS;
}

} // namespace hot_cli

#endif // HOT_TOOLS_JOBS_LANDMARKS_H
