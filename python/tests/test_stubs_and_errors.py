# Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
# SPDX-License-Identifier: GPL-3.0-or-later
"""The type stubs (__init__.pyi, _core.pyi, collection.pyi, py.typed) against the built module,
and the error classes: hot.Error, its subclasses InputError (also a ValueError) and
ComputationError (also a RuntimeError), the class of every Error_code.

The runtime signature of a pybind11 function is read from pybind11's own record of it (the
signature it prints when no overload accepts the arguments: the py::arg names and defaults of
python/src/*.cpp), because the module disables pybind11's docstring signatures: the first line
of __doc__ is written by hand, and is checked against the stub too. A parameter renamed or a
default changed in the C++ sources without the stub fails here."""

import ast
import importlib
import importlib.util
import inspect
import os
import pickle
import re
import subprocess
import sys

import numpy as np
import pytest

import hyperbolic_orbifold_tutte as hot
from hyperbolic_orbifold_tutte import _core

_collection_module = importlib.import_module("hyperbolic_orbifold_tutte.collection")  # (hot.collection is the function)

PACKAGE_DIR = os.path.dirname(hot.__file__)  # <build>/python/hyperbolic_orbifold_tutte (the copies)
SOURCE_DIR = os.environ.get("HOT_SOURCE_DIR") or os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
EXAMPLES_DIR = os.path.join(SOURCE_DIR, "python", "examples")
STUBS = ("__init__.pyi", "_core.pyi", "collection.pyi")

NO_DEFAULT = object()


# ---------------------------------------------------------------------------------------
# signatures as lists of (name, kind, default): kind "positional" or "keyword"
# ---------------------------------------------------------------------------------------

def _split_top_level(text, sep=","):
    """text split at `sep` outside brackets and quotes"""
    parts, depth, quote, start = [], 0, None, 0
    for i, c in enumerate(text):
        if quote:
            if c == quote and text[i - 1] != "\\":
                quote = None
        elif c in "'\"":
            quote = c
        elif c in "([{":
            depth += 1
        elif c in ")]}":
            depth -= 1
        elif c == sep and depth == 0:
            parts.append(text[start:i])
            start = i + 1
    parts.append(text[start:])
    return [p.strip() for p in parts if p.strip()]


def _literal(text):
    try:
        return ast.literal_eval(text)
    except (ValueError, SyntaxError):
        return ("unparsed", text)


def parse_text_signature(line, name=""):
    """`name(a: T, b: T = 1, *, c=None, ...) -> R` (a docstring's; pybind11's record has no
    name: `(a: T, ...) -> R`) as (parameters, rest): rest None, or the parameters after an
    elision `...` (some of the others)"""
    assert line.startswith(name + "("), "%r does not start with %s(" % (line, name)
    start = len(name)
    depth, quote = 0, None
    for end in range(start, len(line)):
        c = line[end]
        if quote:
            if c == quote:
                quote = None
        elif c in "'\"":
            quote = c
        elif c in "([{":
            depth += 1
        elif c in ")]}":
            depth -= 1
            if depth == 0:
                break
    params, kind, rest = [], "positional", None
    for item in _split_top_level(line[start + 1:end]):
        if item == "*":
            kind = "keyword"
            continue
        if item == "...":
            rest = []
            continue
        if item == "/":
            continue
        head, eq, default = item.partition("=")
        pname = head.split(":")[0].strip()
        if pname == "self":
            continue
        (params if rest is None else rest).append((pname, kind, _literal(default.strip()) if eq else NO_DEFAULT))
    return params, rest


def pybind11_signature(func):
    """the parameters pybind11 recorded for `func` (py::arg names and defaults): the signature
    its TypeError prints for a call no overload accepts (nothing is computed)"""
    with pytest.raises(TypeError) as info:
        func(__hot_stub_probe__=None)
    message = str(info.value)
    lines = [l.strip() for l in message.splitlines() if l.strip().startswith(("1. ", "2. "))]
    assert len(lines) == 1 and lines[0].startswith("1. "), "one overload expected, the TypeError says:\n" + message
    return parse_text_signature(lines[0][3:])[0]


