# Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
# SPDX-License-Identifier: GPL-3.0-or-later
"""hot.collection() on a Dask LocalCluster of two worker processes, one of them killed (SIGKILL)
while the tasks run: the collection completes with the command line's files, byte for byte
(report.json apart from its times). The tasks are slowed by the test-only hook
HOT_COLLECTION_TEST_DELAY (inherited by the worker processes) so that the kill lands mid-run."""

import os
import signal
import threading
import time

import pytest

import hyperbolic_orbifold_tutte as hot
from hot_testing import assert_same_files, make_hands


@pytest.fixture(scope="module")
def hands(tmp_path_factory, meshes, cli):
    d = tmp_path_factory.mktemp("hands_faults")
    manifest, _ = make_hands(d, meshes, cli)
    return d, manifest


def test_dask_worker_killed_mid_run(hands, monkeypatch):
    distributed = pytest.importorskip("distributed")
    d, manifest = hands
    out = d / "dask_killed"
    monkeypatch.setenv("HOT_COLLECTION_TEST_DELAY", "0.4")  # (before the workers start: they inherit it)
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None) as cluster, \
            distributed.Client(cluster) as client:
        pids = client.run(os.getpid)
        assert len(pids) == 2
        result = {}

        def run():
            try:
                result["report"] = hot.collection(manifest, out, all_pairs=True, client=client, progress=False)
            except BaseException as e:  # (reported by the assertion below)
                result["error"] = e

        t = threading.Thread(target=run)
        t.start()
        deadline = time.monotonic() + 60
        parts = out / ".parts"
        while time.monotonic() < deadline and not (parts.is_dir() and any(n.startswith("mesh_") for n in os.listdir(parts))):
            time.sleep(0.02)
        assert parts.is_dir(), "no task ended within 60 s"
        victim = sorted(pids.values())[0]
        os.kill(victim, signal.SIGKILL)
        killed_mid_run = t.is_alive()
        t.join(120)
        assert not t.is_alive(), "the collection did not end after a worker was killed"
    assert "error" not in result, "the collection failed after a worker was killed: %r" % result.get("error")
    assert killed_mid_run, "the collection had ended before the worker was killed"
    assert_same_files(d / "cli", out)


def test_second_collection_into_a_folder_in_use_refuses(hands):
    d, manifest = hands
    out = d / "locked"
    os.makedirs(out)
    import fcntl
    fd = os.open(out, os.O_RDONLY)
    try:
        fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)  # (as a command-line run holds it)
        with pytest.raises(RuntimeError, match="in use by another collection run"):
            hot.collection(manifest, out, progress=False)
    finally:
        os.close(fd)
    assert not (out / "report.json").exists()
