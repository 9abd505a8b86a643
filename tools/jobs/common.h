// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef HOT_TOOLS_JOBS_COMMON_H
#define HOT_TOOLS_JOBS_COMMON_H

// What several commands share: cut graph files as vertices of a mesh read for a job, the
// --progress flag, the line saying what --repair changed.

#include "command_line.h"
#include "hot_app/job_input.h"
#include "hot_app/io/cut_graph_file.h"

#include <CGAL/Hyperbolic_orbifold_Tutte/Embedding_statistics.h>

#include <iostream>
#include <set>
#include <string>
#include <vector>

namespace hot_cli {

// the cut graph of a file (--cut-graph: vertex paths of the mesh file, with --repair of the
// input file) as vertices of the mesh read by read_mesh_and_landmarks()
inline std::vector<std::vector<SM_vertex> > read_cut_graph_of(const std::string& path, const Surface_mesh& m, const hot_tools::Input_mesh& in)
{
  std::vector<std::vector<std::size_t> > ids;
  require(hot_tools::read_cut_graph(path, ids));
  const std::vector<SM_vertex> verts(vertices(m).begin(), vertices(m).end());
  std::vector<std::vector<SM_vertex> > paths;
  for(const auto& p : ids) {
    paths.emplace_back();
    for(std::size_t id : p) {
      std::size_t i = id;
      if(in.repaired)
        i = id < in.prep.number_of_input_vertices ? in.prep.prepared_vertex[id] : HOT::Mesh_preparation::npos;
      if(i >= verts.size())
        throw Failure{HOT::ERROR_LANDMARK_OUT_OF_RANGE, path + ": vertex " + std::to_string(id) + " of the cut graph is not a vertex of the mesh"};
      paths.back().push_back(verts[i]);
    }
  }
  return paths;
}

// the cut graph an embedding used (Embedding_statistics::cut_graph), numbered as the files
inline std::vector<std::vector<std::size_t> > cut_graph_in_files(const HOT::Embedding_statistics& st, const Surface_mesh& m,
                                                                 const hot_tools::Input_mesh* in)
{
  const std::vector<SM_vertex> verts(vertices(m).begin(), vertices(m).end());
  std::vector<std::vector<std::size_t> > r;
  for(const auto& p : st.cut_graph) {
    r.emplace_back();
    for(std::size_t i : p) r.back().push_back(hot_tools::output_vertex(verts[i], in));
  }
  return r;
}

// the flags and --progress
inline std::set<std::string> with_progress_flag(std::set<std::string> flags)
{
  flags.insert("progress");
  return flags;
}

// one line on stdout saying what --repair and --snap-landmarks changed
inline void print_repair(const std::string& path, const Input& in)
{
  if(in.file.repaired)
    std::cout << "repaired " << path << ": " << in.file.prep.summary() << std::endl;
  for(const auto& s : in.snaps)
    std::cout << "snapped landmark " << s.landmark << " of " << path << " from vertex " << s.from << " to boundary vertex "
              << s.to << " (distance " << s.distance << ")" << std::endl;
}

} // namespace hot_cli

#endif // HOT_TOOLS_JOBS_COMMON_H
