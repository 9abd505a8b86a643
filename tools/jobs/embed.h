// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef HOT_TOOLS_JOBS_EMBED_H
#define HOT_TOOLS_JOBS_EMBED_H

// The `embed` command: its options (Embed_command: the application layer's Embed_job and the
// command line's files), its call of the library (embed_mesh(), hot_app/embed_job.h), its
// outputs (OBJ, SVG, report, cut graph).

#include "jobs/common.h"
#include "hot_app/embed_job.h"
#include "hot_app/io/cut_graph_file.h"
#include "hot_app/io/embedding_obj.h"
#include "hot_app/io/reports.h"
#include "hot_app/io/svg.h"
#include "hot_app/io/timings.h"

#include <CGAL/Hyperbolic_orbifold_Tutte/hyperbolic_orbifold_Tutte_embedding.h>

#include <complex>
#include <iostream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace hot_cli {

// Writes the embedding's SVG: the tiling (faded tile copies), the embedded mesh in the
// tile and its images around it, cones in distinct colours (paper, Figure 1).
inline void write_embedding_svg(std::ostream& os, const Surface_mesh& m,
                                const Surface_mesh::Property_map<SM_halfedge, Kernel::Point_2>& uv,
                                const HOT::Orbifold_tile<>& tile, const std::vector<SM_vertex>& landmarks,
                                const std::string& title)
{
  typedef std::complex<double> C;
  hot_tools::Poincare_svg svg;
  svg.begin(os, title);
  const int n = tile.number_of_corners();
  std::vector<C> corners;
  for(int i = 0; i < n; ++i)
    corners.push_back(C(tile.corner(i).x(), tile.corner(i).y()));
  // copies of the mesh: as many group elements as keep the picture below ~400k segments
  const std::size_t edges_per_copy = 3 * num_faces(m);
  int depth = 2;
  while(depth > 0 && tile.group_elements(depth).size() * edges_per_copy > 400000)
    --depth;
  const std::vector<HOT::Orbifold_tile<>::Isometry> group = tile.group_elements(std::max(depth, 2));
  for(std::size_t e = 1; e < group.size(); ++e) {
    std::vector<C> img;
    for(const C& c : corners)
      img.push_back(group[e].apply(c));
    svg.path(os, svg.geodesic_path(img, true), "#e3ebf3", "#9fb3c8", 0.6);
  }
  std::vector<HOT::Orbifold_tile<>::Isometry> copies(group.begin(), group.begin() + (depth > 0 ? tile.group_elements(depth).size() : 1));
  for(std::size_t e = 0; e < copies.size(); ++e) {
    std::ostringstream d;
    d.precision(6);
    for(SM_face f : faces(m)) {
      // each edge once per face: draw the face's three edges as straight segments (short edges)
      bool first = true;
      for(SM_halfedge h : halfedges_around_face(halfedge(f, m), m)) {
        const C z = copies[e].apply(C(get(uv, h).x(), get(uv, h).y()));
        d << (first ? "M" : "L") << svg.X(z) << "," << svg.Y(z);
        first = false;
      }
      d << "Z";
    }
    svg.path(os, d.str(), "none", e == 0 ? "#1d3557" : "#9aa7b8", e == 0 ? 0.25 : 0.15);
  }
  svg.path(os, svg.geodesic_path(corners, true), "none", "#c1121f", 1.5);
  for(int i = 0; i < n; ++i) // (a corner that is no cone, a node of a genus-g cut graph: a small white dot)
    svg.dot(os, corners[i], tile.corner_cone(i) < 0 ? 3 : 6,
            tile.corner_cone(i) < 0 ? std::string("white")
                                    : hot_tools::Poincare_svg::palette(tile.corner_cone(i), tile.number_of_cones(), 0.75, 1.0));
  (void)landmarks;
  svg.end(os);
}

// the options of `embed`: the embedding's (Embed_job, and its call of the library, embed_mesh():
// hot_app/embed_job.h) and the command line's files and input options
struct Embed_command : Embed_job
{
  std::string cones_path, out_path;
  std::optional<std::string> svg_path, report_path;
  std::optional<HOT::Orbifold_type> required_type;
  hot_tools::Repair_options repair;
  std::optional<std::string> cut_graph_path, cut_graph_out; // genus g >= 1: --cut-graph, --cut-graph-out
  std::vector<std::size_t> explicit_order; // --order I0,I1,...: the landmarks' positions in the order of the cut
};

