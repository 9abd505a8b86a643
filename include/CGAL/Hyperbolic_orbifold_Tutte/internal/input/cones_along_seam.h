// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_INPUT_CONES_ALONG_SEAM_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_INPUT_CONES_ALONG_SEAM_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Hyperbolic_orbifold_Tutte/error_code.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/Orbifold_type.h>

#include <CGAL/Hyperbolic_orbifold_Tutte/internal/core/orbifold_enums.h>
#include <CGAL/boost/graph/iterator.h>

#include <cstddef>
#include <set>
#include <string>
#include <vector>

// The landmarks of a cone map in the format of CGAL's Surface_mesh_parameterization
// (`locate_cones()`: seam-mesh vertices tagged First_unique_cone, Second_unique_cone and
// Duplicated_cone), in their order along the seam.

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {
namespace internal {

// The vertices of the underlying mesh that the cone map marks, in the order met along the
// border of `mesh` (the loop of `bhd`): from the first unique cone to the second for a
// sphere-type seam (each duplicated cone stands twice on the border, once on each side of
// the seam: it is taken on the first side); for a disk (no seams), every cone once, from
// the first unique cone if one is tagged, else from the first met after `bhd`.
template <class SeamMesh, class ConeMap>
Status cones_along_seam(const SeamMesh& mesh, typename boost::graph_traits<SeamMesh>::halfedge_descriptor bhd,
                        const ConeMap& cmap, Orbifold_type type,
                        std::vector<typename boost::graph_traits<typename SeamMesh::TriangleMesh>::vertex_descriptor>& out)
{
  namespace SMP = CGAL::Surface_mesh_parameterization;
  typedef typename SeamMesh::TriangleMesh TM;
  typedef typename boost::graph_traits<TM>::vertex_descriptor TM_vertex;
  typedef typename boost::graph_traits<TM>::halfedge_descriptor TM_halfedge;
  const TM& tm = mesh.mesh();
  auto base = [&](const typename boost::graph_traits<SeamMesh>::vertex_descriptor& v) {
    return target(TM_halfedge(v.hd), tm);
  };
  std::set<TM_vertex> cones;
  std::size_t unique = 0;
  TM_vertex first = TM_vertex(), second = TM_vertex();
  for(const auto& c : cmap) {
    cones.insert(base(c.first));
    if(c.second == SMP::First_unique_cone) { first = base(c.first); ++unique; }
    if(c.second == SMP::Second_unique_cone) { second = base(c.first); ++unique; }
  }
  out.clear();
  if(type == Sphere_type && (unique != 2 || first == second))
    return Status::failure(ERROR_WRONG_PARAMETER, "the cone map must tag one First_unique_cone and one "
                                                  "Second_unique_cone, the two ends of the seam");
  // the border loop, as vertices of the underlying mesh
  std::vector<TM_vertex> loop;
  for(auto h : halfedges_around_face(bhd, mesh))
    loop.push_back(base(target(h, mesh)));
  std::size_t start = loop.size();
  for(std::size_t i = 0; i < loop.size() && start == loop.size(); ++i)
    if(unique > 0 ? loop[i] == first : cones.count(loop[i]) != 0)
      start = i;
  if(start == loop.size())
    return Status::failure(ERROR_WRONG_PARAMETER, "no cone of the cone map is on the border of the seam mesh");
  std::set<TM_vertex> met;
  for(std::size_t j = 0; j < loop.size(); ++j) {
    const TM_vertex v = loop[(start + j) % loop.size()];
    if(cones.count(v) && met.insert(v).second)
      out.push_back(v);
    if(type == Sphere_type && v == second)
      break;
  }
  if(met.size() != cones.size())
    return Status::failure(ERROR_WRONG_PARAMETER, std::to_string(cones.size() - met.size()) +
                                                  " cones of the cone map are not on the seam between its two ends");
  return Status();
}

} // namespace internal
} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_INPUT_CONES_ALONG_SEAM_H
