// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef HOT_APP_JOB_INPUT_H
#define HOT_APP_JOB_INPUT_H

// The mesh types of the jobs (the command-line program's and the Python module's), and reading
// a job's mesh with its landmarks.

#include "hot_app/job_support.h"
#include "hot_app/io/embedding_obj.h"
#include "hot_app/io/prepared_input.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/Chart_point.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/Embedding_locator.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/Orbifold_embedding.h>

#include <optional>
#include <string>
#include <vector>

namespace hot_cli {

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef CGAL::Surface_mesh<Kernel::Point_3> Surface_mesh;
typedef boost::graph_traits<Surface_mesh>::vertex_descriptor SM_vertex;
typedef boost::graph_traits<Surface_mesh>::halfedge_descriptor SM_halfedge;
typedef boost::graph_traits<Surface_mesh>::face_descriptor SM_face;

typedef Surface_mesh::Property_map<SM_halfedge, Kernel::Point_2> UV_map;
typedef Surface_mesh::Property_map<SM_halfedge, HOT::Chart_point<Kernel::Point_2> > Chart_map;
// an embedding with everything needed to read it (the library's result type), and its locator
typedef HOT::Orbifold_embedding<Surface_mesh, UV_map, Chart_map> Embedding_result;
typedef HOT::Embedding_locator<Surface_mesh, UV_map> Locator;

// the result object of an embedding of `m` computed into `uv` and `charts`, read with `layout`
// (the layout part of its statistics, or the one a file gives), of the landmarks as given to it
// (`layout.landmark_order` orders them)
inline Embedding_result embedding_result(const Surface_mesh& m, UV_map uv, Chart_map charts, const HOT::Embedding_layout& layout,
                                         const std::vector<SM_vertex>& landmarks)
{
  Embedding_result r(m, uv, charts);
  r.layout() = layout;
  r.set_landmarks(landmarks);
  r.set_valid();
  return r;
}

// the locator of a map's target (or, for the colours, of its source): in its tile (of its cut
// graph for genus g >= 1, of its signature otherwise), with its charts, the model the maps use
inline Locator target_locator(const Embedding_result& r)
{
  Locator loc(r, HOT::Hyperboloid_linear);
  if(!loc.is_valid() && r.layout().genus > 0)
    throw Failure{HOT::ERROR_WRONG_PARAMETER, "the target's tile could not be built from its cut graph"};
  return loc;
}

// a mesh file read for a job (as is, or prepared with --repair), its addressing by the file's
// vertices, and the landmarks moved by --snap-landmarks
struct Input
{
  hot_tools::Input_mesh file;
  std::vector<hot_tools::Landmark_snap_record> snaps;
};

// reads and checks (or prepares) a mesh and its landmarks (without --repair the same calls as
// the fuzz target, fuzz/fuzz_mesh_reader.cpp); returns the orbifold type (required or detected)
inline HOT::Orbifold_type read_mesh_and_landmarks(const std::string& mesh_path, const std::string& cones_path,
                                           std::optional<HOT::Orbifold_type> required_type,
                                           const hot_tools::Repair_options& repair, Surface_mesh& m,
                                           std::vector<SM_vertex>& landmarks, Input& in,
                                           std::size_t minimum = HOT::minimum_number_of_landmarks)
{
  HOT::Mesh_info info;
  // --repair aims at the orbifold the landmarks ask for (the component that holds them, the
  // holes under them closed), except with --snap-landmarks, which asks for a disk whose
  // boundary the landmarks are moved to; a landmark file that cannot be read is said below
  std::vector<std::size_t> ids;
  if(repair.repair && !repair.snap_landmarks && !hot_tools::read_landmarks(cones_path, ids, true))
    ids.clear();
  require(hot_tools::read_input_mesh(mesh_path, required_type, repair, m, in.file, &info, ids));
  require(hot_tools::read_input_landmarks(cones_path, m, in.file, info.type, repair.snap_landmarks, landmarks, &in.snaps, minimum));
  return info.type;
}

// the 0-based indices, in the files (the input file's, then the added ones), of vertices of a
// mesh read by read_mesh_and_landmarks()
inline std::vector<std::size_t> file_indices(const std::vector<SM_vertex>& vs, const hot_tools::Input_mesh& in)
{
  std::vector<std::size_t> r;
  for(SM_vertex v : vs)
    r.push_back(hot_tools::output_vertex(v, &in));
  return r;
}

} // namespace hot_cli

#endif // HOT_APP_JOB_INPUT_H
