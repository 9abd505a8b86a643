// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef HOT_PYTHON_HOT_PYTHON_H
#define HOT_PYTHON_HOT_PYTHON_H

// What the translation units of the Python extension `_core` share: the mesh types (those of
// the command-line program), the error type that becomes `hyperbolic_orbifold_tutte.Error`,
// numpy helpers (arrays read in place, arrays that own C++ buffers), the mesh built from
// (V, F) as the command line's reader builds it, the `Embedding` class, and one
// registration function per area of the module (module.cpp calls them in order).
//
// Areas and their files:
//   register_errors, register_io (read_mesh, select_landmarks)      module.cpp
//   register_embedding (embed, Embedding), register_maps (map,      embedding.cpp
//     map_meshes: the CLI's map on arrays, its landmark order choice)
//   register_collection (the jobs of collection())                  collection.cpp
//   register_distortion (map_distortion)                            distortion.cpp
//   register_view (view: the command line's view job's folder)      view.cpp
// compute_embedding() and map_embeddings() (embedding.cpp) are the embed and map of the module
// without Python, for those areas to reuse (an Embedding_ptr is the Python class Embedding).

// the mesh's header first: Seam_mesh calls CGAL::halfedges(tm) etc. qualified
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Hyperbolic_orbifold_Tutte/Chart_point.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/Embedding_statistics.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/Map_refinement_statistics.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/check_input.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/error_code.h>

#include "hot_app/job_input.h"
#include "hot_app/io/prepared_input.h"
#include "hot_app/io/reports.h"

#include <pybind11/eval.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace hot_python {

namespace py = pybind11;
namespace HOT = CGAL::Hyperbolic_orbifold_Tutte;

// (the jobs' mesh types, application/hot_app/job_input.h)
using hot_cli::Kernel;
using hot_cli::Surface_mesh;
using hot_cli::SM_vertex;
using hot_cli::SM_halfedge;
using hot_cli::SM_face;
using hot_cli::UV_map;
using hot_cli::Chart_map;

// ---------------------------------------------------------------------------------------
// Errors: every failure is raised as a hyperbolic_orbifold_tutte.Error (its subclass InputError
// or ComputationError by the code: the table in module.cpp) with the library's message, `.code`
// the Error_code's name ("ERROR_NON_MANIFOLD"), `.code_value` its number, `.description`.
// ---------------------------------------------------------------------------------------

struct Hot_error
{
  HOT::Error_code code;
  std::string message;
};

// the name of an Error_code ("OK", "ERROR_...")
const char* error_code_name(HOT::Error_code code);

// throws the failure of `s` as a Hot_error
inline void require(const HOT::Status& s)
{
  if(!s)
    throw Hot_error{s.code, s.message};
}

[[noreturn]] inline void fail(HOT::Error_code code, const std::string& message)
{
  throw Hot_error{code, message};
}

// ---------------------------------------------------------------------------------------
// numpy
// ---------------------------------------------------------------------------------------

typedef py::array_t<double, py::array::c_style | py::array::forcecast> Double_array;
typedef py::array_t<std::int64_t, py::array::c_style | py::array::forcecast> Index_array;