def inspect_signature(func):
    params = []
    for p in inspect.signature(func).parameters.values():
        if p.name == "self":
            continue
        assert p.kind in (p.POSITIONAL_OR_KEYWORD, p.KEYWORD_ONLY), "%s: *args/**kwargs not expected" % func
        params.append((p.name, "keyword" if p.kind == p.KEYWORD_ONLY else "positional",
                       NO_DEFAULT if p.default is p.empty else p.default))
    return params


def stub_signature(node):
    """a stub's def as (parameters); a default `...` is ("unparsed", "...")"""
    a = node.args
    assert not a.vararg and not a.kwarg and not a.posonlyargs, "%s: unexpected *args/**kwargs in the stub" % node.name
    params = []
    defaults = [NO_DEFAULT] * (len(a.args) - len(a.defaults)) + [_literal(ast.unparse(d)) for d in a.defaults]
    for arg, d in zip(a.args, defaults):
        if arg.arg != "self":
            params.append((arg.arg, "positional", d))
    for arg, d in zip(a.kwonlyargs, a.kw_defaults):
        params.append((arg.arg, "keyword", NO_DEFAULT if d is None else _literal(ast.unparse(d))))
    return params


def same_default(a, b):
    if a is NO_DEFAULT or b is NO_DEFAULT:
        return a is b
    return type(a) is type(b) and a == b


def describe(params):
    return ", ".join(n + ("" if k == "positional" else " (keyword-only)") + ("" if d is NO_DEFAULT else " = %r" % (d,))
                     for n, k, d in params)


def check_overloads(where, runtime, overloads):
    """every overload of a stubbed function has the runtime's parameter names and kinds and
    no other default; the last one (or the only one) has all of its defaults"""
    for i, params in enumerate(overloads):
        assert [(n, k) for n, k, _ in params] == [(n, k) for n, k, _ in runtime], \
            "%s: the stub's parameters (%s) are not the runtime's (%s)" % (where, describe(params), describe(runtime))
        for (n, _, d), (_, _, r) in zip(params, runtime):
            if d is not NO_DEFAULT:
                assert same_default(d, r), "%s: parameter %s: default %r in the stub, %r at runtime" % (
                    where, n, d, None if r is NO_DEFAULT else r)
    last = overloads[-1]
    for (n, _, d), (_, _, r) in zip(last, runtime):
        assert same_default(d, r), "%s: parameter %s: default %s in the stub, %s at runtime" % (
            where, n, "none" if d is NO_DEFAULT else repr(d), "none" if r is NO_DEFAULT else repr(r))


# ---------------------------------------------------------------------------------------
# the stubs
# ---------------------------------------------------------------------------------------

class Stub:
    """a .pyi file: its public names, its functions (each a list of overloads) and classes"""

    def __init__(self, path):
        with open(path) as f:
            self.tree = ast.parse(f.read(), filename=path)
        self.functions, self.classes, self.variables, self.imports, self.all = {}, {}, set(), {}, None
        for node in self.tree.body:
            if isinstance(node, ast.FunctionDef):
                self.functions.setdefault(node.name, []).append(node)
            elif isinstance(node, ast.ClassDef):
                self.classes[node.name] = node
            elif isinstance(node, ast.AnnAssign) and isinstance(node.target, ast.Name):
                self.variables.add(node.target.id)
            elif isinstance(node, ast.Assign) and any(isinstance(t, ast.Name) and t.id == "__all__" for t in node.targets):
                self.all = ast.literal_eval(node.value)
            elif isinstance(node, ast.Assign):
                self.variables.update(t.id for t in node.targets if isinstance(t, ast.Name))
            elif isinstance(node, ast.ImportFrom) and node.level == 1:
                for alias in node.names:
                    if alias.asname == alias.name:  # (an explicit re-export)
                        self.imports[alias.name] = node.module

    def public_names(self):
        names = set(self.functions) | set(self.classes) | self.variables | set(self.imports)
        return {n for n in names if not n.startswith("_")}


