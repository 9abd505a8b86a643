# Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Hyperbolic orbifold Tutte embeddings of triangle meshes and bijective maps between surfaces.

The Python face of the Hyperbolic_orbifold_Tutte package (Aigerman and Lipman, SIGGRAPH
Asia 2016) and of its command-line program: the same reader, the same embedding, the same
writers, the same numbers.

    import hyperbolic_orbifold_tutte as hot
    V, F = hot.read_mesh("bear.off")               # float64 (n, 3), int64 (m, 3)
    lm = hot.select_landmarks(V, F, 7)              # as `landmarks --count 7`
    e = hot.embed(V, F, lm)                         # certified, or hot.Error
    e.uv                                            # (m, 3, 2) Poincare points per corner
    e.report["certificate"]["bijective"]            # the report of `embed --report`
    e.write_obj("bear.obj")                         # the bytes of `embed --out`
    r = hot.map_meshes(V, F, lm, V2, F2, lm2)       # `map`: both embedded in one order, A onto B
    images = hot.surface_points(r["faces"], r["bary"], V2, F2)  # where vertex i of A goes on B
    e2 = hot.embed(V2, F2, lm2, order=e.landmark_order)  # (or in two steps)
    faces, bary = hot.map(e, e2)                    # as `map`'s MAP.txt
    d = hot.map_distortion(V, F, hot.surface_points(faces, bary, V2, F2))  # per-face distortion
    hot.collection("list.txt", "out", all_pairs=True, client=None)  # or a dask.distributed.Client
    values = hot.transfer(faces, bary, F2, values2) # a function on mesh 2 pulled back to mesh 1

Every failure raises a hot.Error (message, .code = the library's Error_code name): a
hot.InputError (also a ValueError) when the input or a parameter is wrong, a
hot.ComputationError (also a RuntimeError) when the input was accepted but no result could be
computed, certified or written; hot.error_classes gives the class of every code. Type stubs
(__init__.pyi, _core.pyi, py.typed) come with the package, for mypy and editors.
Array inputs may be any array-like (numpy arrays of any numeric dtype and memory layout,
lists, tuples): C-contiguous float64 vertices and int64 indices are read in place, anything
else is converted once; wrong shapes, non-numeric data or non-integer indices raise InputError.
The computations release the GIL: embeddings of several meshes run in parallel in threads
(concurrent.futures, Dask's threaded scheduler).
"""

import numpy as _np

from ._core import (ComputationError, Embedding, Error, InputError, embed, error_classes, error_codes, map, map_distortion,
                    map_meshes, read_mesh, select_landmarks, view)
from .collection import collection

__all__ = [
    "collection",
    "map_distortion",
    "Embedding",
    "Error",
    "InputError",
    "ComputationError",
    "embed",
    "error_classes",
    "error_codes",
    "map",
    "map_meshes",
    "read_mesh",
    "select_landmarks",
    "transfer",
    "surface_points",
    "view",
]


# ---------------------------------------------------------------------------------------
# maps (map() itself is in the C++ core)
# ---------------------------------------------------------------------------------------

def _as_array(a, what):
    """`a` (any array-like) as a numpy array (no copy if it is one); InputError if numpy cannot
    make a numeric array of it (a ragged list, strings)"""
    try:
        r = _np.asarray(a)
    except (ValueError, TypeError) as e:
        raise InputError("transfer: %s is not an array of numbers (%s)" % (what, e), "ERROR_WRONG_PARAMETER") from None
    if r.dtype.kind not in "biuf":
        raise InputError("transfer: %s must hold numbers, got dtype %s" % (what, r.dtype), "ERROR_WRONG_PARAMETER")
    return r


def transfer(faces, bary, F_b, values_b):
    """transfer(faces, bary, F_b, values_b) -> values on the source's vertices

    Carries a function given on the vertices of a target mesh B over a map computed by
    map(): for source vertex i, the sum over the corners of face faces[i] of B of
    bary[i, c] * values_b[F_b[faces[i], c]].

    faces: int array (n,), bary: float array (n, 3) (map()'s result); F_b: B's faces
    (mB, 3); values_b: array (nB,) or (nB, k) (a scalar or a vector per vertex of B,
    e.g. B's vertex positions VB, which gives the image points of the map).
    Returns a float array of shape (n,) or (n, k). Vectorised numpy; no loop in Python.
    Any array-like is accepted (lists, float32, int32, Fortran order: read through
    numpy.asarray). Raises InputError (code ERROR_WRONG_PARAMETER) on inconsistent shapes or
    indices, non-numeric data or non-integer indices.

    Example:
        >>> faces, bary = hot.map(a, b)
        >>> colours_on_a = hot.transfer(faces, bary, FB, colours_on_b)  # (nA, 3) from (nB, 3)
    """
    faces = _as_array(faces, "faces")
    bary = _as_array(bary, "bary")
    F_b = _as_array(F_b, "F_b")
    values_b = _as_array(values_b, "values_b")
    if not _np.issubdtype(bary.dtype, _np.number) or _np.issubdtype(bary.dtype, _np.complexfloating):
        raise InputError("transfer: bary must hold real numbers, got %s" % bary.dtype, "ERROR_WRONG_PARAMETER")
    bary = bary.astype(_np.float64, copy=False)
    if faces.ndim != 1 or bary.shape != (faces.shape[0], 3):
        raise InputError("transfer: faces must have shape (n,) and bary (n, 3), got %s and %s"
                    % (faces.shape, bary.shape), "ERROR_WRONG_PARAMETER")
    if F_b.ndim != 2 or F_b.shape[1] != 3 or not _np.issubdtype(F_b.dtype, _np.integer):
        raise InputError("transfer: F_b must be an integer array of shape (m, 3), got %s %s"
                    % (F_b.shape, F_b.dtype), "ERROR_WRONG_PARAMETER")
    if not _np.issubdtype(faces.dtype, _np.integer):
        raise InputError("transfer: faces must hold integers, got %s" % faces.dtype, "ERROR_WRONG_PARAMETER")
    if values_b.ndim not in (1, 2):
        raise InputError("transfer: values_b must have shape (nB,) or (nB, k), got %s" % (values_b.shape,),
                    "ERROR_WRONG_PARAMETER")
    if faces.size and (faces.min() < 0 or faces.max() >= F_b.shape[0]):
        raise InputError("transfer: faces holds an index out of range (F_b has %d faces)" % F_b.shape[0],
                    "ERROR_WRONG_PARAMETER")
    corners = F_b[faces]                                    # (n, 3) vertex indices of B
    if corners.size and (corners.min() < 0 or corners.max() >= values_b.shape[0]):
        raise InputError("transfer: F_b refers to vertices beyond values_b's %d rows" % values_b.shape[0],
                    "ERROR_WRONG_PARAMETER")
    v = values_b[corners]                                   # (n, 3) or (n, 3, k)
    if values_b.ndim == 1:
        return _np.einsum("ij,ij->i", bary, v)
    return _np.einsum("ij,ijk->ik", bary, v)


def surface_points(faces, bary, V_b, F_b):
    """surface_points(faces, bary, V_b, F_b) -> (n, 3) float array

    The points of the target surface B where map() sends the source's vertices:
    transfer(faces, bary, F_b, V_b).

    Example:
        >>> r = hot.map_meshes(VA, FA, la, VB, FB, lb)
        >>> images = hot.surface_points(r["faces"], r["bary"], VB, FB)  # (nA, 3)
    """
    return transfer(faces, bary, F_b, V_b)
