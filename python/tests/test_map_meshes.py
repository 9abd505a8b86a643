# Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
# SPDX-License-Identifier: GPL-3.0-or-later
"""hot.map_meshes(): mesh A onto mesh B in one call (the command line's `map`: the landmark
order chosen as `map --order auto` chooses it, both meshes embedded in it, A mapped onto B),
and the coercion of array inputs (any array-like; C-contiguous float64 / int64 read in place).

The ground truth of a map onto a copy with the same triangulation is vertex i -> vertex i."""

import inspect
import json
import os

import numpy as np
import pytest

import hyperbolic_orbifold_tutte as hot
from hot_testing import flat_disk, read_map, read_off, run_cli, write_cones


def rigid_copy(V):
    """V rotated about an oblique axis and moved (no scaling): an isometry of the surface"""
    axis = np.array([1.0, 2.0, 3.0]) / np.sqrt(14.0)
    a = 0.9
    K = np.array([[0, -axis[2], axis[1]], [axis[2], 0, -axis[0]], [-axis[1], axis[0], 0]])
    R = np.eye(3) + np.sin(a) * K + (1 - np.cos(a)) * K @ K  # Rodrigues
    return V @ R.T + np.array([3.0, -1.0, 0.25])


def diagonal(V):
    return np.linalg.norm(V.max(0) - V.min(0))


@pytest.fixture(scope="module")
def bear_pair(bear):
    V, F, lm, _ = bear
    W = rigid_copy(V)
    return V, F, lm, W, hot.map_meshes(V, F, lm, W, F, lm)


# ---------------------------------------------------------------------------------------
# (a) a rigid copy: the map recovers the motion; landmarks onto landmarks
# ---------------------------------------------------------------------------------------

def test_rigid_copy_is_recovered(bear_pair):
    V, F, lm, W, r = bear_pair
    assert set(r) == {"faces", "bary", "unreliable", "source", "target", "landmark_order", "landmark_order_from",
                      "orders_tried", "refused", "added"}
    assert r["faces"].shape == (len(V),) and r["bary"].shape == (len(V), 3) and r["unreliable"] is None and r["added"] is None
    assert r["source"].certified and r["target"].certified
    # A rigid motion changes no length or angle and keeps the triangulation: the two meshes
    # give the same cotangent weights, the same landmark distances (so the same tour) and the
    # same equations, so the embeddings agree up to floating-point rounding and the solver's
    # tolerance, and the map is the identity up to the same: far below 1e-6 of the diagonal
    # (the brief asked for below 1% of it; an isometry leaves nothing to approximate).
    images = hot.surface_points(r["faces"], r["bary"], W, F)
    error = np.linalg.norm(images - W, axis=1) / diagonal(W)
    assert error.mean() < 1e-6 and error.max() < 1e-4
    # landmark i of A onto landmark i of B: the vertex itself, bary a unit vector there
    for i in lm:
        corners = F[r["faces"][i]]
        assert i in corners
        assert r["bary"][i][list(corners).index(i)] == pytest.approx(1.0, abs=1e-12)
        assert np.linalg.norm(images[i] - W[i]) < 1e-9 * diagonal(W)
    # the order: the source's tour (the same distances on both meshes: a tie, the source's)
    assert r["landmark_order_from"] == "source" and r["orders_tried"] == 1 and r["refused"] == []
    assert np.array_equal(r["landmark_order"], r["source"].landmark_order)
    assert np.array_equal(r["landmark_order"], r["target"].landmark_order)
    assert np.array_equal(r["landmark_order"], hot.embed(V, F, lm).landmark_order)  # embed's tsp = the source's tour


# ---------------------------------------------------------------------------------------
# (b) the same numbers as the two-step call with the order given
# ---------------------------------------------------------------------------------------

