// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef HOT_TOOLS_JOBS_COLLECTION_H
#define HOT_TOOLS_JOBS_COLLECTION_H

// The `collection` command: in one process (resumable, or in memory when an embedding refuses
// the first tour) or as separate stages (--stage, --shard); the stages' jobs are the
// application layer's (hot_app/collection_stages.h), shared with the Python module.

#include "jobs/map_pair.h"
#include "hot_app/collection_stages.h"

#include <CGAL/Hyperbolic_orbifold_Tutte/Orbifold_collection.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <exception>
#include <functional>
#include <iostream>
#include <mutex>
#include <optional>
#include <sstream>
#include <string>
#include <thread>
#include <utility>
#include <vector>

namespace hot_cli {

typedef HOT::Orbifold_collection<Surface_mesh, CGAL::Parallel_tag> Collection;
typedef hot_tools::Collection_maps Collection_maps;

// reads and checks every mesh of the manifest into the collection; returns the orbifold type
inline HOT::Orbifold_type read_collection(const Manifest& entries, const hot_tools::Repair_options& repair, Collection& coll,
                                          std::vector<hot_tools::Input_mesh>& inputs, std::size_t minimum)
{
  HOT::Orbifold_type type = HOT::Sphere_type;
  std::size_t k = 0;
  for(std::size_t i = 0; i < entries.size(); ++i) {
    Embedded e;
    read_and_check(entries[i].first, entries[i].second, repair, e, minimum);
    inputs.push_back(e.in.file);
    if(i == 0) {
      type = e.type;
      k = e.landmarks.size();
    }
    if(e.type != type || e.landmarks.size() != k)
      throw Failure{HOT::ERROR_WRONG_PARAMETER, entries[i].first + ": its topology or number of landmarks differs from the first mesh's"};
    coll.add_mesh(e.mesh, e.landmarks);
  }
  return type;
}

// embeds the collection (in parallel), progress on stderr; a failure names the mesh's file
inline void embed_collection(const Manifest& entries, Collection& coll)
{
  const std::size_t N = entries.size();
  std::vector<HOT::Error_code> codes(N, HOT::OK);
  coll.set_progress_callback([&](const Collection::Progress& p) {
    if(p.stage == Collection::Progress::Mesh_embedded) {
      codes[p.source] = p.code;
      std::cerr << "  embedded " << p.done << "/" << p.total << ": " << entries[p.source].first << " (" << p.seconds << " s)" << std::endl;
    } else if(p.done == p.total || p.done % std::max<std::size_t>(1, p.total / 20) == 0) {
      std::cerr << "  mapped " << p.done << "/" << p.total << " pairs (last: " << p.source << " -> " << p.target << ", "
                << p.seconds << " s)" << std::endl;
    }
  });
  const HOT::Error_code ec = coll.embed();
  if(ec == HOT::OK)
    return;
  if(coll.order_attempts().size() > 1) // (every order tried: the collection's message names each, and why it failed)
    throw Failure{ec, coll.message()};
  for(std::size_t i = 0; i < N; ++i)
    if(codes[i] != HOT::OK)
      throw Failure{codes[i], entries[i].first + ": " + coll.statistics(i).message};
  for(std::size_t i = 1; i < N; ++i)
    if(coll.statistics(i).landmark_order_reversed != coll.statistics(0).landmark_order_reversed)
      throw Failure{HOT::ERROR_WRONG_PARAMETER, entries[i].first + ": its landmarks run around the boundary the other way than the first mesh's: "
                                                "the correspondence would reverse orientation"};
  if(ec == HOT::ERROR_CUT_FAILED && coll.order().size() != coll.landmarks(0).size())
    throw Failure{ec, "the landmark tour could not be computed on " + std::string(coll.message().compare(0, 7, "mesh 0:") == 0 ? "the first mesh" : "a mesh")};
  throw Failure{ec, coll.message()};
}

// computes the maps the command needs (in parallel) and the cycle consistency over the
// triples (see Collection_maps); a point not located fails
inline Collection_maps map_collection(Collection& coll, bool all_pairs)
{
  const std::size_t N = coll.number_of_meshes();
  const Collection_pairs cp = collection_pairs(N, all_pairs);
  const auto& triples = cp.triples;
  coll.compute_maps(cp.pairs); // in parallel
  // failures are reported in the order the maps are used
  Collection_maps r;
  r.used.assign(N, std::vector<char>(N, 0));
  auto use_map = [&](std::size_t a, std::size_t b) {
    const std::vector<Collection::Location>& f = coll.map(a, b);
    if(r.used[a][b]) return;
    r.used[a][b] = 1;
    for(std::size_t v = 0; v < f.size(); ++v)
      if(!f[v].success)
        throw Failure{HOT::ERROR_POINT_NOT_LOCATED, "vertex " + std::to_string(v) + " of mesh " + std::to_string(a) + " could not be located on mesh " + std::to_string(b)};
  };
  for(const auto& t : triples) {
    use_map(t[0], t[1]);
    use_map(t[0], t[2]);
    const double e = coll.cycle_consistency_error(t[0], t[1], t[2]);
    if(std::isinf(e))
      throw Failure{HOT::ERROR_POINT_NOT_LOCATED, "a point of mesh " + std::to_string(t[1]) + " could not be located on mesh " + std::to_string(t[2])};
    r.cycle = std::max(r.cycle, e);
    ++r.triples;
  }
  if(all_pairs)
    for(std::size_t a = 0; a < N; ++a)
      for(std::size_t b = 0; b < N; ++b)
        if(a != b) use_map(a, b);
  return r;
}

// DIR/<i>_<name>.obj per mesh, with --all-pairs DIR/<a>_to_<b>.map.txt per ordered pair, and
// DIR/report.json
inline void write_collection_files(const Collection_job& job, Collection& coll, HOT::Orbifold_type type,
                                   const Collection_maps& maps, const std::vector<hot_tools::Input_mesh>& inputs)
{
  auto addressed = [&](std::size_t i) { return inputs[i].repaired ? &inputs[i] : nullptr; };
  const std::size_t N = job.size();
  std::vector<std::string> mesh_paths;
  for(const auto& e : job.entries)
    mesh_paths.push_back(e.first);
  make_folder(job.dir);
  Output_files files;
  for(std::size_t i = 0; i < N; ++i) {
    const HOT::Embedding_statistics& st = coll.statistics(i);
    hot_tools::Embedding_cones cones;
    cones.type = type;
    cones.reversed = st.landmark_order_reversed;
    cones.landmark = coll.order();
    for(std::size_t c : coll.order()) {
      cones.vertex.push_back(hot_tools::output_vertex(coll.landmarks(i)[c], addressed(i)));
      cones.order.push_back(coll.cone_orders().empty() ? 2 : coll.cone_orders()[c]);
    }
    files.write(job.obj_path(i),
                [&](std::ostream& os) { hot_tools::write_embedding_obj(os, coll.embedding(i), addressed(i), &cones); });
  }
  if(job.all_pairs)
    for(std::size_t a = 0; a < N; ++a)
      for(std::size_t b = 0; b < N; ++b) {
        if(a == b) continue;
        const auto& f = coll.map(a, b);
        files.write(job.map_path(a, b), [&](std::ostream& os) { hot_tools::write_map(os, coll.mesh(b), coll.locator(b), f, addressed(a)); });
      }
  files.write(job.dir + "/report.json", [&](std::ostream& os) { hot_tools::write_collection_report(os, mesh_paths, coll, type, maps, &inputs); });
  files.commit();
}

// --shard I/N: this job's share, I in [0, N)
inline std::pair<std::size_t, std::size_t> parse_shard(const Options& opt)
{
  if(!opt.has("shard"))
    return std::make_pair(std::size_t(0), std::size_t(1));
  const std::string s = opt.get("shard");
  const std::size_t slash = s.find('/');
  std::size_t i = 0, n = 0;
  bool ok = slash != std::string::npos && slash > 0 && slash + 1 < s.size();
  for(std::size_t k = 0; ok && k < s.size(); ++k)
    if(k != slash) ok = std::isdigit(static_cast<unsigned char>(s[k])) != 0;
  if(ok && slash <= 9 && s.size() - slash - 1 <= 9) {
    i = std::stoul(s.substr(0, slash));
    n = std::stoul(s.substr(slash + 1));
  } else
    ok = false;
  if(!ok || n == 0 || i >= n)
    throw Usage_error{"--shard must be I/N with 0 <= I < N (e.g. 0/8), got '" + s + "'"};
  return std::make_pair(i, n);
}

// runs job(k) for k in [0, n) in `threads` threads (the first failure is rethrown once all stop;
// the others stop taking new work)
inline void run_in_threads(std::size_t n, std::size_t threads, const std::function<void(std::size_t)>& job)
{
  std::atomic<std::size_t> next(0);
  std::atomic<bool> failed(false);
  std::exception_ptr first;
  std::mutex m;
  auto worker = [&] {
    for(std::size_t k; !failed && (k = next++) < n;) {
      try {
        job(k);
      } catch(...) {
        std::lock_guard<std::mutex> g(m);
        if(!first) first = std::current_exception();
        failed = true;
      }
    }
  };
  std::vector<std::thread> pool;
  for(std::size_t t = 1; t < std::min(threads, n); ++t) pool.emplace_back(worker);
  worker();
  for(std::thread& t : pool) t.join();
  if(first)
    std::rethrow_exception(first);
}

// the shard's share of n items: shard.first, shard.first + shard.second, ...
inline std::vector<std::size_t> shard_items(std::size_t n, std::pair<std::size_t, std::size_t> shard)
{
  std::vector<std::size_t> r;
  for(std::size_t k = shard.first; k < n; k += shard.second) r.push_back(k);
  return r;
}

// --stage embed: the shard's meshes embedded (those embedded before skipped)
inline void run_collection_embed_stage(const Collection_job& job, std::pair<std::size_t, std::size_t> shard, std::size_t threads, bool summary, std::ostream& log)
{
  std::mutex out;
  std::size_t done = 0, skipped = 0;
  const std::vector<std::size_t> todo = shard_items(job.size(), shard);
  // (the collection's order is computed, reading every mesh, only when some mesh is left)
  std::optional<Collection_order> co;
  for(std::size_t i : todo) {
    if(embedding_done(job, i)) {
      check_parts_options(job, "embed");
      log << "  " << job.entries[i].first << ": embedded before (" << job.parts() << ")" << std::endl;
      ++skipped;
    } else if(!co)
      co = collection_order(job);
  }
  run_in_threads(todo.size(), threads, [&](std::size_t k) {
    const std::size_t i = todo[k];
    if(embedding_done(job, i))
      return;
    const double t = embed_collection_mesh(job, *co, i);
    std::lock_guard<std::mutex> g(out);
    ++done;
    log << "  embedded " << done << "/" << todo.size() - skipped << ": " << job.entries[i].first << " (" << t << " s)" << std::endl;
  });
  if(summary)
    std::cout << "collection shard " << shard.first << "/" << shard.second << ": embedded " << done << " of " << job.size() << " meshes into "
              << job.dir << (skipped > 0 ? " (" + std::to_string(skipped) + " embedded before)" : std::string()) << std::endl;
}

// --stage refine: the shard's meshes refined onto mesh 0 (those refined before skipped)
inline void run_collection_refine_stage(const Collection_job& job, std::pair<std::size_t, std::size_t> shard, std::size_t threads, bool summary, std::ostream& log)
{
  std::mutex out;
  std::size_t done = 0, skipped = 0;
  if(job.refine <= 0)
    throw Usage_error{"--stage refine needs --refine [N] (in every stage's job)"};
  const std::vector<std::size_t> todo = shard_items(job.size(), shard);
  run_in_threads(todo.size(), threads, [&](std::size_t k) {
    const std::size_t i = todo[k];
    const bool before = refinement_done(job, i);
    const double t = refine_collection_mesh(job, i);
    std::lock_guard<std::mutex> g(out);
    if(before) {
      log << "  " << job.entries[i].first << ": refined before (" << job.parts() << ")" << std::endl;
      ++skipped;
      return;
    }
    if(i > 0) {
      const HOT::Map_refinement_statistics st = read_refine_part(job, i);
      log << "  refined " << job.entries[i].first << " onto " << job.entries[0].first << ": " << hot_tools::refinement_line(st, t) << std::endl;
    }
    ++done;
  });
  if(summary)
    std::cout << "collection shard " << shard.first << "/" << shard.second << ": refined " << done << " of " << job.size() << " meshes in "
              << job.dir << (skipped > 0 ? " (" + std::to_string(skipped) + " refined before)" : std::string()) << std::endl;
}

// --stage maps: the shard's pairs mapped (those mapped before skipped)
inline void run_collection_maps_stage(const Collection_job& job, std::pair<std::size_t, std::size_t> shard, std::size_t threads, bool summary, std::ostream& log)
{
  std::mutex out;
  std::size_t done = 0, skipped = 0;
  const Collection_pairs cp = collection_pairs(job.size(), job.all_pairs);
  const std::vector<std::size_t> todo = shard_items(cp.pairs.size(), shard);
  std::vector<std::size_t> left;
  for(std::size_t p : todo) {
    if(map_done(job, cp.pairs[p].first, cp.pairs[p].second)) {
      check_parts_options(job, "maps");
      ++skipped;
    } else
      left.push_back(p);
  }
  if(skipped > 0)
    log << "  " << skipped << " of " << todo.size() << " pairs mapped before (" << job.parts() << ")" << std::endl;
  run_in_threads(left.size(), threads, [&](std::size_t k) {
    const std::size_t p = left[k];
    const double t = map_collection_pair(job, cp.pairs[p].first, cp.pairs[p].second);
    std::lock_guard<std::mutex> g(out);
    ++done;
    if(done == left.size() || done % std::max<std::size_t>(1, left.size() / 20) == 0)
      log << "  mapped " << done << "/" << left.size() << " pairs (last: " << cp.pairs[p].first << " -> " << cp.pairs[p].second << ", " << t
                << " s)" << std::endl;
  });
  if(summary)
    std::cout << "collection shard " << shard.first << "/" << shard.second << ": mapped " << done << " of " << cp.pairs.size() << " pairs in "
              << job.dir << (skipped > 0 ? " (" + std::to_string(skipped) + " mapped before)" : std::string()) << std::endl;
}

// `collection --stage embed|refine|maps|merge [--shard I/N]`: the collection as separate jobs
// (hot_app/collection_stages.h): the embed stage embeds meshes I, I + N, ...; the maps stage computes the
// maps I, I + N, ... of the collection's list of pairs from the stored embeddings; the merge
// writes report.json once both stages are done for every shard. A mesh or pair whose part is
// already in DIR/.parts (a job run again) is skipped, with a line on stderr. `threads`: the
// single-process run's (the stage's meshes or pairs in parallel); `summary`: its line on stdout
inline int run_collection_stage(const Collection_job& job, const std::string& stage, std::pair<std::size_t, std::size_t> shard,
                                std::size_t threads = 1, bool summary = true, std::ostream& log = std::cerr)
{
  if(stage == "embed")
    run_collection_embed_stage(job, shard, threads, summary, log);
  else if(stage == "refine")
    run_collection_refine_stage(job, shard, threads, summary, log);
  else if(stage == "maps")
    run_collection_maps_stage(job, shard, threads, summary, log);
  else if(stage == "merge") {
    if(shard.second != 1)
      throw Usage_error{"--stage merge runs once, without --shard"};
    const hot_tools::Collection_report r = merge_collection(job);
    if(summary)
      std::cout << "collection of " << job.size() << " meshes merged; " << r.triples << " triples checked, cycle consistency " << r.cycle
                << "; wrote " << job.dir << "/report.json" << std::endl;
  } else
    throw Usage_error{"--stage must be embed, refine, maps or merge, got '" + stage + "'"};
  return EXIT_SUCCESS;
}

// The single-process collection in memory (Orbifold_collection: its embeddings tried in the
// other meshes' tours when one refuses the first), its files written at the end
inline int run_collection_in_memory(const Collection_job& job)
{
  Collection coll;
  coll.set_cone_orders(job.orders);
  coll.set_landmark_order_choice(job.order == "given" ? Collection::Given_landmark_order
                                 : job.order == "tsp" ? Collection::Tour_of_first_mesh : Collection::Tour_of_any_mesh);
  std::vector<hot_tools::Input_mesh> inputs;
  const HOT::Orbifold_type type = read_collection(job.entries, job.repair, coll, inputs, minimum_landmarks(job.orders));
  embed_collection(job.entries, coll);
  if(job.refine > 0) { // every mesh's embedding fitted to mesh 0's metric; the maps through the one orbifold
    const HOT::Error_code ec = coll.refine(job.refine, 0);
    if(ec != HOT::OK)
      throw Failure{ec, "--refine: " + coll.message()};
    for(std::size_t i = 1; i < job.size(); ++i) {
      const HOT::Map_refinement_statistics st = coll.refinement_statistics(i);
      std::cerr << "  refined " << job.entries[i].first << " onto " << job.entries[0].first << ": " << hot_tools::refinement_line(st, st.seconds) << std::endl;
    }
  }
  const Collection_maps maps = map_collection(coll, job.all_pairs);
  write_collection_files(job, coll, type, maps, inputs);
  std::cout << "landmark order:";
  for(std::size_t i : coll.order()) std::cout << " " << i;
  const std::vector<Collection::Order_attempt>& tried = coll.order_attempts();
  std::cout << " (" << (tried.back().mesh < job.size() ? "the tour of mesh " + std::to_string(tried.back().mesh) : std::string("the given order"));
  for(std::size_t a = 0; a + 1 < tried.size(); ++a)
    std::cout << "; " << (tried[a].mesh < job.size() ? "the tour of mesh " + std::to_string(tried[a].mesh) : std::string("the given order"))
              << " was refused by " << tried[a].message;
  std::cout << ")" << std::endl;
  std::cout << "collection of " << job.size() << " meshes embedded" << (job.all_pairs ? " and mapped pairwise" : "") << "; "
            << maps.triples << " triples checked, cycle consistency " << maps.cycle << "; wrote " << job.dir << std::endl;
  return EXIT_SUCCESS;
}

// The single-process collection (no --stage): resumable. It holds DIR's lock exclusively and
// runs the separate jobs' stages in this process (the meshes and pairs of a stage in threads),
// each embedding, refinement and map checkpointed in DIR/.parts as it ends; run again after a
// kill, it skips what is there and gives the files of an uninterrupted run. A finished
// collection (DIR/report.json, no DIR/.parts) run again is computed again, with a note on
// stderr. When an embedding job fails (e.g. a mesh refuses the first tour), the collection runs
// in memory instead (Orbifold_collection tries the other meshes' tours), as before: then it
// writes its files only at the end. A data failure of a new run removes the files it wrote; an
// I/O failure (disk full, unwritable folder) keeps the complete parts for a rerun.
inline int run_collection_resumable(const Collection_job& job)
{
  const bool existed = folder_exists(job.dir);
  Collection_lock lock(job.dir, true, true);
  remove_parts_folder(job.parts() + ".removing"); // (a merge killed while removing the parts)
  const bool resuming = folder_exists(job.parts());
  std::ostringstream embed_log; // (on stderr once the embed stage is done: a failure is one line)
  if(resuming)
    embed_log << "  resuming the collection in " << job.dir << " from " << job.parts() << std::endl;
  else if(regular_file_exists(job.dir + "/report.json"))
    embed_log << "  note: " << job.dir << " holds a finished collection: computing it again" << std::endl;
  // what a failed new run removes: the files it wrote
  std::vector<std::string> outputs;
  for(std::size_t i = 0; i < job.size(); ++i) outputs.push_back(job.obj_path(i));
  if(job.all_pairs)
    for(std::size_t a = 0; a < job.size(); ++a)
      for(std::size_t b = 0; b < job.size(); ++b)
        if(a != b) outputs.push_back(job.map_path(a, b));
  std::vector<std::string> new_files;
  for(const std::string& f : outputs)
    if(!regular_file_exists(f)) new_files.push_back(f);
  auto remove_written = [&] {
    remove_parts_folder(job.parts());
    for(const std::string& f : new_files) std::remove(f.c_str());
    if(!existed) rmdir(job.dir.c_str());
  };
  const std::size_t threads = std::max(1u, std::thread::hardware_concurrency());
  const std::pair<std::size_t, std::size_t> all(0, 1);
  try {
    run_collection_stage(job, "embed", all, threads, false, embed_log);
  } catch(const Failure&) { // (as before: in memory, the other tours tried; its own message)
    remove_parts_folder(job.parts());
    for(const std::string& f : new_files) std::remove(f.c_str());
    try {
      return run_collection_in_memory(job);
    } catch(const Failure&) {
      if(!existed) rmdir(job.dir.c_str());
      throw;
    }
  }
  std::cerr << embed_log.str() << std::flush;
  hot_tools::Collection_report r;
  try {
    if(job.refine > 0)
      run_collection_stage(job, "refine", all, threads, false);
    run_collection_stage(job, "maps", all, threads, false);
    r = merge_collection(job);
  } catch(const Failure&) {
    if(!resuming)
      remove_written();
    throw;
  }
  std::cout << "landmark order:";
  for(std::size_t i : r.order) std::cout << " " << i;
  std::cout << " (" << (r.order_from == "given" ? std::string("the given order") : "the tour of " + r.order_from) << ")" << std::endl;
  std::cout << "collection of " << job.size() << " meshes embedded" << (job.all_pairs ? " and mapped pairwise" : "") << "; " << r.triples
            << " triples checked, cycle consistency " << r.cycle << "; wrote " << job.dir << std::endl;
  return EXIT_SUCCESS;
}

inline int run_collection(int argc, char** argv)
{
  std::set<std::string> flags = repair_flags();
  flags.insert("all-pairs");
  flags.insert("progress"); // (accepted: the collection's per-mesh lines on stderr are its progress, always written)
  const Options opt(argc, argv, 2, {"manifest", "out", "max-hole", "target-genus", "max-handle", "cone-orders", "stage", "shard", "order"}, flags,
                    {"refine"});
  const int refine = !opt.has("refine") ? 0 : opt.get("refine").empty() ? 100 : static_cast<int>(opt.get_int("refine", 0, 100000));
  Collection_job job;
  job.manifest_path = opt.get("manifest");
  job.dir = opt.get("out");
  job.all_pairs = opt.has("all-pairs");
  job.set_repair(parse_repair_options(opt));
  job.orders = parse_cone_orders(opt);
  job.order = parse_common_order(opt);
  job.refine = refine;
  const std::pair<std::size_t, std::size_t> shard = parse_shard(opt);
  if(opt.has("shard") && !opt.has("stage"))
    throw Usage_error{"--shard needs --stage embed, refine or maps (then --stage merge once)"};
  job.entries = read_manifest(job.manifest_path);
  if(opt.has("stage")) {
    const std::string stage = opt.get("stage");
    if(stage != "embed" && stage != "refine" && stage != "maps" && stage != "merge")
      throw Usage_error{"--stage must be embed, refine, maps or merge, got '" + stage + "'"};
    if(stage == "merge" && shard.second != 1)
      throw Usage_error{"--stage merge runs once, without --shard"};
    // shards of a stage share DIR; the merge has it alone
    Collection_lock lock(job.dir, stage == "merge", stage == "embed");
    if(stage == "merge")
      remove_parts_folder(job.parts() + ".removing");
    return run_collection_stage(job, stage, shard);
  }
  return run_collection_resumable(job);
}

} // namespace hot_cli

#endif // HOT_TOOLS_JOBS_COLLECTION_H
