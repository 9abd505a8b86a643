# Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
# SPDX-License-Identifier: GPL-3.0-or-later
"""The module against the command-line program: the same landmarks, the same corner
coordinates (bit for bit), the same OBJ bytes, the same report fields, the same maps; and
maps checked against the ground truth of deformed copies (vertex i <-> vertex i)."""

import json
import os
import subprocess

import numpy as np
import pytest

import hyperbolic_orbifold_tutte as hot
from hot_testing import (diagonal, flat_disk, read_cones, read_map, read_obj_embedding, read_off, run_awk, run_cli,
                         write_cones, write_off)


@pytest.fixture(scope="module")
def work(tmp_path_factory):
    return tmp_path_factory.mktemp("cli")


@pytest.fixture(scope="module")
def bear(cli, meshes, work):
    """bear.off with the CLI's 7 landmarks, embedded by the CLI (OBJ, report) and by the module"""
    path = os.path.join(meshes, "bear.off")
    cones = work / "bear.cones"
    run_cli(cli, "landmarks", "--mesh", path, "--count", 7, "--out", cones)
    run_cli(cli, "embed", "--mesh", path, "--cones", cones, "--out", work / "bear.obj", "--report", work / "bear.json")
    V, F = hot.read_mesh(path)
    lm = read_cones(cones)
    e = hot.embed(V, F, lm, name=path)
    return dict(path=path, cones=cones, V=V, F=F, lm=lm, e=e, obj=work / "bear.obj", report=work / "bear.json")


def test_read_mesh_is_the_file(bear):
    V, F = read_off(bear["path"])  # parsed here
    assert bear["V"].dtype == np.float64 and bear["V"].shape == V.shape
    assert bear["F"].dtype == np.int64 and bear["F"].shape == F.shape
    assert np.array_equal(bear["V"], V)
    assert np.array_equal(bear["F"], F)


def test_select_landmarks_is_the_cli_landmarks_command(bear):
    lm = hot.select_landmarks(bear["V"], bear["F"], 7)
    assert lm.dtype == np.int64
    assert np.array_equal(lm, bear["lm"])


def test_uv_is_the_obj_vt_of_every_corner(bear):
    vt, fv, ft = read_obj_embedding(bear["obj"])
    e = bear["e"]
    assert np.array_equal(fv, bear["F"])  # the OBJ's faces are F, corners in F's order
    assert e.uv.shape == (len(bear["F"]), 3, 2)
    # exactly: == on every coordinate (17 significant digits in the file read back as the same double)
    assert np.array_equal(e.uv, vt[ft])
    assert len(vt) > len(bear["V"])  # the cut duplicates the seam vertices


def test_write_obj_gives_the_cli_bytes(bear, work):
    out = work / "module.obj"
    bear["e"].write_obj(out)
    assert out.read_bytes() == bear["obj"].read_bytes()


def test_report_is_the_cli_report(bear):
    with open(bear["report"]) as f:
        cli = json.load(f)
    r = bear["e"].report
    assert sorted(r.keys()) == sorted(cli.keys())
    assert r["mesh"] == cli["mesh"]
    for key in ("vertices", "faces", "cones", "orbifold", "weights", "order", "landmark_order_used", "cone_orders",
                "genus", "cut_mesh_vertices", "iterations", "energy", "certificate"):
        if key == "certificate":
            assert {k: v for k, v in r[key].items()} == cli[key]
        else:
            assert r[key] == cli[key], key
    assert r["certificate"]["bijective"] is True and bear["e"].certified is True
    e = bear["e"]
    assert list(e.landmarks[e.landmark_order]) == cli["landmark_order_used"]
    assert sorted(e.landmark_order) == list(range(7))


def test_cone_orders_2_3_7_as_the_cli(cli, meshes, work):
    path = os.path.join(meshes, "bear.off")
    lm = [8768, 4116, 9726]
    cones = write_cones(work / "237.cones", lm)
    run_cli(cli, "embed", "--mesh", path, "--cones", cones, "--cone-orders", "2,3,7", "--out", work / "237.obj")
    V, F = hot.read_mesh(path)
    e = hot.embed(V, F, lm, cone_orders=[2, 3, 7])
    e.write_obj(work / "237_module.obj")
    assert (work / "237_module.obj").read_bytes() == (work / "237.obj").read_bytes()
    assert sorted(e.cone_orders) == [2, 3, 7]


def map_error(faces, bary, V_target, F_target, truth):
    """max and mean distance of the mapped points to the true images, relative to the diagonal"""
    p = hot.surface_points(faces, bary, V_target, F_target)
    d = np.linalg.norm(p - truth, axis=1) / diagonal(truth)
    return d.max(), d.mean()


