// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef HOT_APP_EMBED_JOB_H
#define HOT_APP_EMBED_JOB_H

// The embedding job and its one call of the library: shared by the command line's `embed`
// (tools/jobs/embed.h, whose Embed_command adds the files and options of the command line) and
// the Python module's embed() (python/src/embedding.cpp), so that both compute an embedding with
// the same named parameters, hence the same numbers.

#include <CGAL/Hyperbolic_orbifold_Tutte/hyperbolic_orbifold_Tutte_embedding.h>

#include "hot_app/job_support.h"
#include "hot_app/io/embedding_cones.h"
#include "hot_app/io/prepared_input.h"
#include "hot_app/io/reports.h"

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace hot_cli {

// what an embedding is computed with (the command line's `embed` adds its files: Embed_command)
struct Embed_job
{
  hot_tools::Embedding_request request; // the mesh, weights and order (empty: the type's default)
  HOT::Weight_type weights = HOT::Cotangent;
  bool mean_value_fallback = false; // the weights were not chosen: a cotangent embedding that fails the certificate is computed again with the mean value weights
  bool recentre = false;
  std::vector<int> orders; // --cone-orders, per landmark in the order given to the library (empty: 2 for all)
  std::function<void(const char*, double)> progress; // the library's progress reports (empty: none)
};

// the certified embedding of `m` with the job's options (the failure's reason otherwise):
// `job.request.type` the orbifold type, `job.request.order` "tsp" or "given"; `charts` receives
// the corners' chart points (charts around cone images are allowed)
template <class TriangleMesh, class Vertex, class UVMap, class ChartMap>
HOT::Embedding_statistics embed_mesh(const Embed_job& job, TriangleMesh& m, const std::vector<Vertex>& landmarks,
                                     UVMap uv, ChartMap charts, const std::vector<std::vector<Vertex> >& cut_graph)
{
  HOT::Embedding_statistics st;
  const HOT::Landmark_order order = job.request.order == "tsp" ? HOT::Tsp_order : HOT::Given_order;
  const HOT::Error_code ec = HOT::hyperbolic_orbifold_Tutte_embedding(
    m, landmarks, uv,
    HOT::parameters::progress(job.progress, HOT::parameters::cut_graph(cut_graph, HOT::parameters::cone_orders(job.orders, HOT::parameters::chart_map(
      charts,
      HOT::parameters::recentring(
        job.recentre,
        HOT::parameters::embedding_statistics(
          &st, HOT::parameters::landmark_order(order, HOT::parameters::weight_type(job.weights, HOT::parameters::mean_value_fallback(
            job.mean_value_fallback, HOT::parameters::orbifold_type(job.request.type)))))))))));
  if(ec != HOT::OK)
    throw Failure{ec, st.message};
  return st;
}

// the orbifold and the cones of an embedding, for the head of its OBJ file (what a map from
// the stored embedding needs): `cones` = the landmarks as given, as vertex numbers of the files
inline hot_tools::Embedding_cones embedding_cones(HOT::Orbifold_type type, const HOT::Embedding_statistics& st,
                                                 const std::vector<std::size_t>& cones)
{
  hot_tools::Embedding_cones c;
  c.type = type;
  c.genus = st.genus;
  c.reversed = st.landmark_order_reversed;
  c.landmark = st.landmark_order;
  for(std::size_t i = 0; i < st.landmark_order.size(); ++i) {
    c.vertex.push_back(cones[st.landmark_order[i]]);
    c.order.push_back(i < st.cone_orders.size() ? st.cone_orders[i] : 2);
  }
  return c;
}

} // namespace hot_cli

#endif // HOT_APP_EMBED_JOB_H
