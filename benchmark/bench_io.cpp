// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Times the command-line tool's file input and output against CGAL's:
//  1. parsing: our readers (application/hot_app/io/read_polygon_soup.h: the file read into memory, parsed
//     into a polygon soup) against CGAL::IO::read_polygon_soup() on the same mesh as OFF, OBJ
//     and PLY (ASCII; the OBJ and PLY copies are written by CGAL with 17 digits, the OFF is
//     the given file), MB/s of the file and the ratio, with a check that both give the same
//     points and faces;
//  2. reading a mesh: our read_mesh() (parse, validate the soup, build the Surface_mesh in
//     linear time) against CGAL::IO::read_polygon_mesh() (what CGAL's orbifold example does);
//  3. writing the embedding OBJ (application/hot_app/io/embedding_obj.h: std::to_chars, blocks of lines
//     formatted in parallel) against the former std::ostream writer (test/reference_embedding_obj.h),
//     MB/s, with a check that the bytes are the same; the uv map is synthetic (a point of the
//     disk per corner, distinct points on a fifth of the faces: seams).
// Each time is the fastest of --repeat runs (default 3).
//   bench_io [--repeat N] MESH.off ...
//   bench_io --write-blob N OUT.off    writes the generated blob of about N vertices (the one
//                                      of bench_parameterizer's generated:N) as OFF, 17 digits
// Run by scripts/benchmark.sh; nothing is asserted here (test_input_checks checks the results).

#include "generated_blob.h"
#include "reference_embedding_obj.h" // (generators/)

#include <hot_app/io/embedding_obj.h>
#include <hot_app/io/read_and_check.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Surface_mesh.h>

#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> SM;
typedef std::chrono::steady_clock Clock;

// the fastest of `repeat` runs of f, in seconds
double fastest(int repeat, const std::function<void()>& f)
{
  double best = -1;
  for(int r = 0; r < repeat; ++r) {
    const auto t = Clock::now();
    f();
    const double s = std::chrono::duration<double>(Clock::now() - t).count();
    if(best < 0 || s < best)
      best = s;
  }
  return best;
}

double megabytes(const std::string& path) { return double(std::filesystem::file_size(path)) / 1e6; }

std::string base_name(const std::string& path) { return std::filesystem::path(path).filename().string(); }

// the soup of our reader equals CGAL's (points bitwise as doubles, faces)
bool same_soup(const hot_tools::Polygon_soup& s, const std::vector<K::Point_3>& p, const std::vector<std::vector<std::size_t> >& f)
{
  if(s.points.size() != p.size() || s.number_of_faces() != f.size())
    return false;
  for(std::size_t i = 0; i < p.size(); ++i)
    if(s.points[i][0] != p[i].x() || s.points[i][1] != p[i].y() || s.points[i][2] != p[i].z())
      return false;
  for(std::size_t j = 0; j < f.size(); ++j)
    if(!std::equal(f[j].begin(), f[j].end(), s.face_vertices.begin() + s.face_begin[j], s.face_vertices.begin() + s.face_begin[j + 1]))
      return false;
  return true;
}

void parse_table(const std::vector<std::string>& files, int repeat, const std::string& tmp)
{
  std::printf("== parsing into a polygon soup: ours (read the file, parse) vs CGAL::IO::read_polygon_soup, fastest of %d\n", repeat);
  std::printf("%-22s %8s %9s %8s %9s %8s %9s %6s\n", "file", "MB", "ours_s", "MB/s", "cgal_s", "MB/s", "cgal/ours", "same");
  for(const std::string& f : files) {
    std::vector<K::Point_3> points;
    std::vector<std::vector<std::size_t> > polygons;
    if(!CGAL::IO::read_polygon_soup(f, points, polygons)) {
      std::printf("%-22s cannot read\n", base_name(f).c_str());
      continue;
    }
    const std::string stem = std::filesystem::path(f).stem().string();
    std::vector<std::string> copies{f, tmp + "/" + stem + ".obj", tmp + "/" + stem + ".ply"};
    CGAL::IO::write_polygon_soup(copies[1], points, polygons, CGAL::parameters::stream_precision(17));
    CGAL::IO::write_polygon_soup(copies[2], points, polygons, CGAL::parameters::stream_precision(17).use_binary_mode(false));
    for(const std::string& c : copies) {
      hot_tools::Polygon_soup soup;
      bool ok = true;
      const double ours = fastest(repeat, [&]() { ok = bool(hot_tools::read_polygon_soup_file(c, soup)) && ok; });
      std::vector<K::Point_3> cp;
      std::vector<std::vector<std::size_t> > cf;
      const double cgal = fastest(repeat, [&]() {
        cp.clear();
        cf.clear();
        ok = CGAL::IO::read_polygon_soup(c, cp, cf) && ok;
      });
      const double mb = megabytes(c);
      std::printf("%-22s %8.2f %9.4f %8.1f %9.4f %8.1f %9.2f %6s\n", base_name(c).c_str(), mb, ours, mb / ours, cgal, mb / cgal,
                  cgal / ours, ok && same_soup(soup, cp, cf) ? "yes" : "NO");
      std::fflush(stdout);
    }
  }
}

