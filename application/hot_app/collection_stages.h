// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef HOT_APP_COLLECTION_STAGES_H
#define HOT_APP_COLLECTION_STAGES_H

// The separate jobs of a collection (collection_job.h says how they share the output folder):
// a mesh's embedding, its refinement onto mesh 0, a pair's map, and the merge.

#include "hot_app/collection_job.h"

#include <CGAL/Hyperbolic_orbifold_Tutte/hyperbolic_orbifold_Tutte_embedding.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/refine_orbifold_map.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/surface_maps.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/check_input.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/input/input_stage.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/input/genus_cut.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <dirent.h>
#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>
#include <algorithm>
#include <array>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace hot_cli {

// The embedding job of mesh i: DIR/<i>_<name>.obj and DIR/.parts/mesh_<i>.json (its line
// "reversed 0|1", then its entry of the report). Returns its embedding time.
inline double embed_collection_mesh(const Collection_job& job, const Collection_order& co, std::size_t i)
{
  check_parts_options(job, "embed");
  if(embedding_done(job, i)) // (a job run again: done before)
    return 0;
  Surface_mesh m;
  std::vector<SM_vertex> landmarks;
  Input in;
  const std::string& path = job.entries[i].first;
  const HOT::Orbifold_type type = read_mesh_and_landmarks(path, job.entries[i].second, std::nullopt, job.repair, m, landmarks, in,
                                                          minimum_landmarks(job.orders));
  if(type != co.type || landmarks.size() != co.landmarks)
    throw Failure{HOT::ERROR_WRONG_PARAMETER, path + ": its topology or number of landmarks differs from the first mesh's"};
  if(type == HOT::Sphere_type) {
    const long long genus = HOT::closed_mesh_genus(m);
    if(genus > 0)
      throw Failure{HOT::ERROR_WRONG_TOPOLOGY, path + ": mesh " + std::to_string(i) + " has genus " + std::to_string(genus) +
                                                 ": collections of closed meshes of genus 1 or more are not built yet; map them in pairs"
                                                 " along corresponding cut graphs"};
  }
  std::vector<SM_vertex> ordered;
  std::vector<int> cut_orders; // (empty: all 2)
  for(std::size_t c : co.order) {
    ordered.push_back(landmarks[c]);
    if(!job.orders.empty()) cut_orders.push_back(job.orders[c]);
  }
  // (as Orbifold_collection::embed() embeds each mesh)
  const UV_map uv = m.add_property_map<SM_halfedge, Kernel::Point_2>("h:uv", Kernel::Point_2(0, 0)).first;
  const Chart_map charts = m.add_property_map<SM_halfedge, HOT::Chart_point<Kernel::Point_2> >("h:chart").first;
  HOT::Embedding_statistics st;
  const HOT::Error_code ec = HOT::hyperbolic_orbifold_Tutte_embedding(
    m, ordered, uv,
    HOT::parameters::cone_orders(cut_orders, HOT::parameters::chart_map(charts, HOT::parameters::orbifold_type(type, HOT::parameters::embedding_statistics(&st)))));
  if(ec != HOT::OK && co.from < job.size() && job.order == "auto" && HOT::is_landmark_order_failure(ec))
    throw Failure{ec, path + ": " + st.message + " (in the landmark order of mesh " + std::to_string(co.from) + "'s tour, the first the"
                  " collection tries; separate jobs try no other: run the collection in one process, which tries the other meshes'"
                  " tours in turn, or force an order with --order)"};
  if(ec != HOT::OK)
    throw Failure{ec, path + ": " + st.message};
  const hot_tools::Input_mesh* addressed = in.file.repaired ? &in.file : nullptr;
  hot_tools::Embedding_cones cones;
  cones.type = type;
  cones.reversed = st.landmark_order_reversed;
  cones.landmark = co.order;
  cones.vertex = file_indices(ordered, in.file);
  cones.order = cut_orders.empty() ? std::vector<int>(co.order.size(), 2) : cut_orders;
  make_folder(job.dir);
  make_folder(job.parts());
  Output_files files;
  const Embedding_result result = embedding_result(m, uv, charts, st, ordered);
  files.write(job.refine > 0 ? job.embedded_path(i) : job.obj_path(i),
              [&](std::ostream& os) { hot_tools::write_embedding_obj(os, result, addressed, &cones); });
  files.write(job.mesh_part(i), [&](std::ostream& os) {
    os << "reversed " << (st.landmark_order_reversed ? 1 : 0) << "\n"
       << "order_from " << (co.from < job.size() ? "mesh " + std::to_string(co.from) : std::string("given")) << "\n"
       << hot_tools::collection_mesh_entry(i, path, num_vertices(m), st, &in.file) << "\n";
  });
  files.commit();
  return st.time_setup + st.time_initialization + st.time_optimization + st.time_certificate;
}

