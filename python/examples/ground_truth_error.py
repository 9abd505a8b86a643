#!/usr/bin/env python3
# Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
# SPDX-License-Identifier: GPL-3.0-or-later
"""The error of the map between two meshes whose vertices correspond (vertex i of A is vertex i of
B, e.g. the TOSCA poses of one class) against that ground truth, in % of B's bounding-box diagonal,
with the map's per-face distortion.

    PYTHONPATH=build/python /usr/bin/python3 python/examples/ground_truth_error.py \\
        A.off A_landmarks.txt B.off B_landmarks.txt
"""

import sys

import numpy as np
from numpy.typing import NDArray

import hyperbolic_orbifold_tutte as hot


def main(a_mesh: str, a_cones: str, b_mesh: str, b_cones: str) -> NDArray[np.float64]:
    VA, FA = hot.read_mesh(a_mesh)
    VB, FB = hot.read_mesh(b_mesh)
    if VA.shape != VB.shape:
        raise SystemExit("the two meshes must have the same vertices (vertex i of A is vertex i of B)")
    la = np.loadtxt(a_cones, dtype=np.int64).ravel()
    lb = np.loadtxt(b_cones, dtype=np.int64).ravel()
    ea = hot.embed(VA, FA, la)
    eb = hot.embed(VB, FB, lb, order=ea.landmark_order)  # the same landmark at the same cone
    faces, bary, unreliable = hot.map(ea, eb, unreliable=True)
    images = hot.surface_points(faces, bary, VB, FB)
    diagonal = np.linalg.norm(VB.max(axis=0) - VB.min(axis=0))
    error: NDArray[np.float64] = np.linalg.norm(images - VB, axis=1) / diagonal * 100
    trusted = np.ones(len(error), dtype=bool)
    trusted[np.asarray(unreliable, dtype=np.int64)] = False
    d = hot.map_distortion(VA, FA, images)
    print("%s -> %s: %d vertices, %d landmarks; error against vertex i, in %% of the diagonal: mean %.3f, median %.3f, max %.2f,"
          " %.1f%% of the vertices within 1%%; without the %d vertices the map flags as unreliable: mean %.3f, max %.2f;"
          " conformal distortion p50 %.3f p99 %.3f, area p50 %.3f p99 %.3f"
          % (a_mesh, b_mesh, len(VA), len(la), error.mean(), np.median(error), error.max(), (error < 1).mean() * 100,
             (~trusted).sum(), error[trusted].mean(), error[trusted].max(),
             d["conformal_summary"]["p50"], d["conformal_summary"]["p99"], d["area_summary"]["p50"], d["area_summary"]["p99"]))
    return error


if __name__ == "__main__":
    if len(sys.argv) != 5:
        raise SystemExit(__doc__)
    main(*sys.argv[1:])