// a numpy array of `shape` over `data`, kept alive by `owner` (a view: no copy); read-only
// unless `writeable`
template <class T>
py::array view_of(const T* data, std::vector<py::ssize_t> shape, py::handle owner, bool writeable = false)
{
  py::array a(py::dtype::of<T>(), std::move(shape), data, owner);
  if(!writeable)
    py::detail::array_proxy(a.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
  return a;
}

// a numpy array that owns `v` (moved into a capsule: no copy)
template <class T>
py::array owning_array(std::vector<T>&& v, std::vector<py::ssize_t> shape)
{
  auto* p = new std::vector<T>(std::move(v));
  py::capsule owner(p, [](void* q) { delete static_cast<std::vector<T>*>(q); });
  return py::array(py::dtype::of<T>(), std::move(shape), p->data(), owner);
}

// Every array input of the module is read by these, once (`what` names it in messages):
// `obj` is any array-like (a numpy array of any numeric dtype and memory layout, a list, a
// tuple). A C-contiguous float64 (vertices) or int64 (indices) array is read in place (no
// copy); anything else is converted once (float32, integers, Fortran order, strided views,
// lists). Wrong shapes, non-numeric data, ragged lists and, for indices, a dtype that is not
// an integer one (a float array, even of whole numbers) fail with ERROR_WRONG_PARAMETER
// (InputError). NaN coordinates are refused by the mesh's checks (mesh_from_arrays()).

// `obj` as a C-contiguous float64 array of shape (n, 3): read in place when it is one already
// (no copy), converted otherwise
Double_array vertex_array(py::handle obj, const char* what = "V");
// `obj` as a C-contiguous int64 array of shape (m, k): an integer dtype only, read
// in place when already C-contiguous int64
Index_array face_array(py::handle obj, const char* what = "F");
// `obj` (a sequence or 1-D array of integers, possibly empty) as integers; `what` names it in
// messages ("cone_orders")
std::vector<std::int64_t> int_list(py::handle obj, const char* what);
// the same as non-negative indices (`code` for a negative one); `what` names one item in
// messages ("landmark")
std::vector<std::size_t> index_list(py::handle obj, const char* what, HOT::Error_code code);

// ---------------------------------------------------------------------------------------
// meshes from arrays
// ---------------------------------------------------------------------------------------

// Builds `mesh` from V (n x 3) and F (m x k) as the command line's reader builds a mesh from a
// file's polygon soup (hot_tools::polygon_soup_to_mesh(): vertex i = V[i], face j = F[j] with
// its first vertex as source(halfedge(face))), then checks it (HOT::check_mesh(), for
// `required_type` or the detected type). Does not need the GIL: `V` and `F` point to the arrays'
// data, held by the caller. Errors as hot_tools::read_and_check_mesh() gives them.
void mesh_from_arrays(const double* V, std::size_t n, const std::int64_t* F, std::size_t m, std::size_t k,
                      std::optional<HOT::Orbifold_type> required_type, Surface_mesh& mesh, HOT::Mesh_info& info);

// the orbifold option: "auto" (std::nullopt), "sphere", "closed" or "disk"
std::optional<HOT::Orbifold_type> parse_orbifold(const std::string& s);

// ---------------------------------------------------------------------------------------
// embeddings
// ---------------------------------------------------------------------------------------

// A certified embedding and the mesh it embeds (the Python class Embedding)
struct Embedding
{
  Surface_mesh mesh;                      // built from (V, F) as the CLI's reader does
  HOT::Orbifold_type type = HOT::Sphere_type;
  long long genus = 0;
  std::vector<SM_vertex> landmarks;       // as given
  std::vector<std::size_t> landmark_ids;  // their vertex indices, as given
  std::vector<std::size_t> order;         // the order used: positions in `landmarks`
  UV_map uv;                              // per corner (halfedge): the Poincare point (tile point)
  Chart_map charts;                       // per corner: its chart point (charts around cone images)
  HOT::Embedding_statistics stats;
  hot_tools::Embedding_request request;   // what the report repeats
  std::string report;                     // the JSON of hot_tools::write_embedding_report()
  std::vector<double> corner_uv;          // m x 3 x 2: the corners in the order of F
  std::vector<std::int64_t> faces;        // m x 3: F
};

typedef std::shared_ptr<Embedding> Embedding_ptr;

// the embedding as the library's result type (its layout: the statistics')
inline hot_cli::Embedding_result result_of(const Embedding& e)
{
  return hot_cli::embedding_result(e.mesh, e.uv, e.charts, e.stats, e.landmarks);
}

// what embed() is asked for, besides the mesh and the landmarks
struct Embed_options
{
  std::optional<HOT::Orbifold_type> type; // std::nullopt: from the mesh
  std::string weights = "cotan";          // cotan, mvc, uniform
  bool mean_value_fallback = false;       // weights=None: cotan, or mvc when the cotangent embedding fails the certificate
  std::string order = "auto";             // auto (the type's default), tsp, given, explicit
  std::vector<std::size_t> explicit_order; // order == "explicit": positions in the landmarks
  std::vector<int> cone_orders;           // per landmark as given (empty: 2 for all)
  bool recentre = false;
  bool has_cut_graph = false;
  std::vector<std::vector<std::size_t> > cut_graph; // vertex paths (genus g >= 1)
  std::string name;                       // the report's "mesh"
  std::function<void(const char*, double)> progress; // the library's progress reports (empty: none)
};

// A Python callable progress(phase: str, fraction: float) told the library's progress reports
// from a computation that runs without the GIL: the GIL is taken for each call; an exception the
// callable raises is kept, the later reports are not passed on, and rethrow() raises it when the
// computation has ended (the computation itself is not interrupted).
class Progress_relay
{
public:
  explicit Progress_relay(py::handle f);
  // the callback to give the library (empty when the callable is None); `prefix` is put before
  // every phase's name (e.g. "source: ")
  std::function<void(const char*, double)> callback(const std::string& prefix = std::string());
  // with the GIL: raises the callable's exception, if it raised one
  void rethrow();
  // runs `work` without the GIL, then raises the callable's exception if it raised one (before
  // any exception of `work`: it came first)
  template <class Work>
  void run_without_gil(Work&& work)
  {
    try {
      py::gil_scoped_release release;
      work();
    } catch(...) {
      rethrow();
      throw;
    }
    rethrow();
  }

private:
  py::object f_;
  bool failed_ = false;
  std::unique_ptr<py::error_already_set> error_;
};

// Computes the embedding of the mesh (V, F) (n x 3, m x k arrays) with the landmarks `ids`
// (vertex indices), as the command line's `embed` does (run_embed()): the mesh read and checked,
// the landmarks checked against it, the same job given to hot_cli::embed_mesh(). Does not need
// the GIL. Failures throw Hot_error.
Embedding_ptr compute_embedding(const double* V, std::size_t n, const std::int64_t* F, std::size_t m, std::size_t k,
                                const std::vector<std::size_t>& ids, const Embed_options& opt);

// The command line's map (run_map()) of two embeddings, checked to be of one orbifold with
// corresponding cones: every vertex of A located on B (`faces`, indices in B's F) and its
// barycentric coordinates w.r.t. the vertices of that face in F's order (`bary`, 3 per vertex,
// hot_tools::input_order_barycentric(), as write_map() writes them); with `unreliable`, the
// vertices of A whose images the map cannot resolve (HOT::map_reliability(), the map report's
// "unreliable_vertices"). With `refine` > 0, the map refined by HOT::refine_orbifold_map() (at
// most `refine` iterations, on a copy of A's corners: A is unchanged; `refinement` gets its
// statistics if not null; `progress`, if not empty, is told the phase "refinement"). Does not
// need the GIL. Failures throw Hot_error.
void map_embeddings(const Embedding& A, const Embedding& B, std::vector<std::int64_t>& faces, std::vector<double>& bary,
                    std::vector<std::int64_t>* unreliable = nullptr, int refine = 0,
                    HOT::Map_refinement_statistics* refinement = nullptr,
                    const std::function<void(const char*, double)>& progress = std::function<void(const char*, double)>());

// ---------------------------------------------------------------------------------------
// registration, one function per area (module.cpp calls them)
// ---------------------------------------------------------------------------------------

void register_errors(py::module_& m);
void register_io(py::module_& m);
void register_embedding(py::module_& m);
void register_maps(py::module_& m);
void register_collection(py::module_& m);
void register_distortion(py::module_& m);
void register_view(py::module_& m);       // view.cpp: view() (the command line's view job)

} // namespace hot_python

#endif // HOT_PYTHON_HOT_PYTHON_H
