# Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Facts an embedding must satisfy, computed here with numpy from e.uv alone (not by the
library): points inside the unit disk, every face positively oriented, the angle sums at the
vertices (2 pi inside, 2 pi / p at a cone of order p, pi / 2 at a disk corner, pi along the
boundary), and the total hyperbolic area of the faces (Gauss-Bonnet: 2 pi (sum(1 - 1/p) - 2) on
a sphere-type orbifold, 2 pi (k/2 - 2) for k cones of order 2; (k - 4) pi / 2 for a disk with k
corners). Then the GIL: embeddings in threads run while Python runs, and give the same bits."""

import concurrent.futures
import os
import threading
import time

import numpy as np
import pytest

import hyperbolic_orbifold_tutte as hot


@pytest.fixture(scope="module")
def mushroom(meshes):
    V, F = hot.read_mesh(os.path.join(meshes, "mushroom.off"))
    lm = hot.select_landmarks(V, F, 6)
    return V, F, lm, hot.embed(V, F, lm)


def corner_angles(uv):
    """the hyperbolic angle of every corner (m, 3) of Poincare triangles (m, 3, 2): at z, the
    angle from the geodesic towards the next corner a to the one towards the previous corner b
    is arg(T(b) / T(a)), T(w) = (w - z) / (1 - conj(z) w), the isometry taking z to 0 (the
    Poincare model is conformal, and geodesics through 0 are straight)"""
    z = uv[..., 0] + 1j * uv[..., 1]
    a = np.roll(z, -1, axis=1)
    b = np.roll(z, 1, axis=1)

    def T(w):
        return (w - z) / (1 - np.conj(z) * w)

    return np.angle(T(b) / T(a))


def klein_orientation(uv):
    """twice the signed Euclidean area of every face's Klein-model triangle (geodesics are
    straight there; K = 2 z / (1 + |z|^2) keeps orientation)"""
    z = uv[..., 0] + 1j * uv[..., 1]
    k = 2 * z / (1 + np.abs(z) ** 2)
    d1, d2 = k[:, 1] - k[:, 0], k[:, 2] - k[:, 0]
    return (np.conj(d1) * d2).imag


def vertex_angle_sums(F, angles, n):
    return np.bincount(F.ravel(), weights=angles.ravel(), minlength=n)


def test_sphere_type_invariants(bear):
    V, F, lm, e = bear
    uv = e.uv
    assert np.all(np.hypot(uv[..., 0], uv[..., 1]) < 1)
    assert np.all(klein_orientation(uv) > 0)
    angles = corner_angles(uv)
    assert np.all(angles > 0) and np.all(angles < np.pi)
    area = np.sum(np.pi - angles.sum(axis=1))
    k = len(lm)
    assert area == pytest.approx(2 * np.pi * (k / 2 - 2), abs=1e-6)  # Gauss-Bonnet, (k - 4) pi
    sums = vertex_angle_sums(F, angles, len(V))
    cone = np.zeros(len(V), dtype=bool)
    cone[lm] = True
    assert np.allclose(sums[cone], np.pi, atol=1e-6)  # cones of order 2: angle pi
    assert np.allclose(sums[~cone], 2 * np.pi, atol=1e-6)  # the others, seam copies added


def test_cones_of_orders_2_3_7(meshes):
    V, F = hot.read_mesh(os.path.join(meshes, "bear.off"))
    lm, orders = [8768, 4116, 9726], [2, 3, 7]
    e = hot.embed(V, F, lm, cone_orders=orders)
    angles = corner_angles(e.uv)
    assert np.all(angles > 0) and np.all(klein_orientation(e.uv) > 0)
    area = np.sum(np.pi - angles.sum(axis=1))
    assert area == pytest.approx(2 * np.pi * (sum(1 - 1 / p for p in orders) - 2), abs=1e-6)
    sums = vertex_angle_sums(F, angles, len(V))
    for v, p in zip(lm, orders):
        assert sums[v] == pytest.approx(2 * np.pi / p, abs=1e-6)


def test_disk_type_invariants(mushroom):
    V, F, lm, e = mushroom
    uv = e.uv
    assert np.all(np.hypot(uv[..., 0], uv[..., 1]) < 1)
    assert np.all(klein_orientation(uv) > 0)
    angles = corner_angles(uv)
    assert np.all(angles > 0)
    k = len(lm)
    assert np.sum(np.pi - angles.sum(axis=1)) == pytest.approx((k - 4) * np.pi / 2, abs=1e-6)
    sums = vertex_angle_sums(F, angles, len(V))
    # the boundary: edges used by one face only
    edges = np.sort(np.concatenate([F[:, [0, 1]], F[:, [1, 2]], F[:, [2, 0]]]), axis=1)
    unique, count = np.unique(edges, axis=0, return_counts=True)
    border = np.zeros(len(V), dtype=bool)
    border[unique[count == 1].ravel()] = True
    corner = np.zeros(len(V), dtype=bool)
    corner[lm] = True
    assert np.allclose(sums[corner], np.pi / 2, atol=1e-6)
    assert np.allclose(sums[border & ~corner], np.pi, atol=1e-6)
    assert np.allclose(sums[~border], 2 * np.pi, atol=1e-6)
    # a disk is not cut: every vertex has one point
    pts = np.zeros((len(V), 2))
    pts[F.ravel()] = uv.reshape(-1, 2)
    assert np.array_equal(pts[F], uv)


def test_map_sends_landmarks_onto_landmarks_and_bary_sums_to_one(bear):
    V, F, lm, e = bear
    faces, bary = hot.map(e, e)  # a mesh onto itself: every vertex onto itself
    assert np.allclose(bary.sum(axis=1), 1)
    assert np.all(bary >= 0)
    p = hot.transfer(faces, bary, F, V)
    assert np.max(np.linalg.norm(p - V, axis=1)) < 1e-9 * np.linalg.norm(V.max(0) - V.min(0))
    # transfer of several columns at once = column by column
    vals = np.stack([V[:, 0], V[:, 1] ** 2], axis=1)
    both = hot.transfer(faces, bary, F, vals)
    assert np.array_equal(both[:, 1], hot.transfer(faces, bary, F, vals[:, 1].copy()))


def test_embed_releases_the_gil(bear):
    """while a thread embeds, the main thread keeps running Python: the longest pause it sees
    is a small part of the embedding's time (it would be all of it with the GIL held)"""
    V, F, lm, _ = bear
    done = threading.Event()

    def work():
        hot.embed(V, F, lm)
        done.set()

    t = threading.Thread(target=work)
    start = last = time.perf_counter()
    t.start()
    longest, loops = 0.0, 0
    while not done.is_set():
        now = time.perf_counter()
        longest = max(longest, now - last)
        last = now
        loops += 1
    t.join()
    duration = time.perf_counter() - start
    print("embed in a thread: %.3f s; the main thread's longest pause %.4f s over %d loops" % (duration, longest, loops))
    assert duration > 0.05
    assert longest < 0.5 * duration


def test_threads_give_the_serial_results(bear, mushroom):
    jobs = [bear[:3], mushroom[:3], bear[:3]]
    serial = [hot.embed(*j) for j in jobs]
    with concurrent.futures.ThreadPoolExecutor(max_workers=3) as pool:
        parallel = list(pool.map(lambda j: hot.embed(*j), jobs))
    for s, p in zip(serial, parallel):
        assert np.array_equal(s.uv, p.uv)
    faces_s, bary_s = hot.map(serial[0], serial[2])
    with concurrent.futures.ThreadPoolExecutor(max_workers=2) as pool:
        results = list(pool.map(lambda ab: hot.map(*ab), [(parallel[0], parallel[2])] * 2))
    for faces, bary in results:
        assert np.array_equal(faces, faces_s) and np.array_equal(bary, bary_s)


def test_dask_threads(bear, mushroom):
    dask = pytest.importorskip("dask")
    tasks = [dask.delayed(hot.embed)(*j) for j in (bear[:3], mushroom[:3])]
    results = dask.compute(*tasks, scheduler="threads")
    assert np.array_equal(results[0].uv, bear[3].uv)
    assert np.array_equal(results[1].uv, mushroom[3].uv)