// the text of the OBJ file `text` (the embedding `e` was read from) with its vt lines replaced
// by e.uv's corners, as write_embedding_obj() writes them; a vt whose corners no longer have one
// point fails (the corners of a cut-mesh vertex move together: they do not part)
inline std::string with_corners(const std::string& text, const Stored_embedding& e)
{
  std::vector<Kernel::Point_2> point;
  std::vector<char> seen;
  for(SM_halfedge h : halfedges(e.mesh)) {
    const std::size_t t = e.corner_vt[h.idx()];
    if(t == Stored_embedding::npos)
      continue;
    if(t >= point.size()) {
      point.resize(t + 1);
      seen.resize(t + 1, 0);
    }
    if(seen[t] && point[t] != get(e.uv, h))
      throw Failure{HOT::ERROR_NO_1_TO_1_MAPPING, e.path + ": two corners of one vt line of the stored embedding moved apart"};
    point[t] = get(e.uv, h);
    seen[t] = 1;
  }
  std::ostringstream os;
  hot_tools::io_impl::Text_buffer b;
  std::size_t t = 0;
  for(std::size_t at = 0; at < text.size();) {
    const std::size_t eol = std::min(text.find('\n', at), text.size());
    if(text.compare(at, 3, "vt ") == 0) {
      if(t >= point.size() || !seen[t])
        throw Failure{HOT::ERROR_READ_FAILED, e.path + ": a vt line on no face"};
      b.put("vt ").put(CGAL::to_double(point[t].x())).put(' ').put(CGAL::to_double(point[t].y())).put('\n');
      ++t;
    } else {
      b.put(std::string_view(text).substr(at, eol - at));
      if(eol < text.size())
        b.put('\n');
    }
    at = eol + 1;
  }
  b.flush_to(os);
  return os.str();
}

// The refinement job of mesh i (collection --refine N, after the embed stage): mesh i's
// embedding refined towards an isometric map onto mesh 0 (refine_orbifold_map(), with the
// parameters Orbifold_collection::refine() gives it in one process), written as
// DIR/<i>_<name>.obj, and its statistics as DIR/.parts/refine_<i>.txt; mesh 0, the reference,
// is copied. Returns the refinement's time.
inline double refine_collection_mesh(const Collection_job& job, std::size_t i)
{
  if(folder_exists(job.parts()))
    check_parts_options(job, "refine");
  if(refinement_done(job, i))
    return 0;
  std::string text;
  if(!hot_tools::read_file_contents(job.embedded_path(i), text))
    throw Failure{HOT::ERROR_READ_FAILED, job.entries[i].first + ": mesh " + std::to_string(i) +
                                            " was not embedded for the refinement (run the embed stage of every shard with --refine first)"};
  HOT::Map_refinement_statistics st;
  if(i != 0) {
    Stored_embedding A, B;
    read_stored_embedding(job.embedded_path(i), A);
    read_stored_embedding(job.embedded_path(0), B);
    check_stored_pair(A, B);
    if(!A.chart_isometries.empty())
      throw Failure{HOT::ERROR_WRONG_PARAMETER, "--refine: mesh " + std::to_string(i) + ": " + job.entries[i].first +
                                                  " is embedded partly in charts around cone images, which the refinement does not handle"};
    std::vector<SM_vertex> ordered;
    for(std::size_t line : A.cones.vertex)
      ordered.push_back(SM_vertex(static_cast<SM_vertex::size_type>(A.line_vertex[line])));
    const Locator lb = stored_locator(B);
    const HOT::Error_code ec = HOT::refine_orbifold_map(A.mesh, ordered, A.uv, B.mesh, lb, st,
      HOT::parameters::refine(job.refine, HOT::parameters::frame(HOT::Hyperbolic_isometry_2<double>(),
        HOT::parameters::cone_orders(job.orders.empty() ? std::vector<int>() : A.cones.order, HOT::parameters::orbifold_type(A.cones.type)))));
    if(ec != HOT::OK)
      throw Failure{ec, "--refine: mesh " + std::to_string(i) + ": " + st.message};
    text = with_corners(text, A);
  }
  Output_files files;
  files.write(job.obj_path(i), [&](std::ostream& os) { os << text; });
  files.write(job.refine_part(i), [&](std::ostream& os) {
    os.precision(17);
    os << "iterations " << st.iterations << "\nstop " << static_cast<int>(st.stop) << "\nenergy_before " << st.energy_before
       << "\nenergy_after " << st.energy_after << "\ntempered_energy_before " << st.tempered_energy_before
       << "\ntempered_energy_after " << st.tempered_energy_after << "\nfree_vertices " << st.free_vertices << "\nundone_moves " << st.undone_moves
       << "\nseconds " << st.seconds << "\nseconds_certificate " << st.seconds_certificate << "\nmessage " << st.message << "\n";
  });
  files.commit();
  return st.seconds;
}

