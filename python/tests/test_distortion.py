# Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
# SPDX-License-Identifier: GPL-3.0-or-later
"""hot.map_distortion(): facts of linear algebra on known maps, and the numbers of the CLI's map
report ("distortion")."""

import json
import os

import numpy as np
import pytest

import hyperbolic_orbifold_tutte as hot
from hot_testing import run_awk, run_cli


def test_identity_and_similarity(meshes):
    V, F = hot.read_mesh(os.path.join(meshes, "bear.off"))
    d = hot.map_distortion(V, F, V)
    assert np.all(d["sigma1"] == 1) and np.all(d["sigma2"] == 1)  # (the identity, exactly: see map_distortion.h)
    assert d["conformal_summary"]["max"] == 1 and d["area_summary"]["max"] == 1
    assert np.all(d["symmetric_dirichlet"] == 4) and d["symmetric_dirichlet_energy"] == pytest.approx(4, rel=1e-14)
    # a rotation and a scaling by 2.5: singular values 2.5, conformal 1, normalised area 1
    c, s = np.cos(0.7), np.sin(0.7)
    R = np.array([[c, -s, 0], [s, c, 0], [0, 0, 1]])
    d = hot.map_distortion(V, F, 2.5 * V @ R.T + [1, 2, 3])
    assert np.allclose(d["sigma1"], 2.5, rtol=1e-10) and np.allclose(d["sigma2"], 2.5, rtol=1e-10)
    assert abs(d["conformal_summary"]["max"] - 1) < 1e-10 and abs(d["area_summary"]["max"] - 1) < 1e-10
    assert d["sigma1"].shape == (len(F),) and d["degenerate_image_faces"] == 0


def test_linear_map_of_a_flat_grid():
    # a grid in the plane z = 0 and its image under M (in the plane): every face has M's singular values
    n = 12
    x, y = np.meshgrid(np.arange(n, dtype=float), np.arange(n, dtype=float), indexing="ij")
    V = np.stack([x.ravel(), y.ravel(), np.zeros(n * n)], axis=1)
    F = []
    for i in range(n - 1):
        for j in range(n - 1):
            a, b, c, e = i * n + j, (i + 1) * n + j, (i + 1) * n + j + 1, i * n + j + 1
            F += [[a, b, c], [a, c, e]]
    F = np.array(F, dtype=np.int64)
    M = np.array([[2.0, 0.5], [0.0, 1.0]])
    W = V.copy()
    W[:, :2] = V[:, :2] @ M.T
    sv = np.linalg.svd(M, compute_uv=False)  # (numpy's SVD: an outside reference)
    d = hot.map_distortion(V, F, W)
    assert np.allclose(d["sigma1"], sv[0], rtol=1e-12) and np.allclose(d["sigma2"], sv[1], rtol=1e-12)
    assert np.allclose(d["conformal"], sv[0] / sv[1], rtol=1e-12)
    assert np.allclose(d["area"], 1, rtol=1e-12)  # a uniform area change, normalised away
    # symmetric Dirichlet of the singular values scaled to keep the areas: 2 (kappa + 1/kappa)
    kappa = sv[0] / sv[1]
    assert np.allclose(d["symmetric_dirichlet"], 2 * (kappa + 1 / kappa), rtol=1e-11)
    assert d["symmetric_dirichlet_energy"] == pytest.approx(2 * (kappa + 1 / kappa), rel=1e-11)
    # a face collapsed by two vertices sent to one point: conformal infinity, counted, no NaN
    W2 = W.copy()
    W2[1] = W2[0]
    d = hot.map_distortion(V, F, W2)
    assert d["degenerate_image_faces"] >= 1 and np.isinf(d["conformal"]).sum() == d["degenerate_image_faces"]
    assert not np.isnan(d["conformal"]).any() and not np.isnan(d["area"]).any()


def test_the_numbers_of_the_cli_map_report(cli, meshes, source_dir, tmp_path):
    bear = os.path.join(meshes, "bear.off")
    bent = run_awk(os.path.join(source_dir, "test", "bend.awk"), bear, tmp_path / "bent.off", R=3)
    cones = tmp_path / "c.txt"
    cones.write_text("10138 5326 2877 3940 7260 13588 121\n")
    run_cli(cli, "map", "--source", bear, "--source-cones", cones, "--target", bent, "--target-cones", cones,
            "--out", tmp_path / "m.txt", "--report", tmp_path / "r.json")
    report = json.load(open(tmp_path / "r.json"))["distortion"]
    VA, FA = hot.read_mesh(bear)
    VB, FB = hot.read_mesh(bent)
    lm = np.array([10138, 5326, 2877, 3940, 7260, 13588, 121])
    ea = hot.embed(VA, FA, lm)
    eb = hot.embed(VB, FB, lm, order=ea.landmark_order)
    faces, bary = hot.map(ea, eb)
    d = hot.map_distortion(VA, FA, hot.surface_points(faces, bary, VB, FB))
    for kind in ("conformal", "area", "symmetric_dirichlet"):
        for key in ("p50", "p90", "p99", "max", "mean"):
            assert d[kind + "_summary"][key] == pytest.approx(report[kind][key], rel=1e-12)
    assert d["symmetric_dirichlet_energy"] == pytest.approx(report["symmetric_dirichlet_energy"], rel=1e-12)
    assert report["symmetric_dirichlet_energy"] >= 4  # (s^2 + 1/s^2 >= 2 for each singular value)
    assert d["conformal_summary"]["p50"] >= 1  # sigma1 >= sigma2


def test_map_refine_moves_towards_the_isometry(bear):
    # bear and a rotated, scaled, moved copy (vertex i <-> i: an isometry up to scale); the
    # source embedded with uniform weights, so that the harmonic map is not that truth. The
    # refined map is closer to it, its symmetric Dirichlet energy lower and never below 4 (its
    # least value, an isometry's); the source embedding is left as it was.
    V, F, lm, _ = bear
    c, s = np.cos(0.7), np.sin(0.7)
    W = 2.0 * V @ np.array([[c, -s, 0], [s, c, 0], [0, 0, 1]]).T + [1, -3, 0.5]
    a = hot.embed(V, F, lm, weights="uniform", order="tsp")
    b = hot.embed(W, F, lm, order=a.landmark_order)
    diag = np.linalg.norm(W.max(0) - W.min(0))

    def error(faces, bary):
        return np.linalg.norm(hot.transfer(faces, bary, F, W) - W, axis=1) / diag

    f0, b0 = hot.map(a, b)
    f1, b1 = hot.map(a, b, refine=40)
    e0, e1 = error(f0, b0), error(f1, b1)
    assert e0.mean() > 0.002  # (else nothing is tested)
    assert e1.mean() < 0.7 * e0.mean() and e1.max() < e0.max()
    d0 = hot.map_distortion(V, F, hot.transfer(f0, b0, F, W))
    d1 = hot.map_distortion(V, F, hot.transfer(f1, b1, F, W))
    assert 4 - 1e-9 <= d1["symmetric_dirichlet_energy"] < d0["symmetric_dirichlet_energy"]
    for i in lm:  # the landmarks stay on their landmarks
        assert np.linalg.norm(hot.transfer(f1[i:i + 1], b1[i:i + 1], F, W)[0] - W[i]) < 1e-9 * diag
    f2, b2 = hot.map(a, b)  # the source is unchanged by the refinement
    assert np.array_equal(f2, f0) and np.array_equal(b2, b0)
    with pytest.raises(hot.Error, match="refine must be"):
        hot.map(a, b, refine=-1)
