// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_ERROR_CODE_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_ERROR_CODE_H

/// \file error_code.h

#include <string>

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {

/*!
\ingroup PkgHyperbolicOrbifoldTutteEnums

The outcome of the package's operations. Every failure caused by the data
(mesh, landmarks, numbers) is reported with one of these codes, never with an
assertion. `error_message()` gives a one-line English description.

Surface_mesh_parameterization's `Error_code` has too few values to say which of
the many input checks failed, hence this richer enumeration.
*/
enum Error_code
{
  OK = 0,                        ///< success
  ERROR_NOT_HYPERBOLIC,          ///< the orbifold signature is not hyperbolic (e.g. fewer than 5 cones)
  ERROR_WRONG_PARAMETER,         ///< a parameter is out of its documented range
  ERROR_EMPTY_MESH,              ///< the mesh has no face
  ERROR_NON_TRIANGULAR_MESH,     ///< a face is not a triangle
  ERROR_NON_MANIFOLD,            ///< the mesh is not a valid 2-manifold (with or without boundary)
  ERROR_SEVERAL_COMPONENTS,      ///< the mesh has more than one connected component
  ERROR_WRONG_TOPOLOGY,          ///< the mesh's topology does not match the orbifold (genus, boundaries)
  ERROR_TOO_FEW_LANDMARKS,       ///< fewer landmarks than the orbifold needs
  ERROR_DUPLICATE_LANDMARK,      ///< a landmark is given twice
  ERROR_LANDMARK_OUT_OF_RANGE,   ///< a landmark index is not a vertex of the mesh
  ERROR_LANDMARK_NOT_ON_BORDER,  ///< a disk-type landmark is not on the boundary loop
  ERROR_DEGENERATE_FACE,         ///< a face has zero area or repeated vertices
  ERROR_NON_FINITE_COORDINATES,  ///< a coordinate is NaN or infinite, or a face's lengths or area overflow or underflow in double precision
  ERROR_CUT_FAILED,              ///< the mesh could not be cut open through the landmarks
  ERROR_CANNOT_SOLVE_LINEAR_SYSTEM, ///< a sparse linear solve failed
  ERROR_NOT_CONVERGED,           ///< the nonlinear solver did not reach its tolerance
  ERROR_NO_1_TO_1_MAPPING,       ///< the result failed the bijectivity certificate
  ERROR_POINT_NOT_LOCATED,       ///< a point could not be located in an embedding
  ERROR_READ_FAILED,             ///< an input file could not be read or parsed
  ERROR_WRITE_FAILED,            ///< an output file could not be written
  ERROR_BOUNDARY_CHORD,          ///< disk type: an inner edge joins two boundary vertices of one tile side (e.g. a boundary ear), whose triangles would be degenerate
  ERROR_POLYGON_NOT_CONVEX,      ///< fixed boundary: the target polygon is not strictly convex, or a corner is not strictly inside the unit disk
  ERROR_CORNERS_NOT_IN_BOUNDARY_ORDER ///< fixed boundary: the corner vertices are not in the order of the boundary loop
};

/// the number of values of `Error_code`
constexpr int number_of_error_codes = ERROR_CORNERS_NOT_IN_BOUNDARY_ORDER + 1;

/*!
\ingroup PkgHyperbolicOrbifoldTutteEnums
returns a one-line description of `code`, never a null pointer.
\param code any value (out-of-range values give "Unknown error code")
\return a static, null-terminated English sentence
*/
inline const char* error_message(Error_code code)
{
  static const char* const messages[] = {
    "Success",
    "The orbifold is not hyperbolic (genus 0: at least 5 cones of angle pi, or cones of orders p with sum(1 - 1/p) > 2; genus 1: a cone)",
    "A parameter is out of its range",
    "The mesh is empty",
    "The mesh has a face that is not a triangle",
    "The mesh is not a valid 2-manifold",
    "The mesh has more than one connected component",
    "The mesh's topology does not match the orbifold (sphere type needs a closed mesh, disk type a disk)",
    "Too few landmarks for a hyperbolic orbifold (genus 0: at least 5 cones of angle pi, or 3 with cone orders above 2; genus 1: at least 1; genus 2 or more: none needed)",
    "A landmark is given twice",
    "A landmark index is not a vertex of the mesh",
    "A disk-type landmark is not on the boundary loop",
    "The mesh has a degenerate face",
    "The mesh has a NaN or infinite coordinate, or coordinates too large or too small for double precision",
    "The mesh could not be cut open through the landmarks",
    "A sparse linear system could not be solved",
    "The nonlinear solver did not converge",
    "The result is not certified bijective",
    "A point could not be located in the embedding",
    "An input file could not be read",
    "An output file could not be written",
    "An inner edge joins two boundary vertices that map to the same side of the disk orbifold's tile (e.g. a boundary ear); its triangles would be degenerate: put a landmark on the boundary between its ends, or split the triangle",
    "The target polygon is not strictly convex, or a corner is not strictly inside the unit disk",
    "The corner vertices are not in the order of the boundary loop (in either direction)"
  };
  static_assert(sizeof(messages) / sizeof(messages[0]) == number_of_error_codes,
                "error_message(): one message per Error_code value");
  const int i = static_cast<int>(code);
  if(i < 0 || i >= number_of_error_codes)
    return "Unknown error code";
  return messages[i];
}

/*!
\ingroup PkgHyperbolicOrbifoldTutteMainClasses
the outcome of an operation, the one way the package reports an error: `code == OK`, or an
error code with a one-line message saying what is wrong and where (`message` may then be
more specific than `error_message(code)`).
*/
struct Status
{
  Error_code code = OK;   ///< `OK` on success
  std::string message;    ///< one line; empty on success
  /// `true` on success
  operator bool() const { return code == OK; }
  /// a failure with `message`, or with `error_message(code)` when `message` is empty
  static Status failure(Error_code code, const std::string& message = std::string())
  {
    Status s;
    s.code = code;
    s.message = message.empty() ? std::string(error_message(code)) : message;
    return s;
  }
};

} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_ERROR_CODE_H