// reads a refine job's part (the refinement's statistics)
inline HOT::Map_refinement_statistics read_refine_part(const Collection_job& job, std::size_t i)
{
  std::ifstream is(job.refine_part(i));
  HOT::Map_refinement_statistics st;
  std::string key;
  int stop = -1;
  if(!(is >> key) || key != "iterations" || !(is >> st.iterations >> key >> stop >> key >> st.energy_before >> key >> st.energy_after >> key >>
                                              st.tempered_energy_before >> key >> st.tempered_energy_after >> key >>
                                              st.free_vertices >> key >> st.undone_moves >> key >> st.seconds >> key >> st.seconds_certificate >> key) ||
     key != "message" || stop < HOT::Refinement_not_run || stop > HOT::Refinement_solver)
    throw Failure{HOT::ERROR_READ_FAILED, job.refine_part(i) + ": missing or unreadable: mesh " + std::to_string(i) +
                                            " was not refined (run the refine stage of every shard first)"};
  st.stop = static_cast<HOT::Refinement_stop>(stop);
  is.get();
  std::getline(is, st.message);
  return st;
}

// the map f_ab of a collection from the stored embeddings; a point not located fails
inline std::vector<Locator::Location> map_stored(const Stored_embedding& A, const Locator& lb, std::size_t a, std::size_t b)
{
  std::vector<Locator::Location> f = HOT::map_vertices(A.result(), lb);
  for(std::size_t v = 0; v < f.size(); ++v)
    if(!f[v].success)
      throw Failure{HOT::ERROR_POINT_NOT_LOCATED, "vertex " + std::to_string(v) + " of mesh " + std::to_string(a) +
                                                    " could not be located on mesh " + std::to_string(b)};
  return f;
}

// The map job of the pair (a, b): DIR/<a>_to_<b>.map.txt with --all-pairs, and
// DIR/.parts/map_<a>_<b>.bin: its time, then per vertex of a its face and barycentric
// coordinates (the locator's order), in the machine's binary doubles. Returns the map's time.
inline double map_collection_pair(const Collection_job& job, std::size_t a, std::size_t b)
{
  if(folder_exists(job.parts()))
    check_parts_options(job, "maps");
  if(map_done(job, a, b)) {
    double seconds = 0;
    std::ifstream is(job.map_part(a, b), std::ios::binary);
    is.read(reinterpret_cast<char*>(&seconds), sizeof(double));
    return seconds;
  }
  if(job.refine > 0) // (the refine stage's files, not a half-done stage's)
    for(std::size_t i : {a, b})
      read_refine_part(job, i);
  Stored_embedding A, B;
  read_stored_embedding(job.obj_path(a), A);
  read_stored_embedding(job.obj_path(b), B);
  check_stored_pair(A, B);
  const Locator lb = stored_locator(B);
  const auto t0 = std::chrono::steady_clock::now();
  const std::vector<Locator::Location> f = map_stored(A, lb, a, b);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  make_folder(job.parts());
  Output_files files;
  if(job.all_pairs)
    files.write(job.map_path(a, b), [&](std::ostream& os) { hot_tools::write_map(os, B.mesh, lb, f, A.line_vertex); });
  files.write(job.map_part(a, b), [&](std::ostream& os) {
    const std::uint64_t n = f.size();
    os.write(reinterpret_cast<const char*>(&seconds), sizeof(double));
    os.write(reinterpret_cast<const char*>(&n), sizeof(n));
    for(const Locator::Location& l : f) {
      const std::uint64_t face = l.face_index;
      os.write(reinterpret_cast<const char*>(&face), sizeof(face));
      os.write(reinterpret_cast<const char*>(l.barycentric.data()), 3 * sizeof(double));
    }
  });
  files.commit();
  return seconds;
}

