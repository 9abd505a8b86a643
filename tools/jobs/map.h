// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef HOT_TOOLS_JOBS_MAP_H
#define HOT_TOOLS_JOBS_MAP_H

// The `map` command: from the meshes (map_pair.h), optionally refined, or from two stored
// embeddings; the map file, its report, the prepared target and the colours.

#include "jobs/map_pair.h"
#include "hot_app/augment.h"
#include "hot_app/io/map_files.h"
#include "hot_app/io/reports.h"

#include <CGAL/Hyperbolic_orbifold_Tutte/surface_maps.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/map_reliability.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/map_distortion.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/refine_orbifold_map.h>

#include <algorithm>
#include <chrono>
#include <iostream>
#include <string>
#include <vector>

namespace hot_cli {

// what `map` reports: sizes, times and the unreliable vertices, numbered as in the files
// the source's vertices (file numbers, increasing) whose image `f` lies on a face that the
// target's repair added to close a hole
inline std::vector<std::size_t> images_in_filled_holes(const Embedded& A, const Embedded& B, const std::vector<Locator::Location>& f)
{
  const std::vector<std::size_t>& filled = B.in.file.prep.filled_faces; // (increasing)
  std::vector<std::size_t> r;
  if(filled.empty())
    return r;
  const std::vector<SM_vertex> va(vertices(A.mesh).begin(), vertices(A.mesh).end());
  for(std::size_t i = 0; i < f.size(); ++i)
    if(std::binary_search(filled.begin(), filled.end(), f[i].face_index))
      r.push_back(hot_tools::output_vertex(va[i], addressing(A.in)));
  std::sort(r.begin(), r.end());
  return r;
}

// the reliability tests' counts (map_reliability()) in a map's report
inline void add_reliability_tests(hot_tools::Map_summary& m, const HOT::Map_reliability& r)
{
  m.reliability_tests = true;
  m.unreliable_by_scale = r.scale_flagged;
  m.unreliable_by_rounding = r.rounding_flagged;
  m.unreliable_by_protrusion = r.protrusion_flagged;
  m.reference_scale = r.reference_scale;
  m.scale_noise = r.scale_noise;
}

inline hot_tools::Map_summary map_summary(const Options& opt, const Embedded& A, const Embedded& B, int k, const HOT::Map_reliability& r)
{
  hot_tools::Map_summary m;
  m.source_path = opt.get("source");
  m.target_path = opt.get("target");
  m.source_vertices = num_vertices(A.mesh);
  m.target_vertices = num_vertices(B.mesh);
  m.type = A.type;
  m.landmarks = static_cast<std::size_t>(k);
  auto seconds = [](const HOT::Embedding_statistics& st) {
    return st.time_setup + st.time_initialization + st.time_optimization + st.time_certificate;
  };
  m.seconds_source = seconds(A.stats);
  m.seconds_target = seconds(B.stats);
  m.source_weights = hot_tools::weights_name(A.stats);
  m.target_weights = hot_tools::weights_name(B.stats);
  m.source_input = addressing(A.in);
  m.target_input = addressing(B.in);
  const std::vector<SM_vertex> va(vertices(A.mesh).begin(), vertices(A.mesh).end());
  const std::vector<SM_vertex> vb(vertices(B.mesh).begin(), vertices(B.mesh).end());
  for(std::size_t i : r.unreliable_vertices)
    m.unreliable.push_back(hot_tools::output_vertex(va[i], m.source_input));
  std::sort(m.unreliable.begin(), m.unreliable.end());
  m.regions = r.regions;
  for(const HOT::Squeezed_region& g : r.regions)
    m.region_vertices.emplace_back(hot_tools::output_vertex(va[g.source_vertex], m.source_input),
                                   hot_tools::output_vertex(vb[g.target_vertex], m.target_input));
  return m;
}

// `map --source-embedding A.obj --target-embedding B.obj`: the map from two stored embeddings
// (stored_embedding.h), without embedding again; the same numbers as `map` on the meshes when
// the two files were embedded with the same landmarks in the same cone order
inline int run_map_stored(const Options& opt)
{
  Progress_line progress("map", opt.has("progress"));
  for(const char* o : {"source", "source-cones", "target", "target-cones", "colors-out", "prepared-target", "max-hole", "target-genus", "max-handle", "cone-orders",
                       "source-cut-graph", "target-cut-graph", "repair", "largest-component", "snap-landmarks"})
    if(opt.has(o))
      throw Usage_error{std::string("--") + o + " does not go with --source-embedding/--target-embedding (the stored embeddings hold the meshes,"
                        " the landmarks and the orbifold)"};
  if(!opt.has("source-embedding") || !opt.has("target-embedding"))
    throw Usage_error{"--source-embedding and --target-embedding go together"};
  const std::string out = opt.get("out");
  Stored_embedding A, B;
  progress.step("read");
  read_stored_embedding(opt.get("source-embedding"), A);
  read_stored_embedding(opt.get("target-embedding"), B);
  check_stored_pair(A, B);
  progress.done("read");
  progress.step("map");
  const auto t0 = std::chrono::steady_clock::now();
  const Locator locB = stored_locator(B);
  const std::vector<Locator::Location> f = HOT::map_vertices(A.result(), locB);
  for(std::size_t i = 0; i < f.size(); ++i)
    if(!f[i].success)
      throw Failure{HOT::ERROR_POINT_NOT_LOCATED, "vertex " + std::to_string(A.vertex_line[i]) + " of the source could not be located on the target"};
  progress.done("map");
  progress.step("reliability");
  const auto t1 = std::chrono::steady_clock::now();
  const HOT::Map_reliability reliability = HOT::map_reliability(A.mesh, A.uv, B.mesh, B.uv, locB, f);
  progress.done("reliability");
  hot_tools::Map_summary m;
  m.source_path = A.path;
  m.target_path = B.path;
  m.source_vertices = num_vertices(A.mesh);
  m.target_vertices = num_vertices(B.mesh);
  m.type = A.cones.type;
  m.landmarks = A.number_of_cones();
  for(std::size_t i : reliability.unreliable_vertices)
    m.unreliable.push_back(A.vertex_line[i]);
  std::sort(m.unreliable.begin(), m.unreliable.end());
  m.regions = reliability.regions;
  for(const HOT::Squeezed_region& g : reliability.regions)
    m.region_vertices.emplace_back(A.vertex_line[g.source_vertex], B.vertex_line[g.target_vertex]);
  add_reliability_tests(m, reliability);
  m.seconds_map = std::chrono::duration<double>(t1 - t0).count();
  m.seconds_reliability = std::chrono::duration<double>(std::chrono::steady_clock::now() - t1).count();
  progress.step("distortion");
  const auto t2 = std::chrono::steady_clock::now(); // the per-face distortion (REPORT.json's "distortion")
  m.distortion = HOT::map_distortion(A.mesh, B.mesh, locB, f);
  m.seconds_distortion = std::chrono::duration<double>(std::chrono::steady_clock::now() - t2).count();
  progress.done("distortion");
  progress.step("write");
  Output_files files;
  files.write(out, [&](std::ostream& os) { hot_tools::write_map(os, B.mesh, locB, f, A.line_vertex); });
  if(opt.has("report"))
    files.write(opt.get("report"), [&](std::ostream& os) { hot_tools::write_map_report(os, m); });
  files.commit();
  progress.done("write");
  progress.clear();
  std::cout << "mapped " << num_vertices(A.mesh) << " vertices of " << A.path << " onto " << B.path << " (stored embeddings); wrote " << out
            << std::endl;
  if(!m.unreliable.empty())
    std::cerr << "warning: the map cannot resolve the images of " << m.unreliable.size() << " of the " << num_vertices(A.mesh)
              << " source vertices (the map squeezes or stretches them far from an isometry, or double cannot resolve them): a protrusion"
              << " without a landmark is the usual cause, put a landmark at the tip of such a protrusion" << std::endl;
  return EXIT_SUCCESS;
}

// --augment: the thin tips that the landmarks leave out, matched across the meshes by
// match_extremities(), added to both meshes' landmarks after the files' ones (each a cone of
// order 2 when --cone-orders is given); what was added goes into `summary`
inline void augment_landmarks(Embedded& A, Embedded& B, std::vector<int>& orders, hot_tools::Map_summary& summary)
{
  const HOT::Extremity_matching<SM_vertex> xm =
    augment_landmarks(A.type, genus_of(A), genus_of(B), A.mesh, A.landmarks, B.mesh, B.landmarks, orders, "--augment");
  summary.augmented = true;
  summary.source_extremities = xm.source_extremities;
  summary.matched_along_map = xm.matched_along_map;
  summary.target_extremities = xm.target_extremities;
  summary.seconds_augment = xm.seconds;
  for(const std::pair<SM_vertex, SM_vertex>& p : xm.pairs)
    summary.added.emplace_back(hot_tools::output_vertex(p.first, addressing(A.in)), hot_tools::output_vertex(p.second, addressing(B.in)));
}

// `map` from the meshes, its first part: reads and checks both meshes (--repair, the handles of
// one cut when the other has genus 0), adds matched extremities to the landmarks (--augment),
// chooses the landmark order and embeds both in the first order both accept (map_pair.h).
// Returns the order used; `refusals`: the orders refused.
inline HOT::Landmark_order_candidate embed_map_meshes(const Options& opt, const hot_tools::Repair_options& repair, std::vector<int>& orders,
                                                      Embedded& A, Embedded& B, std::vector<std::string>& refusals, Progress_line& progress,
                                                      hot_tools::Map_summary& summary)
{
  progress.step("read");
  read_and_check(opt.get("source"), opt.get("source-cones"), repair, A, minimum_landmarks(orders), &progress);
  read_and_check(opt.get("target"), opt.get("target-cones"), repair, B, minimum_landmarks(orders), &progress);
  progress.clear(); // (match_genus_zero() may write on stdout)
  match_genus_zero(opt, repair, A, B, minimum_landmarks(orders));
  progress.done("read");
  check_map_pair(A, B);
  if(opt.has("refine")) // (refused before the embeddings, not after)
    if(const HOT::Status refusal = HOT::check_refinable_source(A.mesh); !refusal)
      throw Failure{refusal.code, "--refine: " + refusal.message};
  // --augment, or --refine without --no-augment on closed genus-0 meshes (elsewhere --refine
  // does not augment: the added landmarks would not fit the orbifold)
  const bool closed_genus_0 = A.type == HOT::Sphere_type && genus_of(A) == 0 && genus_of(B) == 0;
  if(opt.has("augment") || (opt.has("refine") && !opt.has("no-augment") && closed_genus_0)) {
    progress.step("augment");
    augment_landmarks(A, B, orders, summary);
    progress.done("augment");
  }
  progress.step("landmark order");
  const std::vector<HOT::Landmark_order_candidate> candidates = map_cone_orders(parse_common_order(opt), A, B);
  progress.done("landmark order");
  std::vector<std::vector<SM_vertex> > ga, gb; // genus g >= 1: the cut graphs
  if(genus_of(A) > 0) {
    for(std::size_t i : candidates[0].order) A.ordered.push_back(A.landmarks[i]);
    map_cut_graphs(opt, A, B, ga, gb);
  } else if(opt.has("source-cut-graph") || opt.has("target-cut-graph"))
    throw Failure{HOT::ERROR_WRONG_PARAMETER, "the meshes have genus 0: a cut graph is for closed meshes of genus 1 or more"};
  const HOT::Landmark_order_candidate chosen = candidates[embed_map_pair(A, B, candidates, orders, ga, gb, refusals, &progress)];
  if(genus_of(A) > 0)
    check_same_polygon(A, B);
  if(A.stats.landmark_order_reversed != B.stats.landmark_order_reversed)
    throw Failure{HOT::ERROR_WRONG_PARAMETER, "the landmarks run clockwise around one boundary and counterclockwise around the other: "
                                              "the correspondence would reverse orientation"};
  return chosen;
}

// the images of the source's vertices on the target; a vertex not located fails (`when`: after what)
inline std::vector<Locator::Location> map_source_vertices(const Embedded& A, const Locator& locB, const std::string& when = std::string())
{
  std::vector<Locator::Location> f = HOT::map_vertices(result_of(A), locB);
  for(std::size_t i = 0; i < f.size(); ++i)
    if(!f[i].success)
      throw Failure{HOT::ERROR_POINT_NOT_LOCATED, "vertex " + std::to_string(i) + " of the source could not be located on the target" + when};
  return f;
}

// --refine N: the source's embedding refined towards an isometry onto the target (A's embedding
// moves, `f` is the refined map); `distortion_before`: the map's distortion before
inline HOT::Map_refinement_statistics refine_map(int refine, Embedded& A, const Embedded& B, const Locator& locB,
                                                 std::vector<Locator::Location>& f, HOT::Map_distortion& distortion_before,
                                                 Progress_line& progress)
{
  HOT::Map_refinement_statistics refinement;
  if(!A.stats.charts.empty()) // (the library refuses the rest: genus 1 or more)
    throw Failure{HOT::ERROR_WRONG_PARAMETER, "--refine handles sources embedded without charts; the source is embedded partly in charts around cone images"};
  distortion_before = HOT::map_distortion(A.mesh, B.mesh, locB, f);
  const std::function<void(const char*, double)> told = [&progress](const char*, double fraction) { progress("refine", fraction); };
  const HOT::Error_code ec = HOT::refine_orbifold_map(A.mesh, A.ordered, A.uv, B.mesh, locB, refinement,
    HOT::parameters::refine(refine, HOT::parameters::frame(A.stats.frame, HOT::parameters::cone_orders(A.stats.cone_orders,
      HOT::parameters::orbifold_type(A.type, HOT::parameters::progress(told))))));
  if(ec != HOT::OK)
    throw Failure{ec, "--refine: " + refinement.message};
  f = map_source_vertices(A, locB, " after the refinement");
  return refinement;
}

// OUT (the map), and the report, the prepared target and the colours when asked for
inline void write_map_outputs(const Options& opt, const std::string& out, const Embedded& A, const Embedded& B, const Locator& locB,
                              const std::vector<Locator::Location>& f, const hot_tools::Map_summary& summary)
{
  Output_files files;
  files.write(out, [&](std::ostream& os) { hot_tools::write_map(os, B.mesh, locB, f, addressing(A.in)); });
  if(opt.has("report"))
    files.write(opt.get("report"), [&](std::ostream& os) { hot_tools::write_map_report(os, summary); });
  if(opt.has("prepared-target"))
    files.write(opt.get("prepared-target"), [&](std::ostream& os) { hot_tools::write_addressed_off(os, B.mesh, B.in.file); });
  if(opt.has("colors-out")) {
    // a smooth colouring of A, carried to B by f_BA
    const Locator locA = target_locator(A);
    const std::vector<Locator::Location> g = HOT::map_vertices(result_of(B), locA);
    files.write(opt.get("colors-out"), [&](std::ostream& os) { hot_tools::write_coloured_ply(os, A.mesh, locA, B.mesh, g, addressing(B.in)); });
  }
  files.commit();
}

// what `map` says on stdout (the order, the refinement, the files) and its warnings on stderr
inline void print_map_result(const Options& opt, const std::string& out, const Embedded& A, const HOT::Landmark_order_candidate& chosen,
                             const std::vector<std::string>& refusals, int refine, const HOT::Map_refinement_statistics& refinement,
                             const hot_tools::Map_summary& summary)
{
  std::cout << "landmark order:";
  for(std::size_t i : chosen.order) std::cout << " " << i;
  std::cout << " (" << order_origin(chosen);
  for(const std::string& r : refusals) std::cout << "; " << r;
  std::cout << ")" << std::endl;
  for(const auto& w : {std::make_pair("source", &summary.source_weights), std::make_pair("target", &summary.target_weights)})
    if(*w.second == "mvc")
      std::cout << "weights: the " << w.first << "'s embedding with the cotangent weights failed the certificate; it is embedded with the"
                << " mean value weights" << std::endl;
  if(summary.augmented) {
    std::cout << "augmented: " << summary.added.size() << " matched extremities added to the landmarks (of "
              << summary.source_extremities << " thin tips on the source, " << summary.target_extremities << " on the target; "
              << summary.matched_along_map << " of the pairs matched along the map)";
    for(const std::pair<std::size_t, std::size_t>& p : summary.added)
      std::cout << "; " << p.first << " -> " << p.second;
    std::cout << std::endl;
  }
  if(refine > 0)
    std::cout << "refined: " << refinement.iterations << " certified iterations, symmetric Dirichlet energy " << refinement.energy_before
              << " -> " << refinement.energy_after << " (4 for an isometry; tempered, as the iterations lower it: " << refinement.tempered_energy_before
              << " -> " << refinement.tempered_energy_after << "), " << refinement.seconds << " s; " << refinement.message << std::endl;
  std::cout << "mapped " << num_vertices(A.mesh) << " vertices of " << opt.get("source") << " onto "
            << opt.get("target") << "; wrote " << out << std::endl;
  if(!summary.unreliable.empty())
    std::cerr << "warning: the map cannot resolve the images of " << summary.unreliable.size() << " of the "
              << num_vertices(A.mesh) << " source vertices (the map squeezes or stretches them far from an isometry, or double cannot"
              << " resolve them" << (opt.has("report") ? "; listed in " + opt.get("report") : std::string("; --report lists them"))
              << "): a protrusion without a landmark is the usual cause, put a landmark at the tip of such a protrusion" << std::endl;
  if(!summary.images_in_filled_holes.empty())
    std::cerr << "warning: " << summary.images_in_filled_holes.size() << " of the " << num_vertices(A.mesh)
              << " source vertices map into holes of the target that --repair closed (not on the target file's surface; "
              << (opt.has("report") ? "listed in " + opt.get("report") : std::string("--report lists them")) << ")" << std::endl;
}

inline int run_map(int argc, char** argv)
{
  std::set<std::string> flags = with_progress_flag(repair_flags());
  flags.insert("augment");
  flags.insert("no-augment");
  const Options opt(argc, argv, 2,
                    {"source", "source-cones", "target", "target-cones", "out", "colors-out", "prepared-target", "report", "max-hole", "target-genus", "max-handle",
                     "cone-orders", "source-cut-graph", "target-cut-graph", "source-embedding", "target-embedding", "order"},
                    flags, {"refine"});
  if(opt.has("source-embedding") || opt.has("target-embedding")) {
    if(opt.has("refine") || opt.has("augment") || opt.has("no-augment"))
      throw Usage_error{opt.has("refine") ? "--refine refines a map computed from the meshes, not from stored embeddings"
                                          : "--augment and --no-augment choose the landmarks of a map computed from the meshes, not of stored embeddings"};
    return run_map_stored(opt);
  }
  if(opt.has("augment") && opt.has("no-augment"))
    throw Usage_error{"--augment and --no-augment do not go together"};
  // (--refine without N: 30 iterations. With Newton's step on the faces that are not squeezed
  // (arap_on_target.h), SHREC'07's humans' transfer AUC is 0.816, 0.820, 0.821 at 20, 30, 40
  // iterations (0.804 at 40 with the proxy alone); the same humans subdivided to 19-40K vertices
  // 0.806 at 30 (0.808 at 40), and 30 keep map --refine within 10 times map on them, which 40
  // did not: benchmark.sh --refine)
  const int refine = !opt.has("refine") ? 0 : opt.get("refine").empty() ? 30 : static_cast<int>(opt.get_int("refine", 0, 100000));
  const std::string out = opt.get("out");
  const hot_tools::Repair_options repair = parse_repair_options(opt);
  std::vector<int> orders = parse_cone_orders(opt); // (landmark i of both files: a cone of order orders[i])
  Progress_line progress("map", opt.has("progress"));
  Embedded A, B;
  std::vector<std::string> refusals;
  hot_tools::Map_summary augmentation; // (--augment's part of the summary)
  const HOT::Landmark_order_candidate chosen = embed_map_meshes(opt, repair, orders, A, B, refusals, progress, augmentation);
  const std::vector<std::size_t>& order = chosen.order;
  const int k = static_cast<int>(order.size());
  progress.step("map");
  const auto t0 = std::chrono::steady_clock::now();
  const Locator locB = target_locator(B);
  std::vector<Locator::Location> f = map_source_vertices(A, locB);
  progress.done("map");
  const auto t1 = std::chrono::steady_clock::now();
  HOT::Map_distortion distortion_before;
  HOT::Map_refinement_statistics refinement;
  if(refine > 0) { // (A's embedding moves: everything below reads the refined map)
    progress.step("refine");
    refinement = refine_map(refine, A, B, locB, f, distortion_before, progress);
    progress.done("refine");
  }
  progress.step("reliability");
  const HOT::Map_reliability reliability = HOT::map_reliability(A.mesh, A.uv, B.mesh, B.uv, locB, f);
  progress.done("reliability");
  hot_tools::Map_summary summary = map_summary(opt, A, B, k, reliability);
  summary.images_in_filled_holes = images_in_filled_holes(A, B, f);
  summary.augmented = augmentation.augmented;
  summary.added = augmentation.added;
  summary.source_extremities = augmentation.source_extremities;
  summary.matched_along_map = augmentation.matched_along_map;
  summary.target_extremities = augmentation.target_extremities;
  summary.seconds_augment = augmentation.seconds_augment;
  add_reliability_tests(summary, reliability);
  summary.landmark_order = order;
  summary.landmark_order_from = chosen.mesh == 0 ? "source" : chosen.mesh == 1 ? "target" : "given";
  summary.orders_tried = refusals.size() + 1;
  summary.seconds_map = std::chrono::duration<double>(t1 - t0).count();
  summary.seconds_reliability = std::chrono::duration<double>(std::chrono::steady_clock::now() - t1).count();
  progress.step("distortion");
  const auto t2 = std::chrono::steady_clock::now(); // the per-face distortion (REPORT.json's "distortion")
  summary.distortion = HOT::map_distortion(A.mesh, B.mesh, locB, f);
  summary.seconds_distortion = std::chrono::duration<double>(std::chrono::steady_clock::now() - t2).count();
  progress.done("distortion");
  summary.refined = refine > 0;
  summary.refinement = refinement;
  summary.distortion_before = distortion_before;
  progress.step("write");
  write_map_outputs(opt, out, A, B, locB, f, summary);
  progress.done("write");
  progress.clear();
  print_map_result(opt, out, A, chosen, refusals, refine, refinement, summary);
  return EXIT_SUCCESS;
}

} // namespace hot_cli

#endif // HOT_TOOLS_JOBS_MAP_H
