// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers
//
// The Python extension `hyperbolic_orbifold_tutte._core`: the module, its error classes, the
// numpy helpers, meshes from arrays and files (read_mesh), and landmark selection. The
// embeddings and maps are in embedding.cpp; each area registers itself (hot_python.h).

#include "hot_python.h"

#include <CGAL/Hyperbolic_orbifold_Tutte/select_landmarks.h>

#include "hot_app/io/polygon_soup.h"
#include "hot_app/io/polygon_soup_to_mesh.h"
#include "hot_app/io/prepared_input.h"
#include "hot_app/io/read_and_check.h"

#include <array>
#include <sstream>

namespace hot_python {

// ---------------------------------------------------------------------------------------
// errors
// ---------------------------------------------------------------------------------------

// The classification of every Error_code: its name and the Python class it raises, one row per
// code in the order of the enumeration (checked below at compile time: a code added to the
// enumeration without a row here does not compile).
//
//   InputError (hot.Error and ValueError): the caller's input or parameters are wrong, and the
//     same call fails again until they are changed: a parameter out of range, a mesh that is
//     not a triangulated 2-manifold of the right topology, degenerate or non-finite geometry,
//     landmarks that are too few, repeated, not vertices, not on the boundary, or that make a
//     non-hyperbolic orbifold, an unreadable or unparsable input file, a fixed-boundary polygon
//     or corner order that is invalid, a disk whose boundary chord the landmarks leave inside
//     one tile side (the message says which landmark to add).
//   ComputationError (hot.Error and RuntimeError): the input was accepted, but no result could
//     be computed, certified or delivered: the cut through the landmarks, a linear solve, the
//     nonlinear solver's convergence, the bijectivity certificate, the location of a point in
//     an embedding, or writing an output file failed. Not "CertificationError": only one of
//     these is the certificate, and a caller who catches it wants all of them (the input was
//     valid, the computation did not succeed).
//   OK is never raised (the base class Error, for completeness of the table).
//
// (Running out of memory is not an Error_code: std::bad_alloc becomes Python's MemoryError.)

namespace {

enum class Error_class { base, input, computation };

struct Error_classification
{
  HOT::Error_code code;
  const char* name;
  Error_class error_class;
};

#define HOT_ERROR_ROW(code, error_class) {HOT::code, #code, Error_class::error_class}

constexpr Error_classification error_table[] = {
  HOT_ERROR_ROW(OK, base),
  HOT_ERROR_ROW(ERROR_NOT_HYPERBOLIC, input),
  HOT_ERROR_ROW(ERROR_WRONG_PARAMETER, input),
  HOT_ERROR_ROW(ERROR_EMPTY_MESH, input),
  HOT_ERROR_ROW(ERROR_NON_TRIANGULAR_MESH, input),
  HOT_ERROR_ROW(ERROR_NON_MANIFOLD, input),
  HOT_ERROR_ROW(ERROR_SEVERAL_COMPONENTS, input),
  HOT_ERROR_ROW(ERROR_WRONG_TOPOLOGY, input),
  HOT_ERROR_ROW(ERROR_TOO_FEW_LANDMARKS, input),
  HOT_ERROR_ROW(ERROR_DUPLICATE_LANDMARK, input),
  HOT_ERROR_ROW(ERROR_LANDMARK_OUT_OF_RANGE, input),
  HOT_ERROR_ROW(ERROR_LANDMARK_NOT_ON_BORDER, input),
  HOT_ERROR_ROW(ERROR_DEGENERATE_FACE, input),
  HOT_ERROR_ROW(ERROR_NON_FINITE_COORDINATES, input),
  HOT_ERROR_ROW(ERROR_CUT_FAILED, computation),
  HOT_ERROR_ROW(ERROR_CANNOT_SOLVE_LINEAR_SYSTEM, computation),
  HOT_ERROR_ROW(ERROR_NOT_CONVERGED, computation),
  HOT_ERROR_ROW(ERROR_NO_1_TO_1_MAPPING, computation),
  HOT_ERROR_ROW(ERROR_POINT_NOT_LOCATED, computation),
  HOT_ERROR_ROW(ERROR_READ_FAILED, input),
  HOT_ERROR_ROW(ERROR_WRITE_FAILED, computation),
  HOT_ERROR_ROW(ERROR_BOUNDARY_CHORD, input),
  HOT_ERROR_ROW(ERROR_POLYGON_NOT_CONVEX, input),
  HOT_ERROR_ROW(ERROR_CORNERS_NOT_IN_BOUNDARY_ORDER, input)
};

#undef HOT_ERROR_ROW

constexpr bool error_table_follows_the_enumeration()
{
  for(int i = 0; i < HOT::number_of_error_codes; ++i)
    if(static_cast<int>(error_table[i].code) != i)
      return false;
  return true;
}

static_assert(sizeof(error_table) / sizeof(error_table[0]) == HOT::number_of_error_codes,
              "error_table: one row per Error_code value (classify the new code as input or computation)");
static_assert(error_table_follows_the_enumeration(), "error_table: the rows follow the order of the enumeration");

const char* error_class_name(Error_class c)
{
  switch(c) {
  case Error_class::input: return "InputError";
  case Error_class::computation: return "ComputationError";
  default: return "Error";
  }
}

} // namespace

const char* error_code_name(HOT::Error_code code)
{
  const int i = static_cast<int>(code);
  return (i >= 0 && i < HOT::number_of_error_codes) ? error_table[i].name : "UNKNOWN";
}

namespace {

// the classes hyperbolic_orbifold_tutte.Error, InputError and ComputationError (created once,
// kept for the process's life), and the one each code raises
py::handle error_class;
py::handle error_class_of_code[HOT::number_of_error_codes];

py::handle class_of(HOT::Error_code code)
{
  const int i = static_cast<int>(code);
  return (i >= 0 && i < HOT::number_of_error_codes) ? error_class_of_code[i] : error_class;
}

const char* const error_class_source = R"PY(
class Error(Exception):
    """The error of every operation of hyperbolic_orbifold_tutte (the base class).

    str(e) and e.message: the library's one-line message (what is wrong and where,
    e.g. "face 3 is not a triangle"); e.code: the name of the library's Error_code
    (e.g. "ERROR_NON_TRIANGULAR_MESH", "ERROR_TOO_FEW_LANDMARKS"); e.code_value: its
    number; e.description: the code's general description (error_message()).

    Raised as one of its subclasses: InputError (also a ValueError) when the input or a
    parameter is wrong, ComputationError (also a RuntimeError) when the input was accepted
    but no result could be computed, certified or written. error_classes gives the class
    of every code.
    """

