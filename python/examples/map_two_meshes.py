#!/usr/bin/env python3
# Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Maps one mesh onto another through a hyperbolic orbifold and carries a function across.

    map_two_meshes.py A.off [B.off] [--landmarks K]

A and B are closed genus-0 meshes (or two disks) whose vertex i correspond at the landmarks:
K landmarks are picked on A (farthest-point sampling) and used as the same vertex numbers on B.
Without B, B is a copy of A bent about its z axis (vertex i of B is the image of vertex i of A),
and the map is checked against that ground truth.

Run with the package on the path, e.g.
    PYTHONPATH=build/python /usr/bin/python3 python/examples/map_two_meshes.py build/data/meshes/bear.off
"""

import argparse
import sys
import time

import numpy as np
from numpy.typing import NDArray

import hyperbolic_orbifold_tutte as hot


def bend(V: NDArray[np.float64], radius: float) -> NDArray[np.float64]:
    """V bent about the z axis into an arc of the given radius in the x-z plane"""
    t = V[:, 2] / radius
    x = radius * (1 - np.cos(t)) + V[:, 0] * np.cos(t)
    z = radius * np.sin(t) - V[:, 0] * np.sin(t)
    return np.stack([x, V[:, 1], z], axis=1)


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("source")
    parser.add_argument("target", nargs="?")
    parser.add_argument("--landmarks", type=int, default=7)
    args = parser.parse_args()

    VA, FA = hot.read_mesh(args.source)
    if args.target:
        VB, FB = hot.read_mesh(args.target)
    else:
        VB, FB = bend(VA, 3 * np.ptp(VA[:, 2])), FA
    landmarks = hot.select_landmarks(VA, FA, args.landmarks)

    t0 = time.perf_counter()
    ea = hot.embed(VA, FA, landmarks)  # the landmark tour on A ...
    eb = hot.embed(VB, FB, landmarks, order=ea.landmark_order)  # ... used on B: landmark i <-> landmark i
    t1 = time.perf_counter()
    faces, bary = hot.map(ea, eb)  # every vertex of A on B: a face of B and barycentric coordinates
    t2 = time.perf_counter()
    print("embedded %s (%d vertices) and its target (%d vertices) in %.2f s, mapped in %.2f s" %
          (args.source, len(VA), len(VB), t1 - t0, t2 - t1))
    print("cone order (vertex numbers):", list(ea.report["landmark_order_used"]),
          "certified:", ea.certified and eb.certified)

    # a function on B (its height) carried to A; and the image points of A's vertices on B
    height_on_a = hot.transfer(faces, bary, FB, VB[:, 1])
    images = hot.surface_points(faces, bary, VB, FB)
    print("height carried from B to A: min %.4f max %.4f" % (height_on_a.min(), height_on_a.max()))
    if not args.target:
        diagonal = np.linalg.norm(VB.max(axis=0) - VB.min(axis=0))
        error = np.linalg.norm(images - VB, axis=1) / diagonal
        print("distance to the true images: mean %.4f%%, max %.4f%% of the diagonal" %
              (100 * error.mean(), 100 * error.max()))
        if error.mean() > 0.02:
            return 1
    return 0


if __name__ == "__main__":
    try:
        sys.exit(main())
    except hot.Error as e:
        print("map_two_meshes.py: %s (%s)" % (e, e.code), file=sys.stderr)
        sys.exit(3)