// --order I0,I1,...: a permutation of the k landmarks' positions (0-based lines of the landmark file)
inline std::vector<std::size_t> parse_landmark_positions(const std::string& s, std::size_t k)
{
  std::vector<std::size_t> perm;
  std::vector<char> seen(k, 0);
  std::istringstream in(s);
  for(std::string t; std::getline(in, t, ',');) {
    const bool digits = !t.empty() && t.size() <= 9 && t.find_first_not_of("0123456789") == std::string::npos;
    if(!digits)
      throw Usage_error{"--order: '" + t + "' is not a landmark position (given, tsp, or a comma-separated permutation of 0.." +
                        std::to_string(k == 0 ? 0 : k - 1) + ")"};
    const std::size_t i = std::stoul(t);
    if(i >= k || seen[i])
      throw Failure{HOT::ERROR_WRONG_PARAMETER, "--order must list each of the " + std::to_string(k) + " landmark positions 0.." +
                                                  std::to_string(k - 1) + " once, got '" + s + "'"};
    seen[i] = 1;
    perm.push_back(i);
  }
  if(perm.size() != k)
    throw Failure{HOT::ERROR_WRONG_PARAMETER, "--order lists " + std::to_string(perm.size()) + " landmark positions for " + std::to_string(k) +
                                                " landmarks"};
  return perm;
}

inline Embed_command parse_embed_options(int argc, char** argv, bool& progress)
{
  std::set<std::string> flags = repair_flags();
  flags.insert("recentre");
  flags.insert("progress");
  const Options opt(argc, argv, 2, {"mesh", "cones", "orbifold", "weights", "order", "out", "svg", "report", "max-hole", "target-genus", "max-handle", "cone-orders",
                                       "cut-graph", "cut-graph-out"}, flags);
  Embed_command job;
  job.request.mesh_path = opt.get("mesh");
  job.cones_path = opt.get("cones");
  job.out_path = opt.get("out");
  if(opt.has("weights")) {
    const std::string w = opt.get("weights");
    if(w == "cotan") job.weights = HOT::Cotangent;
    else if(w == "mvc") job.weights = HOT::Mean_value;
    else if(w == "uniform") job.weights = HOT::Uniform;
    else throw Usage_error{"--weights must be cotan, mvc or uniform, got '" + w + "'"};
    job.request.weights = w;
  } else
    job.mean_value_fallback = true; // (as map and collection: the cotangent weights, or the mean value ones if those fail the certificate)
  if(opt.has("order") && opt.get("order").find_first_of("0123456789") != std::string::npos)
    job.request.order = opt.get("order"); // (a list: parsed once the landmarks are read)
  else
    job.request.order = parse_order(opt, std::string());
  if(opt.has("orbifold"))
    job.required_type = parse_orbifold(opt.get("orbifold"));
  if(opt.has("svg"))
    job.svg_path = opt.get("svg");
  if(opt.has("report"))
    job.report_path = opt.get("report");
  job.recentre = opt.has("recentre");
  job.orders = parse_cone_orders(opt);
  job.repair = parse_repair_options(opt);
  if(opt.has("cut-graph"))
    job.cut_graph_path = opt.get("cut-graph");
  if(opt.has("cut-graph-out"))
    job.cut_graph_out = opt.get("cut-graph-out");
  progress = opt.has("progress");
  return job;
}

// OUT.obj, and the picture and the report when asked for
inline void write_embed_outputs(const Embed_command& job, const Surface_mesh& m, const UV_map& uv, const Chart_map& charts,
                                const std::vector<SM_vertex>& landmarks, const HOT::Embedding_statistics& st, const Input& in)
{
  const HOT::Orbifold_type type = job.request.type;
  const Embedding_result result = embedding_result(m, uv, charts, st, landmarks);
  HOT::Orbifold_tile<> tile;
  result.tile(tile);
  if(st.recentred)
    tile = tile.transformed(st.frame); // the tile of the written coordinates

  Output_files files;
  const hot_tools::Embedding_cones cones = embedding_cones(type, st, job.request.cones);
  hot_tools::timings().phase("tile");
  files.write(job.out_path, [&](std::ostream& os) { hot_tools::write_embedding_obj(os, result, in.file.repaired ? &in.file : nullptr, &cones); });
  hot_tools::timings().phase("write the OBJ");
  if(job.svg_path) {
    std::ostringstream title;
    if(st.genus > 0)
      title << "closed surface of genus " << st.genus << ", " << landmarks.size() << " cones, ";
    else
      title << (type == HOT::Sphere_type ? "sphere" : "disk") << "-type orbifold, " << landmarks.size() << " cones, ";
    title << num_vertices(m) << " vertices, certified bijective";
    files.write(*job.svg_path, [&](std::ostream& os) { write_embedding_svg(os, m, uv, tile, landmarks, title.str()); });
  }
  if(job.report_path)
    files.write(*job.report_path, [&](std::ostream& os) {
      hot_tools::write_embedding_report(os, job.request, num_vertices(m), num_faces(m), st);
    });
  if(job.cut_graph_out && st.genus > 0) {
    files.write(*job.cut_graph_out, [&](std::ostream& os) {
      hot_tools::write_cut_graph(os, cut_graph_in_files(st, m, in.file.repaired ? &in.file : nullptr));
    });
  }
  files.commit();
  hot_tools::timings().phase("write svg, report");
}