    _default_code = "ERROR_WRONG_PARAMETER"

    def __init__(self, message, code=None, code_value=None, description=None):
        super().__init__(message)
        if code is None:
            code = self._default_code
        known = _codes.get(code, (None, None))
        self.message = message
        self.code = code
        self.code_value = known[0] if code_value is None else code_value
        self.description = known[1] if description is None else description

    def __reduce__(self):
        # (pickled with its code, e.g. from a Dask worker; the class by its name in the package)
        return (type(self), (self.message, self.code, self.code_value, self.description), self.__dict__)


class InputError(Error, ValueError):
    """The input or a parameter is wrong (a hot.Error and a ValueError): an argument out of
    its range, a mesh that is not a valid triangulated 2-manifold of the right topology,
    degenerate or non-finite geometry, too few, repeated or misplaced landmarks, a signature
    that is not hyperbolic, an unreadable input file. The same call fails again until the
    input is changed; e.code says which check failed."""

    _default_code = "ERROR_WRONG_PARAMETER"


class ComputationError(Error, RuntimeError):
    """The input was accepted but no result could be computed, certified or delivered (a
    hot.Error and a RuntimeError): the cut through the landmarks, a linear or nonlinear
    solve, the bijectivity certificate, the location of a point in an embedding, or writing
    an output file failed; e.code says which."""

