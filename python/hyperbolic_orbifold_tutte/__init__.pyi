# Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Type stubs of the package hyperbolic_orbifold_tutte (__init__.py; the extension's in _core.pyi)."""

from numpy.typing import ArrayLike, NDArray
import numpy as np

from ._core import ComputationError as ComputationError
from ._core import Embedding as Embedding
from ._core import Error as Error
from ._core import InputError as InputError
from ._core import embed as embed
from ._core import error_classes as error_classes
from ._core import error_codes as error_codes
from ._core import map as map
from ._core import map_distortion as map_distortion
from ._core import map_meshes as map_meshes
from ._core import read_mesh as read_mesh
from ._core import select_landmarks as select_landmarks
from ._core import view as view
from .collection import collection as collection

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

# faces (n,) and bary (n, 3): map()'s result; values_b (nB,) or (nB, k) -> (n,) or (n, k)
def transfer(faces: ArrayLike, bary: ArrayLike, F_b: ArrayLike, values_b: ArrayLike) -> NDArray[np.float64]: ...
def surface_points(faces: ArrayLike, bary: ArrayLike, V_b: ArrayLike, F_b: ArrayLike) -> NDArray[np.float64]: ...