@pytest.fixture(scope="module")
def stubs():
    r = {}
    for name in STUBS:
        path = os.path.join(PACKAGE_DIR, name)
        assert os.path.exists(path), "%s is not next to the package (python/CMakeLists.txt copies the stubs)" % path
        r[name] = Stub(path)
    return r


def test_the_stubs_are_in_the_package(stubs):
    assert os.path.exists(os.path.join(PACKAGE_DIR, "py.typed")), "the PEP 561 marker py.typed"
    for name in STUBS:  # (the copies are the sources')
        with open(os.path.join(PACKAGE_DIR, name)) as a, open(os.path.join(SOURCE_DIR, "python", "hyperbolic_orbifold_tutte", name)) as b:
            assert a.read() == b.read(), "%s: the build tree's copy differs from the source (reconfigure)" % name


def test_every_public_name_has_a_stub(stubs):
    init, core = stubs["__init__.pyi"], stubs["_core.pyi"]
    runtime = {n for n in dir(hot) if not n.startswith("_") and not inspect.ismodule(getattr(hot, n))}
    assert set(hot.__all__) == runtime, "hot.__all__ and the package's public names differ"
    assert init.all == hot.__all__, "__all__ of __init__.pyi is not the package's"
    assert init.public_names() == runtime, "names without a stub: %s; stubs without a name: %s" % (
        sorted(runtime - init.public_names()), sorted(init.public_names() - runtime))
    for name, module in init.imports.items():
        if module == "_core":
            assert name in core.public_names(), "%s is re-exported from _core.pyi, which does not declare it" % name
    core_runtime = {n for n in dir(_core) if not n.startswith("_")}
    assert core.public_names() == core_runtime, "names of _core without a stub: %s; stubs without a name: %s" % (
        sorted(core_runtime - core.public_names()), sorted(core.public_names() - core_runtime))
    # the class Embedding: every property and method
    embedding = {n for n in dir(hot.Embedding) if not n.startswith("_")}
    stubbed = {n.name for n in core.classes["Embedding"].body if isinstance(n, ast.FunctionDef) and not n.name.startswith("_")}
    assert stubbed == embedding, "Embedding: without a stub %s, stubbed but absent %s" % (
        sorted(embedding - stubbed), sorted(stubbed - embedding))


def _pybind11_functions():
    funcs = [getattr(_core, n) for n in dir(_core) if not n.startswith("_") and type(getattr(_core, n)).__name__ == "builtin_function_or_method"]
    funcs.append(hot.Embedding.write_obj)
    return funcs