// reads a map job's part: its time and the locations (face index and barycentric coordinates)
inline std::vector<Locator::Location> read_map_part(const Collection_job& job, std::size_t a, std::size_t b, double& seconds)
{
  const std::string path = job.map_part(a, b);
  std::ifstream is(path, std::ios::binary);
  std::uint64_t n = 0;
  if(!is.read(reinterpret_cast<char*>(&seconds), sizeof(double)) || !is.read(reinterpret_cast<char*>(&n), sizeof(n)) || n > (std::uint64_t(1) << 40))
    throw Failure{HOT::ERROR_READ_FAILED, path + ": missing or unreadable: the map of mesh " + std::to_string(a) + " onto mesh " +
                                            std::to_string(b) + " was not computed (run the maps stage of every shard first)"};
  std::vector<Locator::Location> f(static_cast<std::size_t>(n));
  for(Locator::Location& l : f) {
    std::uint64_t face = 0;
    if(!is.read(reinterpret_cast<char*>(&face), sizeof(face)) || !is.read(reinterpret_cast<char*>(l.barycentric.data()), 3 * sizeof(double)))
      throw Failure{HOT::ERROR_READ_FAILED, path + ": truncated"};
    l.face_index = static_cast<std::size_t>(face);
    l.success = true;
  }
  return f;
}

// the largest distance, over the vertices x of a, between f_bc(f_ab(x)) and f_ac(x) on c,
// relative to c's bounding-box diagonal (Orbifold_collection::cycle_consistency_error())
inline double stored_cycle_error(const Stored_embedding& B, const Stored_embedding& C, const Locator& lb, const Locator& lc,
                                 const std::vector<Locator::Location>& fab, const std::vector<Locator::Location>& fac,
                                 std::size_t b, std::size_t c)
{
  const CGAL::Bbox_3 bb = CGAL::Polygon_mesh_processing::bbox(C.mesh);
  const double diag = std::sqrt(CGAL::square(bb.xmax() - bb.xmin()) + CGAL::square(bb.ymax() - bb.ymin()) +
                                CGAL::square(bb.zmax() - bb.zmin()));
  const std::size_t nf = num_faces(B.mesh);
  double worst = 0;
  for(std::size_t v = 0; v < fab.size(); ++v) {
    if(fab[v].face_index >= nf || fac[v].face_index >= num_faces(C.mesh))
      throw Failure{HOT::ERROR_READ_FAILED, "a stored map names a face its target does not have"};
    const Locator::Location l = lc.locate(lb.disk_point(fab[v]));
    if(!l.success)
      throw Failure{HOT::ERROR_POINT_NOT_LOCATED, "a point of mesh " + std::to_string(b) + " could not be located on mesh " + std::to_string(c)};
    const auto p = HOT::surface_point(l, lc, get(CGAL::vertex_point, C.mesh));
    const auto q = HOT::surface_point(fac[v], lc, get(CGAL::vertex_point, C.mesh));
    worst = std::max(worst, std::sqrt(CGAL::to_double(CGAL::squared_distance(p, q))) / diag);
  }
  return worst;
}