    _default_code = "ERROR_NO_1_TO_1_MAPPING"
)PY";

} // namespace

void register_errors(py::module_& m)
{
  py::dict codes, numbered; // name -> description, name -> (number, description)
  for(int i = 0; i < HOT::number_of_error_codes; ++i) {
    const HOT::Error_code c = static_cast<HOT::Error_code>(i);
    codes[py::str(error_code_name(c))] = HOT::error_message(c);
    numbered[py::str(error_code_name(c))] = py::make_tuple(i, HOT::error_message(c));
  }
  py::dict ns;
  ns["__name__"] = "hyperbolic_orbifold_tutte";
  ns["__builtins__"] = py::module_::import("builtins");
  ns["_codes"] = numbered;
  py::exec(error_class_source, ns);
  py::dict by_name; // class name -> class
  for(const char* name : {"Error", "InputError", "ComputationError"}) {
    py::object cls = ns[name];
    cls.attr("__module__") = "hyperbolic_orbifold_tutte";
    m.attr(name) = cls;
    by_name[name] = cls;
    cls.inc_ref(); // never released: the translator may run until the interpreter ends
  }
  error_class = by_name["Error"].ptr();
  py::dict classes; // code name -> class
  for(int i = 0; i < HOT::number_of_error_codes; ++i) {
    error_class_of_code[i] = by_name[error_class_name(error_table[i].error_class)].ptr();
    classes[py::str(error_table[i].name)] = error_class_of_code[i];
  }
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if(p) std::rethrow_exception(p);
    } catch(const Hot_error& e) {
      // (a message with bytes that are not UTF-8, e.g. from a file name, gets replacement characters)
      py::object message = py::reinterpret_steal<py::object>(
        PyUnicode_DecodeUTF8(e.message.data(), static_cast<Py_ssize_t>(e.message.size()), "replace"));
      if(!message) {
        PyErr_Clear();
        message = py::str("(unprintable message)");
      }
      try {
        const py::handle cls = class_of(e.code);
        py::object instance = cls(message, error_code_name(e.code), static_cast<int>(e.code), HOT::error_message(e.code));
        PyErr_SetObject(cls.ptr(), instance.ptr());
      } catch(py::error_already_set& x) {
        x.restore();
      }
    }
  });
  m.attr("error_codes") = codes;
  m.attr("error_classes") = classes;
}

// ---------------------------------------------------------------------------------------
// numpy helpers
// ---------------------------------------------------------------------------------------

namespace {

// `obj` (any array-like: a numpy array of any dtype and memory layout, a list, a tuple) as a
// numpy array, without a copy when it is one already; what numpy cannot make an array of (a
// ragged list, ...) is an InputError naming `what`
py::array as_numpy_array(py::handle obj, const char* what)
{
  try {
    return py::module_::import("numpy").attr("asarray")(obj);
  } catch(py::error_already_set& e) {
    if(!e.matches(PyExc_ValueError) && !e.matches(PyExc_TypeError))
      throw;
    fail(HOT::ERROR_WRONG_PARAMETER, std::string(what) + " is not an array of numbers (" + std::string(py::str(e.value())) + ")");
  }
}

std::string shape_of(const py::array& a)
{
  std::ostringstream os;
  os << "(";
  for(py::ssize_t i = 0; i < a.ndim(); ++i)
    os << (i ? ", " : "") << a.shape(i);
  os << (a.ndim() == 1 ? ",)" : ")");
  return os.str();
}

char kind_of(const py::array& a)
{
  return a.dtype().kind();
}

std::string dtype_of(const py::array& a)
{
  return std::string(py::str(a.dtype()));
}

// `a` as C-contiguous int64: an integer array of any width or byte order (read in place when
// it is C-contiguous int64 already, converted otherwise); a real array is refused even when its
// values are whole numbers (faces and landmarks are indices: 2.5 or NaN is a mistake upstream,
// and a silent truncation would hide it)
Index_array integer_array(const py::array& a, const std::string& what, const char* holds)
{
  const char kind = kind_of(a);
  if(kind != 'i' && kind != 'u' && a.size() > 0)
    fail(HOT::ERROR_WRONG_PARAMETER, what + " must hold " + holds + ", got dtype '" + dtype_of(a) + "'" +
                                       (kind == 'f' ? " (convert with .astype(np.int64) if the values are whole numbers)" : ""));
  Index_array d = Index_array::ensure(a);
  if(!d)
    fail(HOT::ERROR_WRONG_PARAMETER, what + " could not be converted to int64");
  return d;
}

} // namespace