def test_stubbed_signatures_are_the_runtime_ones(stubs):
    core = stubs["_core.pyi"]
    checked = []
    for func in _pybind11_functions():
        name = func.__name__
        if name in core.functions:
            overloads = core.functions[name]
        else:  # a method
            cls = core.classes["Embedding"]
            overloads = [n for n in cls.body if isinstance(n, ast.FunctionDef) and n.name == name]
        assert overloads, "%s has no stub" % name
        runtime = pybind11_signature(func)
        check_overloads("_core.pyi: " + name, runtime, [stub_signature(n) for n in overloads])
        # the hand-written first line of the docstring says the same (or its first parameters,
        # `...`, and some others: "f(a, b, ..., refine=N)")
        first_line = func.__doc__.splitlines()[0]
        documented, rest = parse_text_signature(first_line, name)
        shown = runtime[:len(documented)] if rest is not None else runtime
        assert [(n, k) for n, k, _ in documented] == [(n, k) for n, k, _ in shown], \
            "%s: the docstring's first line (%s) is not the signature (%s)" % (name, first_line, describe(runtime))
        others = {n: r for n, _, r in runtime[len(documented):]}
        for n, _, d in rest or []:
            assert n in others, "%s: the docstring's first line (%s) names %s, not a parameter" % (name, first_line, n)
            documented.append((n, None, d))
            shown.append((n, None, others[n]))
        for (n, _, d), (_, _, r) in zip(documented, shown):
            if not (isinstance(d, tuple) and d[:1] == ("unparsed",)):  # (a placeholder such as refine=N)
                assert same_default(d, r), "%s: the docstring gives %s the default %r, the function %r" % (name, n, d, r)
        checked.append(name)
    assert {"read_mesh", "select_landmarks", "embed", "map", "map_distortion", "write_obj", "collection_plan"} <= set(checked)
    # the functions written in Python
    for stub, module, names in (("__init__.pyi", hot, ("transfer", "surface_points")),
                                ("collection.pyi", _collection_module, ("collection",))):
        for name in names:
            overloads = stubs[stub].functions.get(name)
            assert overloads, "%s: no stub of %s" % (stub, name)
            check_overloads("%s: %s" % (stub, name), inspect_signature(getattr(module, name)), [stub_signature(n) for n in overloads])
    # the error classes (Python classes)
    for name in ("Error",):
        init = [n for n in core.classes[name].body if isinstance(n, ast.FunctionDef) and n.name == "__init__"]
        check_overloads("_core.pyi: %s.__init__" % name, inspect_signature(getattr(hot, name).__init__), [stub_signature(n) for n in init])


def test_help_shows_an_example_of_every_public_function():
    # help(hot.f) ends with an "Example:" block whose >>> lines call f (the issue: "help() on
    # every function shows its parameters and an example"); the parameters are the first line,
    # checked above
    public = [getattr(hot, n) for n in hot.__all__]
    funcs = [(f.__name__, f) for f in public if callable(f) and not inspect.isclass(f)]
    funcs += [("write_obj", hot.Embedding.write_obj)]
    assert len(funcs) >= 9, [n for n, _ in funcs]
    for name, func in funcs:
        doc = func.__doc__ or ""
        assert "\nExample:" in doc or "\n    Example:" in doc, "%s: no Example: in its docstring" % name
        calls = [line for line in doc.split("Example:", 1)[1].splitlines()
                 if line.strip().startswith(">>>") and re.search(r"(^|[^A-Za-z0-9_])%s\(" % re.escape(name), line)]
        assert calls, "%s: its example does not call it" % name


def test_the_signature_check_can_fail():
    # the comparison itself: a renamed parameter, a changed default, a parameter made keyword-only
    runtime = [("V", "positional", NO_DEFAULT), ("k", "keyword", 7)]
    check_overloads("same", runtime, [[("V", "positional", NO_DEFAULT), ("k", "keyword", 7)]])
    for wrong in ([("V", "positional", NO_DEFAULT), ("count", "keyword", 7)],
                  [("V", "positional", NO_DEFAULT), ("k", "keyword", 8)],
                  [("V", "positional", NO_DEFAULT), ("k", "keyword", True)],
                  [("V", "positional", NO_DEFAULT), ("k", "positional", 7)],
                  [("V", "positional", NO_DEFAULT)]):
        with pytest.raises(AssertionError):
            check_overloads("wrong", runtime, [wrong])
    # pybind11's record: the py::arg names, not the docstring's
    assert pybind11_signature(hot.select_landmarks) == [("V", "positional", NO_DEFAULT), ("F", "positional", NO_DEFAULT),
                                                        ("k", "positional", NO_DEFAULT)]
    assert ("max_handle", "keyword", 0.2) in pybind11_signature(hot.read_mesh)


# ---------------------------------------------------------------------------------------
# the examples type-check against the stubs
# ---------------------------------------------------------------------------------------

