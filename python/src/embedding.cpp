// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers
//
// The Python extension's embeddings (embed, the class Embedding) and maps (map): the
// command line's `embed` and `map` on arrays. The embedding is computed by the command
// line's own call (hot_cli::embed_mesh(), application/hot_app/embed_job.h) on a mesh built as its reader
// builds it, so the numbers are the command line's, bit for bit; the OBJ file and the report
// are written by its writers (application/hot_app/io).

#include "hot_python.h"

#include <CGAL/Hyperbolic_orbifold_Tutte/Embedding_locator.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/Orbifold_tile.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/landmark_tour.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/map_reliability.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/refine_orbifold_map.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/surface_maps.h>

#include "hot_app/augment.h"
#include "hot_app/embed_job.h"
#include "hot_app/job_support.h"
#include "hot_app/map_order.h"
#include "hot_app/io/embedding_obj.h"
#include "hot_app/io/map_files.h"
#include "hot_app/io/reports.h"

#include <algorithm>
#include <array>
#include <sstream>
#include <stdexcept>
#include <type_traits>

namespace hot_python {

// ---------------------------------------------------------------------------------------
// embed
// ---------------------------------------------------------------------------------------

namespace {

// the first step of compute_embedding(): `e`'s mesh built from (V, F) and checked, its type,
// genus and landmarks (checked as read_and_check_landmarks() checks a landmark file's indices)
void read_mesh_and_landmarks(const double* V, std::size_t n, const std::int64_t* F, std::size_t m, std::size_t k,
                             const std::vector<std::size_t>& ids, const Embed_options& opt, Embedding& e)
{
  Surface_mesh& mesh = e.mesh;
  HOT::Mesh_info info;
  mesh_from_arrays(V, n, F, m, k, opt.type, mesh, info);
  e.type = info.type;
  e.genus = e.type == HOT::Sphere_type ? HOT::closed_mesh_genus(mesh) : 0;
  for(int p : opt.cone_orders)
    if(!hot_tools::is_cone_order(p))
      fail(HOT::ERROR_WRONG_PARAMETER, "cone_orders must be integers from 2 to 1000000 (one per landmark, e.g. [2, 3, 7])");
  const std::size_t minimum =
    HOT::minimum_number_of_landmarks_of(mesh, e.type, hot_cli::minimum_landmarks(opt.cone_orders));
  require(HOT::check_landmarks(mesh, ids, e.type, e.landmarks, minimum));
  e.landmark_ids = ids;
}

} // namespace

Embedding_ptr compute_embedding(const double* V, std::size_t n, const std::int64_t* F, std::size_t m, std::size_t k,
                                const std::vector<std::size_t>& ids, const Embed_options& opt)
{
  auto e = std::make_shared<Embedding>();
  Surface_mesh& mesh = e->mesh;
  read_mesh_and_landmarks(V, n, F, m, k, ids, opt, *e);

  // the order: the type's default, the library's tour, as given, or explicit
  hot_cli::Embed_job job;
  std::string order_name = opt.order;
  if(order_name == "auto")
    order_name = (e->type == HOT::Sphere_type && e->genus == 0) ? "tsp" : "given";
  std::vector<SM_vertex> landmarks = e->landmarks; // in the order given to the library
  std::vector<std::size_t> permutation(ids.size());
  for(std::size_t i = 0; i < permutation.size(); ++i) permutation[i] = i;
  job.orders = opt.cone_orders;
  if(order_name == "explicit") {
    const std::vector<std::size_t>& p = opt.explicit_order;
    std::vector<bool> seen(ids.size(), false);
    bool ok = p.size() == ids.size();
    for(std::size_t i = 0; ok && i < p.size(); ++i) {
      ok = p[i] < ids.size() && !seen[p[i]];
      if(ok) seen[p[i]] = true;
    }
    if(!ok)
      fail(HOT::ERROR_WRONG_PARAMETER, "order must be 'auto', 'tsp', 'given' or a permutation of the " + std::to_string(ids.size()) +
                                         " landmark positions 0.." + std::to_string(ids.size() == 0 ? 0 : ids.size() - 1) +
                                         " (e.g. another embedding's landmark_order)");
    permutation = p;
    for(std::size_t i = 0; i < p.size(); ++i) landmarks[i] = e->landmarks[p[i]];
    if(!opt.cone_orders.empty()) {
      if(opt.cone_orders.size() != ids.size())
        fail(HOT::ERROR_WRONG_PARAMETER, std::to_string(opt.cone_orders.size()) + " cone orders are given for " +
                                           std::to_string(ids.size()) + " landmarks (one per landmark is needed)");
      for(std::size_t i = 0; i < p.size(); ++i) job.orders[i] = opt.cone_orders[p[i]];
    }
  }

  // genus g >= 1: the cut graph, as read_cut_graph_of() reads a file's
  std::vector<std::vector<SM_vertex> > cut_graph;
  if(opt.has_cut_graph) {
    if(e->genus == 0)
      fail(HOT::ERROR_WRONG_PARAMETER, "cut_graph: the mesh has genus 0; a cut graph is for a closed mesh of genus 1 or more");
    const std::vector<SM_vertex> verts(vertices(mesh).begin(), vertices(mesh).end());
    for(const auto& path : opt.cut_graph) {
      cut_graph.emplace_back();
      for(std::size_t id : path) {
        if(id >= verts.size())
          fail(HOT::ERROR_LANDMARK_OUT_OF_RANGE, "cut_graph: vertex " + std::to_string(id) + " of the cut graph is not a vertex of the mesh");
        cut_graph.back().push_back(verts[id]);
      }
    }
  }

  // the job of run_embed()
  job.request.mesh_path = opt.name;
  job.request.type = e->type;
  job.request.weights = opt.weights;
  job.request.order = order_name == "explicit" ? "given" : order_name;
  job.request.cones = ids;
  job.mean_value_fallback = opt.mean_value_fallback;
  if(opt.weights == "cotan") job.weights = HOT::Cotangent;
  else if(opt.weights == "mvc") job.weights = HOT::Mean_value;
  else if(opt.weights == "uniform") job.weights = HOT::Uniform;
  else fail(HOT::ERROR_WRONG_PARAMETER, "weights must be 'cotan', 'mvc' or 'uniform', got '" + opt.weights + "'");
  job.recentre = opt.recentre;
  job.progress = opt.progress;

  e->uv = mesh.add_property_map<SM_halfedge, Kernel::Point_2>("h:uv", Kernel::Point_2(0, 0)).first;
  e->charts = mesh.add_property_map<SM_halfedge, HOT::Chart_point<Kernel::Point_2> >("h:chart").first;
  try {
    e->stats = hot_cli::embed_mesh(job, mesh, landmarks, e->uv, e->charts, cut_graph);
  } catch(const hot_cli::Failure& f) {
    fail(f.code, f.message);
  }
  // the order used, as positions in the landmarks as given
  for(std::size_t& i : e->stats.landmark_order) i = permutation[i];
  e->order = e->stats.landmark_order;
  job.request.order = order_name;
  e->request = job.request;
  std::ostringstream report;
  hot_tools::write_embedding_report(report, e->request, num_vertices(mesh), num_faces(mesh), e->stats);
  e->report = report.str();

  // the corners' points in the order of F (face j's corners from its first vertex,
  // source(halfedge(f)), as the OBJ writer writes them), and F itself
  e->corner_uv.reserve(6 * num_faces(mesh));
  e->faces.reserve(3 * num_faces(mesh));
  for(SM_face f : faces(mesh))
    for(SM_halfedge h : halfedges_around_face(prev(halfedge(f, mesh), mesh), mesh)) {
      const Kernel::Point_2& p = get(e->uv, h);
      e->corner_uv.push_back(p.x());
      e->corner_uv.push_back(p.y());
      e->faces.push_back(static_cast<std::int64_t>(target(h, mesh).idx()));
    }
  return e;
}

Progress_relay::Progress_relay(py::handle f) : f_(py::reinterpret_borrow<py::object>(f))
{
  if(!f_.is_none() && !PyCallable_Check(f_.ptr()))
    fail(HOT::ERROR_WRONG_PARAMETER, "progress must be None or a callable progress(phase, fraction)");
}

std::function<void(const char*, double)> Progress_relay::callback(const std::string& prefix)
{
  if(f_.is_none())
    return {};
  return [this, prefix](const char* phase, double fraction) {
    if(failed_)
      return;
    py::gil_scoped_acquire gil;
    try {
      f_(prefix + phase, fraction);
    } catch(py::error_already_set& e) {
      failed_ = true;
      error_ = std::make_unique<py::error_already_set>(std::move(e));
    }
  };
}

void Progress_relay::rethrow()
{
  if(!error_)
    return;
  py::error_already_set e = std::move(*error_);
  error_.reset();
  throw e;
}

namespace {

// embed()'s and map_meshes()' `weights` into `opt`: None, the cotangent weights with the mean
// value fallback (as the command line without --weights); a name, those weights alone
void parse_weights(py::handle weights, Embed_options& opt)
{
  opt.mean_value_fallback = weights.is_none();
  if(weights.is_none())
    opt.weights = "cotan";
  else if(py::isinstance<py::str>(weights))
    opt.weights = weights.cast<std::string>(); // (checked by compute_embedding())
  else
    fail(HOT::ERROR_WRONG_PARAMETER, "weights must be None, 'cotan', 'mvc' or 'uniform'");
}

// embed()'s and map_meshes()' `order` and `cone_orders` into `opt`
void parse_order_options(py::handle order, py::handle cone_orders, Embed_options& opt)
{
  if(py::isinstance<py::str>(order)) {
    opt.order = order.cast<std::string>();
    if(opt.order != "auto" && opt.order != "tsp" && opt.order != "given")
      fail(HOT::ERROR_WRONG_PARAMETER, "order must be 'auto', 'tsp', 'given' or a sequence of landmark positions, got '" + opt.order + "'");
  } else {
    opt.order = "explicit";
    for(std::int64_t i : int_list(order, "order"))
      opt.explicit_order.push_back(i < 0 ? std::size_t(-1) : static_cast<std::size_t>(i)); // (negative: not a permutation)
  }
  if(!cone_orders.is_none())
    for(std::int64_t p : int_list(cone_orders, "cone_orders"))
      opt.cone_orders.push_back(hot_tools::is_cone_order(p) ? static_cast<int>(p) : 0); // (0: refused below)
}

Embedding_ptr embed(py::handle V, py::handle F, py::handle landmarks, const std::string& orbifold, py::handle weights,
                    py::handle order, py::handle cone_orders, bool recentre, py::handle cut_graph, const std::string& name,
                    py::handle progress)
{
  Progress_relay relay(progress);
  const Double_array Va = vertex_array(V);
  const Index_array Fa = face_array(F);
  const std::vector<std::size_t> ids = index_list(landmarks, "landmark", HOT::ERROR_LANDMARK_OUT_OF_RANGE);
  Embed_options opt;
  opt.type = parse_orbifold(orbifold);
  parse_weights(weights, opt);
  opt.recentre = recentre;
  opt.name = name;
  parse_order_options(order, cone_orders, opt);
  if(!cut_graph.is_none()) {
    opt.has_cut_graph = true;
    for(py::handle path : cut_graph)
      opt.cut_graph.push_back(index_list(path, "cut graph vertex", HOT::ERROR_LANDMARK_OUT_OF_RANGE));
  }
  opt.progress = relay.callback();
  Embedding_ptr e;
  relay.run_without_gil([&] {
    e = compute_embedding(Va.data(), static_cast<std::size_t>(Va.shape(0)), Fa.data(), static_cast<std::size_t>(Fa.shape(0)),
                          static_cast<std::size_t>(Fa.shape(1)), ids, opt);
  });
  return e;
}

// the vertices of the embedded mesh: a view of its points (Surface_mesh stores them as one
// array of Point_3, three doubles each)
py::array vertex_view(py::object self)
{
  const Embedding& e = self.cast<const Embedding&>();
  static_assert(sizeof(Kernel::Point_3) == 3 * sizeof(double), "Epick's Point_3 is three doubles");
  const Kernel::Point_3* p = e.mesh.points().data();
  const std::size_t n = num_vertices(e.mesh);
  const double* data = reinterpret_cast<const double*>(p);
  if(n > 0 && &e.mesh.point(SM_vertex(static_cast<SM_vertex::size_type>(n - 1))).x() != data + 3 * (n - 1))
    fail(HOT::ERROR_WRONG_PARAMETER, "internal: the mesh's points are not one array"); // (cannot happen: checked for safety)
  return view_of(data, {static_cast<py::ssize_t>(n), 3}, self);
}

void write_obj(const Embedding& e, py::handle path)
{
  const py::bytes b = py::module_::import("os").attr("fsencode")(path);
  const std::string p(b);
  py::gil_scoped_release release;
  const hot_cli::Embedding_result result = result_of(e);
  try {
    // as the CLI's `embed` writes OUT.obj (write_embed_outputs(), without --repair)
    const hot_tools::Embedding_cones cones = hot_cli::embedding_cones(e.type, e.stats, e.landmark_ids);
    hot_cli::write_file_atomically(p, [&](std::ostream& os) { hot_tools::write_embedding_obj(os, result, nullptr, &cones); });
  } catch(const std::runtime_error& x) {
    fail(HOT::ERROR_WRITE_FAILED, x.what());
  }
}

template <class T>
py::list list_of_lists(const std::vector<std::vector<T> >& v)
{
  py::list r;
  for(const auto& row : v) {
    py::list l;
    for(const T& x : row) l.append(x);
    r.append(l);
  }
  return r;
}

template <class T>
py::array int64_array(const std::vector<T>& v)
{
  std::vector<std::int64_t> r(v.begin(), v.end());
  const py::ssize_t n = static_cast<py::ssize_t>(r.size());
  return owning_array(std::move(r), {n});
}

// register_embedding(): the Embedding class (its properties and methods)
void register_embedding_class(py::module_& m)
{
  py::class_<Embedding, Embedding_ptr>(m, "Embedding", R"doc(A certified hyperbolic orbifold Tutte embedding of a triangle mesh (returned by embed()).

It holds the mesh it embeds (built from V and F as the command line's reader builds a
mesh), the corner coordinates and the statistics. Arrays it returns are read-only views
of its own memory (no copy), valid as long as any of them or the object is alive.)doc")
    .def_property_readonly(
      "uv",
      [](py::object self) {
        const Embedding& e = self.cast<const Embedding&>();
        return view_of(e.corner_uv.data(), {static_cast<py::ssize_t>(e.faces.size() / 3), 3, 2}, self);
      },
      R"doc(float64 array of shape (m, 3, 2): the Poincare-disk coordinates of every face corner, corners
in the order of the face's vertices in F. The same numbers as the `vt` the command line's
OBJ gives that corner (a vertex on the cut has a different point on each side of it).
Where a face is written in a chart around a cone image (report "charted_faces" > 0), its
corners here are the tile points rounded to double, as the OBJ's vt lines.
A read-only view: calling e.uv twice gives two views of the same memory.)doc")
    .def_property_readonly("V", &vertex_view,
                           "float64 array of shape (n, 3): the vertices of the embedded mesh (a read-only view of its points)")
    .def_property_readonly(
      "F",
      [](py::object self) {
        const Embedding& e = self.cast<const Embedding&>();
        return view_of(e.faces.data(), {static_cast<py::ssize_t>(e.faces.size() / 3), 3}, self);
      },
      "int64 array of shape (m, 3): the faces of the embedded mesh (those given, a read-only view)")
    .def_property_readonly(
      "certified", [](const Embedding& e) { return e.stats.certificate.is_bijective(); },
      "bool: the bijectivity certificate's verdict (always True for a returned embedding: a failed one raises Error)")
    .def_property_readonly(
      "report",
      [](const Embedding& e) { return py::module_::import("json").attr("loads")(e.report); },
      R"doc(dict: the report of the command line's `embed --report` for this embedding (the same writer,
parsed with json.loads): sizes, cones, orbifold, weights, order, landmark_order_used (vertex
indices), cone_orders, genus, time per phase, iterations, energy, recentring, charts, certificate.
"mesh" is the name given to embed(). A new dict on every access.)doc")
    .def_property_readonly("report_json", [](const Embedding& e) { return e.report; },
                           "str: the report as the command line writes it (JSON text)")
    .def_property_readonly(
      "landmarks", [](const Embedding& e) { return int64_array(e.landmark_ids); },
      "int64 array: the landmarks (vertex indices) as given to embed()")
    .def_property_readonly(
      "landmark_order", [](const Embedding& e) { return int64_array(e.order); },
      R"doc(int64 array: the order of the landmarks used (the cone order), as positions in `landmarks`:
e.landmarks[e.landmark_order] is the report's "landmark_order_used". Give it as `order` to
embed a second mesh with corresponding landmarks in the same cone order, for map().)doc")
    .def_property_readonly(
      "cone_orders", [](const Embedding& e) { return std::vector<int>(e.stats.cone_orders.begin(), e.stats.cone_orders.end()); },
      "list of int: the order p of every cone (angle 2 pi / p) in the cone order (2 for all unless cone_orders was given)")
    .def_property_readonly(
      "orbifold", [](const Embedding& e) { return std::string(e.type == HOT::Sphere_type ? "sphere" : "disk"); },
      "str: 'sphere' (a closed mesh, of any genus) or 'disk'")
    .def_property_readonly("genus", [](const Embedding& e) { return e.genus; }, "int: the genus of the mesh (0 for the disk type)")
    .def_property_readonly("recentred", [](const Embedding& e) { return e.stats.recentred; },
                           "bool: the coordinates are in a moved frame (recentre=True was needed; see the report's frame)")
    .def_property_readonly(
      "cut_graph", [](const Embedding& e) { return list_of_lists(e.stats.cut_graph); },
      R"doc(list of lists of int: genus g >= 1, the cut graph used (vertex paths); give it as `cut_graph` to
embed a deformed copy of the mesh (the same faces) along the corresponding graph. Empty for genus 0.)doc")
    .def("write_obj", &write_obj, py::arg("path"),
         R"doc(write_obj(path)

Writes the embedding as the command line's `embed --out` writes OUT.obj (the same writer,
the same bytes): v = the vertices, vt = one Poincare point per cut-mesh vertex, f v/vt = the
faces in order, and the charts around cone images as comment lines when there are some.
The file is written to path.tmp and renamed when complete. Errors raise Error.

Example:
    >>> e = hot.embed(V, F, hot.select_landmarks(V, F, 7))
    >>> e.write_obj("bear_embedding.obj")   # then: hyperbolic_orbifold_tutte certify ...)doc")
    .def("__repr__", [](const Embedding& e) {
      std::ostringstream os;
      os << "<hyperbolic_orbifold_tutte.Embedding: " << num_vertices(e.mesh) << " vertices, " << num_faces(e.mesh) << " faces, "
         << (e.type == HOT::Sphere_type ? (e.genus > 0 ? "closed, genus " + std::to_string(e.genus) : std::string("sphere type")) : "disk type")
         << ", " << e.landmarks.size() << " landmarks, " << (e.stats.certificate.is_bijective() ? "certified bijective" : "not certified")
         << ">";
      return os.str();
    });
}

} // namespace