def test_same_as_the_two_step_call(bear_pair):
    V, F, lm, W, r = bear_pair
    a = hot.embed(V, F, lm)
    b = hot.embed(W, F, lm, order=a.landmark_order)
    faces, bary = hot.map(a, b)
    assert np.array_equal(faces, r["faces"]) and np.array_equal(bary, r["bary"])
    assert np.array_equal(a.uv, r["source"].uv) and np.array_equal(b.uv, r["target"].uv)
    # unreliable=True and refine=N are map()'s (without the landmarks refine adds by default)
    r2 = hot.map_meshes(V, F, lm, W, F, lm, unreliable=True, refine=3, augment=False)
    faces2, bary2, flagged = hot.map(a, b, unreliable=True, refine=3)
    assert np.array_equal(r2["faces"], faces2) and np.array_equal(r2["bary"], bary2)
    assert np.array_equal(r2["unreliable"], flagged) and r2["added"] is None
    # refine=N augments by default on a closed genus-0 pair: the same as augment=True
    r3 = hot.map_meshes(V, F, lm, W, F, lm, refine=3)
    r4 = hot.map_meshes(V, F, lm, W, F, lm, refine=3, augment=True)
    assert r3["added"] is not None and np.array_equal(r3["added"], r4["added"])
    assert np.array_equal(r3["faces"], r4["faces"]) and np.array_equal(r3["bary"], r4["bary"])


def test_order_given_and_tsp(bear_pair):
    V, F, lm, W, r = bear_pair
    g = hot.map_meshes(V, F, lm, W, F, lm, order="given")
    assert g["landmark_order_from"] == "given" and np.array_equal(g["landmark_order"], np.arange(len(lm)))
    p = list(r["landmark_order"])[::-1]
    e = hot.map_meshes(V, F, lm, W, F, lm, order=p)
    assert e["landmark_order_from"] == "given" and list(e["landmark_order"]) == p
    t = hot.map_meshes(V, F, lm, W, F, lm, order="tsp")
    assert t["landmark_order_from"] == "source" and np.array_equal(t["faces"], r["faces"])


# ---------------------------------------------------------------------------------------
# (c) the order choice is the command line's: `map --order auto`'s report says which mesh's
# tour it took and in which order; map_meshes() on the same meshes takes the same (here the
# target's tour; a pair where a mesh refuses the first order, orders_tried 2, is not built:
# none is known cheaply)
# ---------------------------------------------------------------------------------------

def test_the_order_is_the_command_lines(cli, meshes, tmp_path):
    A = os.path.join(meshes, "bear.off")
    VA, FA = hot.read_mesh(A)
    la = hot.select_landmarks(VA, FA, 7)
    # B: A stretched 6 times along y: the distances between the landmarks change and B's own
    # tour differs from A's; A's tour is then much longer than B's tour on B, while B's tour
    # costs A little, so the ranking takes the target's tour (the case the source's tour loses)
    VB = VA * np.array([1.0, 6.0, 1.0])
    B = tmp_path / "B.off"
    with open(B, "w") as f:
        f.write("OFF\n%d %d 0\n" % (len(VB), len(FA)))
        f.writelines("%.17g %.17g %.17g\n" % tuple(p) for p in VB)
        f.writelines("3 %d %d %d\n" % tuple(t) for t in FA)
    cones = write_cones(tmp_path / "cones.txt", la)
    run_cli(cli, "map", "--source", A, "--source-cones", cones, "--target", B, "--target-cones", cones,
            "--out", tmp_path / "map.txt", "--report", tmp_path / "report.json")
    report = json.load(open(tmp_path / "report.json"))
    r = hot.map_meshes(VA, FA, la, VB, FA, la)
    assert report["landmark_order_from"] == "target"
    assert r["landmark_order_from"] == report["landmark_order_from"]
    assert np.array_equal(r["landmark_order"], hot.embed(VB, FA, la).landmark_order)  # B's own tour
    assert not np.array_equal(r["landmark_order"], hot.embed(VA, FA, la).landmark_order)
    assert r["orders_tried"] == report["orders_tried"]
    assert list(r["landmark_order"]) == list(report["landmark_order"])  # (positions in the landmarks)
    faces, bary = read_map(tmp_path / "map.txt")
    assert np.array_equal(faces, r["faces"])
    assert np.allclose(bary, r["bary"], rtol=0, atol=1e-15)


# ---------------------------------------------------------------------------------------
# (d) coercion: any array-like gives the same result; C-contiguous float64 / int64 in place
# ---------------------------------------------------------------------------------------