def _examples():
    files = sorted(os.path.join(EXAMPLES_DIR, f) for f in os.listdir(EXAMPLES_DIR) if f.endswith(".py"))
    assert files, "no example in " + EXAMPLES_DIR
    return files


def test_the_examples_use_stubbed_names_only(stubs):
    # (what mypy checks fully below, when it is installed: here the stub files parse, every
    # hot.<name> the examples use is declared, with parameters of the stub as keywords)
    init, core = stubs["__init__.pyi"], stubs["_core.pyi"]
    declared = init.public_names()
    used = set()
    for path in _examples():
        with open(path) as f:
            tree = ast.parse(f.read(), filename=path)
        for node in ast.walk(tree):
            if isinstance(node, ast.Attribute) and isinstance(node.value, ast.Name) and node.value.id == "hot":
                assert node.attr in declared, "%s:%d: hot.%s has no stub" % (path, node.lineno, node.attr)
                used.add(node.attr)
            if isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute) and isinstance(node.func.value, ast.Name) \
                    and node.func.value.id == "hot":
                name = node.func.attr
                defs = init.functions.get(name) or core.functions.get(name) or \
                    stubs["collection.pyi"].functions.get(name) or []
                allowed = {p[0] for d in defs for p in stub_signature(d)}
                for kw in node.keywords:
                    if defs and kw.arg is not None:
                        assert kw.arg in allowed, "%s:%d: hot.%s(%s=...) is not a parameter of its stub" % (
                            path, node.lineno, name, kw.arg)
    assert {"read_mesh", "embed", "map"} <= used


def _mypy_available():
    return importlib.util.find_spec("mypy") is not None


def _run_mypy(files, cache_dir):
    env = dict(os.environ)
    env["MYPYPATH"] = os.path.dirname(PACKAGE_DIR)  # the package with its stubs (the build tree's copies)
    return subprocess.run([sys.executable, "-m", "mypy", "--strict", "--no-error-summary", "--cache-dir", str(cache_dir)] + files,
                          capture_output=True, text=True, env=env, timeout=600)


def test_the_examples_pass_mypy_strict(tmp_path_factory):
    # (scripts/install-deps.sh installs Debian's python3-mypy: its absence is a failure, not a skip)
    assert _mypy_available(), "mypy is not importable by %s: install Debian's python3-mypy (scripts/install-deps.sh)" % sys.executable
    cache = tmp_path_factory.mktemp("mypy_cache")
    r = _run_mypy(_examples(), cache)
    assert r.returncode == 0, "mypy --strict on python/examples:\n" + r.stdout + r.stderr
    # and it sees a misuse: a wrong type, a parameter that does not exist, a name without a stub
    bad = tmp_path_factory.mktemp("bad") / "bad_example.py"
    bad.write_text("import hyperbolic_orbifold_tutte as hot\n"
                   "V, F = hot.read_mesh('a.off')\n"
                   "e = hot.embed(V, F, [0, 1, 2, 3, 4], weights=3)\n"
                   "f, b = hot.map(e, e, refinement=2)\n"
                   "hot.no_such_function()\n"
                   "x: int = e.uv\n")
    r = _run_mypy([str(bad)], cache)
    assert r.returncode != 0
    for line in (3, 4, 5, 6):
        assert "bad_example.py:%d:" % line in r.stdout, "mypy missed the error of line %d:\n%s" % (line, r.stdout)


# ---------------------------------------------------------------------------------------
# the error classes
# ---------------------------------------------------------------------------------------

