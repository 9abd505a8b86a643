// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Issue 39 exploration: landmark augmentation by matched extremities. The orbifold map A -> B
// (embed both, map, refine) is computed with the user's landmarks; extremities of each shape
// (local maxima of the geodesic distance to the current landmarks, on that shape alone) are
// matched through the map (nearest extremity of B to the image of an extremity of A, mutual
// through the map B -> A, unambiguous), the matched pairs appended to the landmarks, and the
// map recomputed. Measured against the ground truth (vertex i of A <-> vertex i of B).
//   augment_prototype A.off LA B.off LB [ROWS] [--iterations N] [--rounds R] [--match harmonic|refined]
//                     [--frac F] [--radius RHO] [--tau T] [--ratio Q] [--drop ROW]
// --frac: an extremity's distance to the landmarks is at least F times the largest (0.2);
// --radius: it is the largest within RHO times that largest distance (0.1);
// --tau: a match is within T diagonals (0.05), mutually; --ratio: the second candidate is at least
// Q times farther (1.5); --drop ROW (leave-one-out, meshes without a vertex truth): the user
// landmark of that row of ROWS is dropped, and the added pair nearest to it is reported.
// --mode map|desc|both: match through the map (nearest extremity to f(a), mutual through B -> A),
// by the intrinsic descriptor (geodesic distances to the user landmarks over sqrt(area); mutual
// nearest, ratio test, relative difference below --tau-desc; the map is not used), or both;
// --tip T: keep only extremities whose geodesic ball (radius --radius times the largest distance)
// has an area below T times pi r^2 (thin protrusions); --top N, --gate G, --by-disagreement.
// Measured best on the wolves (session of 5 Dec 2026, T chosen on these wolves):
//   --radius 0.25 --mode desc --tau-desc 0.1 --tip 0.65 (one round)
// On meshes without a vertex truth (different vertex counts) the error figures are meaningless.
#include "../bench_common.h"

#include <CGAL/Polygon_mesh_processing/measure.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <limits>
#include <queue>
#include <string>
#include <vector>

typedef K::Point_2 Point_2;
typedef K::Point_3 Point_3;
typedef SM::Property_map<SM_halfedge, Point_2> UV;
typedef HOT::Embedding_locator<SM, UV> Locator;

static bool truth = true; // vertex i of A <-> vertex i of B

// geodesic (edge graph) distances from the sources, up to `limit`
static std::vector<double> dijkstra(const SM& m, const std::vector<SM_vertex>& sources,
                                    double limit = std::numeric_limits<double>::infinity())
{
  std::vector<double> d(num_vertices(m), std::numeric_limits<double>::infinity());
  typedef std::pair<double, std::size_t> QE;
  std::priority_queue<QE, std::vector<QE>, std::greater<QE> > q;
  for(SM_vertex s : sources) { d[s.idx()] = 0; q.push(QE(0, s.idx())); }
  while(!q.empty()) {
    const QE e = q.top();
    q.pop();
    if(e.first > d[e.second] || e.first > limit) continue;
    const SM_vertex v(static_cast<SM::size_type>(e.second));
    for(SM_vertex w : vertices_around_target(halfedge(v, m), m)) {
      const double nd = e.first + std::sqrt(CGAL::squared_distance(m.point(v), m.point(w)));
      if(nd < d[w.idx()] && nd <= limit) { d[w.idx()] = nd; q.push(QE(nd, w.idx())); }
    }
  }
  return d;
}

struct Params { double frac = 0.2, radius = 0.1, tau = 0.05, ratio = 1.5, tau_desc = 0.05, gate = 0; int mode = 0; std::size_t top = 1000; double tip = 1e9; bool by_disagreement = false; }; // mode 0 map, 1 descriptor, 2 both

// the intrinsic descriptor of every vertex: its geodesic distances to the landmarks, over sqrt(area)
static std::vector<std::vector<double> > descriptors(const SM& m, const std::vector<SM_vertex>& landmarks)
{
  const double s = std::sqrt(CGAL::Polygon_mesh_processing::area(m));
  std::vector<std::vector<double> > out(num_vertices(m), std::vector<double>(landmarks.size()));
  for(std::size_t j = 0; j < landmarks.size(); ++j) {
    const std::vector<double> d = dijkstra(m, std::vector<SM_vertex>(1, landmarks[j]));
    for(std::size_t i = 0; i < d.size(); ++i) out[i][j] = d[i] / s;
  }
  return out;
}