def test_map_bear_onto_a_bent_copy_is_the_cli_map(bear, cli, source_dir, work):
    bent = run_awk(os.path.join(source_dir, "test", "bend.awk"), bear["path"], work / "bent.off", R=3)
    run_cli(cli, "map", "--source", bear["path"], "--source-cones", bear["cones"], "--target", bent,
            "--target-cones", bear["cones"], "--out", work / "map.txt")
    VB, FB = hot.read_mesh(bent)
    eb = hot.embed(VB, FB, bear["lm"], order=bear["e"].landmark_order)
    faces, bary = hot.map(bear["e"], eb)
    cli_faces, cli_bary = read_map(work / "map.txt")
    assert faces.shape == (len(bear["V"]),) and bary.shape == (len(bear["V"]), 3)
    assert np.array_equal(faces, cli_faces)
    assert np.array_equal(bary, cli_bary)  # bit for bit (written with 17 digits)
    # the ground truth: vertex i of the bent copy is the image of vertex i
    worst, mean = map_error(faces, bary, VB, FB, VB)
    print("bear -> bent bear: max %.5f mean %.6f of the diagonal" % (worst, mean))
    # (the bend stretches the bear's surface by up to +-20%: measured max 4.6%, mean 0.58%)
    assert mean < 0.01 and worst < 0.06
    # landmarks onto landmarks
    for v in bear["lm"]:
        j = int(np.argmax(bary[v]))
        assert FB[faces[v], j] == v and bary[v, j] > 1 - 1e-9


def check_disk_map_against_cli(cli, path, k, bent, work, name):
    """the module's disk-type embedding and map (path -> bent) against the CLI's; returns the map"""
    cones = work / (name + ".cones")
    run_cli(cli, "landmarks", "--mesh", path, "--count", k, "--out", cones)
    run_cli(cli, "embed", "--mesh", path, "--cones", cones, "--out", work / (name + ".obj"))
    run_cli(cli, "map", "--source", path, "--source-cones", cones, "--target", bent, "--target-cones", cones,
            "--out", work / (name + "_map.txt"))
    V, F = hot.read_mesh(path)
    lm = hot.select_landmarks(V, F, k)
    assert np.array_equal(lm, read_cones(cones))
    ea = hot.embed(V, F, lm)
    assert ea.orbifold == "disk" and ea.report["order"] == "given"
    ea.write_obj(work / (name + "_module.obj"))
    assert (work / (name + "_module.obj")).read_bytes() == (work / (name + ".obj")).read_bytes()
    VB, FB = hot.read_mesh(bent)
    eb = hot.embed(VB, FB, lm, order=ea.landmark_order)
    faces, bary = hot.map(ea, eb)
    cli_faces, cli_bary = read_map(work / (name + "_map.txt"))
    assert np.array_equal(faces, cli_faces) and np.array_equal(bary, cli_bary)
    for v in lm:  # corners onto corners
        j = int(np.argmax(bary[v]))
        assert FB[faces[v], j] == v and bary[v, j] > 1 - 1e-9
    return faces, bary, VB, FB


def test_map_mushroom_onto_a_bent_copy_is_the_cli_map(cli, meshes, source_dir, work):
    path = os.path.join(meshes, "mushroom.off")  # libcgal-demo's disk
    bent = run_awk(os.path.join(source_dir, "test", "bend.awk"), path, work / "bent_mushroom.off", R=3)
    check_disk_map_against_cli(cli, path, 6, bent, work, "mushroom")


def test_map_a_flat_disk_onto_an_isometric_bend_is_the_cli_map_and_the_identity(cli, source_dir, work):
    V, F = flat_disk()  # in the plane x = 0, bent about the z axis: an isometry
    path = write_off(work / "disk.off", V, F)
    bent = run_awk(os.path.join(source_dir, "test", "bend.awk"), path, work / "bent_disk.off", R=3)
    faces, bary, VB, FB = check_disk_map_against_cli(cli, str(path), 6, bent, work, "disk")
    worst, mean = map_error(faces, bary, VB, FB, VB)
    print("flat disk -> isometric bend: max %.2e mean %.2e of the diagonal" % (worst, mean))
    assert worst < 1e-3  # (measured 2e-5)


