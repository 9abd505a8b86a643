// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

// register_collection: the jobs of a collection (application/hot_app/collection_stages.h, those of the
// command line's `collection --stage ...`) as functions of `_core`, which the package's
// collection() runs in order, in threads or as tasks of a Dask cluster
// (hyperbolic_orbifold_tutte/collection.py). Each releases the GIL while it computes.

#include "hot_python.h"

#include "hot_app/collection_stages.h"

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace hot_python {

namespace {

// what every job is given, from the Python arguments
hot_cli::Collection_job make_job(const std::string& manifest, const std::string& out_dir, bool all_pairs, py::handle cone_orders,
                                 bool repair, std::optional<double> max_hole, bool largest_component, bool snap_landmarks, int refine)
{
  if(refine < 0)
    fail(HOT::ERROR_WRONG_PARAMETER, "refine must be 0 (no refinement) or a number of iterations, got " + std::to_string(refine));
  hot_cli::Collection_job job;
  job.manifest_path = manifest;
  job.dir = out_dir;
  job.all_pairs = all_pairs;
  if(max_hole && (!(*max_hole >= 0) || !(*max_hole <= 1e6)))
    fail(HOT::ERROR_WRONG_PARAMETER, "max_hole must be a number >= 0 (a length in bounding box diagonals), got " + std::to_string(*max_hole));
  if((largest_component || max_hole) && !repair)
    fail(HOT::ERROR_WRONG_PARAMETER, std::string(largest_component ? "largest_component" : "max_hole") + " needs repair=True");
  hot_tools::Repair_options r; // (as the command line's collection --repair)
  r.repair = repair;
  r.largest_component = largest_component;
  r.snap_landmarks = snap_landmarks;
  if(max_hole) {
    r.max_hole = *max_hole;
    r.max_hole_given = true;
  }
  job.set_repair(r);
  job.refine = refine;
  if(!cone_orders.is_none())
    for(std::int64_t p : int_list(cone_orders, "cone_orders")) {
      if(!hot_tools::is_cone_order(p))
        fail(HOT::ERROR_WRONG_PARAMETER, "cone_orders: every order must be an integer >= 2, got " + std::to_string(p));
      job.orders.push_back(static_cast<int>(p));
    }
  return job;
}

// runs f with the GIL released; the jobs' failures become Hot_error
template <class F>
auto run_job(F&& f) -> decltype(f())
{
  try {
    py::gil_scoped_release release;
    return f();
  } catch(const hot_cli::Failure& e) {
    throw Hot_error{e.code, e.message};
  } catch(const std::runtime_error& e) { // (files: a folder that cannot be created, ...)
    throw Hot_error{HOT::ERROR_WRITE_FAILED, e.what()};
  }
}

#define HOT_JOB_ARGS                                                                                                                   \
  py::arg("manifest"), py::arg("out_dir"), py::arg("all_pairs") = false, py::arg("cone_orders") = py::none(),                        \
    py::arg("repair") = false, py::arg("max_hole") = py::none(), py::arg("largest_component") = false, py::arg("snap_landmarks") = false, \
    py::arg("refine") = 0

} // namespace

void register_collection(py::module_& m)
{
  m.def(
    "collection_plan",
    [](const std::string& manifest, const std::string& out_dir, bool all_pairs, py::handle cone_orders, bool repair, std::optional<double> max_hole,
       bool largest_component, bool snap_landmarks, int refine) {
      hot_cli::Collection_job job = make_job(manifest, out_dir, all_pairs, cone_orders, repair, max_hole, largest_component, snap_landmarks, refine);
      std::pair<hot_cli::Collection_order, hot_cli::Collection_pairs> r = run_job([&] {
        job.entries = hot_cli::read_manifest(job.manifest_path);
        return std::make_pair(hot_cli::collection_order(job), hot_cli::collection_pairs(job.size(), job.all_pairs));
      });
      py::dict d;
      py::list meshes, pairs, triples;
      for(const auto& e : job.entries) meshes.append(py::make_tuple(e.first, e.second));
      for(const auto& p : r.second.pairs) pairs.append(py::make_tuple(p.first, p.second));
      for(const auto& t : r.second.triples) triples.append(py::make_tuple(t[0], t[1], t[2]));
      d["meshes"] = meshes;
      d["orbifold"] = r.first.type == HOT::Sphere_type ? "sphere" : "disk";
      d["landmarks"] = r.first.landmarks;
      d["order"] = r.first.order;
      d["pairs"] = pairs;
      d["triples"] = triples;
      return d;
    },
    HOT_JOB_ARGS,
    "collection_plan(manifest, out_dir, all_pairs=False, cone_orders=None, repair=False, ...) -> dict\n\n"
    "Reads the manifest and its first mesh: the meshes (paths resolved), the orbifold, the number of\n"
    "landmarks, the cone order used for every mesh (the paper's tour on the first mesh), the ordered\n"
    "pairs the collection maps and the triples whose cycle consistency it measures.");

  m.def(
    "collection_embed",
    [](std::size_t i, const std::string& orbifold, std::size_t landmarks, const std::vector<std::size_t>& order, const std::string& manifest,
       const std::string& out_dir, bool all_pairs, py::handle cone_orders, bool repair, std::optional<double> max_hole, bool largest_component,
       bool snap_landmarks, int refine) {
      hot_cli::Collection_job job = make_job(manifest, out_dir, all_pairs, cone_orders, repair, max_hole, largest_component, snap_landmarks, refine);
      hot_cli::Collection_order co;
      co.type = orbifold == "disk" ? HOT::Disk_type : HOT::Sphere_type;
      co.landmarks = landmarks;
      co.order = order;
      return run_job([&] {
        job.entries = hot_cli::read_manifest(job.manifest_path);
        if(i >= job.size())
          throw hot_cli::Failure{HOT::ERROR_WRONG_PARAMETER, "mesh " + std::to_string(i) + " is not in the manifest's " + std::to_string(job.size())};
        return hot_cli::embed_collection_mesh(job, co, i);
      });
    },
    py::arg("i"), py::arg("orbifold"), py::arg("landmarks"), py::arg("order"), HOT_JOB_ARGS,
    "collection_embed(i, orbifold, landmarks, order, manifest, out_dir, ...) -> seconds\n\n"
    "The embedding job of mesh i (collection_plan()'s orbifold, landmarks and order): writes\n"
    "out_dir/<i>_<name>.obj and its entry of the report (out_dir/.parts).");

  m.def(
    "collection_refine",
    [](std::size_t i, const std::string& manifest, const std::string& out_dir, bool all_pairs, py::handle cone_orders, bool repair,
       std::optional<double> max_hole, bool largest_component, bool snap_landmarks, int refine) {
      hot_cli::Collection_job job = make_job(manifest, out_dir, all_pairs, cone_orders, repair, max_hole, largest_component, snap_landmarks, refine);
      return run_job([&] {
        job.entries = hot_cli::read_manifest(job.manifest_path);
        if(i >= job.size())
          throw hot_cli::Failure{HOT::ERROR_WRONG_PARAMETER, "mesh " + std::to_string(i) + " is not in the manifest's " + std::to_string(job.size())};
        if(job.refine <= 0)
          throw hot_cli::Failure{HOT::ERROR_WRONG_PARAMETER, "collection_refine() needs refine > 0 (the number of iterations)"};
        return hot_cli::refine_collection_mesh(job, i);
      });
    },
    py::arg("i"), HOT_JOB_ARGS,
    "collection_refine(i, manifest, out_dir, ..., refine=N) -> seconds\n\n"
    "The refinement job of mesh i (after the embedding jobs, with the same refine=N given to every\n"
    "job): mesh i's embedding refined onto mesh 0's (at most N certified iterations; mesh 0 is\n"
    "copied), written as out_dir/<i>_<name>.obj, its statistics for the merge (out_dir/.parts).");

  m.def(
    "collection_map",
    [](std::size_t a, std::size_t b, const std::string& manifest, const std::string& out_dir, bool all_pairs, py::handle cone_orders,
       bool repair, std::optional<double> max_hole, bool largest_component, bool snap_landmarks, int refine) {
      hot_cli::Collection_job job = make_job(manifest, out_dir, all_pairs, cone_orders, repair, max_hole, largest_component, snap_landmarks, refine);
      return run_job([&] {
        job.entries = hot_cli::read_manifest(job.manifest_path);
        if(a >= job.size() || b >= job.size() || a == b)
          throw hot_cli::Failure{HOT::ERROR_WRONG_PARAMETER, "(" + std::to_string(a) + ", " + std::to_string(b) +
                                                               ") is not a pair of distinct meshes of the manifest"};
        return hot_cli::map_collection_pair(job, a, b);
      });
    },
    py::arg("a"), py::arg("b"), HOT_JOB_ARGS,
    "collection_map(a, b, manifest, out_dir, ...) -> seconds\n\n"
    "The map job of the pair (a, b), from the stored embeddings (no embedding again): writes\n"
    "out_dir/<a>_to_<b>.map.txt (all_pairs) and the map for the merge (out_dir/.parts).");

  m.def(
    "collection_merge",
    [](const std::string& manifest, const std::string& out_dir, bool all_pairs, py::handle cone_orders, bool repair, std::optional<double> max_hole,
       bool largest_component, bool snap_landmarks, int refine) {
      hot_cli::Collection_job job = make_job(manifest, out_dir, all_pairs, cone_orders, repair, max_hole, largest_component, snap_landmarks, refine);
      const hot_tools::Collection_report r = run_job([&] {
        job.entries = hot_cli::read_manifest(job.manifest_path);
        return hot_cli::merge_collection(job);
      });
      return py::make_tuple(r.triples, r.cycle);
    },
    HOT_JOB_ARGS,
    "collection_merge(manifest, out_dir, ...) -> (triples, cycle_consistency)\n\n"
    "The merge: measures the cycle consistency from the stored maps, writes out_dir/report.json\n"
    "and removes out_dir/.parts.");
}

#undef HOT_JOB_ARGS

} // namespace hot_python
