# Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
# SPDX-License-Identifier: GPL-3.0-or-later
"""hot.collection(): in threads and on a Dask LocalCluster of two worker processes, the files of
the command line's `collection`, byte for byte (report.json apart from its times)."""

import json
import os

import pytest

import hyperbolic_orbifold_tutte as hot
from hot_testing import assert_same_files, make_hands, run_cli


@pytest.fixture(scope="module")
def hands(tmp_path_factory, meshes, cli):
    """hot_testing.make_hands(), and the command line's refined collection of the same shapes"""
    d = tmp_path_factory.mktemp("hands")
    manifest, n_vertices = make_hands(d, meshes, cli)
    run_cli(cli, "collection", "--manifest", manifest, "--out", d / "cli_refined", "--all-pairs", "--refine", 10)
    return d, manifest, n_vertices


def check_report(report, out, n_vertices):
    assert report == json.load(open(os.path.join(out, "report.json")))
    assert len(report["meshes"]) == 4 and all(m["bijective"] for m in report["meshes"])
    assert all(m["vertices"] == n_vertices for m in report["meshes"])
    assert report["triples_checked"] == 24  # every ordered triple of 4 distinct meshes
    assert len(report["pairs"]) == 12       # every ordered pair
    # the maps are cycle consistent (the paper's section 7): f_bc(f_ab(x)) = f_ac(x) up to rounding
    assert report["cycle_consistency_max_rel_error"] < 1e-9


def test_collection_in_threads_is_the_command_lines(hands):
    d, manifest, nv = hands
    out = d / "threads"
    report = hot.collection(manifest, out, all_pairs=True, threads=2, progress=False)
    assert_same_files(d / "cli", out)
    check_report(report, out, nv)
    assert len([n for n in os.listdir(out) if n.endswith(".map.txt")]) == 12
    for n in os.listdir(out):
        if n.endswith(".map.txt"):
            assert sum(1 for _ in open(out / n)) == nv  # one line per vertex of the source


def check_refinement(report):
    """every mesh but the reference refined: its map onto mesh 0 nearer an isometry (the tempered
    symmetric Dirichlet energy that the iterations lower, 4 for an isometry up to scale, lower and
    not below 4)"""
    r = report["refinement"]
    assert r["reference"] == 0 and [m["mesh"] for m in r["meshes"]] == [1, 2, 3]
    for m in r["meshes"]:
        assert m["iterations"] >= 1
        assert 4 - 1e-9 <= m["tempered_energy_after"] < m["tempered_energy_before"]
        assert m["symmetric_dirichlet_energy_after"] >= 4 - 1e-9


def test_refined_collection_in_threads_is_the_command_lines(hands):
    d, manifest, nv = hands
    out = d / "threads_refined"
    report = hot.collection(manifest, out, all_pairs=True, threads=2, progress=False, refine=10)
    assert_same_files(d / "cli_refined", out)
    check_report(report, out, nv)
    check_refinement(report)
    assert "refinement" not in json.load(open(d / "cli" / "report.json"))
    with pytest.raises(hot.Error, match="refine must be 0"):
        hot.collection(manifest, d / "o_refine", refine=-1, progress=False)
    assert not os.path.exists(d / "o_refine")


def test_collection_on_a_dask_local_cluster_is_the_command_lines(hands, capsys):
    import distributed  # (Debian's python3-distributed, installed by scripts/install-deps.sh)
    d, manifest, nv = hands
    out = d / "dask"
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None) as cluster, \
            distributed.Client(cluster) as client:
        assert len(client.scheduler_info()["workers"]) == 2
        report = hot.collection(manifest, out, all_pairs=True, client=client)
        # one embedding task per mesh, one map task per pair: none embeds again
        log = capsys.readouterr().err
        assert log.count("  embedded ") == 4
        assert "mapped 12/12 pairs" in log
        # a failure in a task comes back as hot.Error, naming the mesh, and leaves no file
        bad = d / "bad.txt"
        bad.write_text("hand_a.off cones.txt\nmissing.off cones.txt\nhand_b.off cones.txt\n")
        with pytest.raises(hot.Error, match="missing.off"):
            hot.collection(bad, d / "dask_bad", client=client, progress=False)
        assert not os.path.exists(d / "dask_bad") or os.listdir(d / "dask_bad") == []
        # refined: one refinement task per mesh after the embeddings, the maps after them
        refined = hot.collection(manifest, d / "dask_refined", all_pairs=True, client=client, refine=10)
        assert capsys.readouterr().err.count("  refined ") == 3
    assert_same_files(d / "cli", out)
    check_report(report, out, nv)
    assert_same_files(d / "cli_refined", d / "dask_refined")
    check_refinement(refined)


def test_collection_errors(hands):
    d, manifest, nv = hands
    with pytest.raises(hot.Error, match="no such file"):
        hot.collection(d / "none.txt", d / "o1", progress=False)
    one = d / "one.txt"
    one.write_text("hand_a.off cones.txt\n")
    with pytest.raises(hot.Error, match="at least 2"):
        hot.collection(one, d / "o2", progress=False)
    five = d / "five.txt"
    five.write_text("1 2 3 4 5\n")
    other = d / "other.txt"
    other.write_text("hand_a.off cones.txt\nhand_b.off five.txt\n")
    with pytest.raises(hot.Error, match="differs from the first mesh"):
        hot.collection(other, d / "o3", progress=False)
    assert not os.path.exists(d / "o3")  # nothing left behind
    with pytest.raises(hot.Error, match="cone_orders"):
        hot.collection(manifest, d / "o4", cone_orders=[2, 1], progress=False)
    with pytest.raises(hot.Error, match="needs repair"):
        hot.collection(manifest, d / "o5", largest_component=True, progress=False)
    with pytest.raises(hot.Error, match="max_hole needs repair"):  # (given, even at the default limit 0.5)
        hot.collection(manifest, d / "o5", max_hole=0.5, progress=False)
    with pytest.raises(hot.Error, match="max_hole must be a number >= 0"):
        hot.collection(manifest, d / "o5", repair=True, max_hole=-1, progress=False)
    assert not os.path.exists(d / "o5")
