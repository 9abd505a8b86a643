// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// hyperbolic_orbifold_tutte: the package's main jobs from the command line.
//
//   hyperbolic_orbifold_tutte embed|map|collection|landmarks|cut|tile|certify ... (--help lists them)
//
// Every error ends the program with a non-zero status and one line on stderr;
// output files are written to a temporary name and renamed only when complete
// (application/hot_app/job_support.h). This file holds main(), the usage and the dispatch;
// each job is a header of jobs/, the files' formats are the headers of application/hot_app/io/.

// the mesh's header first: Seam_mesh calls CGAL::halfedges(tm) etc. qualified
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

// one header per job (jobs/): its options, its run_JOB(); the jobs and file formats it shares
// with the Python module are the application layer's (application/hot_app/)
#include "command_line.h"
#include "jobs/tile.h"
#include "jobs/embed.h"
#include "jobs/map.h"
#include "jobs/collection.h"
#include "jobs/landmarks.h"
#include "jobs/cut.h"
#include "jobs/certify.h"
#include "jobs/view.h"

#include <cstdlib>
#include <exception>
#include <iostream>
#include <string>

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
  "      Without --weights: the cotangent weights, or the mean value weights when the cotangent\n"
  "      embedding fails the certificate (as map and collection; the report's \"weights\" says\n"
  "      which); --weights cotan never falls back.\n"
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
  "      [--report REPORT.json] [--cone-orders P1,P2,...] [--order auto|tsp|given] [--augment|--no-augment] [--refine [N]] [--progress] [REPAIR]\n"
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
  "      --refine [N]: refines the map towards an isometry (at most N iterations, default 30,\n"
  "      each certified bijective; landmarks kept; genus 0, a source without charts): lowers the\n"
  "      symmetric Dirichlet energy (4 for an isometry up to scale); REPORT.json's \"refinement\"\n"
  "      gives its iterations, stop, energies, time and the \"distortion_before\" it\n"
  "      --augment: first adds to both meshes' landmarks the thin tips the landmarks leave out\n"
  "      (a tail, a heel), matched by their geodesic distances to the landmarks (closed genus 0;\n"
  "      order 2 with --cone-orders); REPORT.json's \"augmentation\" lists the pairs added\n"
  "      (source vertex, target vertex), which follow the files' landmarks in \"landmark_order\";\n"
  "      --refine augments so on closed genus-0 meshes unless --no-augment is given\n"
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

const char* const usage_view =
  "  hyperbolic_orbifold_tutte view --embedding E.obj --out DIR\n"
  "  hyperbolic_orbifold_tutte view --source-embedding A.obj --target-embedding B.obj --out DIR\n"
  "  hyperbolic_orbifold_tutte view --collection COLLECTION_DIR --out DIR\n"
  "      writes DIR/index.html (with data.js, viewer.js, three.min.js): opens offline in a browser;\n"
  "      an embedding (embed's OBJ): the surface textured by the hyperbolic tiling beside the disk;\n"
  "      a map between stored embeddings (as map --source-embedding): both surfaces, A's colour\n"
  "      field carried to B, landmarks, distortion, unreliable vertices, click to see a point's image;\n"
  "      a collection's folder: every shape, the first one's colours carried to all\n";

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
                                {"certify", usage_certify}, {"view", usage_view}};

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
    if(command == "view")
      return run_view(argc, argv);
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