// relative difference of two descriptors
static double desc_diff(const std::vector<double>& x, const std::vector<double>& y)
{
  double n = 0, d = 0;
  for(std::size_t j = 0; j < x.size(); ++j) { n += x[j] * x[j] + y[j] * y[j]; d += (x[j] - y[j]) * (x[j] - y[j]); }
  return std::sqrt(2 * d / n);
}

// extremities of m: vertices whose geodesic distance to the landmarks is the largest within a
// geodesic ball of radius `radius` times the largest distance, and at least `frac` times it
// tipness: the area of the extremity's geodesic ball of that radius over the flat disk's pi r^2
// (a tip of a thin protrusion: small; a maximum on a flat region: about 1); those above P.tip dropped
static std::vector<SM_vertex> extremities(const SM& m, const std::vector<SM_vertex>& landmarks, const Params& P,
                                          std::vector<double>& tipness)
{
  tipness.assign(num_vertices(m), -1);
  std::vector<double> varea(num_vertices(m), 0);
  for(SM_face f : faces(m)) {
    const double a = CGAL::Polygon_mesh_processing::face_area(f, m) / 3;
    for(SM_vertex v : vertices_around_face(halfedge(f, m), m)) varea[v.idx()] += a;
  }
  const std::vector<double> d = dijkstra(m, landmarks);
  double dmax = 0;
  for(double x : d) if(std::isfinite(x)) dmax = (std::max)(dmax, x);
  std::vector<std::pair<double, SM_vertex> > cand;
  for(SM_vertex v : vertices(m)) {
    if(d[v.idx()] < P.frac * dmax) continue;
    bool top = true;
    for(SM_vertex w : vertices_around_target(halfedge(v, m), m)) if(d[w.idx()] > d[v.idx()]) { top = false; break; }
    if(top) cand.push_back(std::make_pair(-d[v.idx()], v));
  }
  std::sort(cand.begin(), cand.end());
  std::vector<SM_vertex> out;
  std::vector<char> suppressed(num_vertices(m), 0);
  for(const auto& c : cand) {
    if(suppressed[c.second.idx()]) continue;
    const double r = P.radius * dmax;
    const std::vector<double> ball = dijkstra(m, std::vector<SM_vertex>(1, c.second), r);
    double area = 0;
    for(std::size_t i = 0; i < ball.size(); ++i) if(std::isfinite(ball[i])) { suppressed[i] = 1; area += varea[i]; }
    tipness[c.second.idx()] = area / (CGAL_PI * r * r);
    if(tipness[c.second.idx()] <= P.tip) out.push_back(c.second);
  }
  return out;
}

struct Figures { double mean = 0, worst = 0; HOT::Map_distortion d; };

static Figures measure(const SM& A, const std::vector<Point_3>& img, const SM& B, const Locator& L,
                       const std::vector<Locator::Location>& locs)
{
  Figures r;
  const double diag = diagonal(B);
  for(SM_vertex v : vertices(A)) {
    const double e = std::sqrt(CGAL::squared_distance(img[v.idx()], B.point(v))) / diag;
    r.mean += e / num_vertices(A);
    r.worst = (std::max)(r.worst, e);
  }
  r.d = HOT::map_distortion(A, B, L, locs);
  return r;
}

struct Run
{
  bool ok = false, certified = false;
  Figures harmonic, refined;
  std::vector<Point_3> f_harm, f_ref; // images of A's vertices on B
  std::vector<Point_3> g_harm, g_ref; // images of B's vertices on A
  double seconds = 0;
  int iterations = 0;
  std::string message;
};

