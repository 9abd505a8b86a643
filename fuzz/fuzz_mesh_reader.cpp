// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// libFuzzer target for the mesh and landmark readers and the input checks, through the
// calls the command-line program makes before embedding (tools/jobs/, application/hot_app/io/:
// read_and_check_mesh(), read_and_check_landmarks(), and for `landmarks`, select_landmarks()),
// on the same mesh type (Surface_mesh of Epick points). Built and run by scripts/fuzz.sh.
//
// Input layout:
//   byte 0      selector: mesh format = s % 5 (off, obj, ply, stl, ts);
//               orbifold option = (s / 5) % 3 (automatic, sphere, disk);
//               landmark file name = (s / 15) % 2 (plain .txt, .selection.txt);
//               (s / 30) % 2: also sample 5 landmarks, as the `landmarks` command does
//   bytes 1-2   L, little endian: the landmark file is the last min(L, rest) bytes
//   then        the mesh file, then the landmark file
// The readers take file names (as the program does), so both parts are written to files
// in a private directory (in /dev/shm when it exists).
//
// Beyond the sanitizers, a result that breaks the readers' contract aborts: a failure
// without a one-line message or with an invalid code, a checked mesh that is not a valid
// polygon mesh or has no type, landmarks that are not distinct vertices in range, on the
// border for the disk type.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Hyperbolic_orbifold_Tutte/error_code.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/check_input.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/select_landmarks.h>

#include <hot_app/io/read_and_check.h>
#include <hot_app/io/prepared_input.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <optional>
#include <set>
#include <string>
#include <unistd.h>
#include <vector>

namespace HOT = CGAL::Hyperbolic_orbifold_Tutte;

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef CGAL::Surface_mesh<Kernel::Point_3> Surface_mesh;
typedef boost::graph_traits<Surface_mesh>::vertex_descriptor SM_vertex;

