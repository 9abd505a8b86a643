// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// refine_orbifold_map() on pose pairs with a ground truth (vertex i of A <-> vertex i of B, the
// same triangulation): error against the truth in % of B's bounding-box diagonal (mean, worst
// vertex), the map's distortion (conformal and area p99, symmetric Dirichlet energy) before and
// after, the ground truth's own distortion (the same figures of vertex i -> vertex i: a map that
// equals the truth has them), the independent certificate of the refined embedding, and the times (the refinement
// against the two embeddings and the map, measured in this run).
//   bench_refine A.off LA B.off LB [ROWS] [--iterations N] [--augment] [--svg PICTURE.svg]
// --augment: the extremities matched by match_extremities() are added to the landmarks first
// (each pair printed with its distance to the truth); the harmonic map is then the augmented one.
// --svg draws A twice, each vertex coloured by its error before and after the refinement (with
// --augment: the harmonic map with the given landmarks only, then the augmented refined one; white
// 0 to dark red at the harmonic map's worst error), the landmarks as dots (the manual's figure).
// LA, LB: landmark files (one vertex index per line, line j of LA corresponds to line j of LB);
// ROWS: an optional file of 0-based rows of LA/LB to use (e.g. tosca_wolf.suggested_rows7.txt).
#include "bench_common.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

typedef K::Point_2 Point_2;
typedef SM::Property_map<SM_halfedge, Point_2> UV;
typedef HOT::Embedding_locator<SM, UV> Locator;

struct Figures
{
  double mean = 0, worst = 0;
  std::size_t worst_vertex = 0;
  std::vector<double> error; // per vertex of A, in diagonals of B
  HOT::Map_distortion d;
};

static Figures measure(const SM& A, const UV& uvA, const SM& B, const Locator& L)
{
  const auto locs = HOT::map_vertices(A, uvA, L);
  Figures r;
  const double diag = diagonal(B);
  for(SM_vertex v : vertices(A)) {
    const K::Point_3 p = HOT::surface_point(locs[v.idx()], L, get(CGAL::vertex_point, B));
    const double e = std::sqrt(CGAL::squared_distance(p, B.point(v))) / diag;
    r.mean += e / num_vertices(A);
    r.error.push_back(e);
    if(e > r.worst) {
      r.worst = e;
      r.worst_vertex = v.idx();
    }
  }
  r.d = HOT::map_distortion(A, B, L, locs);
  return r;
}

static void print(const char* what, const Figures& f)
{
  std::printf("  %-8s error mean %.3f%% worst %.2f%% (vertex %zu)  conformal p99 %.3f  area p99 %.3f  symmetric Dirichlet %.4f\n", what,
              100 * f.mean, 100 * f.worst, f.worst_vertex, f.d.conformal_summary.p99, f.d.area_summary.p99, f.d.symmetric_dirichlet_energy);
}

