// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef HOT_APP_COLLECTION_JOB_H
#define HOT_APP_COLLECTION_JOB_H

// A collection computed as separate jobs, which may run in different processes or on different
// machines sharing the output folder (`collection --stage embed|maps --shard I/N`, then
// `--stage merge`; the Python module's Dask collection). This header: the job, its manifest, its
// folder, its parts and locks, and the collection's cone order; the jobs themselves:
// collection_stages.h.
//   - an embedding job per mesh: reads it and its landmarks, embeds it with the collection's
//     cone order (collection_order(): the best of the meshes' tours, as Orbifold_collection
//     ranks them, computed alike by every job; no other order is tried when a mesh refuses it,
//     since the other jobs have used it: the message says to run the collection in one process,
//     which tries the others, or to force an order), writes DIR/<i>_<name>.obj and its entry of
//     the report (DIR/.parts/mesh_<i>.json);
//   - with --refine N, a refinement job per mesh (after the embeddings; the embed stage then
//     writes DIR/.parts/embedded_<i>.obj): mesh i's embedding refined onto mesh 0's, written as
//     DIR/<i>_<name>.obj, its statistics as DIR/.parts/refine_<i>.txt;
//   - a map job per pair (a, b) the collection computes: reads the two stored embeddings (no
//     embedding again), maps a onto b, writes DIR/<a>_to_<b>.map.txt (--all-pairs) and the
//     map itself for the cycle check (DIR/.parts/map_<a>_<b>.bin) and its time;
//   - the merge: checks every part is there, computes the cycle consistency over the triples
//     from the stored maps and embeddings, writes DIR/report.json and removes DIR/.parts.
// The files are those of the single-process `collection`, byte for byte (report.json apart
// from its times): the same embedding with the same parameters, maps from embeddings read back
// exactly (stored_embedding.h), the same writers.
//
// Faults. Every file is written atomically (write_file_atomically(): FILE.tmp, checked, then
// renamed), a job's files in the order output then part: a part in DIR/.parts exists only when
// its job is complete. A job whose part is there skips its mesh or pair (embedding_done(),
// refinement_done(), map_done()), so a job, a stage or the whole collection run again after a
// kill resumes where it stopped and recomputes nothing finished. The parts belong to the options
// they were computed with: the first job of each kind writes them (DIR/.parts/embed.options:
// the manifest's meshes, the repair options, the cone orders and order; refine.options: N;
// maps.options: --all-pairs), and a job given other ones refuses to mix them. Locks
// (Collection_lock, flock(2) on DIR itself, released by the kernel when the process dies, so a
// killed run leaves no stale lock): the embed, refine and maps jobs take a shared lock (shards
// run at once), the merge and the single-process collection an exclusive one.

#include "hot_app/job_input.h"
#include "hot_app/stored_embedding.h"
#include "hot_app/io/map_files.h"
#include "hot_app/io/reports.h"

#include <CGAL/Hyperbolic_orbifold_Tutte/hyperbolic_orbifold_Tutte_embedding.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/refine_orbifold_map.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/surface_maps.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/check_input.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/landmark_tour.h>
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

typedef std::vector<std::pair<std::string, std::string> > Manifest; // (mesh path, cones path) per line

// the manifest's entries, relative paths resolved against the manifest's folder
inline Manifest read_manifest(const std::string& manifest)
{
  std::string manifest_text; // a missing file, a directory etc. get their own reason
  require(hot_tools::read_file_contents(manifest, manifest_text));
  std::istringstream in(manifest_text);
  const std::string base = manifest.find('/') == std::string::npos ? std::string(".") : manifest.substr(0, manifest.find_last_of('/'));
  auto resolve = [&](const std::string& f) { return (!f.empty() && f[0] == '/') ? f : base + "/" + f; };
  Manifest entries;
  std::string line;
  std::size_t line_no = 0;
  while(std::getline(in, line)) {
    ++line_no;
    const std::size_t hash = line.find('#');
    if(hash != std::string::npos) line = line.substr(0, hash);
    std::istringstream ls(line);
    std::vector<std::string> fields;
    for(std::string f; ls >> f;)
      fields.push_back(f);
    if(fields.empty()) continue;
    if(fields.size() != 2)
      throw Failure{HOT::ERROR_READ_FAILED, manifest + ": line " + std::to_string(line_no) + ": expected 'mesh_path cones_path', found " +
                                            std::to_string(fields.size()) + (fields.size() == 1 ? " field" : " fields")};
    entries.push_back(std::make_pair(resolve(fields[0]), resolve(fields[1])));
  }
  if(entries.size() < 2)
    throw Failure{HOT::ERROR_WRONG_PARAMETER, manifest + ": the manifest lists " + std::to_string(entries.size()) +
                                              " mesh" + (entries.size() == 1 ? "" : "es") + ", a collection needs at least 2"};
  return entries;
}

