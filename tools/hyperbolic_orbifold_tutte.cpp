// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// hyperbolic_orbifold_tutte: the package's main jobs from the command line.
//
//   hyperbolic_orbifold_tutte embed|map|collection|landmarks|cut|tile|certify ... (--help lists them)
//
// Every error ends the program with a non-zero status and one line on stderr;
// output files are written to a temporary name and renamed only when complete
// (command_line.h). The files' formats are written by the headers of io/.

// the mesh's header first: Seam_mesh calls CGAL::halfedges(tm) etc. qualified
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Hyperbolic_orbifold_Tutte/Orbifold_tile.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/hyperbolic_orbifold_Tutte_embedding.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/Embedding_locator.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/Orbifold_collection.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/surface_maps.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/map_reliability.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/refine_orbifold_map.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/select_landmarks.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/landmark_tour.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/cut_through_landmarks.h>

#include "command_line.h"
#include "cli_types.h"
#include "collection_jobs.h"
#include "certify_command.h"
#include "embed_job.h"
#include "io/cut_graph_file.h"
#include "io/embedding_obj.h"
#include "io/map_files.h"
#include "io/read_and_check.h"
#include "io/reports.h"
#include "io/selection.h"
#include "io/svg.h"
#include "io/timings.h"

#include <sys/stat.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <functional>
#include <iostream>
#include <mutex>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <thread>

namespace HOT = CGAL::Hyperbolic_orbifold_Tutte;