Double_array vertex_array(py::handle obj, const char* what)
{
  const py::array a = as_numpy_array(obj, what);
  if(a.ndim() != 2 || a.shape(1) != 3)
    fail(HOT::ERROR_WRONG_PARAMETER, std::string(what) + " must be an array of shape (n, 3) (one row x y z per vertex), got shape " + shape_of(a));
  const char kind = kind_of(a);
  if(kind != 'f' && kind != 'i' && kind != 'u')
    fail(HOT::ERROR_WRONG_PARAMETER, std::string(what) + " must hold real numbers, got dtype '" + dtype_of(a) + "'");
  // (no copy when `a` is a C-contiguous float64 array already: ensure() returns it; else one
  // converted copy: float32, integers, Fortran order, strides)
  Double_array d = Double_array::ensure(a);
  if(!d)
    fail(HOT::ERROR_WRONG_PARAMETER, std::string(what) + " could not be converted to float64");
  return d;
}

Index_array face_array(py::handle obj, const char* what)
{
  const py::array a = as_numpy_array(obj, what);
  if(a.ndim() != 2)
    fail(HOT::ERROR_WRONG_PARAMETER, std::string(what) + " must be an array of shape (m, 3) (one row of vertex indices per face), got shape " + shape_of(a));
  return integer_array(a, what, "integer vertex indices");
}

std::vector<std::int64_t> int_list(py::handle obj, const char* what)
{
  const py::array a = as_numpy_array(obj, what);
  std::vector<std::int64_t> r;
  if(a.size() == 0)
    return r;
  if(a.ndim() != 1)
    fail(HOT::ERROR_WRONG_PARAMETER, std::string(what) + " must be a sequence of integers (one dimension), got shape " + shape_of(a));
  const Index_array d = integer_array(a, what, "integers");
  r.assign(d.data(), d.data() + d.size());
  return r;
}

std::vector<std::size_t> index_list(py::handle obj, const char* what, HOT::Error_code code)
{
  const std::string plural = std::string("the ") + what + "s";
  std::vector<std::size_t> r;
  const std::vector<std::int64_t> v = int_list(obj, plural.c_str());
  for(std::size_t i = 0; i < v.size(); ++i) {
    if(v[i] < 0)
      fail(code, std::string(what) + " " + std::to_string(i) + " is " + std::to_string(v[i]) + ", not a vertex index (a non-negative integer)");
    r.push_back(static_cast<std::size_t>(v[i]));
  }
  return r;
}

// ---------------------------------------------------------------------------------------
// meshes from arrays, as the command line's reader builds them from a file's soup
// ---------------------------------------------------------------------------------------