// the maps a collection computes: over which triples the cycle consistency is measured (all of
// them up to 6 meshes, else N consecutive ones), and the ordered pairs mapped, without repeats:
// those of the triples (f_ab, f_ac), then with --all-pairs every ordered pair
struct Collection_pairs
{
  std::vector<std::array<std::size_t, 3> > triples;
  std::vector<std::pair<std::size_t, std::size_t> > pairs;
};

inline Collection_pairs collection_pairs(std::size_t N, bool all_pairs)
{
  Collection_pairs r;
  if(N >= 3) {
    if(N <= 6) {
      for(std::size_t a = 0; a < N; ++a)
        for(std::size_t b = 0; b < N; ++b)
          for(std::size_t c = 0; c < N; ++c)
            if(a != b && b != c && a != c) r.triples.push_back({{a, b, c}});
    } else {
      for(std::size_t a = 0; a < N; ++a) r.triples.push_back({{a, (a + 1) % N, (a + 2) % N}});
    }
  }
  std::vector<std::vector<char> > seen(N, std::vector<char>(N, 0));
  auto add = [&](std::size_t a, std::size_t b) {
    if(a != b && !seen[a][b]) {
      seen[a][b] = 1;
      r.pairs.emplace_back(a, b);
    }
  };
  for(const auto& t : r.triples) {
    add(t[0], t[1]);
    add(t[0], t[2]);
  }
  if(all_pairs)
    for(std::size_t a = 0; a < N; ++a)
      for(std::size_t b = 0; b < N; ++b) add(a, b);
  return r;
}

// what every job of a collection is given
struct Collection_job
{
  std::string manifest_path, dir;
  Manifest entries;
  bool all_pairs = false;
  hot_tools::Repair_options repair;
  std::vector<int> orders; // --cone-orders, per landmark in the class-wide order (empty: 2 for all)
  std::string order = "auto"; // --order given|tsp|auto
  int refine = 0;             // --refine N: the refine stage fits meshes 1, 2, ... to mesh 0's metric

  // the --repair options of every mesh: a collection's closed meshes are of genus 0, so with
  // --repair the handles of the others are cut (target genus 0) unless --target-genus is given
  void set_repair(const hot_tools::Repair_options& r)
  {
    repair = r;
    if(repair.repair && repair.target_genus < 0)
      repair.target_genus = 0;
  }

  std::size_t size() const { return entries.size(); }
  // <i>_<name>: the name of mesh i's files
  std::string stem(std::size_t i) const
  {
    const std::string& p = entries[i].first;
    const std::string f = p.substr(p.find_last_of('/') + 1);
    return std::to_string(i) + "_" + f.substr(0, f.find_last_of('.'));
  }
  std::string obj_path(std::size_t i) const { return dir + "/" + stem(i) + ".obj"; }
  std::string map_path(std::size_t a, std::size_t b) const { return dir + "/" + std::to_string(a) + "_to_" + std::to_string(b) + ".map.txt"; }
  std::string parts() const { return dir + "/.parts"; }
  std::string mesh_part(std::size_t i) const { return parts() + "/mesh_" + std::to_string(i) + ".json"; }
  std::string map_part(std::size_t a, std::size_t b) const { return parts() + "/map_" + std::to_string(a) + "_" + std::to_string(b) + ".bin"; }
  // with --refine: the embed stage's embedding (the refine stage writes obj_path(i) from it and
  // leaves it, so that a refine job run again refines the same embedding), the refinement's part
  std::string embedded_path(std::size_t i) const { return parts() + "/embedded_" + std::to_string(i) + ".obj"; }
  std::string refine_part(std::size_t i) const { return parts() + "/refine_" + std::to_string(i) + ".txt"; }
};

