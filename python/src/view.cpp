// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

// view(obj, out_dir): the folder of the command line's `view` job (hot_app/view.h) for an
// Embedding, a map_meshes() result or a sequence of Embeddings (a map, or a collection).

#include "hot_python.h"

#include "hot_app/stored_embedding.h" // hot_cli::Locator
#include "hot_app/view.h"

#include <string>
#include <vector>

namespace hot_python {

namespace {

typedef hot_cli::Locator Locator;

// the locator of an embedding, as the module's map uses it (target_locator(), embedding.cpp)
Locator embedding_locator(const Embedding& B)
{
  const Locator loc(result_of(B), HOT::Hyperboloid_linear);
  if(!loc.is_valid() && B.stats.genus > 0)
    fail(HOT::ERROR_WRONG_PARAMETER, "view: the tile of a genus " + std::to_string(B.stats.genus) + " embedding could not be built");
  return loc;
}

hot_cli::View_input view_input(const Embedding& e, const Locator& loc, const std::string& name)
{
  hot_cli::View_input in;
  in.name = name;
  in.mesh = &e.mesh;
  in.uv = e.uv;
  in.charts = e.charts;
  in.chart_isometries = e.stats.charts;
  in.locator = &loc;
  for(std::size_t p : e.order) { // (landmark p as given, at the cone of its place in the order)
    in.landmark_numbers.push_back(p);
    in.landmark_vertices.push_back(e.landmarks[p].idx());
  }
  std::vector<int> orders = e.stats.cone_orders;
  if(orders.empty())
    orders.assign(e.landmarks.size(), 2);
  in.signature = HOT::Orbifold_signature(e.type, orders);
  in.genus = e.genus;
  return in;
}

std::vector<Embedding_ptr> embeddings_of(py::handle obj)
{
  std::vector<Embedding_ptr> r;
  if(py::isinstance<Embedding>(obj)) {
    r.push_back(obj.cast<Embedding_ptr>());
    return r;
  }
  if(py::isinstance<py::dict>(obj)) {
    const py::dict d = py::reinterpret_borrow<py::dict>(obj);
    if(d.contains("source") && d.contains("target") && py::isinstance<Embedding>(d["source"]) && py::isinstance<Embedding>(d["target"])) {
      r.push_back(d["source"].cast<Embedding_ptr>());
      r.push_back(d["target"].cast<Embedding_ptr>());
      return r;
    }
  } else if(py::isinstance<py::sequence>(obj) && !py::isinstance<py::str>(obj)) {
    for(py::handle x : py::reinterpret_borrow<py::sequence>(obj)) {
      if(!py::isinstance<Embedding>(x)) {
        r.clear();
        break;
      }
      r.push_back(x.cast<Embedding_ptr>());
    }
    if(r.size() >= 2)
      return r;
  }
  fail(HOT::ERROR_WRONG_PARAMETER, "view: obj must be an Embedding, the dict map_meshes() returns, or a sequence of at least 2 "
                                   "Embeddings (a map from the first onto the second, or a collection), got " +
                                   std::string(py::str(py::type::of(obj).attr("__name__"))));
}

void view(py::handle obj, py::handle out_dir)
{
  const std::vector<Embedding_ptr> E = embeddings_of(obj);
  const py::bytes b = py::module_::import("os").attr("fsencode")(out_dir);
  const std::string dir(b);
  py::gil_scoped_release release;
  std::vector<Locator> L;
  L.reserve(E.size()); // (the inputs point to them)
  std::vector<hot_cli::View_input> in;
  try {
    for(const Embedding_ptr& e : E) L.push_back(embedding_locator(*e));
    for(std::size_t i = 0; i < E.size(); ++i)
      in.push_back(view_input(*E[i], L[i], E.size() == 1 ? "mesh" : E.size() == 2 ? (i == 0 ? "source" : "target") : "mesh " + std::to_string(i)));
    for(std::size_t i = 1; i < E.size(); ++i)
      if(E[i]->type != E[0]->type || E[i]->order.size() != E[0]->order.size() || E[i]->stats.landmark_order_reversed != E[0]->stats.landmark_order_reversed)
        fail(HOT::ERROR_WRONG_PARAMETER, "view: embedding " + std::to_string(i) + " is not of the first one's orbifold, or runs the other way"
                                         " (embed them with the same landmark order, as map() needs)");
    const hot_cli::View_data d = E.size() == 1 ? hot_cli::view_embedding(in[0])
                                               : hot_cli::view_maps(in, E.size() == 2 ? "map" : "collection",
                                                                    E.size() == 2 ? "source -> target" : "collection");
    hot_cli::write_view_folder(dir, d);
  } catch(const hot_cli::Failure& f) {
    fail(f.code, "view: " + f.message);
  } catch(const std::runtime_error& x) {
    fail(HOT::ERROR_WRITE_FAILED, std::string("view: ") + x.what());
  }
}

} // namespace

void register_view(py::module_& m)
{
  m.def("view", &view, py::arg("obj"), py::arg("out_dir"),
        R"doc(view(obj, out_dir)

Writes the folder of the command line's ``view`` job: out_dir/index.html (with data.js,
viewer.js and Debian's three.min.js), which opens offline in any browser (file://, no server).

obj is an Embedding (the surface textured by the hyperbolic tiling beside the Poincare disk
with the mesh and the cut), the dict map_meshes() returns or a pair (a, b) of Embeddings
embedded in one landmark order, as map(a, b) takes them (both surfaces, a colour field of A
carried to B, numbered landmarks, per-face distortion, unreliable vertices, click a point to see
its image), or a list of three or more such Embeddings (a collection: the first one's colours
carried to all). An existing out_dir is replaced only if it is a view folder (or empty).

Raises InputError for another obj, ComputationError when the folder cannot be written.

Example:
    >>> e = hot.embed(V, F, lm)
    >>> hot.view(e, "bear_view")               # then open bear_view/index.html
    >>> r = hot.map_meshes(VA, FA, la, VB, FB, lb)
    >>> hot.view(r, "map_view"))doc");
}

} // namespace hot_python