static Run run(SM& A, const std::vector<SM_vertex>& lma, SM& B, const std::vector<SM_vertex>& lmb, int iterations)
{
  Run R;
  const auto t0 = Clock::now();
  UV uvA = A.add_property_map<SM_halfedge, Point_2>("h:uv", Point_2(0, 0)).first;
  UV uvB = B.add_property_map<SM_halfedge, Point_2>("h:uv", Point_2(0, 0)).first;
  HOT::Embedding_statistics sa, sb;
  if(HOT::hyperbolic_orbifold_Tutte_embedding(A, lma, uvA, HOT::parameters::embedding_statistics(&sa, HOT::parameters::landmark_order(HOT::Tsp_order))) != HOT::OK) {
    R.message = "A refused: " + sa.message;
    return R;
  }
  std::vector<SM_vertex> lma_o, lmb_o;
  for(std::size_t i : sa.landmark_order) { lma_o.push_back(lma[i]); lmb_o.push_back(lmb[i]); }
  if(HOT::hyperbolic_orbifold_Tutte_embedding(B, lmb_o, uvB, HOT::parameters::embedding_statistics(&sb)) != HOT::OK) {
    R.message = "B refused: " + sb.message;
    return R;
  }
  if(sa.recentred || sb.recentred || sa.charted_faces || sb.charted_faces)
    std::printf("    (note: recentred %d/%d, charted faces %zu/%zu)\n", sa.recentred, sb.recentred, sa.charted_faces, sb.charted_faces);
  const HOT::Orbifold_type type = CGAL::is_closed(B) ? HOT::Sphere_type : HOT::Disk_type;
  const int k = static_cast<int>(lma.size());
  const auto images = [&](const SM& X, UV uvX, const SM& Y, const Locator& LY, std::vector<Locator::Location>* keep) {
    const auto locs = HOT::map_vertices(X, uvX, LY);
    std::vector<Point_3> out;
    for(SM_vertex v : vertices(X)) out.push_back(HOT::surface_point(locs[v.idx()], LY, get(CGAL::vertex_point, Y)));
    if(keep) *keep = locs;
    return out;
  };
  {
    const Locator LB(B, uvB, type, k, HOT::Hyperboloid_linear);
    const Locator LA(A, uvA, type, k, HOT::Hyperboloid_linear);
    std::vector<Locator::Location> locs;
    R.f_harm = images(A, uvA, B, LB, &locs);
    R.harmonic = measure(A, R.f_harm, B, LB, locs);
    R.g_harm = images(B, uvB, A, LA, nullptr);
  }
  const Locator LB(B, uvB, type, k, HOT::Hyperboloid_linear);
  HOT::Map_refinement_statistics rs;
  if(HOT::refine_orbifold_map(A, lma_o, uvA, B, LB, rs,
                              HOT::parameters::refine(iterations, HOT::parameters::frame(sa.frame, HOT::parameters::orbifold_type(type)))) != HOT::OK) {
    R.message = "refinement refused: " + rs.message;
    return R;
  }
  R.iterations = rs.iterations;
  HOT::Embedding_certificate cert;
  std::string why;
  R.certified = HOT::certify_hyperbolic_orbifold_embedding(A, lma_o, uvA, cert, &why,
                                                           HOT::parameters::frame(sa.frame, HOT::parameters::orbifold_type(type))) == HOT::OK &&
                cert.is_bijective();
  if(!R.certified) R.message = "certificate: " + why;
  {
    std::vector<Locator::Location> locs;
    R.f_ref = images(A, uvA, B, LB, &locs);
    R.refined = measure(A, R.f_ref, B, LB, locs);
    const Locator LA(A, uvA, type, k, HOT::Hyperboloid_linear); // the refined embedding of A
    R.g_ref = images(B, uvB, A, LA, nullptr);
  }
  R.seconds = seconds_since(t0);
  R.ok = true;
  A.remove_property_map(uvA);
  B.remove_property_map(uvB);
  return R;
}

static double dist(const Point_3& p, const Point_3& q) { return std::sqrt(CGAL::squared_distance(p, q)); }