inline void make_folder(const std::string& dir)
{
  if(mkdir(dir.c_str(), 0777) != 0 && errno != EEXIST)
    throw std::runtime_error("cannot create the folder '" + dir + "': " + std::strerror(errno));
}

inline bool regular_file_exists(const std::string& path)
{
  struct stat st;
  return stat(path.c_str(), &st) == 0 && S_ISREG(st.st_mode);
}

inline bool folder_exists(const std::string& path)
{
  struct stat st;
  return stat(path.c_str(), &st) == 0 && S_ISDIR(st.st_mode);
}

// A lock on the collection's folder (flock(2) on DIR itself: no lock file, and the kernel
// releases it when the process ends, killed or not): shared for the embed, refine and maps jobs
// (shards of one collection run at once), exclusive for the merge and the single-process run.
// A job that cannot have it at once refuses with one line. The folder is created first if
// `create` (else a missing folder is not locked: there is nothing in it to protect).
class Collection_lock
{
public:
  Collection_lock(const std::string& dir, bool exclusive, bool create)
  {
    if(create)
      make_folder(dir);
    fd_ = open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if(fd_ < 0) {
      if(errno == ENOENT && !create)
        return;
      throw std::runtime_error("cannot open the folder '" + dir + "': " + std::strerror(errno));
    }
    if(flock(fd_, (exclusive ? LOCK_EX : LOCK_SH) | LOCK_NB) != 0) {
      const int err = errno;
      close(fd_);
      fd_ = -1;
      if(err == EWOULDBLOCK)
        throw std::runtime_error("'" + dir + "' is in use by another collection run (" +
                                 (exclusive ? std::string("a collection, a merge or a stage job") : std::string("a collection or a merge")) +
                                 " holds its lock): wait for it to end, or use another --out");
      // (a file system without flock on folders, e.g. NFS, where Linux emulates it with fcntl
      // locks that need a file open for writing: the collection runs unlocked, as before)
      if(err == EBADF || err == ENOLCK || err == EINVAL || err == EOPNOTSUPP)
        return;
      throw std::runtime_error("cannot lock the folder '" + dir + "': " + std::strerror(err));
    }
  }
  Collection_lock(const Collection_lock&) = delete;
  Collection_lock& operator=(const Collection_lock&) = delete;
  ~Collection_lock()
  {
    if(fd_ >= 0)
      close(fd_); // (releases the lock)
  }

private:
  int fd_ = -1;
};

// removes the folder `path` and the files in it (not recursive: the parts folder holds files)
inline void remove_parts_folder(const std::string& path)
{
  if(DIR* d = opendir(path.c_str())) {
    std::vector<std::string> names;
    while(const dirent* e = readdir(d)) {
      const std::string n = e->d_name;
      if(n != "." && n != "..") names.push_back(n);
    }
    closedir(d);
    for(const std::string& n : names) std::remove((path + "/" + n).c_str());
  }
  rmdir(path.c_str());
}

// what the parts of each kind depend on, beyond the meshes' files themselves
inline std::string parts_options_text(const Collection_job& job, const std::string& kind)
{
  std::ostringstream os;
  os.precision(17);
  if(kind == "embed") {
    for(const auto& e : job.entries) os << "mesh " << e.first << " " << e.second << "\n";
    const hot_tools::Repair_options& r = job.repair;
    os << "repair " << r.repair << " " << r.largest_component << " " << r.snap_landmarks << " " << r.max_hole_given << " " << r.max_hole << " "
       << r.target_genus << " " << r.max_handle << "\ncone_orders";
    for(int p : job.orders) os << " " << p;
    os << "\norder " << job.order << "\nrefine " << (job.refine > 0 ? 1 : 0) << "\n";
  } else if(kind == "refine")
    os << "refine " << job.refine << "\n";
  else
    os << "all_pairs " << (job.all_pairs ? 1 : 0) << "\nrefine " << (job.refine > 0 ? 1 : 0) << "\n";
  return os.str();
}