namespace {

using namespace hot_cli;

// The usage text, one section per job: `--help` prints the head, every job's section in this
// order and the REPAIR options (the same bytes as ever: a promise); `JOB --help` (or -h, or
// `help JOB`) the head, the job's section and REPAIR when the section names [REPAIR].
const char* const usage_head = "usage:\n";

const char* const usage_tile =
  "  hyperbolic_orbifold_tutte tile --orbifold sphere|disk --cones K --svg FILE [--depth D]\n"
  "  hyperbolic_orbifold_tutte tile --orbifold sphere --cone-orders P1,P2,... --svg FILE [--depth D]\n"
  "      draws the basic tile of the orbifold with K cones and its images under the group\n"
  "      (products of at most D side pairings, default 3) in the Poincare disk\n";

const char* const usage_embed =
  "  hyperbolic_orbifold_tutte embed --mesh IN --cones CONES [--orbifold sphere|disk]\n"
  "      [--weights cotan|mvc|uniform] [--order given|tsp|I0,I1,...] --out OUT.obj [--svg PICTURE.svg]\n"
  "      [--report REPORT.json] [--recentre] [--cone-orders P1,P2,...] [--progress] [REPAIR]\n"
  "      embeds the mesh into the hyperbolic orbifold whose cones are the landmarks CONES\n"
  "      (0-based vertex indices); OUT.obj holds the input vertices (v), one Poincare point\n"
  "      per cut-mesh vertex (vt) and the input faces (f v/vt); the result is certified\n"
  "      bijective or the program fails. --order defaults to tsp for sphere type; --order\n"
  "      I0,I1,... puts the landmarks (0-based lines of CONES) in that order (e.g. another\n"
  "      embedding's \"landmark_positions_used\", for a map between stored embeddings).\n"
  "      OUT.obj's head says the orbifold and the cones ('# hot orbifold', '# hot cone' lines).\n"
  "      --cone-orders: the order p of every landmark's cone (angle 2 pi/p), in the order of\n"
  "      CONES (default 2 for all: angle pi); sphere type; the orbifold must be hyperbolic,\n"
  "      sum(1 - 1/p) > 2: 3 cones (2,3,7), (3,3,4), (2,4,5), 4 cones (2,2,2,3), 5 of any orders\n"
  "      --recentre: a part too squeezed for double in the tile (a long protrusion without\n"
  "      landmarks) may be solved in a moved frame; the report then gives the frame.\n"
  "      A closed mesh of genus g >= 1 is detected and cut along a graph (2g shortest handle\n"
  "      loops and the paths to the landmarks); it needs 1 landmark for g = 1, none for g >= 2\n"
  "      (CONES may be an empty file); the report gives \"genus\" and the \"cut_graph\".\n"
  "      --progress: the progress of the phases on stderr, one line per update ('embed:\n"
  "      optimization 45%': read, input, cut, initialization, optimization, certificate, write);\n"
  "      on a terminal it is shown without --progress too, as one line updated in place\n";

const char* const usage_map =
  "  hyperbolic_orbifold_tutte map --source A --source-cones CA --target B --target-cones CB\n"
  "      --out MAP.txt [--colors-out B_colored.ply] [--prepared-target B_prepared.off]\n"
  "      [--report REPORT.json] [--cone-orders P1,P2,...] [--order auto|tsp|given] [--refine [N]] [--progress] [REPAIR]\n"
  "      maps every vertex of A onto B through the common orbifold (landmark i of CA to\n"
  "      landmark i of CB), both embedded in one landmark order: for sphere type (genus 0) by\n"
  "      default (auto) the tour of A or of B whose cut is the least longer than each mesh's own\n"
  "      tour on the mesh where it is the most so, the other one if a mesh refuses it; tsp: A's\n"
  "      tour only; given: as in the files (disk type always). The order used is on stdout and\n"
  "      in REPORT.json (\"landmark_order\", \"landmark_order_from\", \"orders_tried\"); MAP.txt: one line 'face b0 b1 b2' per vertex of A (with --repair:\n"
  "      per vertex of A's file, then per vertex the repair added; '-1 0 0 0' for a vertex on\n"
  "      no face; faces are those of the repaired B, written by --prepared-target).\n"
  "      Vertices of A the map cannot resolve (in a protrusion without a landmark, squeezed by\n"
  "      both embeddings below their disagreement) get a one-line warning on stderr;\n"
  "      REPORT.json lists them (\"unreliable_vertices\", numbered as MAP.txt's lines), with\n"
  "      the squeezed regions, the sizes and the times, and the map's per-face distortion\n"
  "      (\"distortion\": percentiles 50, 90, 99, max and mean of the conformal distortion\n"
  "      sigma1/sigma2 and of the area distortion sigma1 sigma2 / (area(f(A))/area(A)) over\n"
  "      A's faces, and the count of degenerate faces; infinity is written \"inf\").\n"
  "      --refine [N]: refines the map towards an isometry (at most N iterations, default 100,\n"
  "      each certified bijective; landmarks kept; genus 0, a source without charts): lowers the\n"
  "      symmetric Dirichlet energy (4 for an isometry up to scale); REPORT.json's \"refinement\"\n"
  "      gives its iterations, stop, energies, time and the \"distortion_before\" it\n"
  "  hyperbolic_orbifold_tutte map --source-embedding A.obj --target-embedding B.obj --out MAP.txt [--report REPORT.json] [--progress]\n"
  "      the same map from two embeddings stored by embed or collection (no embedding again):\n"
  "      they must put the same landmarks at the same cones (embed B with --order set to A's\n"
  "      \"landmark_positions_used\"); MAP.txt has one line per v line of A.obj; REPORT.json as map's\n"
  "      --progress: the progress of the phases on stderr, as embed's ('map: source optimization 45%')\n";

const char* const usage_collection =
  "  hyperbolic_orbifold_tutte collection --manifest LIST.txt --out DIR [--all-pairs] [--cone-orders P1,...] [--refine [N]] [REPAIR]\n"
  "      [--order auto|tsp|given] [--stage embed|refine|maps|merge [--shard I/N]] [--progress]\n"
  "      embeds every mesh of LIST.txt (lines 'mesh_path cones_path') in one landmark order (as\n"
  "      map's --order, over all the meshes' tours; tsp: the first mesh's) and maps them onto\n"
  "      each other; writes DIR/<i>_<name>.obj, DIR/report.json (and DIR/<a>_to_<b>.map.txt).\n"
  "      As separate jobs (array jobs of a batch scheduler; the same options in every job):\n"
  "      --stage embed --shard I/N embeds meshes I, I+N, ...; then --stage maps --shard I/N maps\n"
  "      its share of the pairs from the stored embeddings; then --stage merge writes\n"
  "      DIR/report.json (the same files as one process; DIR/.parts holds the jobs' results).\n"
  "      --refine [N]: fits every mesh's embedding to the first mesh's metric (map --refine\n"
  "      onto it, at most N iterations, default 100); the maps stay compositions through the one\n"
  "      orbifold (cycle consistent); report.json's \"refinement\" per mesh. As separate jobs,\n"
  "      --stage refine --shard I/N refines meshes I, I+N, ... between the embed and maps stages\n"
  "      (--refine [N] given to every stage's job)\n"
  "      Killed and run again (the same command), the collection or a stage job resumes from\n"
  "      DIR/.parts (what is done is skipped); DIR is locked while a collection or merge runs\n"
  "      (the shards of a stage run together); files are renamed into place only when complete\n";

const char* const usage_landmarks =
  "  hyperbolic_orbifold_tutte landmarks --mesh IN --count K --out CONES [--progress] [REPAIR]\n"
  "      writes K well-spread landmarks of the mesh (vertices of the file, also with --repair)\n"
  "      --progress: the progress of the phases on stderr, as embed's\n";

const char* const usage_cut =
  "  hyperbolic_orbifold_tutte cut --mesh IN --cones CONES [--order given|tsp] --out OUT.selection.txt\n"
  "      cuts the closed genus-0 mesh along a simple path through the cones in order (the\n"
  "      given one by default, or the paper's tour) and writes it as CGAL's selection file:\n"
  "      line 1 the cones in that order, line 2 empty, line 3 the seam edges 's0 t0 s1 t1 ...'\n"
  "      (for Seam_mesh::add_seams() and Surface_mesh_parameterization::locate_cones())\n";

const char* const usage_certify =
  "  hyperbolic_orbifold_tutte certify --mesh IN --embedding E.obj --cones CONES [--orbifold sphere|disk]\n"
  "      [--cone-orders P1,P2,...] [--frame A_RE,A_IM,B_RE,B_IM] [--report REPORT.json] [--progress]\n"
  "      checks that E.obj (v, vt and 'f v/vt v/vt v/vt' lines, from embed or any other program)\n"
  "      is a bijection of IN onto the orbifold whose cones are CONES (in any order), from the\n"
  "      file alone and independently of the solver: faces are IN's faces, points finite and in\n"
  "      the disk, cones at tile corners (the cone order is found), a disk's boundary on its\n"
  "      sides' segments, faces positively oriented (exact), angle sums (certified), seams glued\n"
  "      by the tile's side pairings, total area. Exit 0 when certified, 4 otherwise, with one\n"
  "      line naming the first failed check and where (0-based face, vertex or edge); the\n"
  "      report (written in both cases) has every count. --cone-orders: one per cone, in CONES'\n"
  "      order (sphere: any hyperbolic orders, e.g. 2,3,7; which tile corner each cone is at is found)\n"
  "      --frame: the frame of a recentred embedding (embed's report), z -> (az + b)/(conj(b) z + conj(a))\n"
  "      A closed mesh of genus g >= 1 (CONES may be empty for g >= 2): no tile; each seam's isometry\n"
  "      is read from its two copies (equal lengths, shared along the cut), angle sums 2 pi (2 pi / p\n"
  "      at a cone) within 1e-6, area 2 pi (2g - 2 + sum(1 - 1/p)); the report gives \"genus\".\n"
  "      --progress: the progress of the phases on stderr, as embed's\n";

const char* const usage_repair =
  "  REPAIR (embed, map, collection, landmarks):\n"
  "      --repair: prepares the mesh first (merges duplicated border vertices, orients, removes\n"
  "      invalid, duplicated and degenerate faces, splits non-manifold vertices, triangulates\n"
  "      polygons, fills holes, splits the inner edges of a disk that join two boundary\n"
  "      vertices) and says what it did; landmark files and written vertex numbers stay those\n"
  "      of the input file, the added vertices come after them\n"
  "      The landmark file guides it: the component holding the landmarks is kept, debris (no\n"
  "      landmark, under 1% of the faces) dropped; landmarks inside the surface close every\n"
  "      boundary loop whatever its length (sphere type); faces closing holes are reported.\n"
  "      --max-hole F: fills boundary loops up to F bounding box diagonals long (default 0.5,\n"
  "      no limit when landmarks inside the surface ask for a sphere)\n"
  "      --largest-component: keeps only the landmarks' (or the largest) component of several\n"
  "      --target-genus G: cuts handles (shortest non-separating loops, both sides closed)\n"
  "      down to genus G; automatic (0) in map when the other mesh is of genus 0, in\n"
  "      collection, and for a disk (its orbifold has genus 0); --max-handle F: the longest\n"
  "      loop cut (default 0.2 diagonals)\n"
  "      --snap-landmarks: moves disk-type corners that are not on the boundary to the\n"
  "      nearest boundary vertex (also without --repair)\n";

struct Job_usage
{
  const char* job;
  const char* text;
};

// the jobs main() runs, in the order of --help
const Job_usage job_usages[] = {{"tile", usage_tile},           {"embed", usage_embed},
                                {"map", usage_map},             {"collection", usage_collection},
                                {"landmarks", usage_landmarks}, {"cut", usage_cut},
                                {"certify", usage_certify}};

std::string usage_text()
{
  std::string s = usage_head;
  for(const Job_usage& u : job_usages)
    s += u.text;
  return s + usage_repair;
}

// the usage of one job; nullptr for an unknown one
const Job_usage* find_job_usage(const std::string& job)
{
  for(const Job_usage& u : job_usages)
    if(job == u.job)
      return &u;
  return nullptr;
}

std::string job_usage_text(const Job_usage& u)
{
  const std::string text = u.text;
  return usage_head + text + (text.find("[REPAIR]") != std::string::npos ? usage_repair : "");
}

int run_tile(int argc, char** argv)
{
  const Options opt(argc, argv, 2, {"orbifold", "cones", "svg", "depth", "cone-orders"});
  const HOT::Orbifold_type type = parse_orbifold(opt.get("orbifold"));
  const std::vector<int> orders = parse_cone_orders(opt);
  const long k = orders.empty() || opt.has("cones") ? opt.get_int("cones", -1000000, 1000000) : static_cast<long>(orders.size());
  const int depth = opt.has("depth") ? static_cast<int>(opt.get_int("depth", 0, 6)) : 3;
  const std::string svg = opt.get("svg");
  if(k > 200)
    throw Usage_error{"--cones must be at most 200 for a picture, got " + std::to_string(k)};

  HOT::Orbifold_tile<> tile;
  if(!orders.empty()) {
    require(HOT::internal::tile_of_cone_orders(type, orders, static_cast<int>(k), tile, HOT::Poincare_disk_traits_2<>()));
  } else {
    const HOT::Error_code ec = HOT::make_orbifold_tile(type, static_cast<int>(k), tile);
    if(ec != HOT::OK)
      throw std::runtime_error(std::string(HOT::error_message(ec)) + ": got " + std::to_string(k) + " cones");
  }

  const std::string pi = "&#960;";
  const std::string multiple = (k == 5) ? std::string() : std::to_string(k - 4);
  std::ostringstream title;
  if(!orders.empty()) {
    std::string list;
    for(int p : orders)
      list += (list.empty() ? "" : ",") + std::to_string(p);
    title.precision(4);
    title << "sphere-type orbifold with cones of orders (" << list << "), tile with " << tile.number_of_corners() << " corners, area "
          << tile.area() / CGAL_PI << pi;
  } else if(type == HOT::Sphere_type)
    title << "sphere-type orbifold, " << k << " cones of angle " << pi << ", tile with " << tile.number_of_corners()
          << " corners, area " << multiple << pi;
  else
    title << "disk-type orbifold, " << k << " corners of angle " << pi << "/2, area " << multiple << pi << "/2";
  write_file_atomically(svg, [&](std::ostream& os) { hot_tools::write_tile_svg(os, tile, depth, title.str()); });
  std::cout << "wrote " << svg << " (" << (type == HOT::Sphere_type ? "sphere" : "disk") << ", " << k << " cones"
            << (orders.empty() ? std::string() : " of the given orders") << ", depth " << depth << ")" << std::endl;
  return EXIT_SUCCESS;
}

// the cut graph of a file (--cut-graph: vertex paths of the mesh file, with --repair of the
// input file) as vertices of the mesh read by read_mesh_and_landmarks()
std::vector<std::vector<SM_vertex> > read_cut_graph_of(const std::string& path, const Surface_mesh& m, const hot_tools::Input_mesh& in)
{
  std::vector<std::vector<std::size_t> > ids;
  require(hot_tools::read_cut_graph(path, ids));
  const std::vector<SM_vertex> verts(vertices(m).begin(), vertices(m).end());
  std::vector<std::vector<SM_vertex> > paths;
  for(const auto& p : ids) {
    paths.emplace_back();
    for(std::size_t id : p) {
      std::size_t i = id;
      if(in.repaired)
        i = id < in.prep.number_of_input_vertices ? in.prep.prepared_vertex[id] : HOT::Mesh_preparation::npos;
      if(i >= verts.size())
        throw Failure{HOT::ERROR_LANDMARK_OUT_OF_RANGE, path + ": vertex " + std::to_string(id) + " of the cut graph is not a vertex of the mesh"};
      paths.back().push_back(verts[i]);
    }
  }
  return paths;
}

// the cut graph an embedding used (Embedding_statistics::cut_graph), numbered as the files
std::vector<std::vector<std::size_t> > cut_graph_in_files(const HOT::Embedding_statistics& st, const Surface_mesh& m,
                                                          const hot_tools::Input_mesh* in)
{
  const std::vector<SM_vertex> verts(vertices(m).begin(), vertices(m).end());
  std::vector<std::vector<std::size_t> > r;
  for(const auto& p : st.cut_graph) {
    r.emplace_back();
    for(std::size_t i : p) r.back().push_back(hot_tools::output_vertex(verts[i], in));
  }
  return r;
}

// the flags and --progress
std::set<std::string> with_progress_flag(std::set<std::string> flags)
{
  flags.insert("progress");
  return flags;
}

// one line on stdout saying what --repair and --snap-landmarks changed
void print_repair(const std::string& path, const Input& in)
{
  if(in.file.repaired)
    std::cout << "repaired " << path << ": " << in.file.prep.summary() << std::endl;
  for(const auto& s : in.snaps)
    std::cout << "snapped landmark " << s.landmark << " of " << path << " from vertex " << s.from << " to boundary vertex "
              << s.to << " (distance " << s.distance << ")" << std::endl;
}

// Writes the embedding's SVG: the tiling (faded tile copies), the embedded mesh in the
// tile and its images around it, cones in distinct colours (paper, Figure 1).
void write_embedding_svg(std::ostream& os, const Surface_mesh& m,
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

// the options of `embed` (Embed_job) and its call of the library (embed_mesh()): embed_job.h

// --order I0,I1,...: a permutation of the k landmarks' positions (0-based lines of the landmark file)
std::vector<std::size_t> parse_landmark_positions(const std::string& s, std::size_t k)
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

Embed_job parse_embed_options(int argc, char** argv, bool& progress)
{
  std::set<std::string> flags = repair_flags();
  flags.insert("recentre");
  flags.insert("progress");
  const Options opt(argc, argv, 2, {"mesh", "cones", "orbifold", "weights", "order", "out", "svg", "report", "max-hole", "target-genus", "max-handle", "cone-orders",
                                       "cut-graph", "cut-graph-out"}, flags);
  Embed_job job;
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
  }
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
void write_embed_outputs(const Embed_job& job, const Surface_mesh& m, const UV_map& uv, const Chart_map& charts,
                         const std::vector<SM_vertex>& landmarks, const HOT::Embedding_statistics& st, const Input& in)
{
  const HOT::Orbifold_type type = job.request.type;
  HOT::Orbifold_tile<> tile;
  HOT::make_embedding_tile(type, st, tile);
  if(st.recentred)
    tile = tile.transformed(st.frame); // the tile of the written coordinates

  Output_files files;
  const hot_tools::Embedding_charts<Chart_map> ch{charts, st.charts, st.chart_corners};
  const hot_tools::Embedding_cones cones = embedding_cones(type, st, job.request.cones);
  hot_tools::timings().phase("tile");
  files.write(job.out_path, [&](std::ostream& os) { hot_tools::write_embedding_obj(os, m, uv, in.file.repaired ? &in.file : nullptr, &ch, &cones); });
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

int run_embed(int argc, char** argv)
{
  hot_tools::timings(); // (HOT_TIMINGS: the phases' clock starts here)
  bool progress_flag = false;
  Embed_job job = parse_embed_options(argc, argv, progress_flag);
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
  const long long genus = type == HOT::Sphere_type ? HOT::internal::closed_mesh_genus(m) : 0;
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
            << (st.recentred ? " in a recentred frame (given in the report)" : "")
            << (st.charted_faces > 0 ? ", " + std::to_string(st.charted_faces) + " faces in charts around cone images" : std::string())
            << "; wrote " << job.out_path << std::endl;
  hot_tools::timings().phase("stdout");
  return EXIT_SUCCESS;
}

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

void read_and_check(const std::string& mesh_path, const std::string& cones_path, const hot_tools::Repair_options& repair, Embedded& e,
                    std::size_t minimum = HOT::minimum_number_of_landmarks, Progress_line* progress = nullptr)
{
  e.type = read_mesh_and_landmarks(mesh_path, cones_path, std::nullopt, repair, e.mesh, e.landmarks, e.in, minimum);
  if(progress && (e.in.file.repaired || !e.in.snaps.empty()))
    progress->clear(); // (a terminal's line, before stdout)
  print_repair(mesh_path, e.in);
}

// the addressing to write a mesh's files with: the file's (--repair), or none (as read)
const hot_tools::Input_mesh* addressing(const Input& in)
{
  return in.file.repaired ? &in.file : nullptr;
}

void embed_in_order(Embedded& e, const std::vector<std::size_t>& order, const std::vector<int>& orders, const std::string& name,
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

long long genus_of(const Embedded& e)
{
  return e.type == HOT::Sphere_type ? HOT::internal::closed_mesh_genus(e.mesh) : 0;
}

// the locator of a map's target (or, for the colours, of its source): in the tile of its cut graph (genus g >= 1), or of its signature
Locator target_locator(const Embedded& B)
{
  if(B.stats.genus > 0) {
    Locator::Tile tile;
    if(HOT::make_embedding_tile(B.type, B.stats, tile) != HOT::OK)
      throw Failure{HOT::ERROR_WRONG_PARAMETER, "the target's tile could not be built from its cut graph"};
    return Locator(B.mesh, B.uv, tile, HOT::Hyperboloid_linear);
  }
  return Locator(B.mesh, B.uv, B.charts, B.stats.charts, HOT::Orbifold_signature(B.type, B.stats.cone_orders), HOT::Hyperboloid_linear);
}

// the source and the target of a map: the same topology and number of landmarks
void check_map_pair(const Embedded& A, const Embedded& B)
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
void match_genus_zero(const Options& opt, const hot_tools::Repair_options& repair, Embedded& A, Embedded& B, std::size_t minimum)
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
void map_cut_graphs(const Options& opt, const Embedded& A, const Embedded& B, std::vector<std::vector<SM_vertex> >& ga,
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
void check_same_polygon(const Embedded& A, const Embedded& B)
{
  const HOT::Embedding_statistics &a = A.stats, &b = B.stats;
  if(a.cut_corner_nodes != b.cut_corner_nodes || a.cut_node_cones != b.cut_node_cones || a.cut_paired_sides != b.cut_paired_sides ||
     a.cone_orders != b.cone_orders)
    throw Failure{HOT::ERROR_WRONG_PARAMETER, "the cut graphs of the source and the target do not correspond: their polygons differ (" +
                                              std::to_string(a.cut_corner_nodes.size()) + " and " + std::to_string(b.cut_corner_nodes.size()) +
                                              " corners, or other side pairings); give corresponding cut graphs"};
}

// The cone orders a map tries in turn, best first, each with the mesh whose tour it is (0 the
// source, 1 the target, npos the given order). Sphere type of genus 0: with --order auto (the
// default) the source's and the target's tours ranked by HOT::rank_landmark_tours() (the
// longest, over the two meshes, of the cut's length in that order over the mesh's own tour's;
// the source's on ties), with --order tsp the source's tour alone, with --order given the
// given order alone. Disk type keeps the given order, genus g >= 1 takes any (the given one).
std::vector<HOT::Landmark_order_candidate> map_cone_orders(const std::string& how, const Embedded& A, const Embedded& B)
{
  HOT::Landmark_order_candidate given;
  for(std::size_t i = 0; i < A.landmarks.size(); ++i) given.order.push_back(i);
  given.mesh = std::size_t(-1);
  given.longest_ratio = 1;
  if(A.type != HOT::Sphere_type || genus_of(A) != 0 || how == "given")
    return {given};
  std::vector<std::vector<std::vector<double> > > D(1, HOT::compute_landmark_distances(A.mesh, A.landmarks, get(CGAL::vertex_point, A.mesh)));
  if(how != "tsp")
    D.push_back(HOT::compute_landmark_distances(B.mesh, B.landmarks, get(CGAL::vertex_point, B.mesh)));
  const std::vector<HOT::Landmark_order_candidate> r = HOT::rank_landmark_tours(D);
  if(r.empty())
    throw Failure{HOT::ERROR_CUT_FAILED, "the landmark tour could not be computed on the " + std::string(
                                           HOT::internal::is_finite_distance_matrix(D[0]) ? "target" : "source")};
  return r;
}

// "the source's tour", "the target's tour" or "the given order"
std::string order_origin(const HOT::Landmark_order_candidate& c)
{
  return c.mesh == 0 ? "the source's tour" : c.mesh == 1 ? "the target's tour" : "the given order";
}

// Embeds the source and the target of a map in the first order of `candidates` both accept;
// an order refused for a reason the order may cause (HOT::is_landmark_order_failure()) passes to
// the next one. Returns the index of the order used; fails when none works, saying which orders
// were tried and why each failed. `refusals` gets one line per order refused.
std::size_t embed_map_pair(Embedded& A, Embedded& B, const std::vector<HOT::Landmark_order_candidate>& candidates,
                           const std::vector<int>& orders, const std::vector<std::vector<SM_vertex> >& ga,
                           const std::vector<std::vector<SM_vertex> >& gb, std::vector<std::string>& refusals,
                           Progress_line* progress = nullptr)
{
  std::string tried;
  for(std::size_t c = 0; c < candidates.size(); ++c) {
    const std::vector<std::size_t>& order = candidates[c].order;
    try {
      // (with a choice, the mesh whose tour it is not first: the more likely to refuse it)
      const bool target_first = candidates.size() > 1 && candidates[c].mesh == 0;
      embed_in_order(target_first ? B : A, order, orders, target_first ? "target" : "source", target_first ? gb : ga, progress);
      embed_in_order(target_first ? A : B, order, orders, target_first ? "source" : "target", target_first ? ga : gb, progress);
      return c;
    } catch(const Failure& f) {
      if(candidates.size() == 1 || !HOT::is_landmark_order_failure(f.code))
        throw;
      std::string list;
      for(std::size_t i : order) list += (list.empty() ? "" : " ") + std::to_string(i);
      refusals.push_back(order_origin(candidates[c]) + " (" + list + ") was refused by the " + f.message);
      if(c + 1 == candidates.size()) {
        std::string why;
        for(const std::string& r : refusals) why += (why.empty() ? "" : "; ") + r;
        throw Failure{f.code, "no landmark order works for both meshes (" + std::to_string(candidates.size()) + " tried): " + why};
      }
    }
  }
  return 0; // (not reached: candidates is never empty)
}

// what `map` reports: sizes, times and the unreliable vertices, numbered as in the files
// the source's vertices (file numbers, increasing) whose image `f` lies on a face that the
// target's repair added to close a hole
std::vector<std::size_t> images_in_filled_holes(const Embedded& A, const Embedded& B, const std::vector<Locator::Location>& f)
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
void add_reliability_tests(hot_tools::Map_summary& m, const HOT::Map_reliability& r)
{
  m.reliability_tests = true;
  m.unreliable_by_scale = r.scale_flagged;
  m.unreliable_by_rounding = r.rounding_flagged;
  m.unreliable_by_protrusion = r.protrusion_flagged;
  m.reference_scale = r.reference_scale;
  m.scale_noise = r.scale_noise;
}

hot_tools::Map_summary map_summary(const Options& opt, const Embedded& A, const Embedded& B, int k, const HOT::Map_reliability& r)
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
int run_map_stored(const Options& opt)
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
  const std::vector<Locator::Location> f = HOT::map_vertices(A.mesh, A.uv, A.charts, A.chart_isometries, locB);
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

int run_map(int argc, char** argv)
{
  const Options opt(argc, argv, 2,
                    {"source", "source-cones", "target", "target-cones", "out", "colors-out", "prepared-target", "report", "max-hole", "target-genus", "max-handle",
                     "cone-orders", "source-cut-graph", "target-cut-graph", "source-embedding", "target-embedding", "order"},
                    with_progress_flag(repair_flags()), {"refine"});
  if(opt.has("source-embedding") || opt.has("target-embedding")) {
    if(opt.has("refine"))
      throw Usage_error{"--refine refines a map computed from the meshes, not from stored embeddings"};
    return run_map_stored(opt);
  }
  const int refine = !opt.has("refine") ? 0 : opt.get("refine").empty() ? 100 : static_cast<int>(opt.get_int("refine", 0, 100000));
  const std::string out = opt.get("out");
  const hot_tools::Repair_options repair = parse_repair_options(opt);
  const std::vector<int> orders = parse_cone_orders(opt); // (landmark i of both files: a cone of order orders[i])
  Progress_line progress("map", opt.has("progress"));
  Embedded A, B;
  progress.step("read");
  read_and_check(opt.get("source"), opt.get("source-cones"), repair, A, minimum_landmarks(orders), &progress);
  read_and_check(opt.get("target"), opt.get("target-cones"), repair, B, minimum_landmarks(orders), &progress);
  progress.clear(); // (match_genus_zero() may write on stdout)
  match_genus_zero(opt, repair, A, B, minimum_landmarks(orders));
  progress.done("read");
  check_map_pair(A, B);
  progress.step("landmark order");
  const std::vector<HOT::Landmark_order_candidate> candidates = map_cone_orders(parse_common_order(opt), A, B);
  progress.done("landmark order");
  std::vector<std::vector<SM_vertex> > ga, gb; // genus g >= 1: the cut graphs
  if(genus_of(A) > 0) {
    for(std::size_t i : candidates[0].order) A.ordered.push_back(A.landmarks[i]);
    map_cut_graphs(opt, A, B, ga, gb);
  } else if(opt.has("source-cut-graph") || opt.has("target-cut-graph"))
    throw Failure{HOT::ERROR_WRONG_PARAMETER, "the meshes have genus 0: a cut graph is for closed meshes of genus 1 or more"};
  std::vector<std::string> refusals;
  const HOT::Landmark_order_candidate& chosen = candidates[embed_map_pair(A, B, candidates, orders, ga, gb, refusals, &progress)];
  const std::vector<std::size_t>& order = chosen.order;
  if(genus_of(A) > 0)
    check_same_polygon(A, B);
  if(A.stats.landmark_order_reversed != B.stats.landmark_order_reversed)
    throw Failure{HOT::ERROR_WRONG_PARAMETER, "the landmarks run clockwise around one boundary and counterclockwise around the other: "
                                              "the correspondence would reverse orientation"};
  const int k = static_cast<int>(order.size());
  progress.step("map");
  const auto t0 = std::chrono::steady_clock::now();
  const Locator locB = target_locator(B);
  std::vector<Locator::Location> f = HOT::map_vertices(A.mesh, A.uv, A.charts, A.stats.charts, locB);
  for(std::size_t i = 0; i < f.size(); ++i)
    if(!f[i].success)
      throw Failure{HOT::ERROR_POINT_NOT_LOCATED, "vertex " + std::to_string(i) + " of the source could not be located on the target"};
  progress.done("map");
  const auto t1 = std::chrono::steady_clock::now();
  HOT::Map_distortion distortion_before;
  HOT::Map_refinement_statistics refinement;
  if(refine > 0) { // (A's embedding moves: everything below reads the refined map)
    progress.step("refine");
    if(!A.stats.charts.empty()) // (the library refuses the rest: genus 1 or more)
      throw Failure{HOT::ERROR_WRONG_PARAMETER, "--refine handles sources embedded without charts; the source is embedded partly in charts around cone images"};
    distortion_before = HOT::map_distortion(A.mesh, B.mesh, locB, f);
    const HOT::Error_code ec = HOT::refine_orbifold_map(A.mesh, A.ordered, A.uv, B.mesh, locB, refinement,
      HOT::parameters::refine(refine, HOT::parameters::frame(A.stats.frame, HOT::parameters::cone_orders(A.stats.cone_orders, HOT::parameters::orbifold_type(A.type)))));
    if(ec != HOT::OK)
      throw Failure{ec, "--refine: " + refinement.message};
    f = HOT::map_vertices(A.mesh, A.uv, A.charts, A.stats.charts, locB);
    for(std::size_t i = 0; i < f.size(); ++i)
      if(!f[i].success)
        throw Failure{HOT::ERROR_POINT_NOT_LOCATED, "vertex " + std::to_string(i) + " of the source could not be located on the target after the refinement"};
    progress.done("refine");
  }
  progress.step("reliability");
  const HOT::Map_reliability reliability = HOT::map_reliability(A.mesh, A.uv, B.mesh, B.uv, locB, f);
  progress.done("reliability");
  hot_tools::Map_summary summary = map_summary(opt, A, B, k, reliability);
  summary.images_in_filled_holes = images_in_filled_holes(A, B, f);
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
  Output_files files;
  files.write(out, [&](std::ostream& os) { hot_tools::write_map(os, B.mesh, locB, f, addressing(A.in)); });
  if(opt.has("report"))
    files.write(opt.get("report"), [&](std::ostream& os) { hot_tools::write_map_report(os, summary); });
  if(opt.has("prepared-target"))
    files.write(opt.get("prepared-target"), [&](std::ostream& os) { hot_tools::write_addressed_off(os, B.mesh, B.in.file); });
  if(opt.has("colors-out")) {
    // a smooth colouring of A, carried to B by f_BA
    const Locator locA = target_locator(A);
    const std::vector<Locator::Location> g = HOT::map_vertices(B.mesh, B.uv, B.charts, B.stats.charts, locA);
    files.write(opt.get("colors-out"), [&](std::ostream& os) { hot_tools::write_coloured_ply(os, A.mesh, locA, B.mesh, g, addressing(B.in)); });
  }
  files.commit();
  progress.done("write");
  progress.clear();
  std::cout << "landmark order:";
  for(std::size_t i : order) std::cout << " " << i;
  std::cout << " (" << order_origin(chosen);
  for(const std::string& r : refusals) std::cout << "; " << r;
  std::cout << ")" << std::endl;
  if(refine > 0)
    std::cout << "refined: " << refinement.iterations << " certified iterations, symmetric Dirichlet energy " << refinement.energy_before
              << " -> " << refinement.energy_after << " (4 for an isometry), " << refinement.seconds << " s; " << refinement.message << std::endl;
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
  return EXIT_SUCCESS;
}

typedef HOT::Orbifold_collection<Surface_mesh, CGAL::Parallel_tag> Collection;
typedef hot_tools::Collection_maps Collection_maps;

// reads and checks every mesh of the manifest into the collection; returns the orbifold type
HOT::Orbifold_type read_collection(const Manifest& entries, const hot_tools::Repair_options& repair, Collection& coll,
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
void embed_collection(const Manifest& entries, Collection& coll)
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
Collection_maps map_collection(Collection& coll, bool all_pairs)
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
void write_collection_files(const Collection_job& job, Collection& coll, HOT::Orbifold_type type,
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
    const hot_tools::Embedding_charts<Collection::Chart_map> ch{coll.chart_map(i), st.charts, st.chart_corners};
    hot_tools::Embedding_cones cones;
    cones.type = type;
    cones.reversed = st.landmark_order_reversed;
    cones.landmark = coll.order();
    for(std::size_t c : coll.order()) {
      cones.vertex.push_back(hot_tools::output_vertex(coll.landmarks(i)[c], addressed(i)));
      cones.order.push_back(coll.cone_orders().empty() ? 2 : coll.cone_orders()[c]);
    }
    files.write(job.obj_path(i),
                [&](std::ostream& os) { hot_tools::write_embedding_obj(os, coll.mesh(i), coll.uv_map(i), addressed(i), &ch, &cones); });
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
std::pair<std::size_t, std::size_t> parse_shard(const Options& opt)
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
void run_in_threads(std::size_t n, std::size_t threads, const std::function<void(std::size_t)>& job)
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

// `collection --stage embed|refine|maps|merge [--shard I/N]`: the collection as separate jobs
// (collection_jobs.h): the embed stage embeds meshes I, I + N, ...; the maps stage computes the
// maps I, I + N, ... of the collection's list of pairs from the stored embeddings; the merge
// writes report.json once both stages are done for every shard. A mesh or pair whose part is
// already in DIR/.parts (a job run again) is skipped, with a line on stderr. `threads`: the
// single-process run's (the stage's meshes or pairs in parallel); `summary`: its line on stdout
int run_collection_stage(const Collection_job& job, const std::string& stage, std::pair<std::size_t, std::size_t> shard,
                         std::size_t threads = 1, bool summary = true, std::ostream& log = std::cerr)
{
  std::mutex out;
  std::size_t done = 0, skipped = 0;
  auto mine = [&](std::size_t n) {
    std::vector<std::size_t> r;
    for(std::size_t k = shard.first; k < n; k += shard.second) r.push_back(k);
    return r;
  };
  if(stage == "embed") {
    const std::vector<std::size_t> todo = mine(job.size());
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
  } else if(stage == "refine") {
    if(job.refine <= 0)
      throw Usage_error{"--stage refine needs --refine [N] (in every stage's job)"};
    const std::vector<std::size_t> todo = mine(job.size());
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
        log << "  refined " << job.entries[i].first << " onto " << job.entries[0].first << ": " << st.iterations
            << " certified iterations, symmetric Dirichlet energy " << st.energy_before << " -> " << st.energy_after << " (" << t << " s)" << std::endl;
      }
      ++done;
    });
    if(summary)
      std::cout << "collection shard " << shard.first << "/" << shard.second << ": refined " << done << " of " << job.size() << " meshes in "
                << job.dir << (skipped > 0 ? " (" + std::to_string(skipped) + " refined before)" : std::string()) << std::endl;
  } else if(stage == "maps") {
    const Collection_pairs cp = collection_pairs(job.size(), job.all_pairs);
    const std::vector<std::size_t> todo = mine(cp.pairs.size());
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
  } else if(stage == "merge") {
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
int run_collection_in_memory(const Collection_job& job)
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
      std::cerr << "  refined " << job.entries[i].first << " onto " << job.entries[0].first << ": " << st.iterations
                << " certified iterations, symmetric Dirichlet energy " << st.energy_before << " -> " << st.energy_after << " (" << st.seconds << " s)" << std::endl;
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
int run_collection_resumable(const Collection_job& job)
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

int run_collection(int argc, char** argv)
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

// With --repair the landmarks are vertices of the input file: a landmark that falls on a vertex
// the repair added (inside a filled hole, or a copy of a split non-manifold vertex) moves to the
// nearest input vertex, ring by ring along the edges, that is not a landmark yet and is on the
// boundary if the landmark was.
std::vector<SM_vertex> input_vertices_only(const Surface_mesh& m, const hot_tools::Input_mesh& in, std::vector<SM_vertex> lm)
{
  const std::size_t n = in.prep.number_of_input_vertices;
  auto on_border = [&](SM_vertex v) { return bool(CGAL::is_border(v, m)); };
  std::set<SM_vertex> taken(lm.begin(), lm.end());
  for(SM_vertex& v : lm) {
    if(hot_tools::output_vertex(v, &in) < n) continue;
    // breadth-first over the one-rings, nearest first within a ring
    std::vector<SM_vertex> ring(1, v);
    std::set<SM_vertex> seen(ring.begin(), ring.end());
    SM_vertex found = v;
    while(found == v && !ring.empty()) {
      std::vector<SM_vertex> next;
      for(SM_vertex u : ring)
        for(SM_vertex w : vertices_around_target(halfedge(u, m), m))
          if(seen.insert(w).second) next.push_back(w);
      std::sort(next.begin(), next.end(), [&](SM_vertex a, SM_vertex b) {
        return CGAL::squared_distance(m.point(a), m.point(v)) < CGAL::squared_distance(m.point(b), m.point(v));
      });
      for(SM_vertex w : next)
        if(found == v && hot_tools::output_vertex(w, &in) < n && !taken.count(w) && on_border(w) == on_border(v)) found = w;
      ring.swap(next);
    }
    taken.erase(v);
    taken.insert(found);
    v = found;
  }
  return lm;
}

int run_landmarks(int argc, char** argv)
{
  const Options opt(argc, argv, 2, {"mesh", "count", "out", "max-hole", "target-genus", "max-handle"}, with_progress_flag(repair_flags()));
  const std::string mesh_path = opt.get("mesh"), out = opt.get("out");
  const long k = opt.get_int("count", 1, 100000);
  const hot_tools::Repair_options repair = parse_repair_options(opt);
  Progress_line progress("landmarks", opt.has("progress"));
  Surface_mesh m;
  Input in;
  progress.step("read");
  require(hot_tools::read_input_mesh(mesh_path, std::nullopt, repair, m, in.file));
  progress.done("read");
  if(in.file.repaired)
    progress.clear(); // (a terminal's line, before stdout)
  print_repair(mesh_path, in);
  if(static_cast<std::size_t>(k) > num_vertices(m))
    throw Usage_error{"--count is larger than the number of vertices (" + std::to_string(num_vertices(m)) + ")"};
  progress.step("select");
  std::vector<SM_vertex> lm = HOT::select_landmarks(m, static_cast<std::size_t>(k));
  if(lm.size() != static_cast<std::size_t>(k))
    throw Failure{HOT::ERROR_WRONG_PARAMETER, "the boundary has fewer than " + std::to_string(k) + " vertices"};
  if(in.file.repaired)
    lm = input_vertices_only(m, in.file, lm);
  progress.done("select");
  progress.step("write");
  write_file_atomically(out, [&](std::ostream& os) {
    for(std::size_t i : file_indices(lm, in.file))
      os << i << "\n";
  });
  progress.done("write");
  progress.clear();
  std::cout << "wrote " << k << " landmarks of " << mesh_path << " to " << out << std::endl;
  return EXIT_SUCCESS;
}

// CGAL's selection file of the cut through the cones (sphere type), for CGAL's orbifold
// example (Seam_mesh::add_seams() and SMP::locate_cones(); CGAL's own
// compute_shortest_paths_between_cones() takes 3 or 4 cones only)
int run_cut(int argc, char** argv)
{
  const Options opt(argc, argv, 2, {"mesh", "cones", "order", "out"});
  const std::string mesh_path = opt.get("mesh"), cones_path = opt.get("cones"), out = opt.get("out");
  const bool tour = parse_order(opt, "given") == "tsp";
  Surface_mesh m;
  HOT::Mesh_info info;
  require(hot_tools::read_and_check_mesh(mesh_path, std::nullopt, m, &info));
  if(info.type != HOT::Sphere_type)
    throw Failure{HOT::ERROR_WRONG_TOPOLOGY, mesh_path + ": the mesh has a boundary loop; only a closed genus-0 mesh "
                                             "(sphere type) is cut, a disk-type orbifold needs no cut"};
  std::vector<SM_vertex> landmarks;
  require(hot_tools::read_and_check_landmarks(cones_path, m, info.type, landmarks));
  std::vector<SM_vertex> cones = landmarks;
  if(tour) {
    const std::vector<std::size_t> order = HOT::compute_landmark_tour(m, landmarks);
    if(order.size() != landmarks.size())
      throw Failure{HOT::ERROR_CUT_FAILED, "the landmark tour could not be computed"};
    for(std::size_t i = 0; i < order.size(); ++i) cones[i] = landmarks[order[i]];
  }
  const HOT::Cut_result<Surface_mesh> cut = HOT::compute_cut_through_landmarks(m, cones, get(CGAL::vertex_point, m));
  if(!cut.ok)
    throw Failure{HOT::ERROR_CUT_FAILED, cut.message};
  write_file_atomically(out, [&](std::ostream& os) { hot_tools::write_selection_file(os, m, cones, cut); });
  std::cout << "wrote the cut of " << mesh_path << " through " << cones.size() << " cones (" << cut.number_of_cut_edges()
            << " seam edges) to " << out << std::endl;
  return EXIT_SUCCESS;
}

} // namespace

int main(int argc, char** argv)
{
  try {
    if(argc < 2)
      throw Usage_error{"missing command"};
    const std::string command = argv[1];
    if(command == "help" && argc > 2) { // help JOB: the job's usage
      const Job_usage* u = find_job_usage(argv[2]);
      if(u == nullptr)
        throw Usage_error{"unknown command '" + std::string(argv[2]) + "'"};
      std::cout << job_usage_text(*u);
      return EXIT_SUCCESS;
    }
    if(command == "--help" || command == "-h" || command == "help") {
      std::cout << usage_text();
      return EXIT_SUCCESS;
    }
    // JOB ... --help (or -h) anywhere: the job's usage, before the job parses or checks anything
    if(const Job_usage* u = find_job_usage(command))
      if(help_requested(argc, argv, 2)) {
        std::cout << job_usage_text(*u);
        return EXIT_SUCCESS;
      }
    if(command == "tile")
      return run_tile(argc, argv);
    if(command == "embed")
      return run_embed(argc, argv);
    if(command == "landmarks")
      return run_landmarks(argc, argv);
    if(command == "map")
      return run_map(argc, argv);
    if(command == "collection")
      return run_collection(argc, argv);
    if(command == "cut")
      return run_cut(argc, argv);
    if(command == "certify")
      return run_certify(argc, argv);
    throw Usage_error{"unknown command '" + command + "'"};
  } catch(const Help_request&) { // (main() answers --help first; Options' own check, for safety)
    const Job_usage* u = find_job_usage(argv[1]);
    std::cout << (u != nullptr ? job_usage_text(*u) : usage_text());
    return EXIT_SUCCESS;
  } catch(const Failure& e) {
    std::cerr << "hyperbolic_orbifold_tutte: " << HOT::error_message(e.code) << ": " << e.message << std::endl;
    return 3;
  } catch(const Usage_error& e) {
    std::cerr << "hyperbolic_orbifold_tutte: " << e.message << " (see --help)" << std::endl;
    return 2;
  } catch(const std::exception& e) {
    std::cerr << "hyperbolic_orbifold_tutte: " << e.what() << std::endl;
    return 1;
  }
}
