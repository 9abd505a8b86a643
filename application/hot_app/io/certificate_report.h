// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_TOOLS_IO_CERTIFICATE_REPORT_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_TOOLS_IO_CERTIFICATE_REPORT_H

// The JSON report of the `certify` command: what was asked, the verdict, and every count and
// measurement of the certificate (Corner_embedding_certificate).

#include <CGAL/Hyperbolic_orbifold_Tutte/Corner_embedding_certificate.h>

#include "reports.h" // json_escape()

#include <cmath>
#include <cstddef>
#include <ostream>
#include <sstream>
#include <string>
#include <vector>

#include <CGAL/disable_warnings.h>

/// \file certificate_report.h

namespace hot_tools {

// what `certify` was asked to check
struct Certify_request
{
  std::string mesh_path, embedding_path, cones_path;
  std::vector<std::size_t> cones;   // 0-based vertex indices, as given
  std::vector<int> cone_orders;     // as given, or empty (all 2)
  double time_read = 0, time_certify = 0; // seconds
  std::size_t chart_points = 0;     // '# hot vtc' lines of the file (points in charts; read)
};

namespace io_impl {

// a number, or null when it is not finite (JSON has no NaN nor infinity)
inline std::string json_number(double x)
{
  if(!std::isfinite(x))
    return "null";
  std::ostringstream os;
  os.precision(17);
  os << x;
  return os.str();
}

inline const char* element_name(HOT::Corner_embedding_certificate::Element_kind k)
{
  typedef HOT::Corner_embedding_certificate C;
  switch(k) {
  case C::Face: return "face";
  case C::Mesh_face: return "mesh_face";
  case C::Vertex: return "vertex";
  case C::Edge: return "edge";
  case C::Chart: return "chart";
  default: return "embedding";
  }
}

} // namespace io_impl

inline void write_certificate_report(std::ostream& os, const Certify_request& q, const HOT::Corner_embedding_certificate& c)
{
  using io_impl::json_number;
  typedef HOT::Corner_embedding_certificate C;
  const int first = c.first_failed_check();
  os << "{\n  \"mesh\": \"" << json_escape(q.mesh_path) << "\",\n  \"embedding\": \"" << json_escape(q.embedding_path)
     << "\",\n  \"cones_file\": \"" << json_escape(q.cones_path) << "\",\n  \"cones\": [";
  for(std::size_t i = 0; i < q.cones.size(); ++i) os << (i ? ", " : "") << q.cones[i];
  os << "],\n  \"cone_orders\": [";
  for(std::size_t i = 0; i < q.cones.size(); ++i) os << (i ? ", " : "") << (q.cone_orders.empty() ? 2 : q.cone_orders[i]);
  os << "],\n  \"orbifold\": \"" << (c.type == HOT::Sphere_type ? "sphere" : "disk") << "\",\n"
     << "  \"genus\": " << c.genus << ",\n"
     << "  \"certified\": " << (c.is_certified() ? "true" : "false") << ",\n"
     << "  \"first_failed_check\": ";
  if(first >= 0)
    os << "\"" << HOT::check_name(static_cast<HOT::Corner_embedding_check>(first)) << "\"";
  else
    os << "null";
  os << ",\n  \"summary\": \"" << json_escape(c.summary()) << "\",\n"
     << "  \"vertices\": " << c.number_of_vertices << ",\n  \"faces\": " << c.number_of_faces << ",\n  \"points\": "
     << c.number_of_points << ",\n  \"seam_edges\": " << c.number_of_seam_edges << ",\n  \"border_vertices\": "
     << c.number_of_border_vertices << ",\n  \"chart_points_not_read\": 0"
     << ",\n  \"charts\": " << c.number_of_charts << ",\n  \"chart_points\": " << c.number_of_chart_points
     << ",\n  \"chart_vtc_lines\": " << q.chart_points << ",\n  \"charted_faces\": " << c.number_of_charted_faces
     << ",\n  \"mixed_faces\": " << c.number_of_mixed_faces << ",\n  \"chart_seam_edges\": " << c.number_of_chart_seam_edges
     << ",\n  \"cone_order\": [";
  for(std::size_t i = 0; i < c.cone_order.size(); ++i) os << (i ? ", " : "") << c.cone_order[i];
  // per given cone, the order of the tile cone it was found at (0: none), and its order measured
  // on the cones' points alone (null: not measured)
  os << "],\n  \"cone_orders_found\": [";
  for(std::size_t i = 0; i < c.cone_orders.size(); ++i) os << (i ? ", " : "") << c.cone_orders[i];
  os << "],\n  \"cone_orders_measured\": [";
  for(std::size_t i = 0; i < c.measured_cone_orders.size(); ++i) os << (i ? ", " : "") << json_number(c.measured_cone_orders[i]);
  os << "],\n  \"seam_edges_per_side\": [";
  for(std::size_t i = 0; i < c.seam_edges_per_side.size(); ++i) os << (i ? ", " : "") << c.seam_edges_per_side[i];
  os << "],\n  \"checks\": {\n";
  for(int i = 0; i < HOT::number_of_corner_embedding_checks; ++i) {
    const C::Check_result& r = c.checks[i];
    os << "    \"" << HOT::check_name(static_cast<HOT::Corner_embedding_check>(i)) << "\": {\"run\": " << (r.run ? "true" : "false")
       << ", \"checked\": " << r.checked << ", \"failures\": " << r.failures << ", \"first_failure\": ";
    if(r.failures == 0) {
      os << "null";
    } else {
      os << "{\"element\": \"" << io_impl::element_name(r.element) << "\"";
      if(r.element == C::Edge)
        os << ", \"vertices\": [" << r.first << ", " << r.second << "]";
      else if(r.element != C::No_element)
        os << ", \"index\": " << r.first;
      os << ", \"message\": \"" << json_escape(r.message) << "\"}";
    }
    os << "}" << (i + 1 < HOT::number_of_corner_embedding_checks ? "," : "") << "\n";
  }
  os << "  },\n  \"measurements\": {\"max_seam_mismatch\": " << json_number(c.max_seam_mismatch)
     << ", \"max_relative_seam_mismatch\": " << json_number(c.max_relative_seam_mismatch)
     << ", \"max_seam_isometry_deviation\": " << json_number(c.max_seam_isometry_deviation)
     << ",\n    \"max_cone_distance\": " << json_number(c.max_cone_distance)
     << ", \"max_border_distance\": " << json_number(c.max_border_distance)
     << ",\n    \"max_angle_sum_deviation\": " << json_number(c.max_angle_sum_deviation)
     << ", \"max_angle_sum_uncertainty\": " << json_number(c.max_angle_sum_uncertainty)
     << ",\n    \"area\": [" << json_number(c.area_lower) << ", " << json_number(c.area_upper)
     << "], \"expected_area\": " << json_number(c.expected_area)
     << ",\n    \"max_chart_origin_offset\": " << json_number(c.max_chart_origin_offset)
     << ", \"max_chart_point_offset_relative_to_bound\": " << json_number(c.max_chart_point_offset)
     << ",\n    \"max_chart_seam_mismatch_relative\": " << json_number(c.max_chart_seam_mismatch)
     << ", \"max_mixed_corner_error\": " << json_number(c.max_mixed_corner_error)
     << ",\n    \"seam_consistency_checks\": " << c.number_of_seam_consistency_checks
     << ", \"seam_isometries\": " << c.number_of_seam_isometries
     << ", \"max_seam_length_mismatch\": " << json_number(c.max_seam_length_mismatch)
     << ", \"max_seam_consistency_mismatch\": " << json_number(c.max_seam_consistency_mismatch) << "},\n"
     << "  \"tolerances\": {\"position_absolute\": " << json_number(c.absolute_tolerance)
     << ", \"position_relative_to_shortest_edge\": " << json_number(c.relative_tolerance)
     << ", \"angle_sum\": " << json_number(0.5 * CGAL_PI) << ", \"area_relative\": 0.5"
     << ", \"chart_origin\": " << json_number(64 * 1.1102230246251565e-16)
     << ", \"angle_sum_closed_genus\": " << json_number(c.angle_sum_tolerance) << "},\n"
     << "  \"time_seconds\": {\"read\": " << json_number(q.time_read) << ", \"certify\": " << json_number(q.time_certify) << "}\n}\n";
}

} // namespace hot_tools

#include <CGAL/enable_warnings.h>

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_TOOLS_IO_CERTIFICATE_REPORT_H
