// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_TOOLS_IO_REPORTS_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_TOOLS_IO_REPORTS_H

// The JSON reports of the `embed`, `map` and `collection` commands.

#include <CGAL/Hyperbolic_orbifold_Tutte/Embedding_certificate.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/Embedding_statistics.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/Orbifold_tile.h> // Orbifold_type
#include <CGAL/Hyperbolic_orbifold_Tutte/map_reliability.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/map_distortion.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/Map_refinement_statistics.h>

#include <cstddef>
#include "prepared_input.h"

#include <cmath>
#include <cstdio>
#include <ostream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <CGAL/disable_warnings.h>

/// \file reports.h

namespace hot_tools {

namespace HOT = CGAL::Hyperbolic_orbifold_Tutte;

// `s` as the inside of a JSON string
inline std::string json_escape(const std::string& s)
{
  std::string r;
  for(char c : s) {
    if(c == '"' || c == '\\') { r += '\\'; r += c; }
    else if(static_cast<unsigned char>(c) < 0x20) { char b[8]; std::snprintf(b, sizeof(b), "\\u%04x", c); r += b; }
    else r += c;
  }
  return r;
}

// `"repair": {...}` for a mesh read with --repair: every count of the preparation, the holes
// filled and the chords split (vertex numbers as in the written files), and a summary line
inline void write_repair_json(std::ostream& os, const HOT::Mesh_preparation& p, const char* indent)
{
  os << "{\"summary\": \"" << json_escape(p.summary()) << "\", \"input_vertices\": " << p.number_of_input_vertices
     << ", \"input_faces\": " << p.number_of_input_faces << ", \"added_vertices\": " << p.number_of_added_vertices()
     << ",\n" << indent << " \"merged_duplicate_vertices\": " << p.merged_duplicate_vertices << ", \"isolated_vertices\": " << p.isolated_vertices
     << ", \"invalid_faces_removed\": " << p.invalid_faces_removed << ", \"duplicate_faces_removed\": " << p.duplicate_faces_removed
     << ", \"reoriented_faces\": " << p.reoriented_faces << ", \"non_manifold_vertices_split\": " << p.non_manifold_vertices_split
     << ",\n" << indent << " \"polygons_triangulated\": " << p.polygons_triangulated << ", \"triangles_from_polygons\": " << p.triangles_from_polygons
     << ", \"degenerate_faces_removed\": " << p.degenerate_faces_removed << ", \"components_removed\": " << p.components_removed
     << ", \"component_faces_removed\": " << p.component_faces_removed << ", \"debris_components_removed\": " << p.debris_components_removed
     << ", \"faces_added_by_hole_filling\": " << p.faces_added_by_hole_filling()
     << ", \"landmarks_decided\": " << (p.landmarks_decided ? "true" : "false")
     << ",\n" << indent << " \"filled_holes\": [";
  for(std::size_t i = 0; i < p.filled_holes.size(); ++i) {
    const HOT::Filled_hole& h = p.filled_holes[i];
    os << (i ? ", " : "") << "{\"vertex\": " << h.vertex << ", \"boundary_vertices\": " << h.boundary_vertices
       << ", \"boundary_length\": " << h.boundary_length << ", \"faces_added\": " << h.faces_added
       << ", \"vertices_added\": " << h.vertices_added << ", \"faired\": " << (h.faired ? "true" : "false") << "}";
  }
  os << "],\n" << indent << " \"split_chords\": [";
  for(std::size_t i = 0; i < p.split_chords.size(); ++i)
    os << (i ? ", " : "") << "[" << p.split_chords[i].first << ", " << p.split_chords[i].second << "]";
  os << "],\n" << indent << " \"cut_handles\": [";
  for(std::size_t i = 0; i < p.cut_handles.size(); ++i) {
    os << (i ? ", " : "") << "{\"length\": " << p.cut_handles[i].length << ", \"vertices\": [";
    for(std::size_t j = 0; j < p.cut_handles[i].vertices.size(); ++j) os << (j ? ", " : "") << p.cut_handles[i].vertices[j];
    os << "]}";
  }
  os << "]}";
}

// `[{"landmark": i, "from": a, "to": b, "distance": d}, ...]` for --snap-landmarks
inline void write_snaps_json(std::ostream& os, const std::vector<Landmark_snap_record>& snaps)
{
  os << "[";
  for(std::size_t i = 0; i < snaps.size(); ++i)
    os << (i ? ", " : "") << "{\"landmark\": " << snaps[i].landmark << ", \"from\": " << snaps[i].from << ", \"to\": "
       << snaps[i].to << ", \"distance\": " << snaps[i].distance << "}";
  os << "]";
}

// what `embed` was asked to do, as its report repeats it
struct Embedding_request
{
  std::string mesh_path;
  std::vector<std::size_t> cones;          // the landmarks as given: 0-based vertex indices
  HOT::Orbifold_type type = HOT::Sphere_type;
  std::string weights = "cotan";           // cotan, mvc or uniform (the report says mvc after a mean value fallback)
  std::string order;                       // given, tsp or explicit (--order I0,I1,...)
  const Input_mesh* input = nullptr;       // with --repair: the preparation (reported)
  const std::vector<Landmark_snap_record>* snaps = nullptr; // with --snap-landmarks
};

// Writes the report of `embed`: the request, the mesh's sizes, the landmark order used, and
// the statistics of the embedding (timings, solver, recentring frame, certificate).
inline void write_embedding_report(std::ostream& os, const Embedding_request& request, std::size_t vertices,
                                   std::size_t faces, const HOT::Embedding_statistics& st)
{
  const std::vector<std::size_t>& cone_indices = request.cones;
  const HOT::Embedding_certificate& c = st.certificate;
  os.precision(17);
  os << "{\n  \"mesh\": \"" << json_escape(request.mesh_path) << "\",\n"
     << "  \"vertices\": " << vertices << ",\n  \"faces\": " << faces << ",\n";
  if(request.input && request.input->repaired) {
    os << "  \"repair\": ";
    write_repair_json(os, request.input->prep, "  ");
    os << ",\n";
  }
  if(request.snaps) {
    os << "  \"snapped_landmarks\": ";
    write_snaps_json(os, *request.snaps);
    os << ",\n";
  }
  os << "  \"cones\": [";
  for(std::size_t i = 0; i < cone_indices.size(); ++i) os << (i ? ", " : "") << cone_indices[i];
  os << "],\n  \"orbifold\": \"" << (request.type == HOT::Sphere_type ? "sphere" : "disk") << "\",\n"
     << "  \"weights\": \"" << (st.mean_value_fallback ? std::string("mvc") : request.weights) << "\",\n  \"order\": \"" << request.order << "\",\n"
     << "  \"landmark_order_used\": [";
  for(std::size_t i = 0; i < st.landmark_order.size(); ++i)
    os << (i ? ", " : "") << cone_indices[st.landmark_order[i]];
  os << "],\n  \"landmark_positions_used\": ["; // (the same, as 0-based lines of the landmark file: --order takes them)
  for(std::size_t i = 0; i < st.landmark_order.size(); ++i)
    os << (i ? ", " : "") << st.landmark_order[i];
  os << "],\n  \"cone_orders\": ["; // (of the cones of landmark_order_used: cone angle 2 pi / order)
  for(std::size_t i = 0; i < st.cone_orders.size(); ++i)
    os << (i ? ", " : "") << st.cone_orders[i];
  os << "],\n  \"landmark_order_reversed\": " << (st.landmark_order_reversed ? "true" : "false") << ",\n"
     << "  \"genus\": " << st.genus << ",\n";
  if(st.genus > 0) { // the polygon of the cut graph (its tile: make_cut_graph_tile())
    auto list = [&](const std::vector<int>& v, bool vertices) {
      os << "[";
      for(std::size_t i = 0; i < v.size(); ++i)
        os << (i ? ", " : "")
           << (vertices && request.input && request.input->repaired ? static_cast<long long>(request.input->prep.output_index[v[i]])
                                                                      : static_cast<long long>(v[i]));
      os << "]";
    };
    os << "  \"cut_graph\": {\"corner_nodes\": ";
    list(st.cut_corner_nodes, false);
    os << ", \"node_vertices\": ";
    list(st.cut_node_vertices, true);
    os << ", \"node_cones\": ";
    list(st.cut_node_cones, false);
    os << ", \"paired_sides\": ";
    list(st.cut_paired_sides, false);
    os << "},\n";
  }
  os << "  \"cut_mesh_vertices\": " << st.number_of_vertices << ",\n"
     << "  \"time_seconds\": {\"setup_and_cut\": " << st.time_setup << ", \"initialization\": "
     << st.time_initialization << ", \"optimization\": " << st.time_optimization << ", \"certificate\": "
     << st.time_certificate << "},\n"
     << "  \"iterations\": " << st.iterations << ",\n  \"initial_energy\": " << st.initial_energy << ",\n"
     << "  \"energy\": " << st.energy << ",\n  \"relative_gradient_norm\": " << st.relative_gradient_norm << ",\n"
     << "  \"rounding_floor\": " << st.rounding_floor << ",\n  \"converged_at_rounding_floor\": "
     << (st.converged_at_rounding_floor ? "true" : "false") << ",\n  \"polishing_iterations\": " << st.polishing_iterations
     << ",\n  \"repaired_vertices\": " << st.repaired_vertices << ",\n"
     << "  \"recentred\": " << (st.recentred ? "true" : "false") << ",\n  \"frame\": {\"a\": ["
     << st.frame.a().real() << ", " << st.frame.a().imag() << "], \"b\": [" << st.frame.b().real() << ", " << st.frame.b().imag()
     << "]},\n"
     << "  \"charted_faces\": " << st.charted_faces << ",\n  \"charts\": [";
  for(std::size_t i = 0; i < st.charts.size(); ++i)
    os << (i ? ", " : "") << "{\"a\": [" << st.charts[i].a().real() << ", " << st.charts[i].a().imag() << "], \"b\": ["
       << st.charts[i].b().real() << ", " << st.charts[i].b().imag() << "], \"tile_corner\": "
       << (i < st.chart_corners.size() ? st.chart_corners[i] : -1) << "}";
  os << "],\n"
     << "  \"certificate\": {\"bijective\": " << (c.is_bijective() ? "true" : "false")
     << ", \"faces\": " << c.number_of_faces << ", \"points_outside_disk\": " << c.points_outside_disk
     << ", \"flipped_faces\": " << c.flipped_faces << ", \"degenerate_faces\": " << c.degenerate_faces
     << ", \"angle_sum_failures\": " << c.angle_sum_failures << ", \"max_angle_sum_error\": " << c.max_angle_sum_error
     << ", \"twin_failures\": " << c.twin_failures << ", \"cone_failures\": " << c.cone_failures
     << ", \"border_failures\": " << c.border_failures << ", \"total_area\": " << c.total_area
     << ", \"expected_area\": " << c.expected_area << "}\n}\n";
}

// a number of a report: JSON has no infinity, so +infinity is written as the string "inf"
// (-infinity as "-inf", NaN as null)
inline void write_json_number(std::ostream& os, double x)
{
  if(std::isnan(x)) os << "null";
  else if(std::isinf(x)) os << (x > 0 ? "\"inf\"" : "\"-inf\"");
  else os << x;
}

// `{"p50": .., "p90": .., "p99": .., "max": .., "mean": ..}`
inline void write_distortion_summary_json(std::ostream& os, const HOT::Distortion_summary& s)
{
  os << "{\"p50\": ";
  write_json_number(os, s.p50);
  os << ", \"p90\": ";
  write_json_number(os, s.p90);
  os << ", \"p99\": ";
  write_json_number(os, s.p99);
  os << ", \"max\": ";
  write_json_number(os, s.max);
  os << ", \"mean\": ";
  write_json_number(os, s.mean);
  os << "}";
}

// what `map` did, as its report gives it: the files, the sizes, the landmarks, the times, the
// vertices whose image cannot be trusted (map_reliability()) and the per-face distortion
// (map_distortion()); vertex numbers are those of the files (with --repair: the input file's
// vertices, then the added ones, as MAP.txt)
struct Map_summary
{
  std::string source_path, target_path;
  std::size_t source_vertices = 0, target_vertices = 0;
  HOT::Orbifold_type type = HOT::Sphere_type;
  std::size_t landmarks = 0;
  double seconds_source = 0, seconds_target = 0, seconds_map = 0, seconds_reliability = 0;
  const Input_mesh* source_input = nullptr;  // with --repair: the preparations (reported)
  const Input_mesh* target_input = nullptr;
  std::vector<std::size_t> unreliable;       // file numbers of the source's vertices, increasing
  // per squeezed region of the source: its report, with its collapse vertices as file numbers
  std::vector<HOT::Squeezed_region> regions;
  // which of map_reliability()'s tests flagged how many of the unreliable vertices (a vertex can
  // fail several), the map's reference scale and scale noise (Map_reliability); written when
  // `reliability_tests` is set
  bool reliability_tests = false;
  std::size_t unreliable_by_scale = 0, unreliable_by_rounding = 0, unreliable_by_protrusion = 0;
  double reference_scale = 1, scale_noise = 0;
  std::vector<std::pair<std::size_t, std::size_t> > region_vertices;
  // the distortion of the map over the faces of the source (prepared, with --repair) and its time
  HOT::Map_distortion distortion;
  double seconds_distortion = 0;
  // the landmark order both meshes were embedded in (positions in the landmark files), whose
  // it is ("source", "target": its tour; "given") and how many orders were tried (0: not known,
  // and not reported)
  std::vector<std::size_t> landmark_order;
  std::string landmark_order_from;
  std::size_t orders_tried = 0;
  // the weights of each mesh's embedding: "cotan", or "mvc" when the cotangent weights'
  // embedding failed the certificate (Embedding_statistics::mean_value_fallback)
  std::string source_weights = "cotan", target_weights = "cotan";
  // the source's vertices (file numbers, increasing) whose image lies on a face the target's
  // repair added to close a hole (Mesh_preparation::filled_faces): not a point of the target
  // file's surface
  std::vector<std::size_t> images_in_filled_holes;
  // map --refine: what refine_orbifold_map() did and the distortion before it (`distortion`
  // is then the refined map's); not written when `refined` is false
  bool refined = false;
  HOT::Map_refinement_statistics refinement;
  HOT::Map_distortion distortion_before;
  // map --augment: the matched extremities added to the landmarks (file numbers of the source's
  // and the target's vertices; landmarks `landmarks - added.size()` on in `landmark_order`), the
  // thin tips found on each mesh and the time; not written when `augmented` is false
  bool augmented = false;
  std::vector<std::pair<std::size_t, std::size_t> > added;
  std::size_t source_extremities = 0, target_extremities = 0, matched_along_map = 0;
  double seconds_augment = 0;
};

// map --augment's block of the report
inline void write_augmentation_json(std::ostream& os, const Map_summary& m)
{
  os << "  \"augmentation\": {\"added\": [";
  for(std::size_t i = 0; i < m.added.size(); ++i)
    os << (i ? ", " : "") << "[" << m.added[i].first << ", " << m.added[i].second << "]";
  os << "], \"source_extremities\": " << m.source_extremities << ", \"target_extremities\": " << m.target_extremities
     << ", \"matched_along_map\": " << m.matched_along_map << ", \"seconds\": " << m.seconds_augment << "},\n";
}

// map --refine's block of the report: the refinement's statistics and the distortion before it
// `"conformal": {..}, "area": {..}, "symmetric_dirichlet": {..}, "symmetric_dirichlet_energy": E`
// (`indent` before "area" and "symmetric_dirichlet")
inline void write_distortion_figures(std::ostream& os, const HOT::Map_distortion& d, const char* indent)
{
  os << "\"conformal\": ";
  write_distortion_summary_json(os, d.conformal_summary);
  os << "," << indent << "\"area\": ";
  write_distortion_summary_json(os, d.area_summary);
  os << "," << indent << "\"symmetric_dirichlet\": ";
  write_distortion_summary_json(os, d.symmetric_dirichlet_summary);
  os << ", \"symmetric_dirichlet_energy\": ";
  write_json_number(os, d.symmetric_dirichlet_energy);
}

// the fields of a refinement's statistics (without braces; `sep` between groups of them)
inline void write_refinement_fields(std::ostream& os, const HOT::Map_refinement_statistics& r, const char* sep)
{
  static const char* const stops[] = {"not_run", "iterations", "converged", "certificate", "solver"};
  os << "\"iterations\": " << r.iterations << ", \"stop\": \"" << stops[r.stop] << "\", \"message\": \"" << json_escape(r.message)
     << "\"," << sep << "\"symmetric_dirichlet_energy_before\": ";
  write_json_number(os, r.energy_before);
  os << ", \"symmetric_dirichlet_energy_after\": ";
  write_json_number(os, r.energy_after);
  os << ", \"tempered_energy_before\": ";
  write_json_number(os, r.tempered_energy_before);
  os << ", \"tempered_energy_after\": ";
  write_json_number(os, r.tempered_energy_after);
  os << ", \"free_vertices\": " << r.free_vertices << ", \"undone_moves\": " << r.undone_moves << "," << sep
     << "\"seconds\": " << r.seconds << ", \"seconds_certificate\": " << r.seconds_certificate;
}

inline void write_refinement_json(std::ostream& os, const HOT::Map_refinement_statistics& r, const HOT::Map_distortion& before)
{
  os << "  \"refinement\": {";
  write_refinement_fields(os, r, "\n                 ");
  os << ",\n                 \"distortion_before\": {";
  write_distortion_figures(os, before, "\n                                       ");
  os << "}},\n";
}

// Writes the report of `map`.
inline void write_map_report(std::ostream& os, const Map_summary& m)
{
  os.precision(17);
  os << "{\n  \"source\": \"" << json_escape(m.source_path) << "\",\n  \"target\": \"" << json_escape(m.target_path) << "\",\n"
     << "  \"source_vertices\": " << m.source_vertices << ",\n  \"target_vertices\": " << m.target_vertices << ",\n"
     << "  \"orbifold\": \"" << (m.type == HOT::Sphere_type ? "sphere" : "disk") << "\",\n  \"landmarks\": " << m.landmarks << ",\n"
     << "  \"weights\": {\"source\": \"" << m.source_weights << "\", \"target\": \"" << m.target_weights << "\"},\n";
  if(m.orders_tried > 0) {
    os << "  \"landmark_order\": [";
    for(std::size_t i = 0; i < m.landmark_order.size(); ++i) os << (i ? ", " : "") << m.landmark_order[i];
    os << "],\n  \"landmark_order_from\": \"" << m.landmark_order_from << "\",\n  \"orders_tried\": " << m.orders_tried << ",\n";
  }
  if(m.source_input && m.source_input->repaired) {
    os << "  \"source_repair\": ";
    write_repair_json(os, m.source_input->prep, "  ");
    os << ",\n";
  }
  if(m.target_input && m.target_input->repaired) {
    os << "  \"target_repair\": ";
    write_repair_json(os, m.target_input->prep, "  ");
    os << ",\n";
  }
  os << "  \"time_seconds\": {\"embedding_source\": " << m.seconds_source << ", \"embedding_target\": " << m.seconds_target
     << ", \"map\": " << m.seconds_map << ", \"reliability\": " << m.seconds_reliability
     << ", \"distortion\": " << m.seconds_distortion << "},\n";
  // per-face distortion summaries (infinity as "inf"), the faces measured, the degenerate ones
  os << "  \"distortion\": {";
  write_distortion_figures(os, m.distortion, "\n                 ");
  os << ",\n                 \"faces\": " << m.distortion.conformal_summary.number_of_faces
     << ", \"degenerate_faces\": " << m.distortion.number_of_degenerate_faces() << "},\n";
  if(m.augmented)
    write_augmentation_json(os, m);
  if(m.refined)
    write_refinement_json(os, m.refinement, m.distortion_before);
  os << "  \"squeezed_regions\": [";
  for(std::size_t i = 0; i < m.regions.size(); ++i) {
    const HOT::Squeezed_region& r = m.regions[i];
    os << (i ? "," : "") << "\n    {\"vertices\": " << r.number_of_vertices << ", \"source_vertex\": " << m.region_vertices[i].first
       << ", \"at_landmark\": " << (r.at_landmark ? "true" : "false");
    if(!r.at_landmark)
      os << ", \"target_vertex\": " << m.region_vertices[i].second << ", \"discrepancy\": " << r.discrepancy
         << ", \"source_size\": " << r.source_size << ", \"target_size\": " << r.target_size
         << ", \"unresolved\": " << (r.unresolved ? "true" : "false") << ", \"scale_disagreement\": " << r.scale_disagreement;
    os << ", \"unreliable_vertices\": " << r.unreliable_vertices << "}";
  }
  os << (m.regions.empty() ? "" : "\n  ") << "],\n";
  if(m.reliability_tests)
    os << "  \"unreliable_by_test\": {\"scale\": " << m.unreliable_by_scale << ", \"rounding\": " << m.unreliable_by_rounding
       << ", \"protrusion\": " << m.unreliable_by_protrusion << "}, \"reference_scale\": " << m.reference_scale
       << ", \"scale_noise\": " << m.scale_noise << ",\n";
  os << "  \"unreliable_vertex_count\": " << m.unreliable.size() << ",\n  \"unreliable_vertices\": [";
  for(std::size_t i = 0; i < m.unreliable.size(); ++i)
    os << (i ? ", " : "") << m.unreliable[i];
  os << "],\n  \"images_in_filled_holes_count\": " << m.images_in_filled_holes.size() << ",\n  \"images_in_filled_holes\": [";
  for(std::size_t i = 0; i < m.images_in_filled_holes.size(); ++i)
    os << (i ? ", " : "") << m.images_in_filled_holes[i];
  os << "]\n}\n";
}

// the maps the `collection` command computed, and the cycle consistency: f_bc(f_ab(x)) against
// f_ac(x), relative to c's bounding-box diagonal, over every triple (all of them up to 6 meshes,
// else N consecutive triples); with --all-pairs f_ab for every ordered pair too
struct Collection_maps
{
  std::vector<std::vector<char> > used; // used[a][b]: f_ab computed (and reported)
  double cycle = 0;
  std::size_t triples = 0;
};

// the weights of an embedding computed with the default ones, as the reports name them: "cotan",
// or "mvc" when the cotangent embedding failed the certificate (Embedding_statistics::mean_value_fallback)
inline const char* weights_name(const HOT::Embedding_statistics& st) { return st.mean_value_fallback ? "mvc" : "cotan"; }

// one line of what a refinement did (the collection's logs)
inline std::string refinement_line(const HOT::Map_refinement_statistics& st, double seconds)
{
  std::ostringstream os;
  os << st.iterations << " certified iterations, symmetric Dirichlet energy " << st.energy_before << " -> " << st.energy_after
     << " (tempered " << st.tempered_energy_before << " -> " << st.tempered_energy_after << "; " << seconds << " s)";
  return os.str();
}

// The entry of mesh i in the report of `collection`: its file, size, embedding time and verdict
// (and what --repair did), as one JSON object (the collection's jobs write it for the merge).
inline std::string collection_mesh_entry(std::size_t i, const std::string& mesh_path, std::size_t vertices,
                                         const HOT::Embedding_statistics& st, const Input_mesh* input = nullptr)
{
  std::ostringstream os;
  os.precision(17);
  os << "{\"index\": " << i << ", \"mesh\": \"" << json_escape(mesh_path) << "\", \"vertices\": " << vertices
     << ", \"embedding_seconds\": " << st.time_setup + st.time_initialization + st.time_optimization + st.time_certificate
     << ", \"iterations\": " << st.iterations << ", \"relative_gradient_norm\": " << st.relative_gradient_norm
     << ", \"bijective\": " << (st.certificate.is_bijective() ? "true" : "false")
     << ", \"weights\": \"" << weights_name(st) << "\"";
  if(input && input->repaired) {
    os << ",\n     \"repair\": ";
    write_repair_json(os, input->prep, "     ");
  }
  os << "}";
  return os.str();
}

// What the report of `collection` says: per mesh its entry (collection_mesh_entry()), the
// orbifold, the landmark order used, per computed map its time, and the cycle consistency.
struct Collection_report
{
  std::vector<std::string> mesh_entries;
  HOT::Orbifold_type type = HOT::Sphere_type;
  std::vector<std::size_t> order;
  std::vector<std::pair<std::pair<std::size_t, std::size_t>, double> > pairs; // ((a, b), seconds), a then b increasing
  // whose the order is ("mesh <i>": its tour; "given") and how many orders were tried (0: not
  // known, and not reported)
  std::string order_from;
  std::size_t orders_tried = 0;
  std::size_t triples = 0;
  double cycle = 0;
  // collection --refine: what refine() did to each mesh (empty: not refined; the reference's
  // entry is not written)
  std::vector<HOT::Map_refinement_statistics> refinement;
  std::size_t refinement_reference = 0;
};

// Writes the report of `collection`.
inline void write_collection_report(std::ostream& os, const Collection_report& r)
{
  os.precision(17);
  os << "{\n  \"meshes\": [\n";
  for(std::size_t i = 0; i < r.mesh_entries.size(); ++i)
    os << "    " << r.mesh_entries[i] << (i + 1 < r.mesh_entries.size() ? "," : "") << "\n";
  os << "  ],\n  \"orbifold\": \"" << (r.type == HOT::Sphere_type ? "sphere" : "disk") << "\",\n  \"cones\": " << r.order.size()
     << ",\n  \"landmark_order_used\": [";
  for(std::size_t i = 0; i < r.order.size(); ++i) os << (i ? ", " : "") << r.order[i];
  os << "],\n";
  if(r.orders_tried > 0)
    os << "  \"landmark_order_from\": \"" << r.order_from << "\",\n  \"orders_tried\": " << r.orders_tried << ",\n";
  if(!r.refinement.empty()) {
    os << "  \"refinement\": {\"reference\": " << r.refinement_reference << ", \"meshes\": [";
    bool first = true;
    for(std::size_t i = 0; i < r.refinement.size(); ++i)
      if(i != r.refinement_reference) {
        os << (first ? "" : ",") << "\n    {\"mesh\": " << i << ", ";
        write_refinement_fields(os, r.refinement[i], " ");
        os << "}";
        first = false;
      }
    os << "\n  ]},\n";
  }
  os << "  \"pairs\": [\n";
  for(std::size_t p = 0; p < r.pairs.size(); ++p)
    os << (p ? ",\n" : "") << "    {\"source\": " << r.pairs[p].first.first << ", \"target\": " << r.pairs[p].first.second
       << ", \"map_seconds\": " << r.pairs[p].second << "}";
  os << "\n  ],\n  \"triples_checked\": " << r.triples << ",\n  \"cycle_consistency_max_rel_error\": " << r.cycle << "\n}\n";
}

// Writes the report of `collection` computed in one process: `mesh_paths[i]` is the file of the
// collection's mesh i.
template <class Collection>
void write_collection_report(std::ostream& os, const std::vector<std::string>& mesh_paths, Collection& coll,
                             HOT::Orbifold_type type, const Collection_maps& maps,
                             const std::vector<Input_mesh>* inputs = nullptr)
{
  const std::size_t N = mesh_paths.size();
  Collection_report r;
  for(std::size_t i = 0; i < N; ++i)
    r.mesh_entries.push_back(collection_mesh_entry(i, mesh_paths[i], num_vertices(coll.mesh(i)), coll.statistics(i),
                                                   inputs ? &(*inputs)[i] : nullptr));
  r.type = type;
  r.order = coll.order();
  if(!coll.order_attempts().empty()) {
    const std::size_t from = coll.order_attempts().back().mesh;
    r.order_from = from < N ? "mesh " + std::to_string(from) : std::string("given");
    r.orders_tried = coll.order_attempts().size();
  }
  for(std::size_t a = 0; a < N; ++a)
    for(std::size_t b = 0; b < N; ++b)
      if(maps.used[a][b])
        r.pairs.push_back(std::make_pair(std::make_pair(a, b), coll.map_seconds(a, b)));
  r.triples = maps.triples;
  r.cycle = maps.cycle;
  bool refined = false;
  for(std::size_t i = 0; i < N; ++i)
    refined = refined || coll.refinement_statistics(i).stop != HOT::Refinement_not_run;
  for(std::size_t i = 0; i < N && refined; ++i) // (mesh 0: the reference of collection --refine)
    r.refinement.push_back(coll.refinement_statistics(i));
  write_collection_report(os, r);
}

} // namespace hot_tools

#include <CGAL/enable_warnings.h>

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_TOOLS_IO_REPORTS_H
