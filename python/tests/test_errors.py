# Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Bad input raises hot.Error with the library's code and a message that says what is wrong,
and never crashes the process (every case runs in this process: a crash fails the run)."""

import os

import numpy as np
import pytest

import hyperbolic_orbifold_tutte as hot
from hot_testing import run_awk, write_off


@pytest.fixture(scope="module")
def bear(meshes):
    V, F = hot.read_mesh(os.path.join(meshes, "bear.off"))
    return V, F, hot.select_landmarks(V, F, 7)


def raises(code, fn, *args, match=None, **kw):
    with pytest.raises(hot.Error) as info:
        fn(*args, **kw)
    e = info.value
    assert e.code == code, "%s: %s" % (e.code, e)
    assert str(e) == e.message and e.message
    assert e.description == hot.error_codes[code]
    if match:
        assert match in e.message, e.message
    return e


def test_the_error_class():
    assert issubclass(hot.Error, Exception)
    e = hot.Error("something", "ERROR_READ_FAILED")
    assert str(e) == "something" and e.code == "ERROR_READ_FAILED"
    assert "ERROR_NON_MANIFOLD" in hot.error_codes and hot.error_codes["OK"] == "Success"


def test_missing_and_unreadable_files(tmp_path):
    missing = str(tmp_path / "none.off")
    raises("ERROR_READ_FAILED", hot.read_mesh, missing, match=missing)
    (tmp_path / "m.xyz").write_text("1 2 3\n")
    raises("ERROR_READ_FAILED", hot.read_mesh, tmp_path / "m.xyz", match="unsupported file extension")
    (tmp_path / "t.off").write_text("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n")
    raises("ERROR_READ_FAILED", hot.read_mesh, str(tmp_path / "t.off"), match="out of range")


def test_index_out_of_range_and_shapes(bear):
    V, F, lm = bear
    bad = F.copy()
    bad[5, 1] = len(V)
    raises("ERROR_WRONG_PARAMETER", hot.embed, V, bad, lm, match="F[5, 1] = %d is not a vertex index" % len(V))
    bad[5, 1] = -1
    raises("ERROR_WRONG_PARAMETER", hot.embed, V, bad, lm, match="F[5, 1] = -1")
    raises("ERROR_WRONG_PARAMETER", hot.embed, V[:, :2], F, lm, match="shape (n, 3)")
    raises("ERROR_WRONG_PARAMETER", hot.embed, V, F.ravel(), lm, match="shape (m, 3)")
    raises("ERROR_WRONG_PARAMETER", hot.embed, V, F.astype(float), lm, match="integer")
    raises("ERROR_WRONG_PARAMETER", hot.select_landmarks, V, bad, 7)
    raises("ERROR_EMPTY_MESH", hot.embed, np.zeros((0, 3)), np.zeros((0, 3), dtype=np.int64), [])


def cube_quads():
    V = np.array([[x, y, z] for x in (0, 1) for y in (0, 1) for z in (0, 1)], dtype=float)
    F = np.array([[0, 1, 3, 2], [4, 6, 7, 5], [0, 4, 5, 1], [2, 3, 7, 6], [0, 2, 6, 4], [1, 5, 7, 3]])
    return V, F


def test_non_triangles(tmp_path):
    V, F = cube_quads()
    raises("ERROR_NON_TRIANGULAR_MESH", hot.embed, V, F, [0, 1, 2, 3, 4], match="only triangle meshes")
    raises("ERROR_NON_TRIANGULAR_MESH", hot.read_mesh, write_off(tmp_path / "cube.off", V, F))
    # the command line's --repair triangulates them
    VR, FR, index = hot.read_mesh(tmp_path / "cube.off", repair=True, return_file_index=True)
    assert FR.shape == (12, 3) and np.array_equal(VR, V) and list(index) == list(range(8))


def test_landmarks(bear, meshes):
    V, F, lm = bear
    raises("ERROR_TOO_FEW_LANDMARKS", hot.embed, V, F, lm[:4], match="at least 5")
    raises("ERROR_TOO_FEW_LANDMARKS", hot.embed, V, F, [])
    raises("ERROR_DUPLICATE_LANDMARK", hot.embed, V, F, list(lm) + [lm[2]], match="given twice")
    raises("ERROR_LANDMARK_OUT_OF_RANGE", hot.embed, V, F, list(lm[:6]) + [len(V)], match="only %d vertices" % len(V))
    raises("ERROR_LANDMARK_OUT_OF_RANGE", hot.embed, V, F, list(lm[:6]) + [-3], match="-3")
    raises("ERROR_WRONG_PARAMETER", hot.embed, V, F, [0.5, 1, 2, 3, 4], match="integer")
    VM, FM = hot.read_mesh(os.path.join(meshes, "mushroom.off"))
    corners = hot.select_landmarks(VM, FM, 5)
    edges = np.sort(np.concatenate([FM[:, [0, 1]], FM[:, [1, 2]], FM[:, [2, 0]]]), axis=1)
    unique, count = np.unique(edges, axis=0, return_counts=True)
    boundary = set(unique[count == 1].ravel())
    inner = next(v for v in range(len(VM)) if v not in boundary)
    raises("ERROR_LANDMARK_NOT_ON_BORDER", hot.embed, VM, FM, list(corners[:4]) + [inner], match="boundary")
    raises("ERROR_WRONG_PARAMETER", hot.select_landmarks, V, F, 0)
    raises("ERROR_WRONG_PARAMETER", hot.select_landmarks, V, F, len(V) + 1, match="larger than the number of vertices")


def test_non_finite_coordinates(bear):
    V, F, lm = bear
    for bad_value in (np.nan, np.inf):
        W = V.copy()
        W[5, 1] = bad_value
        raises("ERROR_NON_FINITE_COORDINATES", hot.embed, W, F, lm, match="vertex 5")
        raises("ERROR_NON_FINITE_COORDINATES", hot.select_landmarks, W, F, 7)


def test_non_manifold_and_non_orientable(tmp_path):
    # three triangles on one edge
    V = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, -1, 0], [0, 0, 1]], dtype=float)
    F = np.array([[0, 1, 2], [1, 0, 3], [0, 1, 4]])
    raises("ERROR_NON_MANIFOLD", hot.embed, V, F, [0, 1, 2, 3, 4], match="non-manifold edge")
    raises("ERROR_NON_MANIFOLD", hot.read_mesh, write_off(tmp_path / "fin.off", V, F), match="fin.off")
    # a Moebius strip: no consistent orientation
    n = 8
    V = []
    for i in range(n):
        a = 2 * np.pi * i / n
        for s in (-0.3, 0.3):
            r = 1 + s * np.cos(a / 2)
            V.append((r * np.cos(a), r * np.sin(a), s * np.sin(a / 2)))
    V = np.array(V)
    F = []
    for i in range(n):
        a0, a1 = 2 * i, 2 * i + 1
        if i < n - 1:
            b0, b1 = 2 * i + 2, 2 * i + 3
        else:
            b0, b1 = 1, 0  # the half twist
        F += [(a0, b0, a1), (a1, b0, b1)]
    F = np.array(F)
    raises("ERROR_NON_MANIFOLD", hot.embed, V, F, [0, 2, 4, 6, 8], match="orientation")
    raises("ERROR_NON_MANIFOLD", hot.read_mesh, write_off(tmp_path / "moebius.off", V, F), match="orientation")


def test_options(bear, tmp_path):
    V, F, lm = bear
    raises("ERROR_WRONG_PARAMETER", hot.embed, V, F, lm, orbifold="torus", match="orbifold")
    raises("ERROR_WRONG_TOPOLOGY", hot.embed, V, F, lm, orbifold="disk")
    raises("ERROR_WRONG_PARAMETER", hot.embed, V, F, lm, weights="harmonic", match="weights")
    raises("ERROR_WRONG_PARAMETER", hot.embed, V, F, lm, weights=3, match="weights")
    raises("ERROR_WRONG_PARAMETER", hot.map_meshes, V, F, lm, V, F, lm, weights=3, match="weights")
    # weights=None (the default) is the cotangent weights when their embedding is certified
    # (else the mean value ones, which bear.off does not need): the same corners, bit for bit
    a, b = hot.embed(V, F, lm), hot.embed(V, F, lm, weights="cotan")
    assert a.report["weights"] == b.report["weights"] == "cotan"
    assert (a.uv == b.uv).all()
    raises("ERROR_WRONG_PARAMETER", hot.embed, V, F, lm, order="random", match="order")
    raises("ERROR_WRONG_PARAMETER", hot.embed, V, F, lm, order=[0, 0, 1, 2, 3, 4, 5], match="permutation")
    raises("ERROR_WRONG_PARAMETER", hot.embed, V, F, lm, order=[0, 1, 2], match="permutation")
    raises("ERROR_WRONG_PARAMETER", hot.embed, V, F, lm, cone_orders=[1, 2, 2, 2, 2, 2, 2], match="cone_orders")
    raises("ERROR_WRONG_PARAMETER", hot.embed, V, F, lm[:3], cone_orders=[2, 3], match="one per landmark")
    raises("ERROR_NOT_HYPERBOLIC", hot.embed, V, F, lm[:3], cone_orders=[2, 3, 6], match="not hyperbolic")
    raises("ERROR_WRONG_PARAMETER", hot.embed, V, F, lm, cut_graph=[[0, 1]], match="genus 0")
    e = hot.embed(V, F, lm)
    raises("ERROR_WRITE_FAILED", e.write_obj, tmp_path / "no" / "such" / "dir.obj")
    raises("ERROR_WRONG_PARAMETER", hot.read_mesh, tmp_path / "x.off", largest_component=True)


def test_incompatible_embeddings_in_map(bear, meshes):
    V, F, lm = bear
    ea = hot.embed(V, F, lm)  # the tour
    assert list(ea.landmark_order) != list(range(7))
    eb = hot.embed(V, F, lm, order="given")
    raises("ERROR_WRONG_PARAMETER", hot.map, ea, eb, match="landmark_order")
    e8 = hot.embed(V, F, hot.select_landmarks(V, F, 8))
    raises("ERROR_WRONG_PARAMETER", hot.map, ea, e8, match="7 landmarks and the target 8")
    VM, FM = hot.read_mesh(os.path.join(meshes, "mushroom.off"))
    disk = hot.embed(VM, FM, hot.select_landmarks(VM, FM, 7))
    raises("ERROR_WRONG_TOPOLOGY", hot.map, ea, disk, match="the source is closed but the target is a disk")
    c1 = hot.embed(V, F, lm[:3], cone_orders=[2, 3, 7])
    c2 = hot.embed(V, F, lm[:3], cone_orders=[3, 2, 7], order=c1.landmark_order)
    raises("ERROR_WRONG_PARAMETER", hot.map, c1, c2, match="cone_orders")
    VE, FE = hot.read_mesh(os.path.join(meshes, "eight.off"))
    VK, FK = hot.read_mesh(os.path.join(meshes, "elk.off"))
    raises("ERROR_WRONG_TOPOLOGY", hot.map, hot.embed(VE, FE, [0]), hot.embed(VK, FK, [0]), match="genus 2 and the target genus 1")
    raises("ERROR_WRONG_PARAMETER", hot.map, ea, None)
    with pytest.raises(TypeError):
        hot.map(ea, "bear")


def test_transfer_checks_its_arguments(bear):
    V, F, lm = bear
    faces, bary = np.array([0, 1]), np.full((2, 3), 1 / 3)
    raises("ERROR_WRONG_PARAMETER", hot.transfer, faces, bary[:, :2], F, V)
    raises("ERROR_WRONG_PARAMETER", hot.transfer, np.array([0, len(F)]), bary, F, V, match="out of range")
    raises("ERROR_WRONG_PARAMETER", hot.transfer, faces, bary, F, V[:2], match="beyond")
    assert hot.transfer(faces, bary, F, V).shape == (2, 3)


def edge_uses(F):
    edges = np.sort(np.concatenate([F[:, [0, 1]], F[:, [1, 2]], F[:, [2, 0]]]), axis=1)
    return np.unique(edges, axis=0, return_counts=True)[1]


def test_repair_with_landmarks(bear, tmp_path):
    # a scan's defects on bear, its vertex numbers kept: an opening of the faces within 0.3 of
    # the diagonal from a vertex far from the landmarks, and a stray triangle (debris)
    V, F, lm = bear
    diagonal = np.linalg.norm(V.max(axis=0) - V.min(axis=0))
    far = int(np.argmax(np.min(np.linalg.norm(V[:, None, :] - V[None, lm, :], axis=2), axis=1)))
    inside = np.linalg.norm(V - V[far], axis=1) < 0.3 * diagonal
    assert not inside[lm].any()
    keep = ~inside[F].any(axis=1)
    n = len(V)
    VD = np.vstack([V, V[0] + 1e-3 * diagonal * np.array([[2, 2, 2], [3, 2, 2], [2, 3, 2]])])
    FD = np.vstack([F[keep], [[n, n + 1, n + 2]]])
    path = write_off(tmp_path / "scan.off", VD, FD)
    # without the landmarks the opening is too long to be a hole: the repair keeps a disk
    VR, FR = hot.read_mesh(path, repair=True)
    assert (edge_uses(FR) == 1).any()
    # the landmarks inside ask for a sphere: closed, the debris dropped, the input's vertices kept
    VS, FS, index = hot.read_mesh(path, repair=True, landmarks=lm, return_file_index=True)
    assert (edge_uses(FS) == 2).all()
    assert len(VS) - 3 * len(FS) // 2 + len(FS) == 2  # Euler: a sphere
    used = np.unique(F[keep])
    assert set(index[index < n]) == set(used) and not ((index >= n) & (index < n + 3)).any()
    assert np.array_equal(VS[index < n], V[index[index < n]])
    raises("ERROR_WRONG_PARAMETER", hot.read_mesh, path, landmarks=lm, match="needs repair")
    raises("ERROR_LANDMARK_OUT_OF_RANGE", hot.read_mesh, path, repair=True, landmarks=list(lm) + [n + 10])
    # a maximum hole length given is a limit again
    raises("ERROR_WRONG_TOPOLOGY", hot.read_mesh, path, repair=True, landmarks=lm, max_hole=0.5, orbifold="sphere")


def test_repair_cuts_handles(bear, meshes, source_dir, tmp_path):
    # topological noise: bear.off with two faces 30 rings apart but close in space joined by a
    # tube (test/add_handle.awk, the vertex numbers kept): genus 1. target_genus=0 cuts the
    # handle: a closed mesh of genus 0 again (Euler), every input vertex kept at its place
    V, F, lm = bear
    path = run_awk(os.path.join(source_dir, "test", "add_handle.awk"), os.path.join(meshes, "bear.off"), tmp_path / "h.off",
                   face=5000, min_rings=30)
    VH, FH = hot.read_mesh(path)
    assert len(VH) == len(V) and len(VH) - 3 * len(FH) // 2 + len(FH) == 0  # genus 1
    VS, FS, index = hot.read_mesh(path, repair=True, landmarks=lm, target_genus=0, return_file_index=True)
    assert (edge_uses(FS) == 2).all()
    assert len(VS) - 3 * len(FS) // 2 + len(FS) == 2  # Euler: genus 0
    n = len(VH)
    assert set(index[index < n]) == set(range(n))
    assert np.array_equal(VS[index < n], VH[index[index < n]])
    # without target_genus the genus is kept
    VK, FK = hot.read_mesh(path, repair=True, landmarks=lm)
    assert len(VK) - 3 * len(FK) // 2 + len(FK) == 0
    # a bound below the loop: refused, saying which handle
    raises("ERROR_WRONG_TOPOLOGY", hot.read_mesh, path, repair=True, landmarks=lm, target_genus=0, max_handle=0.001,
           match="handle 1 of 1")
    raises("ERROR_WRONG_PARAMETER", hot.read_mesh, path, target_genus=0, match="needs repair")
    raises("ERROR_WRONG_PARAMETER", hot.read_mesh, path, repair=True, target_genus=-1, match="target_genus")