// extremity pairs matched through the map f: A -> B (images fA of A's vertices) and g: B -> A
static std::vector<std::pair<SM_vertex, SM_vertex> > match(const SM& A, const std::vector<SM_vertex>& lma, const std::vector<Point_3>& fA,
                                                          const SM& B, const std::vector<SM_vertex>& lmb, const std::vector<Point_3>& gB,
                                                          const Params& P)
{
  std::vector<double> tipA, tipB;
  const std::vector<SM_vertex> xa = extremities(A, lma, P, tipA), xb = extremities(B, lmb, P, tipB);
  const double diagA = diagonal(A), diagB = diagonal(B);
  std::printf("    extremities: %zu on A, %zu on B\n", xa.size(), xb.size());
  // the nearest and second nearest of `xs` on `M` to the point p
  const auto nearest = [](const SM& M, const std::vector<SM_vertex>& xs, const Point_3& p, double& d1, double& d2) {
    SM_vertex best;
    d1 = d2 = std::numeric_limits<double>::infinity();
    for(SM_vertex x : xs) {
      const double d = dist(M.point(x), p);
      if(d < d1) { d2 = d1; d1 = d; best = x; }
      else if(d < d2) d2 = d;
    }
    return best;
  };
  const auto DA = descriptors(A, lma), DB = descriptors(B, lmb);
  // descriptor-nearest and second nearest of `xs` to the descriptor x
  const auto dnearest = [](const std::vector<std::vector<double> >& D, const std::vector<SM_vertex>& xs, const std::vector<double>& x,
                           double& d1, double& d2) {
    SM_vertex best;
    d1 = d2 = std::numeric_limits<double>::infinity();
    for(SM_vertex v : xs) {
      const double d = desc_diff(D[v.idx()], x);
      if(d < d1) { d2 = d1; d1 = d; best = v; }
      else if(d < d2) d2 = d;
    }
    return best;
  };
  std::vector<std::pair<SM_vertex, SM_vertex> > out;
  const std::vector<double> dA = dijkstra(A, lma);
  const double dAmax = *std::max_element(dA.begin(), dA.end());
  for(SM_vertex a : xa) {
    if(xb.empty()) break;
    double d1, d2, e1, e2;
    SM_vertex b;
    std::string verdict = "accepted";
    if(P.mode == 1) {
      b = dnearest(DB, xb, DA[a.idx()], d1, d2);
      if(d1 > P.tau_desc) verdict = "desc too far";
      else if(d2 < P.ratio * d1) verdict = "desc ambiguous";
      else {
        const SM_vertex a2 = dnearest(DA, xa, DB[b.idx()], e1, e2);
        if(a2 != a) verdict = "desc not mutual";
        else if(e2 < P.ratio * e1) verdict = "desc ambig back";
      }
    } else {
      b = nearest(B, xb, fA[a.idx()], d1, d2);
      if(d1 > P.tau * diagB) verdict = "too far";
      else if(d2 < P.ratio * d1) verdict = "ambiguous";
      else {
        const SM_vertex a2 = nearest(A, xa, gB[b.idx()], e1, e2);
        if(a2 != a || e1 > P.tau * diagA) verdict = "not mutual";
        else if(e2 < P.ratio * e1) verdict = "ambiguous back";
      }
      if(P.mode == 2 && verdict == "accepted" && desc_diff(DA[a.idx()], DB[b.idx()]) > P.tau_desc) verdict = "desc differs";
    }
    if(verdict == "accepted" && dist(fA[a.idx()], B.point(b)) < P.gate * diagB) verdict = "map agrees";
    for(const auto& pr : out) if(pr.second == b) verdict = "b taken";
    std::printf("    a %5zu (d %.2f tip %.2f/%.2f) -> b %5zu  |f(a)-b| %5.2f%%  desc diff %.3f  %-16s", std::size_t(a.idx()), dA[a.idx()] / dAmax, tipA[a.idx()], tipB[b.idx()], std::size_t(b.idx()),
                100 * dist(fA[a.idx()], B.point(b)) / diagB, desc_diff(DA[a.idx()], DB[b.idx()]), verdict.c_str());
    if(truth) std::printf(" true-image error of b %.2f%%", 100 * dist(B.point(b), B.point(SM_vertex(a.idx()))) / diagB);
    std::printf("\n");
    if(verdict == "accepted") out.push_back(std::make_pair(a, b));
    if(!P.by_disagreement && out.size() >= P.top) break; // the extremities come farthest first
  }
  if(P.by_disagreement) { // the pairs where the current map is the farthest from the match first
    std::stable_sort(out.begin(), out.end(), [&](const std::pair<SM_vertex, SM_vertex>& x, const std::pair<SM_vertex, SM_vertex>& y) {
      return dist(fA[x.first.idx()], B.point(x.second)) > dist(fA[y.first.idx()], B.point(y.second));
    });
    if(out.size() > P.top) out.resize(P.top);
  }
  return out;
}