// draws A, seen along -z (orthographic, painter's algorithm, Lambert shading), each face coloured
// by the mean error of its vertices (white at 0, dark red at `top`), into the square
// [x0, x0 + size] x [0, size]; the landmarks as black dots
static void draw_errors(std::ostream& os, const SM& A, const std::vector<double>& error, double top,
                        const std::vector<SM_vertex>& landmarks, double x0, double size)
{
  const CGAL::Bbox_3 bb = CGAL::Polygon_mesh_processing::bbox(A);
  const double scale = 0.9 * size / (std::max)(bb.xmax() - bb.xmin(), bb.ymax() - bb.ymin());
  const double cx = (bb.xmin() + bb.xmax()) / 2, cy = (bb.ymin() + bb.ymax()) / 2;
  const auto at = [&](SM_vertex v) {
    return std::make_pair(x0 + size / 2 + scale * (A.point(v).x() - cx), size / 2 - scale * (A.point(v).y() - cy));
  };
  std::vector<std::pair<double, SM_face> > order;
  for(SM_face f : faces(A)) {
    double z = 0;
    for(SM_vertex v : vertices_around_face(halfedge(f, A), A)) z += A.point(v).z();
    order.push_back(std::make_pair(z, f));
  }
  std::sort(order.begin(), order.end());
  const K::Vector_3 light(0.3, 0.4, 1.0);
  char line[256];
  for(const auto& of : order) {
    std::vector<SM_vertex> vs;
    for(SM_vertex v : vertices_around_face(halfedge(of.second, A), A)) vs.push_back(v);
    const K::Vector_3 n = CGAL::cross_product(A.point(vs[1]) - A.point(vs[0]), A.point(vs[2]) - A.point(vs[0]));
    const double len = std::sqrt(n.squared_length());
    const double shade = len > 0 ? 0.45 + 0.55 * std::abs(n * light) / (len * std::sqrt(light.squared_length())) : 0.7;
    const double t = (std::min)(1.0, (error[vs[0].idx()] + error[vs[1].idx()] + error[vs[2].idx()]) / (3 * top));
    // white -> yellow -> red -> dark red
    const double r = t < 0.75 ? 1.0 : 1.0 - 1.6 * (t - 0.75), g = t < 0.25 ? 1.0 : (std::max)(0.0, 1.0 - 2 * (t - 0.25)),
                 b = (std::max)(0.0, 1.0 - 4 * t);
    std::snprintf(line, sizeof(line), "<polygon fill=\"#%02x%02x%02x\" stroke=\"#%02x%02x%02x\" stroke-width=\"0.3\" points=\"",
                  int(255 * shade * r), int(255 * shade * g), int(255 * shade * b), int(255 * shade * r), int(255 * shade * g), int(255 * shade * b));
    os << line;
    for(SM_vertex v : vs) {
      std::snprintf(line, sizeof(line), "%.1f,%.1f ", at(v).first, at(v).second);
      os << line;
    }
    os << "\"/>\n";
  }
  for(SM_vertex v : landmarks) {
    std::snprintf(line, sizeof(line), "<circle cx=\"%.1f\" cy=\"%.1f\" r=\"4\" fill=\"black\"/>\n", at(v).first, at(v).second);
    os << line;
  }
}

// A and B embedded in one landmark order (A's tour): the corners in property maps named `name`,
// A's statistics, A's landmarks in cone order
struct Embedded_pair
{
  UV uvA, uvB;
  HOT::Embedding_statistics sa;
  std::vector<SM_vertex> ordered;
};

static bool embed_pair(SM& A, const std::vector<SM_vertex>& lma, SM& B, const std::vector<SM_vertex>& lmb, const std::string& name,
                       Embedded_pair& e)
{
  e.uvA = A.add_property_map<SM_halfedge, Point_2>(name, Point_2(0, 0)).first;
  e.uvB = B.add_property_map<SM_halfedge, Point_2>(name, Point_2(0, 0)).first;
  HOT::Embedding_statistics sb;
  if(HOT::hyperbolic_orbifold_Tutte_embedding(A, lma, e.uvA, HOT::parameters::embedding_statistics(&e.sa, HOT::parameters::landmark_order(HOT::Tsp_order))) != HOT::OK) {
    std::printf("A refused: %s\n", e.sa.message.c_str());
    return false;
  }
  std::vector<SM_vertex> lmb_o;
  e.ordered.clear();
  for(std::size_t i : e.sa.landmark_order) {
    e.ordered.push_back(lma[i]);
    lmb_o.push_back(lmb[i]);
  }
  if(HOT::hyperbolic_orbifold_Tutte_embedding(B, lmb_o, e.uvB, HOT::parameters::embedding_statistics(&sb)) != HOT::OK) {
    std::printf("B refused: %s\n", sb.message.c_str());
    return false;
  }
  return true;
}

static HOT::Orbifold_type orbifold_type_of(const SM& B) { return CGAL::is_closed(B) ? HOT::Sphere_type : HOT::Disk_type; }