def test_array_likes_give_the_same_map(bear_pair):
    V, F, lm, W, r = bear_pair
    variants = [
        (np.asfortranarray(V), np.asfortranarray(F), np.asarray(lm, dtype=np.int32)),   # Fortran order, int32
        (V, F.astype(np.int32), list(lm)),                                           # int32 faces, a list
        (np.repeat(V, 2, axis=0)[::2], np.asfortranarray(F.astype(np.uint32)), tuple(int(i) for i in lm)),  # strided, a tuple
    ]
    for VA, FA, la in variants:
        assert not (VA.flags.c_contiguous and FA.dtype == np.int64 and FA.flags.c_contiguous)  # (each converted)
        m = hot.map_meshes(VA, FA, la, W, F, lm)
        assert np.array_equal(m["faces"], r["faces"]) and np.array_equal(m["bary"], r["bary"])
    # a float32 target: converted once to float64, the same as converting it first
    W32 = W.astype(np.float32)
    m32 = hot.map_meshes(V, F, lm, W32, F, lm)
    m64 = hot.map_meshes(V, F, lm, W32.astype(np.float64), F, lm)
    assert np.array_equal(m32["faces"], m64["faces"]) and np.array_equal(m32["bary"], m64["bary"])
    # lists of lists give the C arrays' numbers exactly
    m = hot.map_meshes(V.tolist(), F.tolist(), lm.tolist(), W.tolist(), F.tolist(), lm.tolist())
    assert np.array_equal(m["faces"], r["faces"]) and np.array_equal(m["bary"], r["bary"])


def test_float32_is_converted_once_to_float64(bear):
    V, F, lm, e = bear
    V32 = V.astype(np.float32)
    a = hot.embed(V32, F, lm)
    b = hot.embed(V32.astype(np.float64), F, lm)  # the conversion numpy makes
    assert np.array_equal(a.uv, b.uv) and np.array_equal(a.V, V32.astype(np.float64))
    # Fortran order, int32 faces, a list of landmarks: the same numbers as the C arrays
    c = hot.embed(np.asfortranarray(V), F.astype(np.int32), list(lm))
    assert np.array_equal(c.uv, e.uv)
    d = hot.map_distortion(np.asfortranarray(V), F.astype(np.int32).tolist(), V.astype(np.float32))
    assert np.array_equal(d["conformal"], hot.map_distortion(V, F, V.astype(np.float32).astype(np.float64))["conformal"])
    faces, bary = hot.map(e, e)
    t = hot.transfer(faces.astype(np.int32).tolist(), bary.astype(np.float32), np.asfortranarray(F.astype(np.int32)), V)
    assert np.allclose(t, V, atol=1e-5 * diagonal(V))


def test_c_float64_int64_stay_in_place(bear_pair):
    # C-contiguous float64 V and int64 F are read in place by map_meshes() too: no conversion
    # copy shows in tracemalloc's peak (numpy's allocations; test_zero_copy.py's measure),
    # while a Fortran-ordered V shows its copy
    from test_zero_copy import traced_peak
    V, F, lm, W, _ = bear_pair
    assert V.flags.c_contiguous and V.dtype == np.float64 and F.dtype == np.int64
    peak = traced_peak(lambda: hot.map_meshes(V, F, lm, W, F, lm))
    assert peak < V.nbytes / 4
    assert traced_peak(lambda: hot.map_meshes(np.asfortranarray(V), F, lm, W, F, lm)) >= V.nbytes


# ---------------------------------------------------------------------------------------
# (e) bad inputs: InputError (a ValueError) with a message
# ---------------------------------------------------------------------------------------

def test_bad_inputs_raise_input_error(bear):
    V, F, lm, _ = bear
    W = rigid_copy(V)
    cases = [
        (dict(VA=V[:, :2]), "VA must be an array of shape \\(n, 3\\)"),
        (dict(FB=F.astype(float) + 0.5), "FB must hold integer vertex indices, got dtype 'float64'"),
        (dict(FA=F.astype(float)), "FA must hold integer vertex indices"),
        (dict(VA=np.full((3, 3), "x")), "VA must hold real numbers"),
        (dict(VA=[[0.0, 1.0, 2.0], [1.0, 2.0]]), "VA is not an array of numbers"),
        (dict(landmarks_b=list(lm)[:-1]), "landmarks"),
        (dict(landmarks_a=[0.5, 1.5]), "must hold integers"),
        (dict(order="sideways"), "order must be"),
        (dict(refine=-1), "refine must be"),
        (dict(orbifold="torus"), "orbifold must be"),
    ]
    base = dict(VA=V, FA=F, landmarks_a=lm, VB=W, FB=F, landmarks_b=lm)
    for change, message in cases:
        args = dict(base, **change)
        kw = {k: args.pop(k) for k in ("order", "refine", "orbifold") if k in args}
        with pytest.raises(hot.InputError, match=message) as info:
            hot.map_meshes(args["VA"], args["FA"], args["landmarks_a"], args["VB"], args["FB"], args["landmarks_b"], **kw)
        assert isinstance(info.value, ValueError) and info.value.code in hot.error_codes
    # NaN coordinates: the mesh's checks, named by the mesh
    Vn = V.copy()
    Vn[5, 1] = np.nan
    with pytest.raises(ValueError, match="the source") as info:
        hot.map_meshes(Vn, F, lm, W, F, lm)
    assert isinstance(info.value, hot.InputError) and info.value.code == "ERROR_NON_FINITE_COORDINATES"
    with pytest.raises(hot.InputError, match="not a vertex index"):
        hot.embed(V, F, [0, 1, -2, 3, 4])
    with pytest.raises(hot.InputError, match="ragged|not an array"):
        hot.transfer([0, 1], [[1, 0, 0], [1, 0]], F, V)


