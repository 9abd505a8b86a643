// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef HOT_TOOLS_JOBS_CUT_H
#define HOT_TOOLS_JOBS_CUT_H

// The `cut` command: CGAL's selection file of the cut through the cones (sphere type), for
// CGAL's orbifold example (Seam_mesh::add_seams() and SMP::locate_cones(); CGAL's own
// compute_shortest_paths_between_cones() takes 3 or 4 cones only).

#include "command_line.h"
#include "hot_app/job_input.h"
#include "hot_app/io/read_and_check.h"
#include "hot_app/io/selection.h"

#include <CGAL/Hyperbolic_orbifold_Tutte/landmark_tour.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/cut_through_landmarks.h>

#include <iostream>
#include <string>
#include <vector>

namespace hot_cli {

inline int run_cut(int argc, char** argv)
{
  const Options opt(argc, argv, 2, {"mesh", "cones", "order", "out"});
  const std::string mesh_path = opt.get("mesh"), cones_path = opt.get("cones"), out = opt.get("out");
  const bool tour = parse_order(opt, "given") == "tsp";
  Surface_mesh m;
  HOT::Mesh_info info;
  require(hot_tools::read_and_check_mesh(mesh_path, std::nullopt, m, &info));
  if(info.type != HOT::Sphere_type)
    throw Failure{HOT::ERROR_WRONG_TOPOLOGY, mesh_path + ": the mesh has a boundary loop; only a closed genus-0 mesh "
                                             "(sphere type) is cut, a disk-type orbifold needs no cut"};
  std::vector<SM_vertex> landmarks;
  require(hot_tools::read_and_check_landmarks(cones_path, m, info.type, landmarks));
  std::vector<SM_vertex> cones = landmarks;
  if(tour) {
    const std::vector<std::size_t> order = HOT::compute_landmark_tour(m, landmarks);
    if(order.size() != landmarks.size())
      throw Failure{HOT::ERROR_CUT_FAILED, "the landmark tour could not be computed"};
    for(std::size_t i = 0; i < order.size(); ++i) cones[i] = landmarks[order[i]];
  }
  const HOT::Cut_result<Surface_mesh> cut = HOT::compute_cut_through_landmarks(m, cones, get(CGAL::vertex_point, m));
  if(!cut.ok)
    throw Failure{HOT::ERROR_CUT_FAILED, cut.message};
  write_file_atomically(out, [&](std::ostream& os) { hot_tools::write_selection_file(os, m, cones, cut); });
  std::cout << "wrote the cut of " << mesh_path << " through " << cones.size() << " cones (" << cut.number_of_cut_edges()
            << " seam edges) to " << out << std::endl;
  return EXIT_SUCCESS;
}

} // namespace hot_cli

#endif // HOT_TOOLS_JOBS_CUT_H
