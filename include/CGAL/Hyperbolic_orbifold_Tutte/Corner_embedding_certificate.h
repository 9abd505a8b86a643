// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_CORNER_EMBEDDING_CERTIFICATE_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_CORNER_EMBEDDING_CERTIFICATE_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Hyperbolic_orbifold_Tutte/Orbifold_type.h>

#include <array>
#include <cstddef>
#include <string>
#include <vector>

/// \file Corner_embedding_certificate.h

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {

/*!
\ingroup PkgHyperbolicOrbifoldTutteEnums

The checks of `certify_corner_embedding()`, in the order in which the first failure is
reported: where the points are, then each face, each vertex's star, each seam, the whole.
*/
enum Corner_embedding_check
{
  Repeated_face_check = 0,   ///< "repeated_face": no face of the embedding is given twice
  Mesh_face_check,           ///< "mesh_faces": the embedding's faces are the mesh's faces, with the mesh's orientation, each one once
  Finite_coordinates_check,  ///< "finite": no NaN or infinite coordinate
  Inside_disk_check,         ///< "inside_disk": every point strictly inside the unit disk (exact)
  Chart_check,               ///< "charts": the chart table (well-formed isometries centred at their tile corners), every chart point in the disk and at its point's place, one chart per face
  Cone_check,                ///< "cones": every cone at a tile corner of its own tile cone; on a disk, consecutive along the boundary
  Border_check,              ///< "border": every disk boundary vertex on the segment of its tile side
  Degenerate_face_check,     ///< "degenerate_face": no face with its three points on one geodesic (exact)
  Orientation_check,         ///< "orientation": every face positively oriented (exact)
  Angle_sum_check,           ///< "angle_sum": per mesh vertex, the angles of all its corners add up to its cone angle (certified)
  Seam_check,                ///< "seams": the two sides of every seam edge related by a side pairing of the tile
  Area_check                 ///< "area": the total hyperbolic area is the orbifold's (Gauss-Bonnet; certified)
};

/// the number of values of `Corner_embedding_check`
constexpr int number_of_corner_embedding_checks = Area_check + 1;

/// \ingroup PkgHyperbolicOrbifoldTutteHelperFunctions
/// the short name of a check (`"orientation"`, `"seams"`, ...), as the command line and its report write it
inline const char* check_name(Corner_embedding_check check)
{
  static const char* const names[] = {"repeated_face", "mesh_faces", "finite", "inside_disk", "charts", "cones", "border",
                                      "degenerate_face", "orientation", "angle_sum", "seams", "area"};
  static_assert(sizeof(names) / sizeof(names[0]) == number_of_corner_embedding_checks,
                "check_name(): one name per Corner_embedding_check value");
  const int i = static_cast<int>(check);
  return (i < 0 || i >= number_of_corner_embedding_checks) ? "unknown" : names[i];
}

/*!
\ingroup PkgHyperbolicOrbifoldTutteMainClasses

The verdict of `certify_corner_embedding()`: per check, whether it ran, how many elements it
checked and how many failed, and where and why the first one failed; what was found (the
cone order, the seams and the side pairings that glue them) and measured (the largest
deviations, the area). The map is certified a bijection onto the orbifold when
`is_certified()`.
*/
struct Corner_embedding_certificate
{
  /// what an element of a failure is
  enum Element_kind
  {
    No_element, ///< the whole embedding
    Face,       ///< a face of the embedding (0-based, in its order: the OBJ file's `f` lines)
    Mesh_face,  ///< a face of the mesh (0-based, in the order of `faces(tm)`)
    Vertex,     ///< a vertex of the mesh (0-based, in the order of `vertices(tm)`)
    Edge,       ///< an edge of the mesh, by its two vertices
    Chart       ///< a chart around a cone image (0-based, in the order of `Corner_embedding::charts`)
  };

  /// the outcome of one check
  struct Check_result
  {
    bool run = false;                   ///< `false` when an earlier failure left nothing to check it on
    std::size_t checked = 0;            ///< the number of elements checked
    std::size_t failures = 0;           ///< the number of elements that failed
    Element_kind element = No_element;  ///< the kind of the first failed element
    std::size_t first = 0;              ///< the first failed element (an edge's first vertex)
    std::size_t second = 0;             ///< an edge's second vertex
    std::string message;                ///< one line: the first failed element and why
  };

  /// the results, indexed by `Corner_embedding_check`
  std::array<Check_result, number_of_corner_embedding_checks> checks;

  Orbifold_type type = Sphere_type;  ///< the orbifold
  int number_of_cones = 0;           ///< its number of cones (sphere type) or corners (disk type)
  std::size_t number_of_faces = 0;   ///< faces of the embedding
  std::size_t number_of_vertices = 0; ///< vertices of the mesh
  std::size_t number_of_points = 0;  ///< points of the embedding
  std::size_t number_of_seam_edges = 0; ///< mesh edges whose two faces give different points to an end
  std::size_t number_of_border_vertices = 0; ///< vertices on the mesh's boundary (disk type)
  std::size_t number_of_charts = 0;        ///< charts around cone images (`Corner_embedding::charts`)
  std::size_t number_of_chart_points = 0;  ///< points given in a chart
  std::size_t number_of_charted_faces = 0; ///< faces checked in a chart's coordinates
  std::size_t number_of_mixed_faces = 0;   ///< charted faces with a corner brought into the chart from its tile point
  std::size_t number_of_chart_seam_edges = 0; ///< seam edges between two charts of one cone (glued by a rotation about the origin)
  /// for each given cone, the tile cone at whose corner it was found (-1: none); the cone order
  std::vector<int> cone_order;
  /// for each given cone, the order of the tile cone at whose corner it was found (the tile's
  /// angles at that cone's corners add up to \f$2\pi\f$ over it; \f$\pi\f$ over it at a
  /// disk's corner), 0 when none: what the certified map has there, checked equal to the given order
  std::vector<int> cone_orders;
  /// for each given cone, its order measured on the cones' points alone: \f$2\pi\f$
  /// (\f$\pi\f$ at a disk's corner) over the sum of the hyperbolic angles at its points of
  /// the polygon that the cones' points form in the order of their arguments about the tile's
  /// centre (the tile itself when the map is right); NaN when the points cannot form it (a
  /// point not valid, more or fewer points than the tile's corners). Informative: no check
  /// depends on it, the message of a cone at no corner cites it when the orders given differ
  std::vector<double> measured_cone_orders;
  /// for each side of the tile, the number of seam edges glued by its side pairing
  std::vector<std::size_t> seam_edges_per_side;

  double max_seam_mismatch = 0;          ///< largest distance of a seam copy from its twin's image by the side pairing (disk coordinates)
  double max_relative_seam_mismatch = 0; ///< the same, relative to the seam edge's length
  double max_seam_isometry_deviation = 0; ///< largest relative coefficient distance of a seam's isometry from its side pairing
  double max_cone_distance = 0;          ///< largest distance of a cone's point from its tile corner
  double max_border_distance = 0;        ///< largest distance of a disk boundary point from its side's segment
  double max_angle_sum_deviation = 0;    ///< largest |angle sum - cone angle| (radians; middle of the enclosure)
  double max_angle_sum_uncertainty = 0;  ///< largest width of an angle sum's certified enclosure
  double max_chart_origin_offset = 0;    ///< largest distance of a chart's origin (its preimage) from its tile corner (upper bound)
  double max_chart_point_offset = 0;     ///< largest distance of a chart point's tile point from its point, relative to its bound
  double max_chart_seam_mismatch = 0;    ///< largest mismatch across a seam between charts of one cone, relative to the points' distance to the origin
  double max_mixed_corner_error = 0;     ///< largest error bound of a corner brought into a chart (chart coordinates)
  double area_lower = 0;                 ///< the total hyperbolic area is at least this (certified)
  double area_upper = 0;                 ///< and at most this
  double expected_area = 0;              ///< the orbifold's area (Gauss-Bonnet)

  /// the genus of the closed surface (0 for a sphere or a disk); for genus \f$g \ge 1\f$ the
  /// map is certified without a tile (see `certify_corner_embedding()`): the seams' isometries
  /// are computed from their copies, and the fields below report them
  int genus = 0;
  std::size_t number_of_seam_consistency_checks = 0; ///< genus \f$g \ge 1\f$: pairs of seam edges at a common vertex copy checked to share their isometry
  std::size_t number_of_seam_isometries = 0;  ///< genus \f$g \ge 1\f$: classes of seam edges sharing one isometry (linked by those checks): the cut's sides glued pairwise
  double max_seam_length_mismatch = 0;        ///< genus \f$g \ge 1\f$: largest distance of a seam edge's far copy from its image by the isometry fixed by the near ends (unequal hyperbolic lengths; disk coordinates)
  double max_seam_consistency_mismatch = 0;   ///< genus \f$g \ge 1\f$: largest distance of a seam copy from its twin's image by the isometry of an adjacent seam edge (disk coordinates)
  double angle_sum_tolerance = 0;             ///< genus \f$g \ge 1\f$: the largest accepted |angle sum - cone angle| (radians, certified); 0: the window of genus 0 (\f$\pi/2\f$, \f$\pi/p\f$)

  double absolute_tolerance = 0; ///< the positions' tolerance (disk coordinates)
  double relative_tolerance = 0; ///< the positions' tolerance relative to the shortest incident edge

  /// the result of `check`
  const Check_result& result(Corner_embedding_check check) const { return checks[check]; }

  /// the first failed check in the order of `Corner_embedding_check`, or -1 when none failed
  int first_failed_check() const
  {
    for(int i = 0; i < number_of_corner_embedding_checks; ++i)
      if(checks[i].failures > 0)
        return i;
    return -1;
  }

  /// `true` when every check ran on a non-empty embedding and none failed: the map is a
  /// bijection of the mesh onto the orbifold
  bool is_certified() const
  {
    if(number_of_faces == 0)
      return false;
    for(const Check_result& c : checks)
      if(!c.run || c.failures > 0)
        return false;
    return true;
  }

  /// one line: `"certified"`, or the first failed check's name and message
  std::string summary() const
  {
    const int f = first_failed_check();
    if(f >= 0)
      return std::string(check_name(static_cast<Corner_embedding_check>(f))) + ": " + checks[f].message;
    if(is_certified())
      return "certified";
    return "not certified: the embedding is empty";
  }
};

} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_CORNER_EMBEDDING_CERTIFICATE_H
