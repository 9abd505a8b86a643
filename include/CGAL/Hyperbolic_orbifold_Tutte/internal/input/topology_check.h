// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_INPUT_TOPOLOGY_CHECK_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_INPUT_TOPOLOGY_CHECK_H

#include <CGAL/Hyperbolic_orbifold_Tutte/error_code.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/genus.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/Orbifold_type.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/core/mesh_graph.h> // border_loops

#include <CGAL/boost/graph/helpers.h>     // is_border
#include <CGAL/Kernel_traits.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <optional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

// The last step of `check_mesh()` (mesh_checks.h runs the others): the topology, and what a mesh
// is, said in the check's messages (genus, boundary loops and their sizes), so that a refusal
// states the mesh and not only the rule.

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {
namespace internal {
namespace check_mesh_impl {

// "1 boundary loop", "3 boundary loops": the messages' counts
inline std::string plural(std::size_t n, const char* singular, const char* plural_form)
{
  std::ostringstream os;
  os << n << " " << (n == 1 ? singular : plural_form);
  return os.str();
}

// 8. topology: what the mesh is, for the messages: "(the mesh: one component of genus 1, closed)"
//    or "(the mesh: one component of genus 0 with 3 boundary loops of 38, 10 and 10 edges,
//    lengths 1.04, 0.175 and 0.175 times the bounding box diagonal)"
template <class TriangleMesh, class VertexPointMap, class Loops>
std::string describe_topology(const TriangleMesh& tm, VertexPointMap vpm, const Loops& loops, long long genus)
{
  std::ostringstream os;
  os.precision(3);
  os << " (the mesh: one component of genus " << genus;
  if(loops.empty())
    return os.str() + ", closed)";
  std::vector<std::pair<double, std::size_t> > sizes; // (length, edges), longest first
  for(const auto& loop : loops) {
    double length = 0;
    for(const auto& h : loop)
      length += std::sqrt(CGAL::to_double(CGAL::squared_distance(get(vpm, source(h, tm)), get(vpm, target(h, tm)))));
    sizes.emplace_back(length, loop.size());
  }
  std::sort(sizes.rbegin(), sizes.rend());
  double lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
  bool first = true;
  for(auto v : vertices(tm)) {
    const auto& p = get(vpm, v);
    const double c[3] = {CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())};
    for(int i = 0; i < 3; ++i) {
      lo[i] = first ? c[i] : (std::min)(lo[i], c[i]);
      hi[i] = first ? c[i] : (std::max)(hi[i], c[i]);
    }
    first = false;
  }
  const double diagonal = std::sqrt(CGAL::square(hi[0] - lo[0]) + CGAL::square(hi[1] - lo[1]) + CGAL::square(hi[2] - lo[2]));
  const std::size_t shown = (std::min)(sizes.size(), std::size_t(6));
  auto list = [&](auto value) {
    for(std::size_t i = 0; i < shown; ++i)
      os << (i == 0 ? "" : (i + 1 == shown && shown == sizes.size() ? " and " : ", ")) << value(sizes[i]);
    if(shown < sizes.size()) os << ", ...";
  };
  os << " with " << sizes.size() << (sizes.size() == 1 ? " boundary loop of " : " boundary loops of ");
  list([](const std::pair<double, std::size_t>& l) { return l.second; });
  os << " edges, length" << (sizes.size() == 1 ? " " : "s ");
  list([&](const std::pair<double, std::size_t>& l) { return diagonal > 0 ? l.first / diagonal : 0.; });
  os << " times the bounding box diagonal)";
  return os.str();
}

// Two border vertices with the same coordinates (the first pair found), if any.
template <class TriangleMesh, class VertexPointMap, class VertexIndex>
bool coincident_border_vertices(const TriangleMesh& tm, VertexPointMap vpm, const VertexIndex& vindex,
                                std::size_t& a, std::size_t& b)
{
  typedef typename boost::graph_traits<TriangleMesh>::halfedge_descriptor halfedge_descriptor;
  struct Key_hash
  {
    std::size_t operator()(const std::array<double, 3>& k) const
    {
      std::size_t h = 0;
      for(double x : k)
        h = h * 1000003u ^ std::hash<double>()(x);
      return h;
    }
  };
  std::unordered_map<std::array<double, 3>, std::size_t, Key_hash> first;
  for(halfedge_descriptor h : halfedges(tm)) {
    if(!is_border(h, tm))
      continue;
    const auto& p = get(vpm, target(h, tm));
    const std::array<double, 3> key = { { CGAL::to_double(p.x()) + 0.0, CGAL::to_double(p.y()) + 0.0,
                                          CGAL::to_double(p.z()) + 0.0 } }; // -0 -> +0
    const std::size_t vi = vindex(target(h, tm));
    auto ins = first.emplace(key, vi);
    if(!ins.second && ins.first->second != vi) {
      a = (std::min)(ins.first->second, vi);
      b = (std::max)(ins.first->second, vi);
      return true;
    }
  }
  return false;
}

// 8. topology: the reason why the mesh (b boundary loops, V-E+F = chi, genus) does not fit
//    an orbifold of `type`, or an empty string
inline std::string wrong_topology_reason(Orbifold_type type, std::size_t b, long long chi, long long genus)
{
  std::ostringstream os;
  if(type == Sphere_type) {
    if(b != 0)
      os << "the sphere-type (closed) orbifold needs a closed mesh, but the mesh has "
         << plural(b, "boundary loop", "boundary loops");
    else if(chi > 2 || chi % 2 != 0)
      os << "the sphere-type (closed) orbifold needs a closed connected orientable mesh, but V-E+F = " << chi
         << " (genus " << genus << ")";
  } else {
    if(b == 0)
      os << "the disk-type orbifold needs a mesh with one boundary loop, but the mesh is closed";
    else if(b != 1)
      os << "the disk-type orbifold needs a mesh with one boundary loop, but the mesh has "
         << plural(b, "boundary loop", "boundary loops");
    else if(chi != 1)
      os << "the disk-type orbifold needs a topological disk, but the mesh has genus " << genus
         << " (V-E+F = " << chi << ")";
  }
  return os.str();
}

// The note added to a topology failure when two border vertices have equal coordinates.
template <class TriangleMesh, class VertexPointMap, class VertexIndex>
std::string coincident_border_note(const TriangleMesh& tm, VertexPointMap vpm, const VertexIndex& vindex)
{
  std::size_t da = 0, db = 0;
  if(!coincident_border_vertices(tm, vpm, vindex, da, db))
    return std::string();
  std::ostringstream os;
  os << " (border vertices " << da << " and " << db << " have the same coordinates:"
     << " duplicated vertices that should be one?)";
  return os.str();
}

// 8. topology: fills the border loops, V-E+F, genus and type of `mi` (a `Mesh_info` whose
//    sizes are filled); the type is `required_type`, or detected from the boundary loops
template <class TriangleMesh, class VertexPointMap, class VertexIndex, class MeshInfo>
Status check_topology(const TriangleMesh& tm, VertexPointMap vpm, const VertexIndex& vindex,
                      std::optional<Orbifold_type> required_type, MeshInfo& mi)
{
  const auto loops = border_loops(tm);
  mi.number_of_border_loops = loops.size();
  mi.euler_characteristic = static_cast<long long>(mi.number_of_vertices)
                          - static_cast<long long>(mi.number_of_edges)
                          + static_cast<long long>(mi.number_of_faces);
  mi.genus = genus_of_surface(mi.euler_characteristic, mi.number_of_border_loops);

  const std::size_t b = mi.number_of_border_loops;
  Orbifold_type type;
  if(required_type) {
    type = *required_type;
  } else if(b == 0) {
    type = Sphere_type;
  } else if(b == 1) {
    type = Disk_type;
  } else {
    std::ostringstream os;
    os << "the mesh has " << b << " boundary loops: sphere-type orbifolds need a closed mesh"
       << " and disk-type orbifolds a mesh with one boundary loop"
       << coincident_border_note(tm, vpm, vindex) << describe_topology(tm, vpm, loops, mi.genus);
    return Status::failure(ERROR_WRONG_TOPOLOGY, os.str());
  }
  mi.type = type;

  const std::string reason = wrong_topology_reason(type, b, mi.euler_characteristic, mi.genus);
  if(!reason.empty()) {
    const bool note = b > (type == Sphere_type ? 0u : 1u);
    return Status::failure(ERROR_WRONG_TOPOLOGY, reason + (note ? coincident_border_note(tm, vpm, vindex) : std::string()) +
                                                   describe_topology(tm, vpm, loops, mi.genus));
  }
  mi.type_known = true;
  return Status();
}

} // namespace check_mesh_impl
} // namespace internal
} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_INPUT_TOPOLOGY_CHECK_H