void mesh_from_arrays(const double* V, std::size_t n, const std::int64_t* F, std::size_t m, std::size_t k,
                      std::optional<HOT::Orbifold_type> required_type, Surface_mesh& mesh, HOT::Mesh_info& info)
{
  hot_tools::Polygon_soup soup;
  soup.points.resize(n);
  for(std::size_t i = 0; i < n; ++i)
    soup.points[i] = {{V[3 * i], V[3 * i + 1], V[3 * i + 2]}};
  soup.face_vertices.resize(m * k);
  soup.face_begin.reserve(m + 1);
  for(std::size_t j = 0; j < m; ++j) {
    for(std::size_t c = 0; c < k; ++c) {
      const std::int64_t v = F[j * k + c];
      if(v < 0 || static_cast<std::uint64_t>(v) >= n)
        fail(HOT::ERROR_WRONG_PARAMETER, "F[" + std::to_string(j) + ", " + std::to_string(c) + "] = " + std::to_string(v) +
                                           " is not a vertex index: V has " + std::to_string(n) + " vertices (valid indices are 0 to " +
                                           std::to_string(n == 0 ? 0 : n - 1) + ")");
      soup.face_vertices[j * k + c] = static_cast<std::size_t>(v);
    }
    soup.face_begin.push_back((j + 1) * k); // (what Polygon_soup::end_face() records once face j is pushed)
  }
  // the reader's steps without the file: validate_polygon_soup() and the builder, then check_mesh()
  require(hot_tools::polygon_soup_to_mesh(soup, mesh));
  require(HOT::check_mesh(mesh, required_type, &info));
}

std::optional<HOT::Orbifold_type> parse_orbifold(const std::string& s)
{
  if(s == "auto")
    return std::nullopt;
  if(s == "sphere" || s == "closed")
    return HOT::Sphere_type;
  if(s == "disk")
    return HOT::Disk_type;
  fail(HOT::ERROR_WRONG_PARAMETER, "orbifold must be 'auto', 'sphere' (or 'closed') or 'disk', got '" + s + "'");
}

// ---------------------------------------------------------------------------------------
// read_mesh, select_landmarks
// ---------------------------------------------------------------------------------------