int main(int argc, char** argv)
{
  std::vector<std::string> args;
  int iterations = 100, rounds = 1, drop = -1;
  bool match_refined = false;
  Params P;
  for(int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if(a == "--iterations" && i + 1 < argc) iterations = std::atoi(argv[++i]);
    else if(a == "--rounds" && i + 1 < argc) rounds = std::atoi(argv[++i]);
    else if(a == "--match" && i + 1 < argc) match_refined = std::string(argv[++i]) == "refined";
    else if(a == "--mode" && i + 1 < argc) { const std::string m = argv[++i]; P.mode = m == "desc" ? 1 : m == "both" ? 2 : 0; }
    else if(a == "--tau-desc" && i + 1 < argc) P.tau_desc = std::atof(argv[++i]);
    else if(a == "--gate" && i + 1 < argc) P.gate = std::atof(argv[++i]);
    else if(a == "--top" && i + 1 < argc) P.top = std::atoi(argv[++i]);
    else if(a == "--tip" && i + 1 < argc) P.tip = std::atof(argv[++i]);
    else if(a == "--by-disagreement") P.by_disagreement = true;
    else if(a == "--frac" && i + 1 < argc) P.frac = std::atof(argv[++i]);
    else if(a == "--radius" && i + 1 < argc) P.radius = std::atof(argv[++i]);
    else if(a == "--tau" && i + 1 < argc) P.tau = std::atof(argv[++i]);
    else if(a == "--ratio" && i + 1 < argc) P.ratio = std::atof(argv[++i]);
    else if(a == "--drop" && i + 1 < argc) drop = std::atoi(argv[++i]);
    else args.push_back(a);
  }
  SM A, B;
  if(args.size() < 4 || !CGAL::IO::read_polygon_mesh(args[0], A) || !CGAL::IO::read_polygon_mesh(args[2], B)) {
    std::printf("usage: augment_prototype A.off LA B.off LB [ROWS] [options]\n");
    return 1;
  }
  truth = num_vertices(A) == num_vertices(B);
  std::vector<std::size_t> la = read_indices(args[1]), lb = read_indices(args[3]);
  std::vector<std::size_t> rows;
  if(args.size() > 4) rows = read_indices(args[4]);
  else for(std::size_t r = 0; r < la.size(); ++r) rows.push_back(r);
  std::vector<SM_vertex> lma, lmb;
  SM_vertex dropped_a, dropped_b;
  for(std::size_t j = 0; j < rows.size(); ++j) {
    const SM_vertex va(static_cast<SM::size_type>(la.at(rows[j]))), vb(static_cast<SM::size_type>(lb.at(rows[j])));
    if(static_cast<int>(j) == drop) { dropped_a = va; dropped_b = vb; continue; }
    lma.push_back(va);
    lmb.push_back(vb);
  }
  std::printf("%s -> %s, %zu landmarks, match through the %s map, rounds %d, frac %.2f radius %.2f tau %.3f ratio %.2f mode %d tau_desc %.3f gate %.3f top %zu tip %.2f\n", args[0].c_str(),
              args[2].c_str(), lma.size(), match_refined ? "refined" : "harmonic", rounds, P.frac, P.radius, P.tau, P.ratio, P.mode, P.tau_desc, P.gate, P.top, P.tip);
  const auto report = [&](const char* what, const Run& R, std::size_t added, std::size_t correct) {
    if(!R.ok) { std::printf("  %s: FAILED %s\n", what, R.message.c_str()); return; }
    std::printf("  RESULT %-10s landmarks %2zu added %zu correct %zu | harmonic %.3f/%.2f | refined %.3f/%.2f | SD %.4f -> %.4f | certified %s | %.1f s\n",
                what, lma.size() + added, added, correct, 100 * R.harmonic.mean, 100 * R.harmonic.worst, 100 * R.refined.mean,
                100 * R.refined.worst, R.harmonic.d.symmetric_dirichlet_energy, R.refined.d.symmetric_dirichlet_energy,
                R.certified ? "yes" : R.message.c_str(), R.seconds);
  };
  Run R = run(A, lma, B, lmb, iterations);
  report("baseline", R, 0, 0);
  if(!R.ok) return 1;
  std::vector<SM_vertex> la2 = lma, lb2 = lmb;
  std::size_t correct = 0;
  const double diagB = diagonal(B);
  for(int round = 1; round <= rounds; ++round) {
    std::printf("  round %d\n", round);
    const auto pairs = match(A, la2, match_refined ? R.f_ref : R.f_harm, B, lb2, match_refined ? R.g_ref : R.g_harm, P);
    if(pairs.empty()) { std::printf("    nothing added\n"); break; }
    for(const auto& pr : pairs) {
      la2.push_back(pr.first);
      lb2.push_back(pr.second);
      if(truth && dist(B.point(pr.second), B.point(SM_vertex(pr.first.idx()))) < 0.01 * diagB) ++correct;
      if(drop >= 0)
        std::printf("    added (%zu, %zu): distance to the dropped landmark on A %.2f%%, of b to its partner on B %.2f%%\n",
                    std::size_t(pr.first.idx()), std::size_t(pr.second.idx()), 100 * dist(A.point(pr.first), A.point(dropped_a)) / diagonal(A),
                    100 * dist(B.point(pr.second), B.point(dropped_b)) / diagB);
    }
    R = run(A, la2, B, lb2, iterations);
    char name[32];
    std::snprintf(name, sizeof(name), "round%d", round);
    report(name, R, la2.size() - lma.size(), correct);
    if(!R.ok) return 1;
  }
  return 0;
}
