# Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Type stubs of hyperbolic_orbifold_tutte.collection (collection.py)."""

import os
from typing import Any, Sequence, Union

_Path = Union[str, os.PathLike[str]]

# client: a dask.distributed.Client or None (threads of this process)
def collection(manifest: _Path, out_dir: _Path, all_pairs: bool = False, client: Any = None,
               cone_orders: Sequence[int] | None = None, repair: bool = False, max_hole: float | None = None,
               largest_component: bool = False, snap_landmarks: bool = False, threads: int | None = None,
               progress: bool = True, refine: int = 0) -> dict[str, Any]: ...
