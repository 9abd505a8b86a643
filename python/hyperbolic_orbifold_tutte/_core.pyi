# Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Type stubs of the extension hyperbolic_orbifold_tutte._core (python/src/*.cpp).

The parameter names and defaults are those of the pybind11 definitions (py::arg); the test
python/tests/test_stubs_and_errors.py checks them against the built module."""

import os
from typing import Any, Callable, Literal, Sequence, TypedDict, Union, overload

import numpy as np
from numpy.typing import ArrayLike, NDArray

_Path = Union[str, bytes, os.PathLike[str], os.PathLike[bytes]]
# vertex indices: a sequence of ints or a 1-D integer array (e.g. select_landmarks()'s result)
_Indices = Union[Sequence[int], NDArray[np.integer[Any]]]
_Orbifold = Literal["auto", "sphere", "closed", "disk"]
_Weights = Literal["cotan", "mvc", "uniform"]

# ---------------------------------------------------------------------------------------
# errors
# ---------------------------------------------------------------------------------------

class Error(Exception):
    """The base class of every error of the package."""

    message: str
    code: str
    code_value: int | None
    description: str | None
    def __init__(self, message: str, code: str | None = None, code_value: int | None = None,
                 description: str | None = None) -> None: ...

class InputError(Error, ValueError):
    """The input or a parameter is wrong."""

class ComputationError(Error, RuntimeError):
    """The input was accepted but no result could be computed, certified or written."""

# the name of every Error_code -> its one-line description
error_codes: dict[str, str]
# the name of every Error_code -> the class it raises (InputError, ComputationError; Error for OK)
error_classes: dict[str, type[Error]]

# ---------------------------------------------------------------------------------------
# meshes, landmarks
# ---------------------------------------------------------------------------------------

@overload
def read_mesh(path: _Path, *, repair: bool = False, orbifold: _Orbifold = "auto", max_hole: float | None = None,
              largest_component: bool = False, return_file_index: Literal[False] = False, landmarks: _Indices | None = None,
              target_genus: int | None = None, max_handle: float = 0.2) -> tuple[NDArray[np.float64], NDArray[np.int64]]: ...
@overload
def read_mesh(path: _Path, *, repair: bool = False, orbifold: _Orbifold = "auto", max_hole: float | None = None,
              largest_component: bool = False, return_file_index: Literal[True], landmarks: _Indices | None = None,
              target_genus: int | None = None,
              max_handle: float = 0.2) -> tuple[NDArray[np.float64], NDArray[np.int64], NDArray[np.int64]]: ...
@overload
def read_mesh(path: _Path, *, repair: bool = False, orbifold: _Orbifold = "auto", max_hole: float | None = None,
              largest_component: bool = False, return_file_index: bool = False, landmarks: _Indices | None = None,
              target_genus: int | None = None, max_handle: float = 0.2
              ) -> tuple[NDArray[np.float64], NDArray[np.int64]] | tuple[NDArray[np.float64], NDArray[np.int64], NDArray[np.int64]]: ...

def select_landmarks(V: ArrayLike, F: ArrayLike, k: int) -> NDArray[np.int64]: ...

# ---------------------------------------------------------------------------------------
# embeddings
# ---------------------------------------------------------------------------------------

class Embedding:
    """A certified hyperbolic orbifold Tutte embedding of a triangle mesh (returned by embed())."""

    @property
    def uv(self) -> NDArray[np.float64]: ...
    @property
    def V(self) -> NDArray[np.float64]: ...
    @property
    def F(self) -> NDArray[np.int64]: ...
    @property
    def certified(self) -> bool: ...
    @property
    def report(self) -> dict[str, Any]: ...
    @property
    def report_json(self) -> str: ...
    @property
    def landmarks(self) -> NDArray[np.int64]: ...
    @property
    def landmark_order(self) -> NDArray[np.int64]: ...
    @property
    def cone_orders(self) -> list[int]: ...
    @property
    def orbifold(self) -> Literal["sphere", "disk"]: ...
    @property
    def genus(self) -> int: ...
    @property
    def recentred(self) -> bool: ...
    @property
    def cut_graph(self) -> list[list[int]]: ...
    def write_obj(self, path: _Path) -> None: ...

def embed(V: ArrayLike, F: ArrayLike, landmarks: _Indices, *, orbifold: _Orbifold = "auto", weights: _Weights | None = None,
          order: Literal["auto", "tsp", "given"] | _Indices = "auto", cone_orders: _Indices | None = None,
          recentre: bool = False, cut_graph: Sequence[_Indices] | None = None, name: str = "",
          progress: Callable[[str, float], object] | None = None) -> Embedding: ...

# ---------------------------------------------------------------------------------------
# maps
# ---------------------------------------------------------------------------------------

@overload
def map(source: Embedding, target: Embedding, *, unreliable: Literal[False] = False,
        refine: int = 0) -> tuple[NDArray[np.int64], NDArray[np.float64]]: ...
@overload
def map(source: Embedding, target: Embedding, *, unreliable: Literal[True],
        refine: int = 0) -> tuple[NDArray[np.int64], NDArray[np.float64], NDArray[np.int64]]: ...
@overload
def map(source: Embedding, target: Embedding, *, unreliable: bool = False, refine: int = 0
        ) -> tuple[NDArray[np.int64], NDArray[np.float64]] | tuple[NDArray[np.int64], NDArray[np.float64], NDArray[np.int64]]: ...

# map_meshes()'s result: map()'s arrays, the two embeddings and the landmark order used
class _MeshMap(TypedDict):
    faces: NDArray[np.int64]
    bary: NDArray[np.float64]
    unreliable: NDArray[np.int64] | None
    source: Embedding
    target: Embedding
    landmark_order: NDArray[np.int64]
    landmark_order_from: Literal["source", "target", "given"]
    orders_tried: int
    refused: list[str]
    added: NDArray[np.int64] | None

def map_meshes(VA: ArrayLike, FA: ArrayLike, landmarks_a: _Indices, VB: ArrayLike, FB: ArrayLike, landmarks_b: _Indices, *,
               orbifold: _Orbifold = "auto", weights: _Weights | None = None, order: Literal["auto", "tsp", "given"] | _Indices = "auto",
               cone_orders: _Indices | None = None, unreliable: bool = False, refine: int = 0, augment: bool | None = None,
               progress: Callable[[str, float], object] | None = None) -> _MeshMap: ...

class _DistortionSummary(TypedDict):
    p50: float
    p90: float
    p99: float
    max: float
    mean: float
    faces: int

class _MapDistortion(TypedDict):
    sigma1: NDArray[np.float64]
    sigma2: NDArray[np.float64]
    conformal: NDArray[np.float64]
    area: NDArray[np.float64]
    symmetric_dirichlet: NDArray[np.float64]
    conformal_summary: _DistortionSummary
    area_summary: _DistortionSummary
    symmetric_dirichlet_summary: _DistortionSummary
    symmetric_dirichlet_energy: float
    degenerate_image_faces: int
    degenerate_source_faces: int
    unmapped_faces: int
    source_area: float
    image_area: float

def map_distortion(V: ArrayLike, F: ArrayLike, images: ArrayLike) -> _MapDistortion: ...

# ---------------------------------------------------------------------------------------
# the viewer (view.cpp): the folder of the command line's view job
# ---------------------------------------------------------------------------------------

def view(obj: Embedding | _MeshMap | Sequence[Embedding], out_dir: _Path) -> None: ...

# ---------------------------------------------------------------------------------------
# the jobs of collection() (hyperbolic_orbifold_tutte/collection.py runs them)
# ---------------------------------------------------------------------------------------

class _CollectionPlan(TypedDict):
    meshes: list[tuple[str, str]]
    orbifold: Literal["sphere", "disk"]
    landmarks: int
    order: list[int]
    pairs: list[tuple[int, int]]
    triples: list[tuple[int, int, int]]

def collection_plan(manifest: str, out_dir: str, all_pairs: bool = False, cone_orders: _Indices | None = None,
                    repair: bool = False, max_hole: float | None = None, largest_component: bool = False,
                    snap_landmarks: bool = False, refine: int = 0) -> _CollectionPlan: ...
def collection_embed(i: int, orbifold: str, landmarks: int, order: Sequence[int], manifest: str, out_dir: str,
                     all_pairs: bool = False, cone_orders: _Indices | None = None, repair: bool = False,
                     max_hole: float | None = None, largest_component: bool = False, snap_landmarks: bool = False,
                     refine: int = 0) -> float: ...
def collection_refine(i: int, manifest: str, out_dir: str, all_pairs: bool = False, cone_orders: _Indices | None = None,
                      repair: bool = False, max_hole: float | None = None, largest_component: bool = False,
                      snap_landmarks: bool = False, refine: int = 0) -> float: ...
def collection_map(a: int, b: int, manifest: str, out_dir: str, all_pairs: bool = False, cone_orders: _Indices | None = None,
                   repair: bool = False, max_hole: float | None = None, largest_component: bool = False,
                   snap_landmarks: bool = False, refine: int = 0) -> float: ...
def collection_merge(manifest: str, out_dir: str, all_pairs: bool = False, cone_orders: _Indices | None = None,
                     repair: bool = False, max_hole: float | None = None, largest_component: bool = False,
                     snap_landmarks: bool = False, refine: int = 0) -> tuple[int, float]: ...
