// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef HOT_TOOLS_JOBS_MAP_PAIR_H
#define HOT_TOOLS_JOBS_MAP_PAIR_H

// The two meshes of a map (and the meshes of a collection): read, checked, embedded with
// their landmarks in cone order; the landmark order chosen by the application layer
// (hot_app/map_order.h, as the Python module's map_meshes() chooses it).

#include "jobs/common.h"
#include "hot_app/map_order.h"
#include "hot_app/stored_embedding.h" // Locator

#include <CGAL/Hyperbolic_orbifold_Tutte/hyperbolic_orbifold_Tutte_embedding.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/cut_graph.h>

#include <functional>
#include <iostream>
#include <string>
#include <vector>

namespace hot_cli {

// Reads, checks and embeds one mesh of a map or a collection with landmarks in cone order.
struct Embedded
{
  Surface_mesh mesh;
  HOT::Orbifold_type type = HOT::Sphere_type;
  std::vector<SM_vertex> landmarks;                  // as read
  std::vector<SM_vertex> ordered;                    // in cone order
  UV_map uv;
  Chart_map charts;                                  // (charts around cone images: see Chart_point)
  HOT::Embedding_statistics stats;
  Input in;                                          // the file's addressing (--repair)
};

inline void read_and_check(const std::string& mesh_path, const std::string& cones_path, const hot_tools::Repair_options& repair, Embedded& e,
                           std::size_t minimum = HOT::minimum_number_of_landmarks, Progress_line* progress = nullptr)
{
  e.type = read_mesh_and_landmarks(mesh_path, cones_path, std::nullopt, repair, e.mesh, e.landmarks, e.in, minimum);
  if(progress && (e.in.file.repaired || !e.in.snaps.empty()))
    progress->clear(); // (a terminal's line, before stdout)
  print_repair(mesh_path, e.in);
}

// the addressing to write a mesh's files with: the file's (--repair), or none (as read)
inline const hot_tools::Input_mesh* addressing(const Input& in)
{
  return in.file.repaired ? &in.file : nullptr;
}

inline void embed_in_order(Embedded& e, const std::vector<std::size_t>& order, const std::vector<int>& orders, const std::string& name,
                           const std::vector<std::vector<SM_vertex> >& cut_graph = {}, Progress_line* progress = nullptr)
{
  e.ordered.clear();
  std::vector<int> ordered_orders; // (empty: 2 for all)
  for(std::size_t i : order) e.ordered.push_back(e.landmarks[i]);
  if(!orders.empty()) {
    if(orders.size() != e.landmarks.size())
      throw Failure{HOT::ERROR_WRONG_PARAMETER, std::to_string(orders.size()) + " cone orders are given for " +
                                                std::to_string(e.landmarks.size()) + " landmarks (one per landmark is needed)"};
    for(std::size_t i : order) ordered_orders.push_back(orders[i]);
  }
  e.uv = e.mesh.add_property_map<SM_halfedge, Kernel::Point_2>("h:uv", Kernel::Point_2(0, 0)).first;
  e.charts = e.mesh.add_property_map<SM_halfedge, HOT::Chart_point<Kernel::Point_2> >("h:chart").first;
  for(SM_halfedge h : halfedges(e.mesh)) { // (as new: a map may embed again in another order)
    e.uv[h] = Kernel::Point_2(0, 0);
    e.charts[h] = HOT::Chart_point<Kernel::Point_2>();
  }
  e.stats = HOT::Embedding_statistics();
  const HOT::Error_code ec = HOT::hyperbolic_orbifold_Tutte_embedding(
    e.mesh, e.ordered, e.uv,
    HOT::parameters::progress(progress ? progress->callback(name) : std::function<void(const char*, double)>(),
    HOT::parameters::cut_graph(cut_graph, HOT::parameters::cone_orders(ordered_orders, HOT::parameters::chart_map(e.charts, HOT::parameters::orbifold_type(e.type, HOT::parameters::embedding_statistics(&e.stats)))))));
  if(ec != HOT::OK)
    throw Failure{ec, name + ": " + e.stats.message};
}

inline long long genus_of(const Embedded& e)
{
  return e.type == HOT::Sphere_type ? HOT::closed_mesh_genus(e.mesh) : 0;
}

// the embedding as the library's result type (its layout: the statistics')
inline Embedding_result result_of(const Embedded& e)
{
  return embedding_result(e.mesh, e.uv, e.charts, e.stats, e.ordered);
}

// the locator of a map's target (or, for the colours, of its source)
inline Locator target_locator(const Embedded& B)
{
  return target_locator(result_of(B));
}

// the source and the target of a map: the same topology and number of landmarks
inline void check_map_pair(const Embedded& A, const Embedded& B)
{
  if(A.type != B.type)
    throw Failure{HOT::ERROR_WRONG_TOPOLOGY, "the source is " + std::string(A.type == HOT::Sphere_type ? "closed" : "a disk") +
                                           " but the target is " + (B.type == HOT::Sphere_type ? "closed" : "a disk")};
  if(A.landmarks.size() != B.landmarks.size())
    throw Failure{HOT::ERROR_WRONG_PARAMETER, "the source has " + std::to_string(A.landmarks.size()) +
                                              " landmarks and the target " + std::to_string(B.landmarks.size())};
  if(genus_of(A) != genus_of(B))
    throw Failure{HOT::ERROR_WRONG_TOPOLOGY, "the source has genus " + std::to_string(genus_of(A)) + " and the target genus " +
                                           std::to_string(genus_of(B)) +
                                           (std::min(genus_of(A), genus_of(B)) == 0 ? " (--repair cuts the handles of the other, topological noise such as"
                                                                                     " fused limbs, up to --max-handle)" : "")};
}

// With --repair, a map between a mesh of genus 0 and one of genus g >= 1 (topological noise of
// a scan: fused fingers, an arm touching the body) reads the latter again with its handles cut
// (--target-genus 0, automatic here); --target-genus given keeps what it asked for.
inline void match_genus_zero(const Options& opt, const hot_tools::Repair_options& repair, Embedded& A, Embedded& B, std::size_t minimum)
{
  if(!repair.repair || opt.has("target-genus") || genus_of(A) == genus_of(B) || std::min(genus_of(A), genus_of(B)) != 0)
    return;
  hot_tools::Repair_options cut = repair;
  cut.target_genus = 0;
  Embedded& E = genus_of(A) > 0 ? A : B;
  const bool source = &E == &A;
  const std::string mesh = opt.get(source ? "source" : "target"), cones = opt.get(source ? "source-cones" : "target-cones");
  std::cout << mesh << " has genus " << genus_of(E) << " and the other mesh genus 0: its handles are cut (--target-genus 0)" << std::endl;
  E = Embedded();
  read_and_check(mesh, cones, cut, E, minimum);
}

// Genus g >= 1: the cut graphs of a map's two meshes, for --source-cut-graph / --target-cut-graph
// or, when only the source's is given or none, the source's own (computed if not given) used on
// the target too when the two meshes have the same faces (a deformed copy); otherwise the
// target's cut graph must be given, since the map depends on it (\ref HOT_Genus).
inline void map_cut_graphs(const Options& opt, const Embedded& A, const Embedded& B, std::vector<std::vector<SM_vertex> >& ga,
                           std::vector<std::vector<SM_vertex> >& gb)
{
  if(opt.has("source-cut-graph"))
    ga = read_cut_graph_of(opt.get("source-cut-graph"), A.mesh, A.in.file);
  if(opt.has("target-cut-graph")) {
    gb = read_cut_graph_of(opt.get("target-cut-graph"), B.mesh, B.in.file);
    if(!opt.has("source-cut-graph"))
      throw Usage_error{"--target-cut-graph needs --source-cut-graph: the two cut graphs must correspond"};
    return;
  }
  bool same_faces = num_vertices(A.mesh) == num_vertices(B.mesh) && num_faces(A.mesh) == num_faces(B.mesh);
  for(auto fa = faces(A.mesh).begin(), fb = faces(B.mesh).begin(); same_faces && fa != faces(A.mesh).end(); ++fa, ++fb) {
    auto ha = halfedge(*fa, A.mesh), hb = halfedge(*fb, B.mesh);
    for(int j = 0; j < 3 && same_faces; ++j, ha = next(ha, A.mesh), hb = next(hb, B.mesh))
      same_faces = target(ha, A.mesh).idx() == target(hb, B.mesh).idx();
  }
  if(!same_faces)
    throw Failure{HOT::ERROR_WRONG_PARAMETER, "the meshes have genus " + std::to_string(genus_of(A)) +
                                              " and not the same faces: a map between them depends on corresponding cut graphs;"
                                              " give both (--source-cut-graph, --target-cut-graph)"};
  if(ga.empty())
    require(HOT::compute_cut_graph(A.mesh, A.ordered, get(CGAL::vertex_point, A.mesh), ga));
  const std::vector<SM_vertex> vb(vertices(B.mesh).begin(), vertices(B.mesh).end());
  for(const auto& p : ga) {
    gb.emplace_back();
    for(SM_vertex v : p) gb.back().push_back(vb[v.idx()]);
  }
}

// Genus g >= 1: the two embeddings must lie in one tile (their cut graphs' polygons equal)
inline void check_same_polygon(const Embedded& A, const Embedded& B)
{
  const HOT::Embedding_statistics &a = A.stats, &b = B.stats;
  if(a.cut_corner_nodes != b.cut_corner_nodes || a.cut_node_cones != b.cut_node_cones || a.cut_paired_sides != b.cut_paired_sides ||
     a.cone_orders != b.cone_orders)
    throw Failure{HOT::ERROR_WRONG_PARAMETER, "the cut graphs of the source and the target do not correspond: their polygons differ (" +
                                              std::to_string(a.cut_corner_nodes.size()) + " and " + std::to_string(b.cut_corner_nodes.size()) +
                                              " corners, or other side pairings); give corresponding cut graphs"};
}

// The cone orders a map tries in turn, best first (--order auto, tsp or given): the
// application layer's choice (map_landmark_orders(), hot_app/map_order.h)
inline std::vector<HOT::Landmark_order_candidate> map_cone_orders(const std::string& how, const Embedded& A, const Embedded& B)
{
  return map_landmark_orders(how, A.type, genus_of(A), A.mesh, A.landmarks, B.mesh, B.landmarks);
}

// Embeds the source and the target of a map in the first order of `candidates` both accept
// (embed_in_first_accepted_order(), hot_app/map_order.h). Returns the index of the order used;
// fails when none works, saying which orders were tried and why each failed. `refusals` gets
// one line per order refused.
inline std::size_t embed_map_pair(Embedded& A, Embedded& B, const std::vector<HOT::Landmark_order_candidate>& candidates,
                                  const std::vector<int>& orders, const std::vector<std::vector<SM_vertex> >& ga,
                                  const std::vector<std::vector<SM_vertex> >& gb, std::vector<std::string>& refusals,
                                  Progress_line* progress = nullptr)
{
  HOT::Error_code code = HOT::OK;
  std::string message;
  const std::size_t c = embed_in_first_accepted_order<Failure>(
    candidates,
    [&](const HOT::Landmark_order_candidate& candidate, bool target_first) {
      embed_in_order(target_first ? B : A, candidate.order, orders, target_first ? "target" : "source", target_first ? gb : ga, progress);
      embed_in_order(target_first ? A : B, candidate.order, orders, target_first ? "source" : "target", target_first ? ga : gb, progress);
    },
    [](const Failure& f) { return f.message; }, refusals, code, message);
  if(c == std::size_t(-1))
    throw Failure{code, message};
  return c;
}

} // namespace hot_cli

#endif // HOT_TOOLS_JOBS_MAP_PAIR_H
