// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_TOOLS_IO_READ_AND_CHECK_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_TOOLS_IO_READ_AND_CHECK_H

// Readers for the command-line program: meshes and landmark files, with a specific
// `Error_code` and a one-line message (starting with the file name) for every bad
// input, and no assertion, exception, huge allocation or hang on hostile files.
//
// Meshes (`read_mesh()`): the file is read as a polygon soup (read_polygon_soup.h, one
// parser per format: off.h, obj.h, ply.h, stl.h, gocad.h), the soup is validated
// (validate_polygon_soup.h), then converted to the mesh by a linear-time builder of our
// own (polygon_soup_to_mesh.h). Landmark files: landmarks.h. This header includes them all.

#include "common.h"
#include "landmarks.h"
#include "polygon_soup.h"
#include "polygon_soup_to_mesh.h"
#include "read_polygon_soup.h"
#include "timings.h"
#include "validate_polygon_soup.h"

#include <CGAL/Hyperbolic_orbifold_Tutte/check_input.h>

#include <CGAL/boost/graph/helpers.h>

#include <boost/graph/graph_traits.hpp>

#include <optional>
#include <string>
#include <vector>

#include <CGAL/disable_warnings.h>

/// \file read_and_check.h

namespace hot_tools {

/*!
Reads a mesh file into `mesh` (cleared first; left empty on failure), keeping the
file's vertex and face order. Errors: ERROR_READ_FAILED (missing / unreadable file,
unsupported extension, parse error, truncated file, implausible counts, out-of-range
index), then the soup errors of `validate_polygon_soup()`. Quads and other polygons,
isolated vertices, several components etc. are read without error; `check_mesh()`
reports them. Every message starts with the file name.
*/
template <class PolygonMesh>
HOT::Status read_mesh(const std::string& path, PolygonMesh& mesh)
{
  CGAL::clear(mesh);
  Polygon_soup soup;
  HOT::Status r = read_polygon_soup_file(path, soup);
  if(!r)
    return r;
  r = polygon_soup_to_mesh(soup, mesh);
  if(!r) {
    CGAL::clear(mesh);
    r.message = path + ": " + r.message;
  }
  return r;
}

// ---------------------------------------------------------------------------
// Reading and checking, as the command-line program does (and the fuzz target)
// ---------------------------------------------------------------------------

/*!
Reads the mesh file `path` (`read_mesh()`) and checks it (`check_mesh()`) for
`required_type`, or, if `std::nullopt`, for the type of its topology; `info` (if not
null) receives the required or detected type. Every message starts with the file name.
A mesh that is neither closed nor a disk gets the first failing check of `check_mesh()`
as its reason (no face, isolated vertex, several components, ..., boundary loops).
*/
template <class TriangleMesh>
HOT::Status read_and_check_mesh(const std::string& path, std::optional<HOT::Orbifold_type> required_type,
                                 TriangleMesh& mesh, HOT::Mesh_info* info = nullptr)
{
  HOT::Status r = read_mesh(path, mesh); // its messages already start with the file name
  if(!r)
    return r;
  r = HOT::check_mesh(mesh, required_type, info);
  timings().phase("check_mesh");
  if(!r)
    r.message = path + ": " + r.message;
  return r;
}

/*!
Reads the landmark file `path` (`read_landmarks()`) and checks the indices against
`mesh` (`check_landmarks()`, which fills `landmarks` on success). Every message starts
with the file name. Precondition: `check_mesh()` succeeded on `mesh` for `type`.
*/
template <class TriangleMesh>
HOT::Status read_and_check_landmarks(const std::string& path, const TriangleMesh& mesh, HOT::Orbifold_type type,
                                      std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>& landmarks,
                                      std::size_t minimum = HOT::minimum_number_of_landmarks)
{
  landmarks.clear();
  minimum = HOT::minimum_number_of_landmarks_of(mesh, type, minimum); // (genus g >= 1: 1 or none)
  std::vector<std::size_t> indices;
  HOT::Status r = read_landmarks(path, indices, minimum <= 1); // (genus g >= 1: check_landmarks() says how many) // its messages already start with the file name
  if(!r)
    return r;
  r = HOT::check_landmarks(mesh, indices, type, landmarks, minimum);
  timings().phase("landmarks");
  if(!r)
    r.message = path + ": " + r.message;
  return r;
}

} // namespace hot_tools

#include <CGAL/enable_warnings.h>

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_TOOLS_IO_READ_AND_CHECK_H