def test_refine_on_a_source_of_genus_2_is_refused_before_the_embeddings(meshes):
    # eight.off (libcgal-demo) is closed of genus 2 (Euler: V - E + F = -2); the refinement moves
    # corners in one disk around the landmarks, so refine=N is refused, and before any embedding
    # phase is reported (the same pair maps without refine)
    V, F = hot.read_mesh(os.path.join(meshes, "eight.off"))
    assert len(V) - 3 * len(F) // 2 + len(F) == -2
    phases = []
    with pytest.raises(hot.InputError, match="^refine: .*genus 2$") as info:
        hot.map_meshes(V, F, [0], V, F, [0], refine=5, progress=lambda phase, fraction: phases.append(phase))
    assert info.value.code == "ERROR_WRONG_PARAMETER"
    assert not any(p.startswith(("source", "target")) for p in phases)
    r = hot.map_meshes(V, F, [0], V, F, [0], progress=lambda phase, fraction: phases.append(phase))
    assert any(p.startswith("source") for p in phases) and len(r["faces"]) == len(V)


def test_meshes_of_different_types_are_refused(bear, meshes):
    V, F, lm, _ = bear
    VD, FD = hot.read_mesh(os.path.join(meshes, "mushroom.off"))  # libcgal-demo's disk
    with pytest.raises(hot.InputError, match="the source is closed but the target is a disk"):
        hot.map_meshes(V, F, lm, VD, FD, hot.select_landmarks(VD, FD, 7))
    # the landmarks of the target are checked against the target, and say so
    with pytest.raises(hot.InputError, match="^the target") as info:
        hot.map_meshes(V, F, lm, V, F, list(lm[:-1]) + [len(V) + 5])
    assert info.value.code == "ERROR_LANDMARK_OUT_OF_RANGE"


def test_a_disk_pair_keeps_the_given_order(meshes):
    VD, FD = hot.read_mesh(os.path.join(meshes, "mushroom.off"))
    lm = hot.select_landmarks(VD, FD, 5)
    W = rigid_copy(VD)
    r = hot.map_meshes(VD, FD, lm, W, FD, lm)
    assert r["landmark_order_from"] == "given" and list(r["landmark_order"]) == [0, 1, 2, 3, 4]
    assert r["source"].orbifold == "disk"
    images = hot.surface_points(r["faces"], r["bary"], W, FD)
    assert np.linalg.norm(images - W, axis=1).mean() < 1e-6 * diagonal(W)  # (an isometry, as above)


# ---------------------------------------------------------------------------------------
# help(): the docstrings show the parameters and an example
# ---------------------------------------------------------------------------------------

def _documented_parameters(func):
    """the parameter names of a public function: its signature (Python) or the first line of
    its docstring (pybind11's functions, whose docstring gives the signature by hand)"""
    try:
        return list(inspect.signature(func).parameters)
    except (TypeError, ValueError):
        first = func.__doc__.splitlines()[0]
        inner = first[first.index("(") + 1:first.index(")")]
        return [p.split("=")[0].strip() for p in inner.split(",") if p.strip() not in ("*", "...", "")]