def test_map_genus_2_onto_a_twisted_copy_is_the_cli_map(cli, meshes, source_dir, work):
    path = os.path.join(meshes, "eight.off")
    none = write_cones(work / "none.cones", [])
    twisted = run_awk(os.path.join(source_dir, "test", "twist.awk"), path, work / "twisted.off", T=1)
    run_cli(cli, "map", "--source", path, "--source-cones", none, "--target", twisted, "--target-cones", none,
            "--out", work / "eight_map.txt")
    V, F = hot.read_mesh(path)
    ea = hot.embed(V, F, [])
    assert ea.genus == 2 and ea.report["genus"] == 2 and len(ea.cut_graph) >= 4
    VB, FB = hot.read_mesh(twisted)
    eb = hot.embed(VB, FB, [], cut_graph=ea.cut_graph)
    faces, bary = hot.map(ea, eb)
    cli_faces, cli_bary = read_map(work / "eight_map.txt")
    assert np.array_equal(faces, cli_faces) and np.array_equal(bary, cli_bary)
    worst, mean = map_error(faces, bary, VB, FB, VB)
    print("eight -> twisted eight: max %.5f mean %.6f of the diagonal" % (worst, mean))
    assert worst < 0.02


def test_charts_and_unreliable_vertices_as_the_cli(cli, source_dir, work):
    """a capsule of length 80 with a landmark at its far tip: embed writes the tube's end in a
    chart around the tip's cone image ('# hot chart' lines); the same bytes, the same vt, and
    the same map onto a bent copy, with the same vertices flagged unreliable"""
    test = os.path.join(source_dir, "test")
    capsule = work / "capsule.off"
    with open(capsule, "w") as out, open(work / "capsule.cones0", "w") as err:
        subprocess.run(["awk", "-v", "L=80", "-v", "S=24", "-f", os.path.join(test, "capsule.awk")], stdout=out, stderr=err,
                       check=True)
    V, F = hot.read_mesh(capsule)
    lm = list(read_cones(work / "capsule.cones0")) + [len(V) - 1]
    cones = write_cones(work / "capsule.cones", lm)
    bent = run_awk(os.path.join(test, "bend.awk"), capsule, work / "bent_capsule.off", R=40)
    run_cli(cli, "embed", "--mesh", capsule, "--cones", cones, "--out", work / "capsule.obj")
    # (--order tsp: the source's tour for both, as the module's embeddings below; the CLI's
    # default may take the target's tour when it is shorter there)
    run_cli(cli, "map", "--source", capsule, "--source-cones", cones, "--target", bent, "--target-cones", cones,
            "--order", "tsp", "--out", work / "capsule_map.txt", "--report", work / "capsule_map.json")
    e = hot.embed(V, F, lm)
    assert e.report["charted_faces"] > 0 and len(e.report["charts"]) >= 1
    e.write_obj(work / "capsule_module.obj")
    assert (work / "capsule_module.obj").read_bytes() == (work / "capsule.obj").read_bytes()
    assert b"# hot chart " in (work / "capsule.obj").read_bytes()
    vt, fv, ft = read_obj_embedding(work / "capsule.obj")
    assert np.array_equal(e.uv, vt[ft])
    VB, FB = hot.read_mesh(bent)
    eb = hot.embed(VB, FB, lm, order=e.landmark_order)
    faces, bary, unreliable = hot.map(e, eb, unreliable=True)
    cli_faces, cli_bary = read_map(work / "capsule_map.txt")
    assert np.array_equal(faces, cli_faces) and np.array_equal(bary, cli_bary)
    with open(work / "capsule_map.json") as f:
        report = json.load(f)
    assert list(unreliable) == report["unreliable_vertices"]


def test_recentring_as_the_cli(cli, source_dir, work):
    """a capsule of length 50 without a landmark at its far end: refused in the tile with the
    library's reason, embedded with recentre=True in a moved frame as `embed --recentre`"""
    capsule = work / "tube.off"
    with open(capsule, "w") as out, open(work / "tube.cones", "w") as err:
        subprocess.run(["awk", "-v", "L=50", "-v", "S=24", "-f", os.path.join(source_dir, "test", "capsule.awk")], stdout=out,
                       stderr=err, check=True)
    run_cli(cli, "embed", "--mesh", capsule, "--cones", work / "tube.cones", "--out", work / "tube.obj", "--recentre",
            "--report", work / "tube.json")
    V, F = hot.read_mesh(capsule)
    lm = read_cones(work / "tube.cones")
    with pytest.raises(hot.Error) as info:
        hot.embed(V, F, lm)
    assert info.value.code == "ERROR_NO_1_TO_1_MAPPING"
    assert "below what double resolves" in str(info.value) and "recentring" in str(info.value)
    e = hot.embed(V, F, lm, recentre=True)
    assert e.recentred and e.report["recentred"] is True
    with open(work / "tube.json") as f:
        assert e.report["frame"] == json.load(f)["frame"]
    e.write_obj(work / "tube_module.obj")
    assert (work / "tube_module.obj").read_bytes() == (work / "tube.obj").read_bytes()
    with pytest.raises(hot.Error) as info:
        hot.map(e, e)
    assert "recentred" in str(info.value)