namespace {

std::string& work_dir()
{
  static std::string dir;
  return dir;
}

void remove_work_dir()
{
  const std::string& d = work_dir();
  if(d.empty())
    return;
  for(const char* name : { "mesh.off", "mesh.obj", "mesh.ply", "mesh.stl", "mesh.ts", "cones.txt", "cones.selection.txt" })
    std::remove((d + "/" + name).c_str());
  rmdir(d.c_str());
}

const std::string& make_work_dir()
{
  std::string& d = work_dir();
  if(d.empty()) {
    std::string templ = std::string(access("/dev/shm", W_OK) == 0 ? "/dev/shm" : "/tmp") + "/hot_fuzz_XXXXXX";
    if(mkdtemp(&templ[0]) == nullptr) {
      std::perror("fuzz_mesh_reader: mkdtemp");
      std::abort();
    }
    d = templ;
    std::atexit(remove_work_dir);
  }
  return d;
}

void write_file(const std::string& path, const std::uint8_t* data, std::size_t size)
{
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  if(!out) {
    std::fprintf(stderr, "fuzz_mesh_reader: cannot write %s\n", path.c_str());
    std::abort();
  }
}

[[noreturn]] void contract_broken(const char* what, const HOT::Status& r)
{
  std::fprintf(stderr, "fuzz_mesh_reader: contract broken: %s (code %d, message '%s')\n", what, int(r.code),
               r.message.c_str());
  std::abort();
}

// every result: a valid code; a failure has a non-empty one-line message
void check_result(const HOT::Status& r)
{
  if(int(r.code) < 0 || int(r.code) >= HOT::number_of_error_codes)
    contract_broken("invalid Error_code", r);
  if(bool(r) != (r.code == HOT::OK))
    contract_broken("operator bool disagrees with the code", r);
  if(!r) {
    if(r.message.empty())
      contract_broken("a failure without message", r);
    if(r.message.find('\n') != std::string::npos || r.message.find('\r') != std::string::npos)
      contract_broken("a message of more than one line", r);
  }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  if(size < 3)
    return 0;
  static const char* const extensions[] = { "off", "obj", "ply", "stl", "ts" };
  const unsigned s = data[0];
  const std::string ext = extensions[s % 5];
  std::optional<HOT::Orbifold_type> required_type;
  if((s / 5) % 3 == 1)
    required_type = HOT::Sphere_type;
  else if((s / 5) % 3 == 2)
    required_type = HOT::Disk_type;
  const bool selection = (s / 15) % 2 == 1;
  const bool sample = (s / 30) % 2 == 1;
  const std::size_t rest = size - 3;
  const std::size_t L = (std::min)(std::size_t(data[1]) | (std::size_t(data[2]) << 8), rest);

  const std::string& dir = make_work_dir();
  const std::string mesh_path = dir + "/mesh." + ext;
  const std::string cones_path = dir + (selection ? "/cones.selection.txt" : "/cones.txt");
  write_file(mesh_path, data + 3, rest - L);
  write_file(cones_path, data + 3 + (rest - L), L);

  // --repair: the preparation either fails with a message or gives a mesh that passes the
  // checks, addressed by the file's vertices
  if((s / 60) % 2 == 1) {
    hot_tools::Repair_options opt;
    opt.repair = true;
    opt.largest_component = (s / 120) % 2 == 1;
    Surface_mesh pm;
    hot_tools::Input_mesh in;
    HOT::Mesh_info pinfo;
    const HOT::Status rp = hot_tools::read_input_mesh(mesh_path, required_type, opt, pm, in, &pinfo);
    check_result(rp);
    if(rp) {
      if(!CGAL::is_valid_polygon_mesh(pm) || !HOT::check_mesh(pm, in.prep.type))
        contract_broken("a prepared mesh that fails the checks", rp);
      const HOT::Mesh_preparation& p = in.prep;
      if(p.output_index.size() != num_vertices(pm) || p.prepared_vertex.size() != p.number_of_input_vertices ||
         in.file_points.size() != p.number_of_input_vertices)
        contract_broken("an addressing of the wrong size", rp);
      for(std::size_t k = 1; k < p.output_index.size(); ++k)
        if(p.output_index[k] <= p.output_index[k - 1])
          contract_broken("output indices not increasing", rp);
      for(std::size_t v : p.prepared_vertex)
        if(v != HOT::Mesh_preparation::npos && v >= num_vertices(pm))
          contract_broken("an input vertex addressed out of range", rp);
    } else if(num_vertices(pm) != 0) {
      contract_broken("a refused preparation leaves a mesh", rp);
    }
    return 0;
  }

  // embed, map, collection, landmarks: the mesh
  Surface_mesh m;
  HOT::Mesh_info info;
  const HOT::Status r = hot_tools::read_and_check_mesh(mesh_path, required_type, m, &info);
  check_result(r);
  if(!r)
    return 0;
  if(!info.type_known || (required_type && info.type != *required_type))
    contract_broken("a checked mesh without its type", r);
  if(!CGAL::is_valid_polygon_mesh(m) || num_faces(m) == 0)
    contract_broken("a checked mesh that is not a valid polygon mesh", r);

  // embed, map, collection: the landmarks
  std::vector<SM_vertex> landmarks;
  const HOT::Status rl = hot_tools::read_and_check_landmarks(cones_path, m, info.type, landmarks);
  check_result(rl);
  if(rl) {
    std::set<SM_vertex> distinct(landmarks.begin(), landmarks.end());
    if(landmarks.size() < HOT::minimum_number_of_landmarks || distinct.size() != landmarks.size())
      contract_broken("accepted landmarks that are too few or not distinct", rl);
    for(SM_vertex v : landmarks) {
      if(std::size_t(v.idx()) >= num_vertices(m))
        contract_broken("an accepted landmark out of range", rl);
      if(info.type == HOT::Disk_type && !CGAL::is_border(v, m))
        contract_broken("an accepted disk-type landmark off the border", rl);
    }
  } else if(!landmarks.empty()) {
    contract_broken("refused landmarks are returned", rl);
  }

  // landmarks: farthest-point / border sampling on the checked mesh
  if(sample && num_vertices(m) >= 5 && num_vertices(m) <= 5000) {
    const std::vector<SM_vertex> lm = HOT::select_landmarks(m, 5);
    std::set<SM_vertex> distinct(lm.begin(), lm.end());
    for(SM_vertex v : lm)
      if(std::size_t(v.idx()) >= num_vertices(m))
        contract_broken("a sampled landmark out of range", r);
    if(distinct.size() != lm.size())
      contract_broken("sampled landmarks are not distinct", r);
  }
  return 0;
}