def test_every_public_function_documents_its_parameters():
    for name in hot.__all__:
        obj = getattr(hot, name)
        if not callable(obj) or isinstance(obj, type):
            continue
        doc = obj.__doc__ or ""
        assert doc.startswith(name + "("), "%s: the docstring does not start with its signature" % name
        body = doc.split("\n", 1)[1] if "\n" in doc else ""
        for p in _documented_parameters(obj):
            assert p in doc, "%s: the docstring does not mention %s" % (name, p)
        # (collection() and map_distortion() have no example yet: collection.py and
        # distortion.cpp were not part of this change)
        if name not in ("collection", "map_distortion"):
            assert "Example" in body or ">>>" in body, "%s: no example in its docstring" % name


def test_help_shows_the_parameters_and_an_example():
    doc = hot.map_meshes.__doc__
    for p in ("VA", "FA", "landmarks_a", "VB", "FB", "landmarks_b", "orbifold", "weights", "order", "cone_orders",
              "unreliable", "refine", "landmark_order_from"):
        assert p in doc
    assert ">>>" in doc
    for name in ("map_meshes", "map", "embed", "read_mesh", "select_landmarks", "transfer", "surface_points"):
        doc = getattr(hot, name).__doc__
        assert "Example" in doc or ">>>" in doc, "%s: no example in its docstring" % name


# ---------------------------------------------------------------------------------------
# augment=True: the command line's map --augment, from the arrays
# ---------------------------------------------------------------------------------------

def test_augment_adds_the_tentacles_without_landmarks(cli, source_dir, tmp_path):
    # An octopus (test/octopus.awk) and a twirled copy (vertex i <-> vertex i), landmarks at the
    # poles and at the tips of tentacles 0-4: tentacles 5-7 are protrusions without a landmark.
    # Facts from the construction: each gets one pair on its tip's cap (the tip and the four
    # rings before it) on both meshes; the map interpolates every pair; the same pairs and the
    # same map as the command line's.
    import subprocess
    script = os.path.join(source_dir, "test", "octopus.awk")
    with open(tmp_path / "o.off", "w") as out, open(tmp_path / "o.std", "w") as err:
        subprocess.run(["awk", "-v", "L=6", "-f", script], stdout=out, stderr=err, check=True)
    with open(tmp_path / "t.off", "w") as out:
        subprocess.run(["awk", "-v", "L=6", "-v", "TWIRL=0.08", "-f", script], stdout=out, stderr=subprocess.DEVNULL, check=True)
    ids = [int(x) for x in open(tmp_path / "o.std").read().split()]
    lm = [ids[0], ids[1]] + [ids[3 + 2 * i] for i in range(5)]
    tips = [ids[3 + 2 * i] for i in (5, 6, 7)]
    VA, FA = read_off(tmp_path / "o.off")
    VB, FB = read_off(tmp_path / "t.off")
    r = hot.map_meshes(VA, FA, lm, VB, FB, lm, augment=True)
    added = r["added"]
    assert added.dtype == np.int64 and added.ndim == 2 and added.shape[1] == 2
    for t in tips:
        on_cap = [(a, b) for a, b in added if t - 64 <= a <= t]
        assert len(on_cap) == 1 and t - 64 <= on_cap[0][1] <= t, (t, added)
    assert sorted(r["landmark_order"]) == list(range(len(lm) + len(added)))
    images = hot.surface_points(r["faces"], r["bary"], VB, FB)
    for a, b in added:
        assert np.linalg.norm(images[a] - VB[b]) < 1e-9 * diagonal(VB)
    write_cones(tmp_path / "o.cones", lm)
    run_cli(cli, "map", "--source", tmp_path / "o.off", "--source-cones", tmp_path / "o.cones", "--target", tmp_path / "t.off",
            "--target-cones", tmp_path / "o.cones", "--out", tmp_path / "m.txt", "--report", tmp_path / "r.json", "--augment")
    report = json.load(open(tmp_path / "r.json"))
    assert [list(p) for p in added] == report["augmentation"]["added"]
    faces, bary = read_map(tmp_path / "m.txt")
    assert np.array_equal(faces, r["faces"]) and np.allclose(bary, r["bary"], rtol=0, atol=1e-15)
    # refusals: an order given as positions; a disk
    with pytest.raises(hot.InputError, match="augment"):
        hot.map_meshes(VA, FA, lm, VB, FB, lm, augment=True, order=list(range(len(lm))))
    VD, FD = flat_disk()
    rim = [len(VD) - 72 + 12 * i for i in range(6)]  # six vertices of the outer ring (6 * 12 vertices)
    with pytest.raises(hot.InputError, match="augment"):
        hot.map_meshes(VD, FD, rim, VD, FD, rim, augment=True)
