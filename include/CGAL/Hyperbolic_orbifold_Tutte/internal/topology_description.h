// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_TOPOLOGY_DESCRIPTION_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_TOPOLOGY_DESCRIPTION_H

#include <CGAL/Kernel_traits.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

// What a mesh is, said in the topology check's messages (genus, boundary loops and their
// sizes), so that a refusal states the mesh and not only the rule.

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {
namespace internal {
namespace check_mesh_impl {

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

} // namespace check_mesh_impl
} // namespace internal
} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_TOPOLOGY_DESCRIPTION_H