namespace {

// the vertices (n x 3) and faces (m x 3, each with its vertices from source(halfedge(f)), the
// first vertex of the file's face) of a mesh read by read_input_mesh()
py::tuple mesh_arrays(const Surface_mesh& mesh)
{
  std::vector<double> V;
  V.reserve(3 * num_vertices(mesh));
  for(SM_vertex v : vertices(mesh)) {
    const Kernel::Point_3& p = mesh.point(v);
    V.push_back(p.x());
    V.push_back(p.y());
    V.push_back(p.z());
  }
  std::vector<std::int64_t> F;
  F.reserve(3 * num_faces(mesh));
  for(SM_face f : faces(mesh))
    for(SM_halfedge h : halfedges_around_face(prev(halfedge(f, mesh), mesh), mesh))
      F.push_back(static_cast<std::int64_t>(target(h, mesh).idx()));
  const py::ssize_t n = static_cast<py::ssize_t>(num_vertices(mesh)), m = static_cast<py::ssize_t>(num_faces(mesh));
  return py::make_tuple(owning_array(std::move(V), {n, 3}), owning_array(std::move(F), {m, 3}));
}

std::string path_string(py::handle path)
{
  // str, bytes or os.PathLike, as the file system's bytes
  const py::bytes b = py::module_::import("os").attr("fsencode")(path);
  return std::string(b);
}

py::object read_mesh(py::handle path, bool repair, const std::string& orbifold, std::optional<double> max_hole, bool largest_component,
                     bool return_file_index, py::handle landmarks, std::optional<long long> target_genus, double max_handle)
{
  const std::string p = path_string(path);
  const std::optional<HOT::Orbifold_type> type = parse_orbifold(orbifold);
  if(max_hole && (!(*max_hole >= 0) || !(*max_hole <= 1e6)))
    fail(HOT::ERROR_WRONG_PARAMETER, "max_hole must be a number >= 0 (a length in bounding box diagonals), got " + std::to_string(*max_hole));
  if(largest_component && !repair)
    fail(HOT::ERROR_WRONG_PARAMETER, "largest_component needs repair=True");
  if(!landmarks.is_none() && !repair)
    fail(HOT::ERROR_WRONG_PARAMETER, "landmarks needs repair=True (they guide the repair)");
  if(target_genus && (*target_genus < 0 || *target_genus > 1000000))
    fail(HOT::ERROR_WRONG_PARAMETER, "target_genus must be an integer >= 0, got " + std::to_string(*target_genus));
  if(target_genus && !repair)
    fail(HOT::ERROR_WRONG_PARAMETER, "target_genus needs repair=True (the handles are cut by the repair)");
  if(!(max_handle >= 0) || !(max_handle <= 1e6))
    fail(HOT::ERROR_WRONG_PARAMETER, "max_handle must be a number >= 0 (a length in bounding box diagonals), got " + std::to_string(max_handle));
  hot_tools::Repair_options opt;
  opt.repair = repair;
  opt.largest_component = largest_component;
  opt.max_hole = max_hole ? *max_hole : 0.5;
  opt.max_hole_given = max_hole.has_value();
  opt.target_genus = target_genus ? *target_genus : -1;
  opt.max_handle = max_handle;
  std::vector<std::size_t> ids;
  if(!landmarks.is_none())
    ids = index_list(landmarks, "landmarks", HOT::ERROR_LANDMARK_OUT_OF_RANGE);
  Surface_mesh mesh;
  hot_tools::Input_mesh in;
  {
    py::gil_scoped_release release;
    require(hot_tools::read_input_mesh(p, type, opt, mesh, in, nullptr, ids)); // the CLI's reader and checks
    for(std::size_t i : ids)
      if(i >= in.prep.number_of_input_vertices)
        fail(HOT::ERROR_LANDMARK_OUT_OF_RANGE, "landmark vertex " + std::to_string(i) + " is not a vertex of " + p + ", which has " +
                                                 std::to_string(in.prep.number_of_input_vertices) + " vertices");
  }
  py::tuple VF = mesh_arrays(mesh);
  if(!return_file_index)
    return std::move(VF);
  std::vector<std::int64_t> index(in.prep.output_index.begin(), in.prep.output_index.end());
  const py::ssize_t n = static_cast<py::ssize_t>(index.size());
  return py::make_tuple(VF[0], VF[1], owning_array(std::move(index), {n}));
}

py::array select_landmarks(py::handle V, py::handle F, long long k)
{
  const Double_array Va = vertex_array(V);
  const Index_array Fa = face_array(F);
  if(k < 1)
    fail(HOT::ERROR_WRONG_PARAMETER, "k must be at least 1, got " + std::to_string(k));
  std::vector<std::int64_t> r;
  {
    py::gil_scoped_release release;
    Surface_mesh mesh;
    HOT::Mesh_info info;
    mesh_from_arrays(Va.data(), static_cast<std::size_t>(Va.shape(0)), Fa.data(), static_cast<std::size_t>(Fa.shape(0)),
                     static_cast<std::size_t>(Fa.shape(1)), std::nullopt, mesh, info);
    // as the CLI's `landmarks --count k`
    if(static_cast<unsigned long long>(k) > num_vertices(mesh))
      fail(HOT::ERROR_WRONG_PARAMETER, "k is larger than the number of vertices (" + std::to_string(num_vertices(mesh)) + ")");
    const std::vector<SM_vertex> lm = HOT::select_landmarks(mesh, static_cast<std::size_t>(k));
    if(lm.size() != static_cast<std::size_t>(k))
      fail(HOT::ERROR_WRONG_PARAMETER, "the boundary has fewer than " + std::to_string(k) + " vertices");
    for(SM_vertex v : lm)
      r.push_back(static_cast<std::int64_t>(v.idx()));
  }
  const py::ssize_t n = static_cast<py::ssize_t>(r.size());
  return owning_array(std::move(r), {n});
}

} // namespace

