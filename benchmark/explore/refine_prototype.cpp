// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// EXPLORATION for issue 39 (maps with low distortion), not a product: the three refinement
// designs measured on TOSCA pose pairs (vertex i <-> vertex i), error against the identity in
// % of the diagonal, per iteration. Built only with -DHOT_BUILD_EXPLORATION=ON.
//   refine_prototype A.off LA B.off LB [ROWS] [--iterations N] [mode and its settings]
// LA, LB: landmark files (landmark j of LA corresponds to landmark j of LB); ROWS: optional
// file of 0-based rows of LA/LB to use. Modes:
//   (default)  re-weighted Tutte by conductivity: every face of A gets a log-conductivity
//              tensor, moved by --alpha times log(sqrt(J^T J)) of the current map (--aniso
//              scales its anisotropic part, --passes N smooths an isotropic version on the
//              vertices, --smooth S a one-ring average), edge weights from the anisotropic
//              P1 stiffness (negatives clamped), A re-embedded by the orbifold Tutte solver.
//              Measured: improves for 1-3 iterations, then oscillates; conformal p99 grows.
//   --arap     target by one ARAP global step on B's tangent planes, turned into weights as
//              the cotangents of the target triangles in B's disk: fails (about 20% of the
//              weights negative even with no move; the re-embedding is worse).
//   --surface-arap N  the map itself refined on B's surface: N local-global ARAP steps
//              (rotations per face of A, a sparse 2n x 2n global step in B's tangent planes,
//              landmarks fixed, images projected back onto B by an AABB tree), no embedding:
//              the error that a certified version of it could reach (--damping, --step).
#include "../bench_common.h"

#include <CGAL/Polygon_mesh_processing/bbox.h>

#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>

#include <algorithm>
#include <complex>
#include <map>
#include <sstream>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

typedef K::Point_2 Point_2;
typedef SM::Property_map<SM_halfedge, Point_2> UV;
typedef HOT::Embedding_locator<SM, UV> Locator;