// The parts of `kind` (embed, refine, maps) in DIR/.parts were computed with this job's options
// (DIR/.parts/<kind>.options, written by the first such job), or throws
inline void check_parts_options(const Collection_job& job, const std::string& kind)
{
  const std::string path = job.parts() + "/" + kind + ".options", text = parts_options_text(job, kind);
  std::string have;
  if(hot_tools::read_file_contents(path, have)) {
    if(have != text)
      throw Failure{HOT::ERROR_WRONG_PARAMETER, job.parts() + " holds the " + kind + " parts of a collection run with other options or"
                                                  " another manifest: run it with the same ones, or remove " + job.parts()};
    return;
  }
  make_folder(job.dir);
  make_folder(job.parts());
  // (jobs running at once may write it together: each under a name of its own, then renamed)
  static std::atomic<unsigned> count(0);
  const std::string tmp = path + "." + std::to_string(getpid()) + "-" + std::to_string(count++) + ".tmp";
  write_file_atomically(tmp, [&](std::ostream& os) { os << text; });
  if(std::rename(tmp.c_str(), path.c_str()) != 0) {
    std::remove(tmp.c_str());
    throw std::runtime_error("cannot write '" + path + "': " + std::strerror(errno));
  }
}

// whether a job's part is complete (its output was renamed into place before it)
inline bool embedding_done(const Collection_job& job, std::size_t i)
{
  return regular_file_exists(job.mesh_part(i)) && regular_file_exists(job.refine > 0 ? job.embedded_path(i) : job.obj_path(i));
}
inline bool refinement_done(const Collection_job& job, std::size_t i)
{
  return regular_file_exists(job.refine_part(i)) && regular_file_exists(job.obj_path(i));
}
inline bool map_done(const Collection_job& job, std::size_t a, std::size_t b)
{
  return regular_file_exists(job.map_part(a, b)) && (!job.all_pairs || regular_file_exists(job.map_path(a, b)));
}

// the collection's orbifold, number of landmarks and cone order: mesh 0's type, and for sphere
// type the first of the meshes' tours as Orbifold_collection ranks them (with --order tsp mesh
// 0's tour; every mesh is read for its landmark distances), the given order (disk, --order given)
struct Collection_order
{
  HOT::Orbifold_type type = HOT::Sphere_type;
  std::size_t landmarks = 0;
  std::vector<std::size_t> order;
  std::size_t from = 0; // the mesh whose tour it is (the number of meshes: the given order)
};

inline Collection_order collection_order(const Collection_job& job)
{
  Collection_order r;
  std::vector<std::vector<std::vector<double> > > D;
  for(std::size_t i = 0; i < job.size(); ++i) {
    Surface_mesh m;
    std::vector<SM_vertex> landmarks;
    Input in;
    const HOT::Orbifold_type type = read_mesh_and_landmarks(job.entries[i].first, job.entries[i].second, std::nullopt, job.repair, m,
                                                            landmarks, in, minimum_landmarks(job.orders));
    if(i == 0) {
      r.type = type;
      r.landmarks = landmarks.size();
      if(!job.orders.empty() && job.orders.size() != landmarks.size())
        throw Failure{HOT::ERROR_WRONG_PARAMETER, std::to_string(job.orders.size()) + " cone orders are given for " +
                                                    std::to_string(landmarks.size()) + " landmarks (one per landmark is needed)"};
      for(std::size_t c = 0; c < landmarks.size(); ++c) r.order.push_back(c);
      r.from = job.size();
      if(type != HOT::Sphere_type || job.order == "given")
        return r;
    } else if(type != r.type || landmarks.size() != r.landmarks || HOT::closed_mesh_genus(m) > 0)
      break; // (its embedding job says why it is refused; the others use mesh 0's tour)
    const HOT::Status s = HOT::check_landmark_vertices(m, landmarks, type, job.orders.empty() ? HOT::minimum_number_of_landmarks : 3);
    if(!s && i == 0)
      throw Failure{s.code, "mesh 0: " + s.message};
    if(s)
      D.push_back(HOT::compute_landmark_distances(m, landmarks, get(CGAL::vertex_point, m)));
    if(!s || (i > 0 && !HOT::internal::is_finite_distance_matrix(D.back()))) {
      D.resize(1);
      break;
    }
    if(job.order == "tsp")
      break;
  }
  const std::vector<HOT::Landmark_order_candidate> ranked = HOT::rank_landmark_tours(D);
  if(ranked.empty())
    throw Failure{HOT::ERROR_CUT_FAILED, "mesh 0: the landmark tour could not be computed"};
  r.order = ranked[0].order;
  r.from = ranked[0].mesh;
  return r;
}

} // namespace hot_cli

#endif // HOT_APP_COLLECTION_JOB_H