inline int run_embed(int argc, char** argv)
{
  hot_tools::timings(); // (HOT_TIMINGS: the phases' clock starts here)
  bool progress_flag = false;
  Embed_command job = parse_embed_options(argc, argv, progress_flag);
  Progress_line progress("embed", progress_flag);
  Surface_mesh m;
  std::vector<SM_vertex> landmarks;
  Input in;
  progress.step("read");
  const HOT::Orbifold_type type =
    read_mesh_and_landmarks(job.request.mesh_path, job.cones_path, job.required_type, job.repair, m, landmarks, in, minimum_landmarks(job.orders));
  progress.done("read");
  if(in.file.repaired || !in.snaps.empty())
    progress.clear(); // (a terminal's line, before stdout)
  print_repair(job.request.mesh_path, in);
  job.request.type = type;
  if(job.request.order.find_first_of("0123456789") != std::string::npos) { // --order I0,I1,...: the landmarks in that order
    job.explicit_order = parse_landmark_positions(job.request.order, landmarks.size());
    std::vector<SM_vertex> reordered;
    std::vector<int> reordered_orders;
    for(std::size_t i : job.explicit_order) {
      reordered.push_back(landmarks[i]);
      if(!job.orders.empty()) reordered_orders.push_back(job.orders[i]);
    }
    landmarks = reordered;
    job.orders = reordered_orders;
    job.request.order = "given";
  }
  const long long genus = type == HOT::Sphere_type ? HOT::closed_mesh_genus(m) : 0;
  if(job.request.order.empty()) // (genus g >= 1: the cut graph joins the landmarks in any order)
    job.request.order = (type == HOT::Sphere_type && genus == 0) ? "tsp" : "given";
  job.request.cones = file_indices(landmarks, in.file);
  job.request.input = &in.file;
  if(job.repair.snap_landmarks)
    job.request.snaps = &in.snaps;

  const UV_map uv = m.add_property_map<SM_halfedge, Kernel::Point_2>("h:uv", Kernel::Point_2(0, 0)).first;
  const Chart_map charts = m.add_property_map<SM_halfedge, HOT::Chart_point<Kernel::Point_2> >("h:chart").first;
  std::vector<std::vector<SM_vertex> > cut_graph;
  if(job.cut_graph_out && genus == 0)
    throw Failure{HOT::ERROR_WRONG_PARAMETER, "--cut-graph-out: the mesh has genus 0 (it is cut along a path through the landmarks, not a graph)"};
  if(job.cut_graph_path) {
    if(genus == 0)
      throw Failure{HOT::ERROR_WRONG_PARAMETER, "--cut-graph: the mesh has genus 0; a cut graph is for a closed mesh of genus 1 or more"};
    cut_graph = read_cut_graph_of(*job.cut_graph_path, m, in.file);
  }
  hot_tools::timings().phase("before the library");
  job.progress = progress.callback();
  HOT::Embedding_statistics st = embed_mesh(job, m, landmarks, uv, charts, cut_graph);
  hot_tools::timings().phase("library (embedding)");
  hot_tools::timings().add(" setup (check, order, cut)", st.time_setup);
  hot_tools::timings().add(" initialization", st.time_initialization);
  hot_tools::timings().add(" optimization", st.time_optimization);
  hot_tools::timings().add(" certificate", st.time_certificate);
  if(!job.explicit_order.empty()) { // (the positions and the cones as in the file)
    for(std::size_t& i : st.landmark_order) i = job.explicit_order[i];
    std::vector<std::size_t> as_given(job.explicit_order.size());
    for(std::size_t j = 0; j < as_given.size(); ++j) as_given[job.explicit_order[j]] = job.request.cones[j];
    job.request.cones = as_given;
    job.request.order = "explicit"; // (the report's "order", as the Python module's)
  }
  progress.step("write");
  write_embed_outputs(job, m, uv, charts, landmarks, st, in);
  progress.done("write");
  progress.clear();
  std::cout << "embedded " << job.request.mesh_path << " (" << num_vertices(m) << " vertices, " << landmarks.size() << " cones, "
            << (genus > 0 ? "closed, genus " + std::to_string(genus) : std::string(type == HOT::Sphere_type ? "sphere" : "disk") + " type") << ") in "
            << st.time_setup + st.time_initialization + st.time_optimization + st.time_certificate << " s, "
            << st.iterations << " Newton iterations, certified bijective"
            << (st.mean_value_fallback ? " with the mean value weights (the cotangent weights' embedding failed the certificate)" : "")
            << (st.recentred ? " in a recentred frame (given in the report)" : "")
            << (st.charted_faces > 0 ? ", " + std::to_string(st.charted_faces) + " faces in charts around cone images" : std::string())
            << "; wrote " << job.out_path << std::endl;
  hot_tools::timings().phase("stdout");
  return EXIT_SUCCESS;
}

} // namespace hot_cli

#endif // HOT_TOOLS_JOBS_EMBED_H