INPUT_CODES = {"ERROR_NOT_HYPERBOLIC", "ERROR_WRONG_PARAMETER", "ERROR_EMPTY_MESH", "ERROR_NON_TRIANGULAR_MESH",
               "ERROR_NON_MANIFOLD", "ERROR_SEVERAL_COMPONENTS", "ERROR_WRONG_TOPOLOGY", "ERROR_TOO_FEW_LANDMARKS",
               "ERROR_DUPLICATE_LANDMARK", "ERROR_LANDMARK_OUT_OF_RANGE", "ERROR_LANDMARK_NOT_ON_BORDER",
               "ERROR_DEGENERATE_FACE", "ERROR_NON_FINITE_COORDINATES", "ERROR_READ_FAILED", "ERROR_BOUNDARY_CHORD",
               "ERROR_POLYGON_NOT_CONVEX", "ERROR_CORNERS_NOT_IN_BOUNDARY_ORDER"}
COMPUTATION_CODES = {"ERROR_CUT_FAILED", "ERROR_CANNOT_SOLVE_LINEAR_SYSTEM", "ERROR_NOT_CONVERGED", "ERROR_NO_1_TO_1_MAPPING",
                     "ERROR_POINT_NOT_LOCATED", "ERROR_WRITE_FAILED"}


def test_the_hierarchy():
    assert issubclass(hot.Error, Exception)
    assert issubclass(hot.InputError, hot.Error) and issubclass(hot.InputError, ValueError)
    assert issubclass(hot.ComputationError, hot.Error) and issubclass(hot.ComputationError, RuntimeError)
    assert not issubclass(hot.InputError, RuntimeError) and not issubclass(hot.ComputationError, ValueError)
    for cls in (hot.Error, hot.InputError, hot.ComputationError):
        assert cls.__module__ == "hyperbolic_orbifold_tutte" and getattr(hot, cls.__name__) is cls
        assert cls.__name__ in hot.__all__
    assert hot.InputError("x").code == "ERROR_WRONG_PARAMETER"
    e = hot.ComputationError("no certificate")
    assert e.code == "ERROR_NO_1_TO_1_MAPPING" and e.code_value == 17 and e.description == hot.error_codes[e.code]
    assert hot.Error("x", "ERROR_READ_FAILED").code_value == 19


def test_every_code_is_classified():
    # (module.cpp's table; a code added to the enumeration without a row does not compile)
    assert set(hot.error_classes) == set(hot.error_codes)
    assert hot.error_classes["OK"] is hot.Error
    assert INPUT_CODES | COMPUTATION_CODES | {"OK"} == set(hot.error_codes), "a code this test does not classify"
    for code in INPUT_CODES:
        assert hot.error_classes[code] is hot.InputError, code
    for code in COMPUTATION_CODES:
        assert hot.error_classes[code] is hot.ComputationError, code


def test_the_errors_pickle_with_their_code():
    # (a Dask worker's error reaches the client pickled)
    for e in (hot.InputError("bad", "ERROR_DUPLICATE_LANDMARK"), hot.ComputationError("no", "ERROR_POINT_NOT_LOCATED"),
              hot.Error("base", "ERROR_READ_FAILED")):
        f = pickle.loads(pickle.dumps(e))
        assert type(f) is type(e) and str(f) == str(e)
        assert (f.code, f.code_value, f.description, f.message) == (e.code, e.code_value, e.description, e.message)


@pytest.fixture(scope="module")
def bear(meshes):
    V, F = hot.read_mesh(os.path.join(meshes, "bear.off"))
    return V, F, hot.select_landmarks(V, F, 7)


def expect(cls, code, fn, *args, **kw):
    with pytest.raises(hot.Error) as info:
        fn(*args, **kw)
    e = info.value
    assert type(e) is cls and e.code == code, "%s %s: %s" % (type(e).__name__, e.code, e)
    assert e.code_value == list(hot.error_codes).index(code) and e.description == hot.error_codes[code] and str(e) == e.message
    return e


