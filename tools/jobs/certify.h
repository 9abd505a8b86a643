// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef HOT_TOOLS_JOBS_CERTIFY_H
#define HOT_TOOLS_JOBS_CERTIFY_H

// The `certify` command: reads a mesh, its cones and an embedding as OBJ (from `embed` or
// from anywhere), and runs certify_corner_embedding() on them. Exit status 0 when the
// embedding is certified a bijection onto the orbifold, 4 when a check fails (one line on
// stderr: the first failed check, where and why), and the program's other statuses for bad
// input (2 usage, 3 data, 1 files). The report, when asked for, is written in both cases.
// A recentred embedding (embed --recentre) is checked in its frame (--frame, from its report).
// --cone-orders gives each cone's order (in the cones file's order, as embed takes them); the
// checker finds which tile corner each cone is at, hence the tile of those orders, on the map.
// The reading and the certificate are the application layer's (hot_app/certify_job.h).

#include "command_line.h"
#include "hot_app/certify_job.h"

#include <chrono>
#include <cmath>
#include <complex>
#include <cstdlib>
#include <iostream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace hot_cli {

// the exit status of `certify` when the embedding is read but not certified
constexpr int not_certified_status = 4;

// --cone-orders: orders separated by commas or spaces, one per cone
inline std::vector<int> parse_cone_orders(const std::string& s)
{
  std::vector<int> orders;
  std::string t = s;
  for(char& ch : t)
    if(ch == ',')
      ch = ' ';
  std::istringstream in(t);
  for(std::string tok; in >> tok;) {
    char* end = nullptr;
    const long v = std::strtol(tok.c_str(), &end, 10);
    if(tok.empty() || *end != '\0' || !hot_tools::is_cone_order(v))
      throw Usage_error{"--cone-orders must list integers of at least 2 (e.g. 2,3,7), got '" + tok + "'"};
    orders.push_back(static_cast<int>(v));
  }
  if(orders.empty())
    throw Usage_error{"--cone-orders lists no order"};
  return orders;
}

// --frame A_RE,A_IM,B_RE,B_IM: the Mobius map z -> (az + b) / (conj(b) z + conj(a)) of a
// recentred embedding (embed's report: "frame": {"a": [re, im], "b": [re, im]})
inline HOT::Hyperbolic_isometry_2<double> parse_frame(const std::string& s)
{
  std::string t = s;
  for(char& ch : t)
    if(ch == ',')
      ch = ' ';
  std::istringstream in(t);
  std::vector<double> x;
  for(std::string tok; in >> tok;) {
    char* end = nullptr;
    const double v = std::strtod(tok.c_str(), &end);
    if(tok.empty() || *end != '\0' || !std::isfinite(v))
      throw Usage_error{"--frame must be four numbers A_RE,A_IM,B_RE,B_IM, got '" + tok + "'"};
    x.push_back(v);
  }
  if(x.size() != 4)
    throw Usage_error{"--frame must be four numbers A_RE,A_IM,B_RE,B_IM (embed's report: \"frame\"), got " + std::to_string(x.size())};
  const std::complex<double> a(x[0], x[1]), b(x[2], x[3]);
  if(!(std::norm(a) > std::norm(b)))
    throw Usage_error{"--frame: |a| must exceed |b| (a Mobius map of the disk)"};
  return HOT::Hyperbolic_isometry_2<double>(a, b);
}

