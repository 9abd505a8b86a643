// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_READ_CONES_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_READ_CONES_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Hyperbolic_orbifold_Tutte/error_code.h>

#include <CGAL/Surface_mesh_parameterization/Error_code.h>
#include <CGAL/boost/graph/iterator.h>

#include <cstddef>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

/// \file read_cones.h

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {

/*!
\ingroup PkgHyperbolicOrbifoldTutteHelperFunctions

reads the cones of an orbifold from the first line of `filename` (the format of CGAL's
`.selection.txt` files: the vertex indices of the first line; the seam edges of its third
line are read by `CGAL::Seam_mesh::add_seams()`), with the signature of
`Surface_mesh_parameterization::read_cones()` but any number of cones (that function
refuses more than 4). Index `i` is the `i`-th vertex of `vertices(tm)`. The cones are
written to `out` in the file's order, which is the order of the seam that
`SMP::compute_shortest_paths_between_cones()` cuts through them.

\tparam TriangleMesh a model of `FaceGraph`
\tparam VertexDescriptorOutputIterator an output iterator of `vertex_descriptor`s of `TriangleMesh`
\param tm the mesh
\param filename the selection file
\param out receives the cones' vertex descriptors, in the file's order
\param status if not null, receives the package's `Error_code` and a one-line message
\return `SMP::OK`, or `SMP::ERROR_WRONG_PARAMETER` when the file cannot be read, its first
        line holds something other than non-negative integers or nothing, an index is not
        a vertex of `tm`, or an index is repeated; nothing is written to `out` then.
*/
template <class TriangleMesh, class VertexDescriptorOutputIterator>
Surface_mesh_parameterization::Error_code read_cones(const TriangleMesh& tm, const char* filename,
                                                     VertexDescriptorOutputIterator out, Status* status = nullptr)
{
  Status local;
  Status& st = status ? *status : local;
  auto fail = [&](Error_code code, const std::string& why) {
    st = Status::failure(code, std::string("read_cones: ") + filename + ": " + why);
    return Surface_mesh_parameterization::ERROR_WRONG_PARAMETER;
  };
  std::ifstream in(filename);
  std::string line;
  if(!in || !std::getline(in, line))
    return fail(ERROR_READ_FAILED, "cannot be read");
  std::istringstream tokens(line);
  std::vector<std::size_t> indices;
  std::set<std::size_t> seen;
  const std::size_t n = num_vertices(tm);
  for(std::string t; tokens >> t;) {
    if(t.find_first_not_of("0123456789") != std::string::npos || t.size() > 18)
      return fail(ERROR_READ_FAILED, "'" + t + "' on the first line is not a vertex index");
    const std::size_t i = std::stoull(t);
    if(i >= n)
      return fail(ERROR_LANDMARK_OUT_OF_RANGE, "index " + t + " is not a vertex of the mesh (" + std::to_string(n) +
                                                 " vertices)");
    if(!seen.insert(i).second)
      return fail(ERROR_DUPLICATE_LANDMARK, "index " + t + " is given twice");
    indices.push_back(i);
  }
  if(indices.empty())
    return fail(ERROR_TOO_FEW_LANDMARKS, "the first line holds no cone");
  std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor> by_index(vertices(tm).begin(),
                                                                                      vertices(tm).end());
  for(std::size_t i : indices)
    *out++ = by_index[i];
  st = Status();
  return Surface_mesh_parameterization::OK;
}

/// \ingroup PkgHyperbolicOrbifoldTutteHelperFunctions
/// `read_cones()` with the file name as a `std::string`
template <class TriangleMesh, class VertexDescriptorOutputIterator>
Surface_mesh_parameterization::Error_code read_cones(const TriangleMesh& tm, const std::string& filename,
                                                     VertexDescriptorOutputIterator out, Status* status = nullptr)
{
  return read_cones(tm, filename.c_str(), out, status);
}

} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_READ_CONES_H