def test_bad_input_raises_input_error(bear, tmp_path):
    V, F, lm = bear
    e = expect(hot.InputError, "ERROR_LANDMARK_OUT_OF_RANGE", hot.embed, V, F, list(lm[:6]) + [len(V)])
    assert isinstance(e, ValueError) and isinstance(e, hot.Error) and not isinstance(e, RuntimeError)
    expect(hot.InputError, "ERROR_WRONG_PARAMETER", hot.embed, V, F, lm, cone_orders=[1, 2, 2, 2, 2, 2, 2])
    expect(hot.InputError, "ERROR_NOT_HYPERBOLIC", hot.embed, V, F, lm[:3], cone_orders=[2, 3, 6])
    expect(hot.InputError, "ERROR_TOO_FEW_LANDMARKS", hot.embed, V, F, lm[:4])
    expect(hot.InputError, "ERROR_READ_FAILED", hot.read_mesh, tmp_path / "none.off")
    # the package's own checks (Python)
    expect(hot.InputError, "ERROR_WRONG_PARAMETER", hot.transfer, np.array([0, len(F)]), np.full((2, 3), 1 / 3), F, V)
    # caught as a ValueError by code that knows nothing of the package
    with pytest.raises(ValueError):
        hot.select_landmarks(V, F, 0)


def capsule(L, S=24):
    """python/tests' copy of test/test_parameterizer.cpp's capsule(): a tube of radius 1 and
    length L closed by two hemispheres, S segments per ring, staggered rings; landmarks: the
    bottom pole and four vertices on a ring of the bottom hemisphere"""
    h = 2 * np.pi / S
    nh = int(round((np.pi / 2) / h))
    rings = [(np.sin(a), np.cos(a)) for a in (-np.pi / 2 + i * (np.pi / 2) / nh for i in range(1, nh + 1))]
    nc = max(1, int(round(L / h)))
    rings += [(L * i / nc, 1.0) for i in range(1, nc + 1)]
    rings += [(L + np.sin(a), np.cos(a)) for a in (i * (np.pi / 2) / nh for i in range(1, nh))]
    V = [(0.0, 0.0, -1.0)]
    for k, (z, r) in enumerate(rings):
        for j in range(S):
            t = 2 * np.pi * (j + 0.5 * (k % 2)) / S
            V.append((r * np.cos(t), r * np.sin(t), z))
    V.append((0.0, 0.0, L + 1))
    top = len(V) - 1

    def at(k, j):
        return 1 + k * S + j % S

    F = [(0, at(0, j + 1), at(0, j)) for j in range(S)]
    for k in range(len(rings) - 1):
        for j in range(S):
            if k % 2 == 0:
                F += [(at(k, j), at(k, j + 1), at(k + 1, j)), (at(k, j + 1), at(k + 1, j + 1), at(k + 1, j))]
            else:
                F += [(at(k, j), at(k, j + 1), at(k + 1, j + 1)), (at(k, j), at(k + 1, j + 1), at(k + 1, j))]
    F += [(top, at(len(rings) - 1, j), at(len(rings) - 1, j + 1)) for j in range(S)]
    lm = [0, at(nh // 3, 0), at(nh // 3, S // 4), at(nh // 3, S // 2), at(nh // 3, 3 * S // 4)]
    return np.array(V), np.array(F, dtype=np.int64), lm


def test_a_result_that_cannot_be_certified_raises_computation_error(bear, tmp_path):
    # a capsule 40 radii long with its landmarks at one end: the far end's triangles shrink below
    # what double resolves, the certificate fails (the C++ test "the limit of double precision")
    V, F, lm = capsule(40)
    e = expect(hot.ComputationError, "ERROR_NO_1_TO_1_MAPPING", hot.embed, V, F, lm)
    assert isinstance(e, RuntimeError) and isinstance(e, hot.Error) and not isinstance(e, ValueError)
    assert "below what double resolves" in e.message, e.message
    # a file that cannot be written
    V, F, lm = bear
    expect(hot.ComputationError, "ERROR_WRITE_FAILED", hot.embed(V, F, lm).write_obj, tmp_path / "no" / "such" / "dir.obj")
