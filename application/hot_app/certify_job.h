// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef HOT_APP_CERTIFY_JOB_H
#define HOT_APP_CERTIFY_JOB_H

// The certify job: a mesh, its cones and an embedding as OBJ (from `embed` or from anywhere)
// read, and certify_corner_embedding() run on them (the command line's `certify`,
// tools/jobs/certify.h, parses its options around these steps and says the verdict). Points
// written in charts around cone images ('# hot chart' and '# hot vtc' lines) are read and
// checked in their charts' coordinates. A closed mesh of genus g >= 1 (embed's OBJ of its cut
// graph's polygon) is certified without a tile: the seams' isometries come from the map.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Hyperbolic_orbifold_Tutte/certify_corner_embedding.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/genus.h>

#include "hot_app/job_support.h"
#include "hot_app/io/certificate_report.h"
#include "hot_app/io/embedding_obj_reader.h"
#include "hot_app/io/landmarks.h"
#include "hot_app/io/read_and_check.h" // read_mesh()

#include <optional>
#include <string>
#include <vector>

namespace hot_cli {

struct Certify_job
{
  typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
  typedef CGAL::Surface_mesh<K::Point_3> Mesh;

  hot_tools::Certify_request q; // the files and the cone orders (and the times, once done)
  std::optional<HOT::Orbifold_type> type; // (none: from the mesh)
  HOT::Hyperbolic_isometry_2<double> frame; // a recentred embedding's frame
  Mesh m;
  std::vector<Mesh::Vertex_index> cones;
  HOT::Corner_embedding embedding;
};

// the first step: the mesh and the cones file (no cone: an empty cones file, for a closed mesh
// of genus g >= 1, Euler characteristic below 2; genus 1 is then refused as not hyperbolic by
// the checker)
inline void read_certify_mesh_and_cones(Certify_job& job)
{
  hot_tools::Certify_request& q = job.q;
  const Certify_job::Mesh& m = job.m;
  require(hot_tools::read_mesh(q.mesh_path, job.m));
  const bool closed_genus = CGAL::is_closed(m) && HOT::euler_characteristic(m) < 2;
  require(hot_tools::read_landmarks(q.cones_path, q.cones, closed_genus));
}

// the second step: the cones as vertices of the mesh, and the embedding's OBJ file
inline void read_certify_embedding(Certify_job& job)
{
  hot_tools::Certify_request& q = job.q;
  const Certify_job::Mesh& m = job.m;
  for(std::size_t v : q.cones) {
    if(v >= num_vertices(m))
      throw Failure{HOT::ERROR_LANDMARK_OUT_OF_RANGE, q.cones_path + ": vertex index " + std::to_string(v) +
                                                        " is not a vertex of the mesh (it has " + std::to_string(num_vertices(m)) + ")"};
    job.cones.push_back(Certify_job::Mesh::Vertex_index(static_cast<Certify_job::Mesh::size_type>(v)));
  }
  std::size_t obj_vertices = 0;
  require(hot_tools::read_embedding_obj(q.embedding_path, job.embedding, obj_vertices, &q.chart_points));
  if(obj_vertices != num_vertices(m))
    throw Failure{HOT::ERROR_WRONG_PARAMETER, q.embedding_path + ": the embedding has " + std::to_string(obj_vertices) +
                                                " vertices (v lines) but the mesh " + std::to_string(num_vertices(m)) +
                                                ": it is not an embedding of this mesh"};
}

// the last step: the certificate (a failure to check at all throws, naming the file or the
// cone orders at fault; a check that fails is the certificate's verdict)
inline HOT::Corner_embedding_certificate certify_embedding(const Certify_job& job)
{
  const hot_tools::Certify_request& q = job.q;
  bool mixed = false; // an order other than 2
  for(int p : q.cone_orders)
    mixed = mixed || p != 2;
  HOT::Corner_embedding_certificate cert;
  std::string why;
  const HOT::Error_code ec =
    job.type ? HOT::certify_corner_embedding(job.m, job.cones, job.embedding, cert, &why,
                                             HOT::parameters::cone_orders(q.cone_orders, HOT::parameters::frame(job.frame, HOT::parameters::orbifold_type(*job.type))))
             : HOT::certify_corner_embedding(job.m, job.cones, job.embedding, cert, &why,
                                             HOT::parameters::cone_orders(q.cone_orders, HOT::parameters::frame(job.frame)));
  if(ec != HOT::OK) {
    // the orders' refusals (not hyperbolic, other than 2 on a disk) name --cone-orders
    const bool orders_refused =
      mixed && (ec == HOT::ERROR_NOT_HYPERBOLIC || (ec == HOT::ERROR_WRONG_PARAMETER && why.find("order") != std::string::npos));
    throw Failure{ec, (orders_refused ? std::string("--cone-orders")
                       : ec == HOT::ERROR_DUPLICATE_LANDMARK || ec == HOT::ERROR_LANDMARK_NOT_ON_BORDER || ec == HOT::ERROR_TOO_FEW_LANDMARKS
                         ? q.cones_path : q.mesh_path) + ": " + why};
  }
  return cert;
}

} // namespace hot_cli

#endif // HOT_APP_CERTIFY_JOB_H