void mesh_table(const std::vector<std::string>& files, int repeat)
{
  std::printf("== reading a mesh: ours (read_mesh: parse, validate the soup, build) vs CGAL::IO::read_polygon_mesh, fastest of %d\n", repeat);
  std::printf("%-22s %9s %9s %9s %9s\n", "file", "vertices", "ours_s", "cgal_s", "cgal/ours");
  for(const std::string& f : files) {
    SM a, b;
    bool ok = true;
    const double ours = fastest(repeat, [&]() { ok = bool(hot_tools::read_mesh(f, a)) && ok; });
    const double cgal = fastest(repeat, [&]() {
      b.clear();
      ok = CGAL::IO::read_polygon_mesh(f, b) && ok;
    });
    std::printf("%-22s %9zu %9.4f %9.4f %9.2f%s\n", base_name(f).c_str(), std::size_t(num_vertices(a)), ours, cgal, cgal / ours,
                ok ? "" : "  (a reader failed)");
    std::fflush(stdout);
  }
}

void write_table(const std::vector<std::string>& files, int repeat, const std::string& tmp)
{
  std::printf("== writing the embedding OBJ: write_embedding_obj vs the former std::ostream writer, fastest of %d\n", repeat);
  std::printf("%-22s %8s %9s %8s %9s %8s %9s %6s\n", "mesh", "MB", "new_s", "MB/s", "former_s", "MB/s", "former/new", "same");
  for(const std::string& f : files) {
    SM m;
    if(!hot_tools::read_mesh(f, m))
      continue;
    auto uv = m.add_property_map<SM::Halfedge_index, K::Point_2>("h:uv").first;
    for(SM::Face_index fc : faces(m))
      for(SM::Halfedge_index h : halfedges_around_face(halfedge(fc, m), m)) {
        const K::Point_3& p = m.point(target(h, m));
        const double r = std::sqrt(p.x() * p.x() + p.y() * p.y() + p.z() * p.z()) + 1;
        const double s = (fc.idx() % 5 == 0) ? 0.8 : 0.9; // a fifth of the faces: other points (seams)
        put(uv, h, K::Point_2(s * p.x() / r, s * p.y() / r));
      }
    const std::string a = tmp + "/new.obj", b = tmp + "/former.obj";
    const double t_new = fastest(repeat, [&]() {
      std::ofstream os(a);
      hot_tools::write_embedding_obj(os, m, uv);
    });
    const double t_old = fastest(repeat, [&]() {
      std::ofstream os(b);
      hot_reference::reference_write_embedding_obj(os, m, uv);
    });
    std::ifstream ia(a, std::ios::binary), ib(b, std::ios::binary);
    std::stringstream sa, sb;
    sa << ia.rdbuf();
    sb << ib.rdbuf();
    const double mb = megabytes(a);
    std::printf("%-22s %8.2f %9.4f %8.1f %9.4f %8.1f %9.2f %6s\n", base_name(f).c_str(), mb, t_new, mb / t_new, t_old, mb / t_old,
                t_old / t_new, sa.str() == sb.str() ? "yes" : "NO");
    std::fflush(stdout);
  }
}

} // namespace

int main(int argc, char** argv)
{
  int repeat = 3;
  std::vector<std::string> files;
  for(int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if(a == "--repeat" && i + 1 < argc) {
      repeat = std::max(1, std::atoi(argv[++i]));
    } else if(a == "--write-blob" && i + 2 < argc) {
      const hot_bench::Blob_mesh blob = hot_bench::generated_blob(std::strtoul(argv[i + 1], nullptr, 10));
      std::ofstream os(argv[i + 2]);
      if(!CGAL::IO::write_OFF(os, blob, CGAL::parameters::stream_precision(17))) {
        std::fprintf(stderr, "bench_io: cannot write %s\n", argv[i + 2]);
        return EXIT_FAILURE;
      }
      std::printf("wrote %s: %zu vertices\n", argv[i + 2], std::size_t(num_vertices(blob)));
      return EXIT_SUCCESS;
    } else {
      files.push_back(a);
    }
  }
  if(files.empty()) {
    std::fprintf(stderr, "usage: bench_io [--repeat N] MESH.off ...   or   bench_io --write-blob N OUT.off\n");
    return EXIT_FAILURE;
  }
  std::string tmp = (std::filesystem::temp_directory_path() / "hot_bench_io_XXXXXX").string();
  if(mkdtemp(&tmp[0]) == nullptr) {
    std::fprintf(stderr, "bench_io: cannot make a temporary directory\n");
    return EXIT_FAILURE;
  }
  parse_table(files, repeat, tmp);
  mesh_table(files, repeat);
  write_table(files, repeat, tmp);
  std::error_code ec;
  std::filesystem::remove_all(tmp, ec);
  return EXIT_SUCCESS;
}
