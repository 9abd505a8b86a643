// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_INPUT_INPUT_STAGE_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_INPUT_INPUT_STAGE_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Hyperbolic_orbifold_Tutte/error_code.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/genus.h>            // Mesh_info
#include <CGAL/Hyperbolic_orbifold_Tutte/parameters.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/core/seam_mesh_storage.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/input/cut_paths.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/input/genus_cut.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/input/landmark_distances.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/input/mesh_checks.h>

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

// The pipeline's first stages, shared by the one-call embedding, the certifier and the
// collection: the orbifold type and the checks of the mesh (prepare), the landmarks' order,
// and the cut through them into a seam mesh. The solve stage is embedding_pipeline.h. A layer
// below the public functions: it runs the steps of check_mesh(), compute_landmark_tour(),
// compute_cut_through_landmarks() and compute_cut_graph() (this folder), not those functions.

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {
namespace internal {

// The orbifold type of the named parameter `orbifold_type`, or, when it is not given,
// the one of the mesh's topology (closed: sphere type; one boundary loop: disk type).
// Returns false when it is not given and the mesh is neither.
template <class TriangleMesh, class NamedParameters>
bool orbifold_type_parameter(const TriangleMesh& tm, const NamedParameters& np, Orbifold_type& type)
{
  if(CGAL::parameters::is_default_parameter<NamedParameters, internal_np::orbifold_type_t>::value)
    return orbifold_type_of_boundary(tm, type);
  type = CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np, internal_np::orbifold_type), Sphere_type);
  return true;
}

// Prepare: the orbifold type (`orbifold_type_parameter()`) and every check of the mesh for it.
template <class TriangleMesh, class VertexPointMap, class NamedParameters>
Status prepare_mesh(const TriangleMesh& tm, VertexPointMap vpm, const NamedParameters& np, Orbifold_type& type)
{
  if(!orbifold_type_parameter(tm, np, type)) {
    // no face, or several boundary loops: check_mesh() says which check fails first
    // (empty, non-manifold, several components, ..., or the boundary loops)
    Mesh_info info;
    const Status r = check_mesh_impl::run_all(tm, vpm, std::nullopt, info);
    return r ? Status::failure(ERROR_WRONG_TOPOLOGY,
                               "the mesh is neither closed nor a disk (it has more than one boundary loop)")
             : r;
  }
  Mesh_info info;
  return check_mesh_impl::run_all(tm, vpm, type, info);
}

// The landmarks in the order of the cut: as given, or (sphere type, `Tsp_order`) along the
// paper's tour; `order[i]` is the index in `landmarks` of the i-th of `ordered`.
template <class TriangleMesh, class VertexPointMap>
Status order_landmarks(const TriangleMesh& tm, VertexPointMap vpm,
                       const std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>& landmarks,
                       Orbifold_type type, Landmark_order how,
                       std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>& ordered,
                       std::vector<std::size_t>& order)
{
  ordered = landmarks;
  order.resize(landmarks.size());
  for(std::size_t i = 0; i < landmarks.size(); ++i)
    order[i] = i;
  if(how != Tsp_order || type != Sphere_type)
    return Status();
  const std::vector<std::size_t> perm = landmark_tour(tm, landmarks, vpm);
  if(perm.size() != landmarks.size())
    return Status::failure(ERROR_CUT_FAILED, "the landmark tour could not be computed");
  for(std::size_t i = 0; i < perm.size(); ++i)
    ordered[i] = landmarks[perm[i]];
  order = perm;
  return Status();
}

// Cut: a sphere-type mesh of genus 0 along a simple path through the landmarks in order, of
// genus g >= 1 along a cut graph (internal/input/genus_cut.h) (seams held
// in the storage's own flags, so the input mesh is not modified and may be const); a disk
// is not cut. `bhd` is a border halfedge of the seam mesh.
template <class TriangleMesh, class VertexPointMap>
Status cut_open(const TriangleMesh& tm, VertexPointMap vpm,
                const std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>& ordered,
                Orbifold_type type, Seam_mesh_storage<TriangleMesh>& seams,
                typename boost::graph_traits<typename Seam_mesh_storage<TriangleMesh>::Mesh>::halfedge_descriptor& bhd,
                long long genus = 0,
                std::vector<std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor> >* cut_paths = nullptr)
{
  if(type == Sphere_type && genus > 0) { // along a cut graph: the given one, or handle loops and paths to the landmarks
    CGAL_precondition(cut_paths != nullptr);
    const Status r = cut_paths->empty() ? cut_graph_through_landmarks(tm, ordered, vpm, *cut_paths)
                                        : check_cut_graph_paths(tm, *cut_paths, ordered);
    if(!r)
      return r;
    for(const auto& path : *cut_paths)
      for(std::size_t j = 1; j < path.size(); ++j)
        if(!seams.mesh.add_seam(path[j - 1], path[j]))
          return Status::failure(ERROR_CUT_FAILED, "the cut graph could not be marked on the seam mesh");
  } else if(type == Sphere_type) {
    std::vector<std::vector<typename boost::graph_traits<TriangleMesh>::halfedge_descriptor> > paths;
    std::size_t attempts = 0;
    const std::string message = cut_through_landmarks(tm, ordered, vpm, default_chord_penalty, 0, paths, attempts);
    if(!message.empty())
      return Status::failure(ERROR_CUT_FAILED, message);
    if(!mark_seams(seams.mesh, tm, paths))
      return Status::failure(ERROR_CUT_FAILED, "the cut could not be marked on the seam mesh");
  }
  if(!seams.border_halfedge(bhd))
    return Status::failure(ERROR_CUT_FAILED, "the cut mesh has no border");
  return Status();
}

} // namespace internal
} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_INPUT_INPUT_STAGE_H