void register_embedding(py::module_& m)
{
  register_embedding_class(m);

  m.def("embed", &embed, py::arg("V"), py::arg("F"), py::arg("landmarks"), py::kw_only(), py::arg("orbifold") = "auto",
        py::arg("weights") = py::none(), py::arg("order") = "auto", py::arg("cone_orders") = py::none(), py::arg("recentre") = false,
        py::arg("cut_graph") = py::none(), py::arg("name") = "", py::arg("progress") = py::none(),
        R"doc(embed(V, F, landmarks, *, orbifold="auto", weights=None, order="auto", cone_orders=None, recentre=False, cut_graph=None, name="", progress=None)

Computes the certified hyperbolic orbifold Tutte embedding of the triangle mesh (V, F)
with the given landmarks at the orbifold's cones, as the command line's `embed` does (the
same reader checks, the same call of the library: the same numbers, bit for bit), and
returns an Embedding. The computation releases the GIL (threads run in parallel).

V: (n, 3) real array; F: (m, 3) integer array of vertex indices. Any array-like: a C-
  contiguous float64 V and int64 F are read in place (no copy); anything else (float32 or
  integer V, int32 F, Fortran order, strided views, lists, tuples) is converted once. A
  wrong shape, non-numeric data, a real-valued F (even of whole numbers) or a NaN
  coordinate raises InputError.
landmarks: vertex indices (a sequence or 1-D integer array): on a closed genus-0 mesh at
  least 5 (3 with cone_orders), genus 1 at least 1, genus 2 or more any number (also
  none); on a disk at least 5 boundary vertices, in boundary order.
orbifold: "auto" (sphere type if the mesh is closed, disk type if it has one boundary
  loop), "sphere" (or "closed") or "disk".
weights: "cotan" (clamped cotangent), "mvc" (mean value) or "uniform"; None (the default):
  the cotangent weights, or the mean value weights when the cotangent embedding fails the
  certificate (as the command line's embed without --weights, map and collection; the
  report's "weights" says which).
order: the cone order of the landmarks: "auto" ("tsp" for a closed genus-0 mesh, "given"
  otherwise, as the command line's default), "tsp" (the paper's tour through the
  landmarks), "given", or a sequence of landmark positions (a permutation of
  0..k-1, e.g. another embedding's landmark_order: landmarks[order[i]] goes to cone i).
cone_orders: the order p of every landmark's cone (angle 2 pi / p), in the order of
  `landmarks` (default 2 for all: angle pi); sphere type; the orbifold must be hyperbolic.
recentre: allows a part too squeezed for double in the tile to be solved in a moved frame
  (the result is then in that frame; maps need embeddings in the tile itself).
cut_graph: genus g >= 1: the graph to cut along (vertex paths, e.g. another embedding's
  cut_graph on a deformed copy); default: computed.
name: the report's "mesh" field.
progress: None, or a callable progress(phase, fraction) told the phases "input", "cut",
  "initialization", "optimization" and "certificate" in that order, each from 0.0 to 1.0
  (the optimization's fraction after each Newton step: the gradient norm's progress towards
  the tolerance on a log scale), from the calling thread, the GIL held; the command line's
  --progress lines. An exception it raises is raised by embed() when the embedding has ended
  (the computation is not interrupted; the later reports are not passed on). The result is
  the same, bit for bit, with or without it.

Every failure (bad input, too few or duplicate landmarks, a non-manifold mesh, no
certified result, ...) raises Error with the library's message.

Example:
    >>> V, F = hot.read_mesh("bear.off")
    >>> e = hot.embed(V, F, hot.select_landmarks(V, F, 7))
    >>> e.uv.shape, e.report["certificate"]["bijective"]   # ((m, 3, 2), True)
    >>> e = hot.embed(V, F, lm, progress=lambda phase, f: print(phase, round(100 * f), "%")))doc");
}

// ---------------------------------------------------------------------------------------
// map
// ---------------------------------------------------------------------------------------

namespace {

typedef hot_cli::Locator Locator;

// the locator of a map's target, the command line's target_locator()
Locator target_locator(const Embedding& B)
{
  try {
    return hot_cli::target_locator(result_of(B));
  } catch(const hot_cli::Failure& f) {
    fail(f.code, f.message);
  }
}

std::string list_string(const std::vector<std::size_t>& v)
{
  std::ostringstream os;
  os << "[";
  for(std::size_t i = 0; i < v.size(); ++i) os << (i ? ", " : "") << v[i];
  os << "]";
  return os.str();
}

// the source and the target of a map must be embedded into one orbifold with corresponding
// cones (the checks of the command line's map, and the ones its single cone order makes
// needless there)
void check_map_pair(const Embedding& A, const Embedding& B)
{
  if(A.type != B.type)
    fail(HOT::ERROR_WRONG_TOPOLOGY, "the source is " + std::string(A.type == HOT::Sphere_type ? "closed" : "a disk") +
                                      " but the target is " + (B.type == HOT::Sphere_type ? "closed" : "a disk"));
  if(A.landmarks.size() != B.landmarks.size())
    fail(HOT::ERROR_WRONG_PARAMETER, "the source has " + std::to_string(A.landmarks.size()) + " landmarks and the target " +
                                       std::to_string(B.landmarks.size()));
  if(A.genus != B.genus)
    fail(HOT::ERROR_WRONG_TOPOLOGY, "the source has genus " + std::to_string(A.genus) + " and the target genus " + std::to_string(B.genus));
  if(A.order != B.order)
    fail(HOT::ERROR_WRONG_PARAMETER, "the landmarks are not in the same cone order: the source's landmark_order is " + list_string(A.order) +
                                       ", the target's " + list_string(B.order) +
                                       " (landmark i of the source corresponds to landmark i of the target: embed the target with "
                                       "order=source.landmark_order)");
  if(A.stats.cone_orders != B.stats.cone_orders)
    fail(HOT::ERROR_WRONG_PARAMETER, "the cones of the source and the target have different orders (cone_orders): "
                                     "the two orbifolds differ");
  if(A.stats.recentred || B.stats.recentred)
    fail(HOT::ERROR_WRONG_PARAMETER, std::string("the ") + (A.stats.recentred ? "source" : "target") +
                                       " was embedded in a recentred frame: maps need embeddings in the tile itself (embed without recentre)");
  if(A.genus > 0) {
    const HOT::Embedding_statistics &a = A.stats, &b = B.stats;
    if(a.cut_corner_nodes != b.cut_corner_nodes || a.cut_node_cones != b.cut_node_cones || a.cut_paired_sides != b.cut_paired_sides)
      fail(HOT::ERROR_WRONG_PARAMETER, "the cut graphs of the source and the target do not correspond: their polygons differ (" +
                                         std::to_string(a.cut_corner_nodes.size()) + " and " + std::to_string(b.cut_corner_nodes.size()) +
                                         " corners, or other side pairings); embed the target with cut_graph=source.cut_graph "
                                         "(a deformed copy) or with a corresponding cut graph");
  }
  if(A.stats.landmark_order_reversed != B.stats.landmark_order_reversed)
    fail(HOT::ERROR_WRONG_PARAMETER, "the landmarks run clockwise around one boundary and counterclockwise around the other: "
                                     "the correspondence would reverse orientation");
}

} // namespace

namespace {

// A's corners as a read-write property map over a vector (a refined copy of A.uv)
struct Corner_vector_map
{
  typedef SM_halfedge key_type;
  typedef Kernel::Point_2 value_type;
  typedef value_type& reference;
  typedef boost::lvalue_property_map_tag category;
  std::vector<value_type>* points;
  friend value_type& get(const Corner_vector_map& m, SM_halfedge h) { return (*m.points)[h.idx()]; }
  friend void put(const Corner_vector_map& m, SM_halfedge h, const value_type& p) { (*m.points)[h.idx()] = p; }
};

} // namespace

void map_embeddings(const Embedding& A, const Embedding& B, std::vector<std::int64_t>& faces, std::vector<double>& bary,
                    std::vector<std::int64_t>* unreliable, int refine, HOT::Map_refinement_statistics* refinement,
                    const std::function<void(const char*, double)>& progress)
{
  check_map_pair(A, B);
  if(refine < 0)
    fail(HOT::ERROR_WRONG_PARAMETER, "refine must be 0 (no refinement) or a number of iterations, got " + std::to_string(refine));
  if(refine > 0 && !A.stats.charts.empty()) // (the library refuses the rest: genus 1 or more)
    fail(HOT::ERROR_WRONG_PARAMETER, "refine handles sources embedded without charts; the source is embedded partly in charts around cone images");
  const Locator locB = target_locator(B);
  if(!locB.is_valid())
    fail(HOT::ERROR_POINT_NOT_LOCATED, "the target's embedding cannot be searched: " + locB.message());
  std::vector<Kernel::Point_2> refined;
  std::vector<Locator::Location> f;
  if(refine > 0) {
    refined.resize(A.mesh.number_of_halfedges() + A.mesh.number_of_removed_halfedges());
    for(SM_halfedge h : halfedges(A.mesh))
      refined[h.idx()] = A.uv[h];
    const Corner_vector_map uv{&refined};
    std::vector<SM_vertex> ordered;
    for(std::size_t i : A.order)
      ordered.push_back(A.landmarks[i]);
    HOT::Map_refinement_statistics st;
    const HOT::Error_code ec = HOT::refine_orbifold_map(A.mesh, ordered, uv, B.mesh, locB, st,
      HOT::parameters::refine(refine, HOT::parameters::frame(A.stats.frame, HOT::parameters::cone_orders(A.stats.cone_orders,
        HOT::parameters::orbifold_type(A.type, HOT::parameters::progress(progress))))));
    if(ec != HOT::OK)
      fail(ec, "refine: " + st.message);
    if(refinement)
      *refinement = st;
    f = HOT::map_vertices(A.mesh, uv, locB);
  } else
    f = HOT::map_vertices(result_of(A), locB);
  faces.resize(f.size());
  bary.resize(3 * f.size());
  for(std::size_t i = 0; i < f.size(); ++i) {
    if(!f[i].success)
      fail(HOT::ERROR_POINT_NOT_LOCATED, "vertex " + std::to_string(i) + " of the source could not be located on the target");
    const std::array<double, 3> b = hot_tools::input_order_barycentric(B.mesh, locB, f[i]);
    faces[i] = static_cast<std::int64_t>(f[i].face_index);
    for(int c = 0; c < 3; ++c) bary[3 * i + c] = b[c];
  }
  if(unreliable) {
    const HOT::Map_reliability r = refine > 0 ? HOT::map_reliability(A.mesh, Corner_vector_map{&refined}, B.mesh, B.uv, locB, f)
                                              : HOT::map_reliability(A.mesh, A.uv, B.mesh, B.uv, locB, f);
    unreliable->assign(r.unreliable_vertices.begin(), r.unreliable_vertices.end());
  }
}

namespace {

py::tuple map(const Embedding_ptr& A, const Embedding_ptr& B, bool unreliable, int refine)
{
  if(!A || !B)
    fail(HOT::ERROR_WRONG_PARAMETER, "map() needs two embeddings");
  std::vector<std::int64_t> faces, flagged;
  std::vector<double> bary;
  {
    py::gil_scoped_release release;
    map_embeddings(*A, *B, faces, bary, unreliable ? &flagged : nullptr, refine);
  }
  const py::ssize_t n = static_cast<py::ssize_t>(faces.size()), u = static_cast<py::ssize_t>(flagged.size());
  py::array f = owning_array(std::move(faces), {n}), b = owning_array(std::move(bary), {n, 3});
  if(!unreliable)
    return py::make_tuple(f, b);
  return py::make_tuple(f, b, owning_array(std::move(flagged), {u}));
}

// the landmark orders map_meshes() tries in turn, best first: the command line's map's choice
// (map_landmark_orders(), application/hot_app/map_order.h); an explicit order alone (mesh npos:
// neither mesh's tour)
std::vector<HOT::Landmark_order_candidate> map_meshes_orders(const Embed_options& opt, const Embedding& A, const Embedding& B)
{
  if(opt.order == "explicit") {
    HOT::Landmark_order_candidate given;
    given.mesh = std::size_t(-1);
    given.longest_ratio = 1;
    given.order = opt.explicit_order; // (checked by compute_embedding())
    return {given};
  }
  try {
    return hot_cli::map_landmark_orders(opt.order, A.type, A.genus, A.mesh, A.landmarks, B.mesh, B.landmarks);
  } catch(const hot_cli::Failure& f) {
    fail(f.code, f.message);
  }
}

struct Mesh_map
{
  Embedding_ptr A, B;
  HOT::Landmark_order_candidate chosen;
  std::vector<std::string> refusals;
  std::vector<std::int64_t> faces, flagged;
  std::vector<double> bary;
  bool augmented = false;
  std::vector<std::int64_t> added; // augmented: (source vertex, target vertex) per pair added
};

// augmented: the thin tips the landmarks leave out, matched across the meshes
// (match_extremities(), as map --augment), appended to both meshes' landmarks (and an order 2
// to the cone orders when some are given)
void augment_landmarks(Embedding& a0, Embedding& b0, std::vector<std::size_t>& ida, std::vector<std::size_t>& idb, Embed_options& opt,
                       std::vector<std::int64_t>& added)
{
  if(opt.order == "explicit")
    fail(HOT::ERROR_WRONG_PARAMETER, "augment adds landmarks, so an order given as positions does not fit: give order \"auto\", \"tsp\" or \"given\"");
  HOT::Extremity_matching<SM_vertex> xm;
  try {
    xm = hot_cli::augment_landmarks(a0.type, a0.genus, b0.genus, a0.mesh, a0.landmarks, b0.mesh, b0.landmarks, opt.cone_orders, "augment");
  } catch(const hot_cli::Failure& f) {
    fail(f.code, f.message);
  }
  for(const std::pair<SM_vertex, SM_vertex>& p : xm.pairs) { // (the meshes' vertex i is row i of V)
    ida.push_back(static_cast<std::size_t>(p.first.idx()));
    idb.push_back(static_cast<std::size_t>(p.second.idx()));
    added.push_back(static_cast<std::int64_t>(p.first.idx()));
    added.push_back(static_cast<std::int64_t>(p.second.idx()));
  }
}

// `progress` with `who` put before every phase's name (empty stays empty)
std::function<void(const char*, double)> told_as(const char* who, const std::function<void(const char*, double)>& progress)
{
  if(!progress)
    return progress;
  return [who, progress](const char* phase, double fraction) { progress((std::string(who) + phase).c_str(), fraction); };
}

// map_meshes() without Python: the command line's run_map() on arrays (the order choice, the
// embeddings in that order, the next order when one is refused for a reason the order may cause,
// the map)
void compute_mesh_map(const Double_array& VA, const Index_array& FA, std::vector<std::size_t> ida, const Double_array& VB,
                      const Index_array& FB, std::vector<std::size_t> idb, Embed_options opt, bool unreliable, int refine,
                      std::optional<bool> augment, Mesh_map& r)
{
  const auto rows = [](const auto& a) { return static_cast<std::size_t>(a.shape(0)); };
  const auto cols = [](const auto& a) { return static_cast<std::size_t>(a.shape(1)); };
  Embedding a0, b0; // the meshes and landmarks, read and checked (for the order choice)
  try {
    read_mesh_and_landmarks(VA.data(), rows(VA), FA.data(), rows(FA), cols(FA), ida, opt, a0);
  } catch(Hot_error& e) {
    e.message = "the source (VA, FA, landmarks_a): " + e.message;
    throw;
  }
  try {
    read_mesh_and_landmarks(VB.data(), rows(VB), FB.data(), rows(FB), cols(FB), idb, opt, b0);
  } catch(Hot_error& e) {
    e.message = "the target (VB, FB, landmarks_b): " + e.message;
    throw;
  }
  // (the command line's check_map_pair(), before the order)
  if(a0.type != b0.type)
    fail(HOT::ERROR_WRONG_TOPOLOGY, "the source is " + std::string(a0.type == HOT::Sphere_type ? "closed" : "a disk") +
                                      " but the target is " + (b0.type == HOT::Sphere_type ? "closed" : "a disk"));
  if(ida.size() != idb.size())
    fail(HOT::ERROR_WRONG_PARAMETER, "the source has " + std::to_string(ida.size()) + " landmarks and the target " + std::to_string(idb.size()) +
                                       " (landmark i of the source corresponds to landmark i of the target)");
  if(a0.genus != b0.genus)
    fail(HOT::ERROR_WRONG_TOPOLOGY, "the source has genus " + std::to_string(a0.genus) + " and the target genus " + std::to_string(b0.genus));
  // genus g >= 1: the target is cut along the source's cut graph, which needs the same faces
  // (the command line's map_cut_graphs() without cut graph files)
  const bool genus_cut = a0.genus > 0;
  if(genus_cut && (rows(VA) != rows(VB) || rows(FA) != rows(FB) || cols(FA) != cols(FB) ||
                   !std::equal(FA.data(), FA.data() + FA.size(), FB.data())))
    fail(HOT::ERROR_WRONG_PARAMETER, "the meshes have genus " + std::to_string(a0.genus) +
                                       " and not the same faces: a map between them depends on corresponding cut graphs;"
                                       " embed both with corresponding cut_graph= and call map()");
  if(refine > 0) // (refused before the embeddings, not after)
    if(const HOT::Status refusal = HOT::check_refinable_source(a0.mesh); !refusal)
      fail(refusal.code, "refine: " + refusal.message);
  // augment=None: with refine > 0 on closed genus-0 meshes (as map --refine without --no-augment)
  r.augmented = augment ? *augment : refine > 0 && a0.type == HOT::Sphere_type && a0.genus == 0 && b0.genus == 0 && opt.order != "explicit";
  if(r.augmented)
    augment_landmarks(a0, b0, ida, idb, opt, r.added);
  const std::vector<HOT::Landmark_order_candidate> candidates = map_meshes_orders(opt, a0, b0);
  const char* embedding = "source"; // (the one being embedded)
  HOT::Error_code code = HOT::OK;
  std::string message;
  const std::size_t c = hot_cli::embed_in_first_accepted_order<Hot_error>(
    candidates,
    [&](const HOT::Landmark_order_candidate& candidate, bool target_first) {
      r.A.reset();
      r.B.reset();
      Embed_options o = opt;
      o.order = "explicit";
      o.explicit_order = candidate.order;
      const auto embed_a = [&] {
        embedding = "source";
        Embed_options oa = o;
        oa.progress = told_as("source: ", opt.progress);
        r.A = compute_embedding(VA.data(), rows(VA), FA.data(), rows(FA), cols(FA), ida, oa);
      };
      const auto embed_b = [&] {
        embedding = "target";
        Embed_options ob = o;
        ob.progress = told_as("target: ", opt.progress);
        if(genus_cut) {
          ob.has_cut_graph = true;
          ob.cut_graph = r.A->stats.cut_graph;
        }
        r.B = compute_embedding(VB.data(), rows(VB), FB.data(), rows(FB), cols(FB), idb, ob);
      };
      if(target_first) {
        embed_b();
        embed_a();
      } else {
        embed_a();
        embed_b();
      }
    },
    [&](const Hot_error& f) { return std::string(embedding) + ": " + f.message; }, r.refusals, code, message);
  if(c == std::size_t(-1))
    fail(code, message);
  r.chosen = candidates[c];
  map_embeddings(*r.A, *r.B, r.faces, r.bary, unreliable ? &r.flagged : nullptr, refine, nullptr, opt.progress);
}

py::dict map_meshes(py::handle VA, py::handle FA, py::handle landmarks_a, py::handle VB, py::handle FB, py::handle landmarks_b,
                    const std::string& orbifold, py::handle weights, py::handle order, py::handle cone_orders, bool unreliable,
                    int refine, std::optional<bool> augment, py::handle progress)
{
  Progress_relay relay(progress);
  const Double_array Va = vertex_array(VA, "VA"), Vb = vertex_array(VB, "VB");
  const Index_array Fa = face_array(FA, "FA"), Fb = face_array(FB, "FB");
  const std::vector<std::size_t> ida = index_list(landmarks_a, "landmark", HOT::ERROR_LANDMARK_OUT_OF_RANGE);
  const std::vector<std::size_t> idb = index_list(landmarks_b, "landmark", HOT::ERROR_LANDMARK_OUT_OF_RANGE);
  Embed_options opt;
  opt.type = parse_orbifold(orbifold);
  parse_weights(weights, opt);
  parse_order_options(order, cone_orders, opt);
  if(refine < 0)
    fail(HOT::ERROR_WRONG_PARAMETER, "refine must be 0 (no refinement) or a number of iterations, got " + std::to_string(refine));
  opt.progress = relay.callback();
  Mesh_map r;
  relay.run_without_gil([&] { compute_mesh_map(Va, Fa, ida, Vb, Fb, idb, opt, unreliable, refine, augment, r); });
  const py::ssize_t n = static_cast<py::ssize_t>(r.faces.size()), u = static_cast<py::ssize_t>(r.flagged.size());
  py::dict d;
  d["faces"] = owning_array(std::move(r.faces), {n});
  d["bary"] = owning_array(std::move(r.bary), {n, 3});
  d["unreliable"] = unreliable ? py::object(owning_array(std::move(r.flagged), {u})) : py::object(py::none());
  d["source"] = r.A;
  d["target"] = r.B;
  d["landmark_order"] = int64_array(r.A->order);
  d["landmark_order_from"] = r.chosen.mesh == 0 ? "source" : r.chosen.mesh == 1 ? "target" : "given";
  d["orders_tried"] = r.refusals.size() + 1;
  py::list refused;
  for(const std::string& x : r.refusals) refused.append(x);
  d["refused"] = refused;
  const py::ssize_t p = static_cast<py::ssize_t>(r.added.size() / 2);
  d["added"] = r.augmented ? py::object(owning_array(std::move(r.added), {p, 2})) : py::object(py::none());
  return d;
}

} // namespace

void register_maps(py::module_& m)
{
  m.def("map_meshes", &map_meshes, py::arg("VA"), py::arg("FA"), py::arg("landmarks_a"), py::arg("VB"), py::arg("FB"), py::arg("landmarks_b"),
        py::kw_only(), py::arg("orbifold") = "auto", py::arg("weights") = py::none(), py::arg("order") = "auto",
        py::arg("cone_orders") = py::none(), py::arg("unreliable") = false, py::arg("refine") = 0, py::arg("augment") = py::none(),
        py::arg("progress") = py::none(),
        R"doc(map_meshes(VA, FA, landmarks_a, VB, FB, landmarks_b, *, orbifold="auto", weights=None, order="auto", cone_orders=None, unreliable=False, refine=0, augment=None, progress=None) -> dict

Maps mesh A = (VA, FA) onto mesh B = (VB, FB) in one call, as the command line's `map`
does: landmark i of landmarks_a corresponds to landmark i of landmarks_b; both meshes are
embedded in one landmark order chosen as `map --order auto` chooses it, then A is mapped
onto B (map()). Releases the GIL.

VA, VB: (n, 3) real arrays; FA, FB: (m, 3) integer arrays; landmarks_a, landmarks_b:
  vertex indices, as many on both. Any array-like is accepted (see embed()).
orbifold, weights, cone_orders: as embed()'s, for both meshes (cone_orders[i] is the
  order of the cone of landmark i of both).
order: "auto" (sphere type of genus 0: the source's landmark tour or the target's, the one
  whose cut is the least longer than each mesh's own tour on the mesh where it is the most
  so (rank_landmark_tours(), the source's on ties); if a mesh refuses it (the cut, the
  solver or the certificate fails), the other one; the disk type and genus g >= 1: the
  given order), "tsp" (the source's tour only), "given" (the order of the landmarks), or
  a sequence of landmark positions (a permutation, as embed()'s order).
unreliable, refine: as map()'s.
augment: True adds to both meshes' landmarks the thin tips the landmarks leave out (a tail, a
  heel), matched by their geodesic distances to the landmarks, as `map --augment` does
  (closed meshes of genus 0; an order 2 is appended to cone_orders when given); the added
  pairs come after the given landmarks (positions k, k+1, ... in "landmark_order").
  None (the default): True when refine > 0 on closed genus-0 meshes and order is not a
  sequence (as `map --refine`), else False; False: never.
progress: as embed()'s, the phases of the two embeddings named "source: PHASE" and
  "target: PHASE" (a mesh embedded again in another order tells its phases again), then
  with refine=N the phase "refinement": 0, i / N after iteration i, 1 at its end.

Returns a dict (the map() result and how it was made):
  "faces", "bary": map()'s result (int64 (nA,), float64 (nA, 3)): vertex i of A goes to
      bary[i] @ VB[FB[faces[i]]] (surface_points(faces, bary, VB, FB));
  "unreliable": with unreliable=True, map()'s third array; else None;
  "source", "target": the two Embedding objects (each certified);
  "landmark_order": the order used (int64 array of landmark positions, the embeddings'
      landmark_order); "landmark_order_from": "source", "target" (whose tour it is) or
      "given"; "orders_tried": 1, or 2 when the first order was refused; "refused": the
      refusals' messages (a list of str, empty when the first order was taken);
  "added": when augmented, the pairs added (int64 (p, 2): source vertex, target vertex,
      possibly none); else None.
The same numbers as the two-step call embed(VA, FA, landmarks_a, order=o),
embed(VB, FB, landmarks_b, order=o), map() with o = the returned landmark_order.
Genus g >= 1: B must have A's faces (a deformed copy): it is cut along A's cut graph.

Bad input (arrays, landmarks, meshes of different types, genera or numbers of landmarks)
raises InputError, prefixed by "the source" or "the target" for a mesh's own checks; an
embedding or map that cannot be computed, ComputationError.

Example:
    >>> r = hot.map_meshes(VA, FA, la, VB, FB, lb)
    >>> images = hot.surface_points(r["faces"], r["bary"], VB, FB)  # (nA, 3) points of B
    >>> r["landmark_order_from"], r["source"].landmark_order)doc");

  m.def("map", &map, py::arg("source"), py::arg("target"), py::kw_only(), py::arg("unreliable") = false, py::arg("refine") = 0,
        R"doc(map(source, target, *, unreliable=False, refine=0) -> (faces, bary) or (faces, bary, unreliable_vertices)

Maps every vertex of the source embedding's mesh A onto the target's mesh B through
their common orbifold (the paper's section 7), as the command line's `map` does: for
vertex i of A, faces[i] is the face of B (an index into B's F, int64 array of shape
(n,)) and bary[i] its barycentric coordinates w.r.t. that face's vertices in F's order
(float64 array of shape (n, 3)): the numbers of the `face b0 b1 b2` lines of the command
line's MAP.txt. The point of B is bary[i] @ VB[FB[faces[i]]] (see transfer()).

Both embeddings must be of one orbifold with corresponding cones: the same type, genus,
number of landmarks, cone orders and cone order (landmark_order). The command line's map
chooses one landmark order for both meshes; map_meshes() does the same from the arrays in
one call. Here embed the target with order=source.landmark_order (and, for genus g >= 1 on
a deformed copy, cut_graph=source.cut_graph). Anything else raises Error saying what differs. Releases
the GIL.

unreliable=True also returns the vertices of A whose images the map cannot resolve (int64
array, increasing): in a protrusion without a landmark, squeezed by both embeddings below
their disagreement (the command line's map report's "unreliable_vertices"; put a landmark
at the tip of such a protrusion).

refine=N (N >= 1) refines the map towards an isometry first, as the command line's
map --refine N does (refine_orbifold_map(): at most N certified iterations lowering the
symmetric Dirichlet energy; landmarks kept, every iterate certified bijective), on a copy
of the source's corners: `source` itself is unchanged. Genus 0 and a source embedded
without charts only (else Error).

Example:
    >>> a = hot.embed(VA, FA, la)
    >>> b = hot.embed(VB, FB, lb, order=a.landmark_order)
    >>> faces, bary = hot.map(a, b, refine=100)
    >>> images = np.einsum("ij,ijk->ik", bary, VB[FB[faces]]))doc");
}

} // namespace hot_python