int main(int argc, char** argv)
{
  std::vector<std::string> args;
  int iterations = 100;
  std::string svg;
  bool augment = false;
  for(int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if(a == "--augment")
      augment = true;
    else if(a == "--iterations" && i + 1 < argc)
      iterations = std::atoi(argv[++i]);
    else if(a == "--svg" && i + 1 < argc)
      svg = argv[++i];
    else
      args.push_back(a);
  }
  SM A, B;
  if(args.size() < 4 || !CGAL::IO::read_polygon_mesh(args[0], A) || !CGAL::IO::read_polygon_mesh(args[2], B) ||
     num_vertices(A) != num_vertices(B)) {
    std::printf("usage: bench_refine A.off LA B.off LB [ROWS] [--iterations N] [--augment] [--svg PICTURE.svg] (A and B with the same vertices)\n");
    return 1;
  }
  std::vector<std::size_t> la = read_indices(args[1]), lb = read_indices(args[3]);
  if(args.size() > 4) {
    std::vector<std::size_t> a2, b2;
    for(std::size_t r : read_indices(args[4])) {
      a2.push_back(la.at(r));
      b2.push_back(lb.at(r));
    }
    la = a2;
    lb = b2;
  }
  std::vector<SM_vertex> lma, lmb;
  for(std::size_t i = 0; i < la.size(); ++i) {
    lma.push_back(SM_vertex(static_cast<SM::size_type>(la[i])));
    lmb.push_back(SM_vertex(static_cast<SM::size_type>(lb[i])));
  }
  const std::size_t user_landmarks = lma.size();
  Figures plain; // (--augment --svg: the harmonic map with the user's landmarks only, drawn on the left)
  if(augment && !svg.empty()) {
    Embedded_pair e0;
    if(!embed_pair(A, lma, B, lmb, "h:uv0", e0))
      return 1;
    plain = measure(A, e0.uvA, B, Locator(B, e0.uvB, orbifold_type_of(B), static_cast<int>(lma.size()), HOT::Hyperboloid_linear));
    A.remove_property_map(e0.uvA);
    B.remove_property_map(e0.uvB);
  }
  const auto t0 = Clock::now();
  if(augment) {
    HOT::Extremity_matching<SM_vertex> xm;
    if(HOT::match_extremities(A, lma, B, lmb, xm) != HOT::OK) {
      std::printf("match_extremities refused: %s\n", xm.message.c_str());
      return 1;
    }
    std::printf("  augmented: %zu pairs of the %zu/%zu thin tips found (%.2f s)\n", xm.pairs.size(), xm.source_extremities,
                xm.target_extremities, xm.seconds);
    for(std::size_t i = 0; i < xm.pairs.size(); ++i) {
      std::printf("    source vertex %zu -> target vertex %zu (tipness %.2f/%.2f, descriptors %.3f apart): %.2f%% of the diagonal from the truth\n",
                  std::size_t(xm.pairs[i].first.idx()), std::size_t(xm.pairs[i].second.idx()), xm.source_tipness[i], xm.target_tipness[i],
                  xm.descriptor_difference[i],
                  100 * std::sqrt(CGAL::squared_distance(B.point(xm.pairs[i].second), B.point(SM_vertex(xm.pairs[i].first.idx())))) / diagonal(B));
      lma.push_back(xm.pairs[i].first);
      lmb.push_back(xm.pairs[i].second);
    }
  }
  Embedded_pair e;
  if(!embed_pair(A, lma, B, lmb, "h:uv", e))
    return 1;
  UV uvA = e.uvA, uvB = e.uvB;
  const HOT::Embedding_statistics& sa = e.sa;
  const std::vector<SM_vertex>& lma_o = e.ordered;
  const HOT::Orbifold_type type = orbifold_type_of(B);
  const Locator L(B, uvB, type, static_cast<int>(lma.size()), HOT::Hyperboloid_linear);
  const Figures before = measure(A, uvA, B, L);
  const double t_map = seconds_since(t0);
  HOT::Map_refinement_statistics rs;
  const HOT::Error_code ec = HOT::refine_orbifold_map(A, lma_o, uvA, B, L, rs,
                                                      HOT::parameters::refine(iterations, HOT::parameters::frame(sa.frame, HOT::parameters::orbifold_type(type))));
  if(ec != HOT::OK) {
    std::printf("refinement refused: %s\n", rs.message.c_str());
    return 1;
  }
  HOT::Embedding_certificate cert;
  std::string why;
  const bool certified = HOT::certify_hyperbolic_orbifold_embedding(A, lma_o, uvA, cert, &why,
                                                                    HOT::parameters::frame(sa.frame, HOT::parameters::orbifold_type(type))) == HOT::OK &&
                         cert.is_bijective();
  const Figures after = measure(A, uvA, B, L);
  if(std::getenv("DUMP_CONFORMAL")) { // (exploring) faces by conformal distortion: graph distance to the nearest landmark
    std::vector<int> dist(num_vertices(A), 1 << 30);
    std::vector<SM_vertex> front(lma.begin(), lma.end());
    for(SM_vertex v : front) dist[v.idx()] = 0;
    for(int r = 0; !front.empty(); ++r) {
      std::vector<SM_vertex> next;
      for(SM_vertex v : front) for(SM_vertex w : vertices_around_target(halfedge(v, A), A)) if(dist[w.idx()] > r + 1) { dist[w.idx()] = r + 1; next.push_back(w); }
      front.swap(next);
    }
    std::vector<int> hist(12, 0), all(12, 0);
    for(SM_face f : faces(A)) {
      int dm = 1 << 30;
      for(SM_vertex v : vertices_around_face(halfedge(f, A), A)) dm = (std::min)(dm, dist[v.idx()]);
      const int b = (std::min)(dm, 11);
      ++all[b];
      if(after.d.conformal[f.idx()] > 2.5) ++hist[b];
    }
    for(int b = 0; b < 12; ++b) std::printf("  rings %d: %d of %d faces with conformal > 2.5\n", b, hist[b], all[b]);
  }
  std::printf("%s -> %s, %zu vertices, %zu landmarks%s\n", args[0].c_str(), args[2].c_str(), num_vertices(A), user_landmarks,
              augment ? (" + " + std::to_string(lma.size() - user_landmarks) + " added").c_str() : "");
  print("harmonic", before);
  print("refined", after);
  std::vector<K::Point_3> truth; // (vertex i of A onto vertex i of B)
  for(SM_vertex v : vertices(A))
    truth.push_back(B.point(v));
  const HOT::Map_distortion td = HOT::map_distortion(A, truth);
  std::printf("  %-8s conformal p99 %.3f  area p99 %.3f  symmetric Dirichlet %.4f\n", "truth", td.conformal_summary.p99, td.area_summary.p99,
              td.symmetric_dirichlet_energy);
  std::printf("  refinement: %d iterations (%s), symmetric Dirichlet energy %.5f -> %.5f, %zu of %zu free vertices' moves undone in the last\n",
              rs.iterations, rs.message.c_str(), rs.energy_before, rs.energy_after, rs.undone_moves, rs.free_vertices);
  std::printf("  independent certificate of the refined embedding: %s\n", certified ? "bijective" : why.c_str());
  std::printf("  time: %sembed both + map %.2f s, refine %.2f s (certificates %.2f s), ratio %.2f\n", augment ? "match extremities + " : "", t_map, rs.seconds, rs.seconds_certificate,
              rs.seconds / t_map);
  if(!svg.empty()) {
    std::ofstream os(svg);
    char caption[256];
    os << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"1000\" height=\"560\" viewBox=\"0 0 1000 560\">\n"
       << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
    const Figures& left = augment ? plain : before;
    const std::vector<SM_vertex> user(lma.begin(), lma.begin() + user_landmarks);
    draw_errors(os, A, left.error, left.worst, user, 0, 500);
    draw_errors(os, A, after.error, left.worst, lma, 500, 500);
    std::snprintf(caption, sizeof(caption), "harmonic orbifold map: error mean %.2f%%, worst %.2f%%", 100 * left.mean, 100 * left.worst);
    os << "<text x=\"250\" y=\"530\" font-family=\"sans-serif\" font-size=\"16\" text-anchor=\"middle\">" << caption << "</text>\n";
    if(augment)
      std::snprintf(caption, sizeof(caption), "augmented (+%zu), refined: mean %.2f%%, worst %.2f%%", lma.size() - user_landmarks,
                    100 * after.mean, 100 * after.worst);
    else
      std::snprintf(caption, sizeof(caption), "refined (%d iterations): mean %.2f%%, worst %.2f%%", rs.iterations, 100 * after.mean, 100 * after.worst);
    os << "<text x=\"750\" y=\"530\" font-family=\"sans-serif\" font-size=\"16\" text-anchor=\"middle\">" << caption << "</text>\n</svg>\n";
    std::printf("  wrote %s\n", svg.c_str());
  }
  return certified ? 0 : 2;
}