void register_io(py::module_& m)
{
  m.def("read_mesh", &read_mesh, py::arg("path"), py::kw_only(), py::arg("repair") = false, py::arg("orbifold") = "auto",
        py::arg("max_hole") = py::none(), py::arg("largest_component") = false, py::arg("return_file_index") = false,
        py::arg("landmarks") = py::none(), py::arg("target_genus") = py::none(), py::arg("max_handle") = 0.2,
        R"doc(read_mesh(path, *, repair=False, orbifold="auto", max_hole=None, largest_component=False, return_file_index=False, landmarks=None, target_genus=None, max_handle=0.2)

Reads a triangle mesh file with the command-line program's reader and checks
(OFF, OBJ, PLY, STL, GOCAD .ts; the format by the extension) and returns (V, F):

  V  float64 array of shape (n, 3), the vertices in the file's order;
  F  int64 array of shape (m, 3), the faces in the file's order, each with its
     vertices in the file's order (the same first vertex).

The arrays own their memory (no copy is made on the way to numpy). The mesh must be
a closed surface or a disk (one boundary loop), as `embed` needs: any other input
raises Error with the reason (non-manifold edge or vertex, inconsistent orientation,
NaN coordinate, several components, ...), the file name first.

orbifold: "auto" (closed or disk, from the mesh), "sphere" (or "closed") or "disk":
  the type the mesh is checked for.
repair: prepares the mesh first as the command line's --repair does (merges
  duplicated border vertices, orients, removes bad faces, splits non-manifold
  vertices, triangulates, drops debris, fills holes up to max_hole bounding box
  diagonals (default 0.5), keeps the largest component with largest_component=True).
  With landmarks (the file's vertex numbers, as a landmark file holds them) it aims at
  the orbifold they ask for: the component that holds them is kept, and unless they
  all lie on one boundary loop every loop is closed whatever its length (unless
  max_hole is given), so a scan with a large opening becomes a sphere. target_genus=g
  (with repair) cuts handles until the mesh has genus g, as --target-genus does: each
  time along the shortest non-separating loop found, both sides closed, refused when
  that loop is longer than max_handle bounding box diagonals (topological noise such
  as fused fingers is cut, a real handle is not); a disk's handles are cut without
  target_genus (a disk-type orbifold has genus 0). V and F are then the prepared
  mesh's, in its own vertex order; with return_file_index=True a third array gives,
  for every vertex of V, its number in the command line's files (the file's vertex,
  or a number after them for a vertex the repair added). A clean mesh is returned as
  without repair.

Example:
    >>> V, F = hot.read_mesh("bear.off")           # (n, 3) float64, (m, 3) int64
    >>> V, F = hot.read_mesh("scan.ply", repair=True, largest_component=True))doc");

  m.def("select_landmarks", &select_landmarks, py::arg("V"), py::arg("F"), py::arg("k"),
        R"doc(select_landmarks(V, F, k)

Returns k well-spread landmarks of the mesh (V, F) as an int64 array of vertex
indices: the same as the command line's `landmarks --count k` on that mesh. A closed
mesh gets farthest-point samples on graph distance; a mesh with a boundary gets k
vertices of its longest boundary loop spaced evenly by arc length, in boundary order
(usable as disk-type corners).

The mesh is built and checked as `embed` builds it (V and F: any array-like, as embed()
reads them); errors raise Error (also when k is larger than the number of vertices, or
than the boundary's).

Example:
    >>> lm = hot.select_landmarks(V, F, 7)          # int64 vertex indices
    >>> e = hot.embed(V, F, lm))doc");
}

} // namespace hot_python

PYBIND11_MODULE(_core, m)
{
  // the docstrings give the Python signatures (pybind11's would show the arguments' C++ types)
  pybind11::options options;
  options.disable_function_signatures();
  m.doc() = "Hyperbolic orbifold Tutte embeddings and bijective maps between surfaces (the C++ core of "
            "hyperbolic_orbifold_tutte: import that package, not this module)";
  hot_python::register_errors(m);
  hot_python::register_io(m);
  hot_python::register_embedding(m);
  hot_python::register_maps(m);
  hot_python::register_collection(m);
  hot_python::register_distortion(m);
  hot_python::register_view(m);
}