int main(int argc, char** argv)
{
  std::vector<std::string> args;
  int iterations = 8;
  double alpha = 1.0, smooth = 0, aniso = 1, damping = 0, step = 1;
  bool arap = false;
  int passes = 0, surface_arap = 0;
  std::string anchors_file;
  int certify_every = 0, walk_depth = 12;
  double anchor_weight = 1;
  for(int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if(a == "--iterations") iterations = std::atoi(argv[++i]);
    else if(a == "--alpha") alpha = std::atof(argv[++i]);
    else if(a == "--smooth") smooth = std::atof(argv[++i]);
    else if(a == "--aniso") aniso = std::atof(argv[++i]);
    else if(a == "--arap") arap = true;
    else if(a == "--surface-arap") surface_arap = std::atoi(argv[++i]);
    else if(a == "--anchors") anchors_file = argv[++i];
    else if(a == "--certify-every") certify_every = std::atoi(argv[++i]);
    else if(a == "--walk-depth") walk_depth = std::atoi(argv[++i]);
    else if(a == "--anchor-weight") anchor_weight = std::atof(argv[++i]);
    else if(a == "--passes") passes = std::atoi(argv[++i]);
    else if(a == "--damping") damping = std::atof(argv[++i]);
    else if(a == "--step") step = std::atof(argv[++i]);
    else args.push_back(a);
  }
  SM A, B;
  if(args.size() < 4 || !CGAL::IO::read_polygon_mesh(args[0], A) || !CGAL::IO::read_polygon_mesh(args[2], B)) {
    std::printf("usage: bench_refine A.off LA B.off LB [ROWS]\n");
    return 1;
  }
  std::vector<std::size_t> la = read_indices(args[1]), lb = read_indices(args[3]);
  if(args.size() > 4) {
    const std::vector<std::size_t> rows = read_indices(args[4]);
    std::vector<std::size_t> a2, b2;
    for(std::size_t r : rows) { a2.push_back(la[r]); b2.push_back(lb[r]); }
    la = a2; lb = b2;
  }
  std::vector<SM_vertex> lma, lmb;
  for(std::size_t i = 0; i < la.size(); ++i) {
    lma.push_back(SM_vertex(static_cast<SM::size_type>(la[i])));
    lmb.push_back(SM_vertex(static_cast<SM::size_type>(lb[i])));
  }
  UV uvA = A.add_property_map<SM_halfedge, Point_2>("h:uv", Point_2(2, 2)).first;
  UV uvB = B.add_property_map<SM_halfedge, Point_2>("h:uv", Point_2(2, 2)).first;
  HOT::Embedding_statistics sa, sb;
  const auto t0 = Clock::now();
  if(HOT::hyperbolic_orbifold_Tutte_embedding(A, lma, uvA, HOT::parameters::embedding_statistics(&sa, HOT::parameters::landmark_order(HOT::Tsp_order))) != HOT::OK) {
    std::printf("A refused: %s\n", sa.message.c_str());
    return 1;
  }
  std::vector<SM_vertex> lma_o, lmb_o;
  for(std::size_t i : sa.landmark_order) { lma_o.push_back(lma[i]); lmb_o.push_back(lmb[i]); }
  if(HOT::hyperbolic_orbifold_Tutte_embedding(B, lmb_o, uvB, HOT::parameters::embedding_statistics(&sb)) != HOT::OK) {
    std::printf("B refused: %s\n", sb.message.c_str());
    return 1;
  }
  const double t_embed = seconds_since(t0);
  {
    std::vector<K::Point_3> truth;
    for(SM_vertex v : vertices(B)) truth.push_back(B.point(v));
    HOT::Map_distortion d = HOT::map_distortion(A, truth);
    std::printf("truth: conformal p50 %.3f p90 %.3f p99 %.3f, area p99 %.3f\n", d.conformal_summary.p50, d.conformal_summary.p90, d.conformal_summary.p99, d.area_summary.p99);
  }
  const HOT::Orbifold_type type = CGAL::is_closed(B) ? HOT::Sphere_type : HOT::Disk_type;
  const Locator L(B, uvB, type, static_cast<int>(la.size()), HOT::Hyperboloid_linear);
  const double diag = diagonal(B);
  const std::size_t nf = num_faces(A), n = num_vertices(A);
  // per face: A's frame (x1 = (l, 0), x2), the log-conductivity (symmetric 2x2)
  std::vector<Eigen::Matrix2d> X(nf), Llog(nf, Eigen::Matrix2d::Zero());
  std::vector<std::array<SM_vertex, 3> > fv(nf);
  for(SM_face f : faces(A)) {
    int k = 0;
    for(SM_vertex v : vertices_around_face(halfedge(f, A), A)) fv[f.idx()][k++] = v;
    const K::Vector_3 a = A.point(fv[f.idx()][1]) - A.point(fv[f.idx()][0]), b = A.point(fv[f.idx()][2]) - A.point(fv[f.idx()][0]);
    const double la2 = std::sqrt(a.squared_length());
    const double bx = (a * b) / la2;
    const double by = std::sqrt(std::max(0.0, b.squared_length() - bx * bx));
    X[f.idx()] << la2, bx, 0, by;
  }
  SM_edge dummy;
  (void)dummy;
  std::vector<double> w(num_edges(A), 1.0);
  // the tangent basis of B's face `b` (in the locator's face order)
  const auto tangent_basis = [&](std::size_t b) {
    Eigen::Vector3d P[3];
    for(int k = 0; k < 3; ++k) { const K::Point_3 p = B.point(L.vertex(L.corner_vertex_index(b, k))); P[k] = Eigen::Vector3d(p.x(), p.y(), p.z()); }
    const Eigen::Vector3d t1 = (P[1] - P[0]).normalized(), nrm = (P[1] - P[0]).cross(P[2] - P[0]).normalized();
    Eigen::Matrix<double, 3, 2> T;
    T.col(0) = t1;
    T.col(1) = nrm.cross(t1);
    return T;
  };
  // one ARAP global step of the images q (moves in the tangent planes T, `fixed` vertices kept,
  // rotations scaled by `scale`, soft anchors of weight `anchor_w`): the 2n moves
  const auto arap_step = [&](const std::vector<Eigen::Vector3d>& q, const std::vector<Eigen::Matrix<double, 3, 2> >& T,
                             const std::vector<char>& fixed, double scale,
                             const std::vector<std::pair<std::size_t, Eigen::Vector3d> >& anchors, double anchor_w) {
    typedef Eigen::Triplet<double> Tr;
    std::vector<Tr> trip;
    Eigen::VectorXd rhs = Eigen::VectorXd::Zero(2 * n);
    for(SM_face f : faces(A)) {
      const auto& c = fv[f.idx()];
      const Eigen::Matrix2d XiT = X[f.idx()].inverse().transpose();
      Eigen::Vector2d g[3];
      g[1] = XiT.col(0); g[2] = XiT.col(1); g[0] = -(g[1] + g[2]);
      const double a = 0.5 * X[f.idx()].determinant();
      Eigen::Matrix<double, 3, 2> J = Eigen::Matrix<double, 3, 2>::Zero();
      for(int j = 0; j < 3; ++j) J += q[c[j].idx()] * g[j].transpose();
      Eigen::JacobiSVD<Eigen::Matrix<double, 3, 2> > svd(J, Eigen::ComputeFullU | Eigen::ComputeFullV);
      const Eigen::Matrix<double, 3, 2> R = scale * svd.matrixU().leftCols<2>() * svd.matrixV().transpose();
      const Eigen::Matrix<double, 3, 2> r = R - J;
      for(int i = 0; i < 3; ++i) {
        const std::size_t vi = c[i].idx();
        if(fixed[vi]) continue;
        rhs.segment<2>(2 * vi) += a * T[vi].transpose() * r * g[i];
        for(int j = 0; j < 3; ++j) {
          const std::size_t vj = c[j].idx();
          if(fixed[vj]) continue;
          const Eigen::Matrix2d Hb = a * g[i].dot(g[j]) * T[vi].transpose() * T[vj];
          for(int r0 = 0; r0 < 2; ++r0) for(int c0 = 0; c0 < 2; ++c0) trip.emplace_back(2 * vi + r0, 2 * vj + c0, Hb(r0, c0));
        }
        if(damping > 0) { trip.emplace_back(2 * vi, 2 * vi, damping * a); trip.emplace_back(2 * vi + 1, 2 * vi + 1, damping * a); }
      }
    }
    for(std::size_t i = 0; i < n; ++i) if(fixed[i]) { trip.emplace_back(2 * i, 2 * i, 1.0); trip.emplace_back(2 * i + 1, 2 * i + 1, 1.0); }
    for(const auto& an : anchors) { // ("vertex face x y z" lines of --anchors)
      const std::size_t v = an.first;
      if(fixed[v]) continue;
      for(int r0 = 0; r0 < 2; ++r0) trip.emplace_back(2 * v + r0, 2 * v + r0, anchor_w);
      rhs.segment<2>(2 * v) += anchor_w * T[v].transpose() * (an.second - q[v]);
    }
    Eigen::SparseMatrix<double> H(2 * n, 2 * n);
    H.setFromTriplets(trip.begin(), trip.end());
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double> > ldlt(H);
    return Eigen::VectorXd(ldlt.solve(rhs));
  };
  for(int it = 0; it <= iterations; ++it) {
    const auto ti = Clock::now();
    const auto locs = HOT::map_vertices(A, uvA, L);
    std::vector<K::Point_3> img(n);
    const auto vpm = get(CGAL::vertex_point, B);
    double sum = 0, worst = 0;
    for(std::size_t i = 0; i < n; ++i) {
      img[i] = locs[i].success ? HOT::surface_point(locs[i], L, vpm) : K::Point_3(NAN, NAN, NAN);
      const double e = std::sqrt(CGAL::squared_distance(img[i], B.point(SM_vertex(static_cast<SM::size_type>(i))))) / diag;
      sum += e;
      worst = std::max(worst, e);
    }
    HOT::Map_distortion d = HOT::map_distortion(A, img);
    std::printf("it %d: mean %.3f%% worst %.2f%%  conformal p50 %.3f p90 %.3f p99 %.3f  area p99 %.3f  (%.2f s)\n", it, 100 * sum / n, 100 * worst,
                d.conformal_summary.p50, d.conformal_summary.p90, d.conformal_summary.p99, d.area_summary.p99, seconds_since(ti));
    std::fflush(stdout);
    if(it == iterations) break;
    if(surface_arap > 0) {
      typedef CGAL::AABB_face_graph_triangle_primitive<SM> Prim;
      typedef CGAL::AABB_tree<CGAL::AABB_traits<K, Prim> > Tree;
      Tree tree(faces(B).first, faces(B).second, B);
      tree.accelerate_distance_queries();
      std::vector<Eigen::Vector3d> q(n);
      std::vector<SM_face> qf(n);
      for(std::size_t i = 0; i < n; ++i) { q[i] = Eigen::Vector3d(img[i].x(), img[i].y(), img[i].z()); qf[i] = locs[i].face; }
      std::vector<char> fixed(n, 0);
      for(SM_vertex v : lma) fixed[v.idx()] = 1;
      const double scale = std::sqrt(d.image_area / d.source_area);
      // Certification of images on B (vertex i of A at q[i] on face qf[i] of B): A's corners in
      // the disk, each from its old corner's location (the element g with g(z) in that face)
      // and a walk over B's faces to the new face, composing the seam pairings met (the
      // isometry taking an edge's two corners in one face's frame to the other's), then the
      // exact certificate; on failure, every corner is moved a fraction alpha of the way along
      // its geodesic, alpha halved until certified.
      typedef HOT::Hyperbolic_isometry_2<double> Iso;
      typedef std::complex<double> Cx;
      const auto cx = [](const Point_2& p) { return Cx(p.x(), p.y()); };
      const auto seam = [&](std::size_t f, std::size_t g, std::size_t u, std::size_t v) { // frame of f -> frame of g
        Cx pf[2], pg[2];
        for(int k = 0; k < 3; ++k) {
          const std::size_t a = L.corner_vertex_index(f, k), b = L.corner_vertex_index(g, k);
          if(a == u) pf[0] = cx(L.corner_point(f, k));
          if(a == v) pf[1] = cx(L.corner_point(f, k));
          if(b == u) pg[0] = cx(L.corner_point(g, k));
          if(b == v) pg[1] = cx(L.corner_point(g, k));
        }
        if(pf[0] == pg[0] && pf[1] == pg[1]) return Iso();
        const Iso tf = Iso::translation_to_origin(pf[0]), tg = Iso::translation_to_origin(pg[0]);
        const double theta = std::arg(tg.apply(pg[1])) - std::arg(tf.apply(pf[1]));
        return Iso::translation_from_origin(pg[0]) * Iso::rotation(theta) * tf;
      };
      const auto certify_images = [&](const std::vector<Eigen::Vector3d>& qq, const std::vector<SM_face>& qqf, int label) {
        auto uvN = A.add_property_map<SM_halfedge, Point_2>("h:uv_refined", Point_2(0, 0)).first;
        std::size_t lost = 0;
        for(SM_halfedge h : halfedges(A)) {
          if(is_border(h, A)) continue;
          const std::size_t i = target(h, A).idx();
          const auto l = L.locate(uvA[h]);
          if(!l.success) { ++lost; continue; }
          const std::size_t goal = qqf[i].idx();
          // BFS from l.face_index to goal
          std::map<std::size_t, Iso> S{{l.face_index, Iso()}};
          std::vector<std::size_t> frontier{l.face_index};
          for(int depth = 0; depth < walk_depth && !S.count(goal); ++depth) {
            std::vector<std::size_t> next_frontier;
            for(std::size_t f : frontier)
              for(SM_halfedge e : halfedges_around_face(halfedge(SM_face(static_cast<SM::size_type>(f)), B), B)) {
                const SM_face g = face(opposite(e, B), B);
                if(g == SM_face() || S.count(g.idx())) continue;
                S[g.idx()] = seam(f, g.idx(), source(e, B).idx(), target(e, B).idx()) * S[f];
                next_frontier.push_back(g.idx());
              }
            frontier.swap(next_frontier);
          }
          if(!S.count(goal)) { ++lost; continue; }
          // barycentric coordinates of qq[i] in the goal face, corners in the locator's order
          Eigen::Vector3d P[3];
          for(int k = 0; k < 3; ++k) { const K::Point_3 pp = B.point(L.vertex(L.corner_vertex_index(goal, k))); P[k] = Eigen::Vector3d(pp.x(), pp.y(), pp.z()); }
          Eigen::Matrix<double, 3, 2> E; E.col(0) = P[1] - P[0]; E.col(1) = P[2] - P[0];
          const Eigen::Vector2d st = (E.transpose() * E).ldlt().solve(E.transpose() * (qq[i] - P[0]));
          std::array<double, 3> bc{{1 - st[0] - st[1], st[0], st[1]}};
          double sum = 0;
          for(double& x : bc) { x = std::max(x, 0.0); sum += x; }
          for(double& x : bc) x /= sum;
          const Point_2 z = L.disk_point(goal, bc);
          const Iso g = S[goal] * l.element;
          const Cx w = g.inverse().apply(cx(z));
          uvN[h] = Point_2(w.real(), w.imag());
        }
        // local backtracking first: the corners of the vertices of faces oriented clockwise in
        // the disk (double) go back to their old place, and their neighbours' too, repeatedly
        {
          const auto orient = [&](SM_face f) {
            Cx z[3]; int k = 0;
            for(SM_halfedge h : halfedges_around_face(halfedge(f, A), A)) z[k++] = cx(uvN[h]);
            // det rows (2x, 2y, 1 + |z|^2)
            const auto row = [](const Cx& w) { return std::array<double, 3>{{2 * w.real(), 2 * w.imag(), 1 + std::norm(w)}}; };
            const auto a = row(z[0]), b = row(z[1]), c = row(z[2]);
            return a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) + a[2] * (b[0] * c[1] - b[1] * c[0]);
          };
          std::vector<char> reverted(n, 0);
          for(int round = 0; round < 50; ++round) {
            std::vector<SM_vertex> bad;
            for(SM_face f : faces(A)) if(!(orient(f) > 0)) for(SM_vertex v : vertices_around_face(halfedge(f, A), A)) bad.push_back(v);
            if(bad.empty()) { std::printf("   local backtracking: %d rounds, %zu vertices reverted\n", round, (std::size_t)std::count(reverted.begin(), reverted.end(), 1)); break; }
            for(SM_vertex v : bad) {
              for(SM_vertex w : vertices_around_target(halfedge(v, A), A)) reverted[w.idx()] = 1;
              reverted[v.idx()] = 1;
            }
            for(SM_halfedge h : halfedges(A)) if(!is_border(h, A) && reverted[target(h, A).idx()]) uvN[h] = uvA[h];
          }
        }
        for(double alpha = 1; alpha > 1e-3; alpha *= 0.5) {
          auto uvT = A.add_property_map<SM_halfedge, Point_2>("h:uv_try", Point_2(0, 0)).first;
          for(SM_halfedge h : halfedges(A)) {
            if(is_border(h, A)) continue;
            const Iso m = Iso::translation_to_origin(cx(uvA[h]));
            const Cx w = m.apply(cx(uvN[h]));
            const double r = std::abs(w);
            const Cx wa = r > 0 ? w / r * std::tanh(alpha * std::atanh(std::min(r, 1 - 1e-16))) : Cx(0, 0);
            const Cx z = m.inverse().apply(wa);
            uvT[h] = Point_2(z.real(), z.imag());
          }
          HOT::Embedding_certificate cert;
          std::string msg;
          const HOT::Error_code ec = HOT::certify_hyperbolic_orbifold_embedding(A, lma_o, uvT, cert, &msg);
          std::printf("   certify (iteration %d, alpha %.4g): %s%s; %zu corners lost\n", label, alpha, ec == HOT::OK ? "" : msg.c_str(),
                      ec == HOT::OK ? (cert.is_bijective() ? "bijective" : "NOT bijective") : "", lost);
          if(ec == HOT::OK && !cert.is_bijective()) {
            std::ostringstream os; os << cert; std::printf("     %s\n", os.str().c_str());
          }
          if(ec == HOT::OK && cert.is_bijective()) {
            // the certified map's error
            const auto locs2 = HOT::map_vertices(A, uvT, L);
            double es = 0, ew = 0;
            for(std::size_t i = 0; i < n; ++i) {
              const double e = locs2[i].success ? std::sqrt(CGAL::squared_distance(HOT::surface_point(locs2[i], L, get(CGAL::vertex_point, B)), B.point(SM_vertex(static_cast<SM::size_type>(i))))) / diag : 1.0;
              es += e; ew = std::max(ew, e);
            }
            std::printf("   certified map: mean %.3f%% worst %.2f%%\n", 100 * es / n, 100 * ew);
            A.remove_property_map(uvT);
            break;
          }
          A.remove_property_map(uvT);
        }
        A.remove_property_map(uvN);
      };
      {
        // sanity: the harmonic map's own images give back a certified embedding
        std::vector<Eigen::Vector3d> q0(n);
        std::vector<SM_face> f0(n);
        for(std::size_t i = 0; i < n; ++i) { q0[i] = Eigen::Vector3d(img[i].x(), img[i].y(), img[i].z()); f0[i] = locs[i].face; }
        certify_images(q0, f0, 0);
      }
      std::vector<std::pair<std::size_t, Eigen::Vector3d> > anchors;
      if(!anchors_file.empty()) {
        std::ifstream in(anchors_file);
        std::size_t v, f; double x, y, z;
        while(in >> v >> f >> x >> y >> z) anchors.push_back({v, Eigen::Vector3d(x, y, z)});
      }
      for(int sa = 1; sa <= surface_arap; ++sa) {
        const auto ts = Clock::now();
        std::vector<Eigen::Matrix<double, 3, 2> > T(n);
        for(std::size_t i = 0; i < n; ++i) T[i] = tangent_basis(qf[i].idx());
        // soft anchors: weight x the mean face area
        const Eigen::VectorXd dd = arap_step(q, T, fixed, scale, anchors, anchor_weight * d.source_area / nf);
        std::vector<K::Point_3> im(n);
        double esum = 0, eworst = 0;
        for(std::size_t i = 0; i < n; ++i) {
          const Eigen::Vector3d x = q[i] + step * T[i] * dd.segment<2>(2 * i);
          const auto pp = tree.closest_point_and_primitive(K::Point_3(x.x(), x.y(), x.z()));
          q[i] = Eigen::Vector3d(pp.first.x(), pp.first.y(), pp.first.z());
          qf[i] = pp.second;
          im[i] = pp.first;
          const double e = std::sqrt(CGAL::squared_distance(pp.first, B.point(SM_vertex(static_cast<SM::size_type>(i))))) / diag;
          esum += e; eworst = std::max(eworst, e);
        }
        if(sa == surface_arap && std::getenv("DUMP")) {
          std::ofstream o(std::getenv("DUMP"));
          for(std::size_t i = 0; i < n; ++i) o << i << " " << std::sqrt(CGAL::squared_distance(im[i], B.point(SM_vertex(static_cast<SM::size_type>(i))))) / diag << "\n";
        }
        if(sa == surface_arap || (certify_every > 0 && sa % certify_every == 0))
          certify_images(q, qf, sa);
        HOT::Map_distortion dd2 = HOT::map_distortion(A, im);
        std::printf("surface arap %d: mean %.3f%% worst %.2f%%  conformal p50 %.3f p90 %.3f p99 %.3f  area p99 %.3f  flipped? degenerate %zu (%.2f s)\n", sa,
                    100 * esum / n, 100 * eworst, dd2.conformal_summary.p50, dd2.conformal_summary.p90, dd2.conformal_summary.p99,
                    dd2.area_summary.p99, dd2.degenerate_image_faces, seconds_since(ts));
      }
      return 0;
    }

    if(arap) {
      const double scale = std::sqrt(d.image_area / d.source_area);
      std::vector<char> fixed(n, 0);
      for(SM_vertex v : lma) fixed[v.idx()] = 1;
      // tangent bases of B at the images
      std::vector<Eigen::Matrix<double, 3, 2> > T(n);
      std::vector<Eigen::Vector3d> q(n);
      for(std::size_t i = 0; i < n; ++i) {
        q[i] = Eigen::Vector3d(img[i].x(), img[i].y(), img[i].z());
        T[i] = tangent_basis(locs[i].face_index);
      }
      const Eigen::VectorXd dd = arap_step(q, T, fixed, scale, {}, 0);
      std::vector<Eigen::Vector3d> qs(n);
      double moved = 0;
      for(std::size_t i = 0; i < n; ++i) { qs[i] = q[i] + step * T[i] * dd.segment<2>(2 * i); moved = std::max(moved, (qs[i] - q[i]).norm()); }
      // target error (the 3D target points against the truth)
      double tsum = 0;
      for(std::size_t i = 0; i < n; ++i) { const K::Point_3 p = B.point(SM_vertex(static_cast<SM::size_type>(i))); tsum += (qs[i] - Eigen::Vector3d(p.x(), p.y(), p.z())).norm() / diag; }
      // weights: cotangents of the target triangles in the disk (B's face of corner 0's image, affine)
      std::fill(w.begin(), w.end(), 0.0);
      std::size_t flipped = 0;
      for(SM_face f : faces(A)) {
        const auto& c = fv[f.idx()];
        const std::size_t b = locs[c[0].idx()].face_index;
        Eigen::Matrix<double, 3, 2> EP;
        Eigen::Matrix2d Z;
        Eigen::Vector3d P[3];
        for(int k = 0; k < 3; ++k) { const K::Point_3 p = B.point(L.vertex(L.corner_vertex_index(b, k))); P[k] = Eigen::Vector3d(p.x(), p.y(), p.z()); }
        EP.col(0) = P[1] - P[0]; EP.col(1) = P[2] - P[0];
        const Point_2 z0 = L.corner_point(b, 0), z1 = L.corner_point(b, 1), z2 = L.corner_point(b, 2);
        Z << z1.x() - z0.x(), z2.x() - z0.x(), z1.y() - z0.y(), z2.y() - z0.y();
        const Eigen::Matrix<double, 2, 3> M = Z * (EP.transpose() * EP).inverse() * EP.transpose();
        Eigen::Vector2d y[3];
        y[0] = Eigen::Vector2d::Zero(); y[1] = M * (qs[c[1].idx()] - qs[c[0].idx()]); y[2] = M * (qs[c[2].idx()] - qs[c[0].idx()]);
        const double det = y[1].x() * y[2].y() - y[1].y() * y[2].x();
        if(!(det > 0)) { ++flipped; continue; }
        for(int k = 0; k < 3; ++k) { // angle at corner k: opposite edge (k+1, k+2)
          const Eigen::Vector2d u = y[(k + 1) % 3] - y[k], v = y[(k + 2) % 3] - y[k];
          const double cot = u.dot(v) / det;
          // edge joining corners k+1 and k+2
          SM_halfedge h = halfedge(f, A);
          for(int s = 0; s < 3; ++s, h = next(h, A)) {
            const SM_vertex s0 = source(h, A), t0 = target(h, A);
            if((s0 == c[(k + 1) % 3] && t0 == c[(k + 2) % 3]) || (t0 == c[(k + 1) % 3] && s0 == c[(k + 2) % 3])) { w[edge(h, A).idx()] += 0.5 * cot; break; }
          }
        }
      }
      std::printf("   arap: target mean error %.3f%%, largest move %.3f%% diag, %zu target triangles flipped\n", 100 * tsum / n, 100 * moved / diag, flipped);
    } else {
    // the global scale of the map
    const double s2 = d.image_area / d.source_area;
    // update the log-conductivity of every face and the edge weights
    std::fill(w.begin(), w.end(), 0.0);
    if(passes > 0) {
      std::vector<double> lf(nf, 0), lv(n, 0), wv(n, 0);
      for(SM_face f : faces(A)) {
        const auto& c = fv[f.idx()];
        const K::Vector_3 qa = img[c[1].idx()] - img[c[0].idx()], qb = img[c[2].idx()] - img[c[0].idx()];
        const double ia = std::sqrt(CGAL::cross_product(qa, qb).squared_length()) / 2, sa = X[f.idx()].determinant() / 2;
        lf[f.idx()] = std::clamp(0.5 * std::log(std::max(ia / (sa * s2), 1e-12)), -2.0, 2.0);
        for(int k = 0; k < 3; ++k) { lv[c[k].idx()] += sa * lf[f.idx()]; wv[c[k].idx()] += sa; }
      }
      for(std::size_t i = 0; i < n; ++i) lv[i] /= wv[i];
      for(int p = 0; p < passes; ++p) {
        std::vector<double> nv(n, 0), cnt(n, 0);
        for(SM_edge e : edges(A)) {
          const std::size_t a = source(halfedge(e, A), A).idx(), b = target(halfedge(e, A), A).idx();
          nv[a] += lv[b]; cnt[a] += 1; nv[b] += lv[a]; cnt[b] += 1;
        }
        for(std::size_t i = 0; i < n; ++i) lv[i] = 0.5 * lv[i] + 0.5 * nv[i] / cnt[i];
      }
      for(SM_face f : faces(A)) {
        const auto& c = fv[f.idx()];
        const double m = (lv[c[0].idx()] + lv[c[1].idx()] + lv[c[2].idx()]) / 3;
        Llog[f.idx()] += alpha * m * Eigen::Matrix2d::Identity();
      }
    }
    for(SM_face f : faces(A)) {
      if(passes > 0) break;
      const auto& c = fv[f.idx()];
      const K::Vector_3 qa = img[c[1].idx()] - img[c[0].idx()], qb = img[c[2].idx()] - img[c[0].idx()];
      Eigen::Matrix2d G;
      G << qa * qa, qa * qb, qa * qb, qb * qb;
      const Eigen::Matrix2d Xi = X[f.idx()].inverse();
      Eigen::Matrix2d M = Xi.transpose() * G * Xi / s2; // J^T J in A's frame
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> es(M);
      Eigen::Vector2d ev = es.eigenvalues();
      for(int j = 0; j < 2; ++j) ev[j] = std::clamp(0.5 * std::log(std::max(ev[j], 1e-12)), -2.0, 2.0); // log sigma
      if(std::isfinite(ev[0]) && std::isfinite(ev[1])) {
        const double m = 0.5 * (ev[0] + ev[1]);
        ev[0] = m + aniso * (ev[0] - m); ev[1] = m + aniso * (ev[1] - m);
        Llog[f.idx()] += alpha * es.eigenvectors() * ev.asDiagonal() * es.eigenvectors().transpose();
      }
    }
    if(smooth > 0) { // average with the neighbours
      std::vector<Eigen::Matrix2d> S = Llog; // (frames differ per face: smooth the isotropic part only)
      for(SM_face f : faces(A)) {
        double tr = 0; int k = 0;
        for(SM_halfedge h : halfedges_around_face(halfedge(f, A), A)) {
          const SM_face g = face(opposite(h, A), A);
          if(g == SM_face()) continue;
          tr += Llog[g.idx()].trace(); ++k;
        }
        const double mine = Llog[f.idx()].trace();
        const double target = (1 - smooth) * mine + smooth * (k ? tr / k : mine);
        S[f.idx()] += 0.5 * (target - mine) * Eigen::Matrix2d::Identity();
      }
      Llog = S;
    }
    for(SM_face f : faces(A)) {
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> es(Llog[f.idx()]);
      const Eigen::Matrix2d Kt = es.eigenvectors() * es.eigenvalues().array().exp().matrix().asDiagonal() * es.eigenvectors().transpose();
      const Eigen::Matrix2d& Xf = X[f.idx()];
      const Eigen::Vector2d x[3] = {Eigen::Vector2d(0, 0), Xf.col(0), Xf.col(1)};
      const double area = 0.5 * Xf.determinant();
      Eigen::Vector2d r[3]; // rotated opposite edges
      for(int i = 0; i < 3; ++i) {
        const Eigen::Vector2d e = x[(i + 2) % 3] - x[(i + 1) % 3];
        r[i] = Eigen::Vector2d(-e.y(), e.x());
      }
      SM_halfedge h = halfedge(f, A); // h: from corner 2 to corner 0? find the edge per pair
      for(int k = 0; k < 3; ++k, h = next(h, A)) {
        // edge of h joins source(h) and target(h): corners i, j; weight -S_ij
        int i = -1, j = -1;
        for(int q = 0; q < 3; ++q) {
          if(fv[f.idx()][q] == source(h, A)) i = q;
          if(fv[f.idx()][q] == target(h, A)) j = q;
        }
        w[edge(h, A).idx()] += -(r[i].dot(Kt * r[j])) / (4 * area);
      }
    }
    }
    double wmax = 0;
    for(double x : w) wmax = std::max(wmax, x);
    std::size_t neg = 0;
    for(double& x : w) if(!(x > 1e-6 * wmax)) { x = 1e-6 * wmax; ++neg; }
    auto wmap = A.add_property_map<SM_edge, double>("e:refine_w", 1.0).first;
    for(SM_edge e : edges(A)) wmap[e] = w[e.idx()];
    HOT::Embedding_statistics s2t;
    const auto tr = Clock::now();
    if(HOT::hyperbolic_orbifold_Tutte_embedding(A, lma_o, uvA, HOT::parameters::embedding_statistics(&s2t, HOT::parameters::edge_weight_map(wmap))) != HOT::OK) {
      std::printf("re-embedding refused: %s\n", s2t.message.c_str());
      return 1;
    }
    std::printf("   clamped %zu of %zu weights; embedding %.2f s (first pair %.2f s)\n", neg, w.size(), seconds_since(tr), t_embed);
  }
  return 0;
}