// The merge: DIR/report.json from the parts, with the cycle consistency over the triples; then
// DIR/.parts is removed. Returns the report's figures.
inline hot_tools::Collection_report merge_collection(const Collection_job& job)
{
  const std::size_t N = job.size();
  hot_tools::Collection_report r;
  int reversed0 = 0;
  for(std::size_t i = 0; i < N; ++i) {
    std::string text;
    if(!hot_tools::read_file_contents(job.mesh_part(i), text))
      throw Failure{HOT::ERROR_READ_FAILED, job.entries[i].first + ": mesh " + std::to_string(i) +
                                              " was not embedded (run the embed stage of every shard first)"};
    const std::size_t eol0 = text.find('\n');
    const std::size_t eol = eol0 == std::string::npos ? eol0 : text.find('\n', eol0 + 1); // (the line "order_from ...")
    if(text.compare(0, 9, "reversed ") != 0 || eol == std::string::npos || text.size() < eol + 2 ||
       text.compare(eol0 + 1, 11, "order_from ") != 0)
      throw Failure{HOT::ERROR_READ_FAILED, job.mesh_part(i) + ": malformed"};
    if(i == 0) {
      r.order_from = text.substr(eol0 + 12, eol - eol0 - 12);
      r.orders_tried = 1;
    }
    const int reversed = text[9] == '1' ? 1 : 0;
    if(i == 0) reversed0 = reversed;
    else if(reversed != reversed0)
      throw Failure{HOT::ERROR_WRONG_PARAMETER, job.entries[i].first + ": its landmarks run around the boundary the other way than the first"
                                                  " mesh's: the correspondence would reverse orientation"};
    r.mesh_entries.push_back(text.substr(eol + 1, text.size() - eol - 2));
  }
  if(job.refine > 0) {
    for(std::size_t i = 0; i < N; ++i)
      r.refinement.push_back(read_refine_part(job, i));
    r.refinement[0] = HOT::Map_refinement_statistics(); // (the reference: as in one process)
    if(std::none_of(r.refinement.begin(), r.refinement.end(), [](const auto& st) { return st.stop != HOT::Refinement_not_run; }))
      r.refinement.clear();
  }
  Stored_embedding first;
  read_stored_embedding(job.obj_path(0), first);
  r.type = first.cones.type;
  r.order = first.cones.landmark;
  const Collection_pairs cp = collection_pairs(N, job.all_pairs);
  std::vector<std::vector<double> > seconds(N, std::vector<double>(N, -1));
  // the triples, grouped by their source (the maps of one source read once)
  std::vector<std::unique_ptr<Stored_embedding> > stored(N);
  std::vector<std::unique_ptr<Locator> > locators(N);
  auto locator = [&](std::size_t i) -> const Locator& {
    if(!locators[i]) {
      stored[i].reset(new Stored_embedding);
      read_stored_embedding(job.obj_path(i), *stored[i]);
      locators[i].reset(new Locator(stored_locator(*stored[i])));
    }
    return *locators[i];
  };
  std::vector<std::vector<std::vector<Locator::Location> > > maps(N);
  auto stored_map = [&](std::size_t a, std::size_t b) -> const std::vector<Locator::Location>& {
    if(maps[a].empty()) maps[a].resize(N);
    if(maps[a][b].empty()) maps[a][b] = read_map_part(job, a, b, seconds[a][b]);
    return maps[a][b];
  };
  std::size_t current = N;
  for(const auto& t : cp.triples) {
    if(t[0] != current) { // (a new source: the previous one's maps are no longer needed)
      if(current < N) maps[current].clear();
      current = t[0];
    }
    const auto& fab = stored_map(t[0], t[1]);
    const auto& fac = stored_map(t[0], t[2]);
    const Locator& lb = locator(t[1]);
    const Locator& lc = locator(t[2]);
    r.cycle = std::max(r.cycle, stored_cycle_error(*stored[t[1]], *stored[t[2]], lb, lc, fab, fac, t[1], t[2]));
    ++r.triples;
  }
  for(const auto& p : cp.pairs)
    if(seconds[p.first][p.second] < 0)
      read_map_part(job, p.first, p.second, seconds[p.first][p.second]);
  for(std::size_t a = 0; a < N; ++a)
    for(std::size_t b = 0; b < N; ++b)
      if(seconds[a][b] >= 0) r.pairs.push_back(std::make_pair(std::make_pair(a, b), seconds[a][b]));
  Output_files files;
  files.write(job.dir + "/report.json", [&](std::ostream& os) { hot_tools::write_collection_report(os, r); });
  files.commit();
  // (renamed first: a merge killed while removing leaves no DIR/.parts that looks like a
  // collection in progress; the next single-process run or merge removes the rest)
  const std::string removing = job.parts() + ".removing";
  remove_parts_folder(removing);
  if(std::rename(job.parts().c_str(), removing.c_str()) == 0)
    remove_parts_folder(removing);
  return r;
}

} // namespace hot_cli

#endif // HOT_APP_COLLECTION_STAGES_H