inline int run_certify(int argc, char** argv)
{
  typedef std::chrono::steady_clock Clock;
  auto seconds = [](Clock::time_point a, Clock::time_point b) { return std::chrono::duration<double>(b - a).count(); };

  const Options opt(argc, argv, 2, {"mesh", "embedding", "cones", "orbifold", "cone-orders", "frame", "report"}, {"progress"});
  Progress_line progress("certify", opt.has("progress"));
  Certify_job job;
  hot_tools::Certify_request& q = job.q;
  q.mesh_path = opt.get("mesh");
  q.embedding_path = opt.get("embedding");
  q.cones_path = opt.get("cones");
  if(opt.has("orbifold"))
    job.type = parse_orbifold(opt.get("orbifold"));
  if(opt.has("cone-orders"))
    q.cone_orders = parse_cone_orders(opt.get("cone-orders"));
  const std::optional<std::string> report = opt.has("report") ? std::optional<std::string>(opt.get("report")) : std::nullopt;
  job.frame = opt.has("frame") ? parse_frame(opt.get("frame")) : HOT::Hyperbolic_isometry_2<double>();

  const Clock::time_point t0 = Clock::now();
  progress.step("read");
  read_certify_mesh_and_cones(job);
  if(!q.cone_orders.empty()) {
    if(q.cone_orders.size() != q.cones.size())
      throw Usage_error{"--cone-orders lists " + std::to_string(q.cone_orders.size()) + " orders for " +
                        std::to_string(q.cones.size()) + " cones"};
  }
  bool mixed = false; // an order other than 2
  for(int p : q.cone_orders)
    mixed = mixed || p != 2;
  read_certify_embedding(job);
  const Clock::time_point t1 = Clock::now();
  progress.done("read");

  progress.step("certificate");
  const HOT::Corner_embedding_certificate cert = certify_embedding(job);
  q.time_read = seconds(t0, t1);
  q.time_certify = seconds(t1, Clock::now());
  progress.done("certificate");
  if(report) {
    progress.step("write");
    write_file_atomically(*report, [&](std::ostream& os) { hot_tools::write_certificate_report(os, q, cert); });
    progress.done("write");
  }
  progress.clear();

  if(!cert.is_certified()) {
    std::cerr << "hyperbolic_orbifold_tutte: not certified: " << cert.summary() << std::endl;
    return not_certified_status;
  }
  if(cert.genus > 0) {
    std::cout << "certified: " << q.embedding_path << " is a bijection of " << q.mesh_path << " onto the closed genus-"
              << cert.genus << " orbifold with " << cert.number_of_cones << " cone" << (cert.number_of_cones == 1 ? "" : "s");
    if(cert.number_of_cones > 0) {
      std::cout << " of orders";
      for(std::size_t i = 0; i < cert.cone_orders.size(); ++i)
        std::cout << (i ? "," : " ") << cert.cone_orders[i];
    }
    std::cout << " (" << cert.number_of_faces << " faces, " << cert.number_of_seam_edges << " seam edges glued by "
              << cert.number_of_seam_isometries << " isometries; largest seam mismatch " << cert.max_seam_mismatch
              << ", angle-sum deviation " << cert.max_angle_sum_deviation << "; read in " << q.time_read << " s, certified in "
              << q.time_certify << " s)" << std::endl;
    return EXIT_SUCCESS;
  }
  std::cout << "certified: " << q.embedding_path << " is a bijection of " << q.mesh_path << " onto the "
            << (cert.type == HOT::Sphere_type ? "sphere" : "disk") << "-type orbifold with " << cert.number_of_cones
            << " cones";
  if(mixed) {
    std::cout << " of orders";
    for(std::size_t i = 0; i < cert.cone_orders.size(); ++i)
      std::cout << (i ? "," : " ") << cert.cone_orders[i];
  }
  std::cout << " (" << cert.number_of_faces << " faces, " << cert.number_of_seam_edges << " seam edges; cone order";
  for(int j : cert.cone_order)
    std::cout << " " << j;
  std::cout << "; largest seam mismatch " << cert.max_seam_mismatch << ", angle-sum deviation " << cert.max_angle_sum_deviation
            << (cert.number_of_charts > 0 ? "; " + std::to_string(cert.number_of_charted_faces) + " faces in " +
                                                std::to_string(cert.number_of_charts) + " chart" + (cert.number_of_charts > 1 ? "s" : "") +
                                                " around cone images"
                                          : std::string())
            << "; read in " << q.time_read << " s, certified in " << q.time_certify << " s)" << std::endl;
  return EXIT_SUCCESS;
}

} // namespace hot_cli

#endif // HOT_TOOLS_JOBS_CERTIFY_H
