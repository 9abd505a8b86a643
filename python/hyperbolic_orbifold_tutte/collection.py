# Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Collections: every mesh of a manifest embedded once, the maps between them computed from the
stored embeddings, the cycle consistency measured, in threads of this process or as tasks of a
Dask cluster. The files are those of the command line's `collection`, byte for byte (report.json
apart from its times)."""

import json as _json
import os as _os
import shutil as _shutil
import sys as _sys
import time as _time
import uuid as _uuid
from concurrent.futures import ThreadPoolExecutor as _ThreadPoolExecutor

from . import _core


def _options(manifest, out_dir, all_pairs, cone_orders, repair, max_hole, largest_component, snap_landmarks, refine):
    return dict(manifest=_os.fspath(manifest), out_dir=_os.fspath(out_dir), all_pairs=bool(all_pairs),
                cone_orders=None if cone_orders is None else [int(p) for p in cone_orders],
                repair=bool(repair), max_hole=None if max_hole is None else float(max_hole), largest_component=bool(largest_component),
                snap_landmarks=bool(snap_landmarks), refine=int(refine))


# The tasks (top-level functions: a Dask worker imports them by name). The map tasks take the
# results of the embedding tasks of their two meshes only to run after them. A task run again
# (Dask retries it when it failed, or when its worker died) skips a mesh or pair whose part is
# complete in out_dir/.parts, and rewrites one left half-done (every file is renamed into place
# only when complete).

def _test_delay():
    """a test-only hook: HOT_COLLECTION_TEST_DELAY seconds of sleep before each task (to kill a
    worker while tasks run)"""
    delay = float(_os.environ.get("HOT_COLLECTION_TEST_DELAY", "0") or 0)
    if delay > 0:
        _time.sleep(delay)


def _embed_task(i, orbifold, landmarks, order, options):
    _test_delay()
    return _core.collection_embed(i, orbifold, landmarks, order, **options)


def _refine_task(i, options, *after):
    _test_delay()
    return _core.collection_refine(i, **options)


def _map_task(a, b, options, *after):
    _test_delay()
    return _core.collection_map(a, b, **options)


def _merge_task(options, *after):
    return _core.collection_merge(**options)


class _Progress:
    """Lines on stderr as the command line prints them: every mesh embedded, every 5% of the maps."""

    def __init__(self, enabled, meshes, pairs):
        self.enabled = enabled
        self.meshes, self.pairs = meshes, pairs
        self.embedded = self.mapped = 0
        self.t0 = _time.monotonic()

    def embedding_done(self, i, seconds):
        self.embedded += 1
        if self.enabled:
            print("  embedded %d/%d: %s (%.3g s)" % (self.embedded, len(self.meshes), self.meshes[i][0], seconds),
                  file=_sys.stderr, flush=True)

    def refinement_done(self, i, seconds):
        if self.enabled and i > 0:
            print("  refined %s onto %s (%.3g s)" % (self.meshes[i][0], self.meshes[0][0], seconds), file=_sys.stderr, flush=True)

    def map_done(self, a, b, seconds):
        self.mapped += 1
        n = len(self.pairs)
        if self.enabled and (self.mapped == n or self.mapped % max(1, n // 20) == 0):
            print("  mapped %d/%d pairs (last: %d -> %d, %.3g s; %.1f s so far)"
                  % (self.mapped, n, a, b, seconds, _time.monotonic() - self.t0), file=_sys.stderr, flush=True)


def _run_in_threads(plan, options, threads, progress):
    order = (plan["orbifold"], plan["landmarks"], list(plan["order"]))
    with _ThreadPoolExecutor(max_workers=threads or _os.cpu_count() or 1) as pool:
        futures = {pool.submit(_embed_task, i, *order, options): i for i in range(len(plan["meshes"]))}
        _drain(futures, progress.embedding_done)
        if options["refine"] > 0:
            futures = {pool.submit(_refine_task, i, options): i for i in range(len(plan["meshes"]))}
            _drain(futures, progress.refinement_done)
        futures = {pool.submit(_core.collection_map, a, b, **options): (a, b) for a, b in plan["pairs"]}
        _drain(futures, lambda ab, seconds: progress.map_done(ab[0], ab[1], seconds))
    return _core.collection_merge(**options)


def _drain(futures, done):
    """done(what, result) as each future ends; the first failure cancels the others and raises"""
    from concurrent.futures import as_completed
    try:
        for f in as_completed(futures):
            done(futures[f], f.result())
    except BaseException:
        for g in futures:
            g.cancel()
        raise


# how many times Dask runs a task again after it raised (a task whose worker died is rescheduled
# by Dask itself, up to its distributed.scheduler.allowed-failures, then fails with KilledWorker)
_RETRIES = 2


def _run_on_dask(plan, options, client, progress):
    import distributed
    token = _uuid.uuid4().hex[:8]
    order = (plan["orbifold"], plan["landmarks"], list(plan["order"]))
    embeds = [client.submit(_embed_task, i, *order, options, key="hot-embed-%d-%s" % (i, token), pure=False,
                          retries=_RETRIES)
              for i in range(len(plan["meshes"]))]
    ready = embeds  # (what a map waits for: its meshes' embeddings, or their refinements)
    refines = []
    if options["refine"] > 0:
        refines = [client.submit(_refine_task, i, options, embeds[0], embeds[i], key="hot-refine-%d-%s" % (i, token), pure=False,
                                 retries=_RETRIES)
                   for i in range(len(plan["meshes"]))]
        ready = refines
    maps = [client.submit(_map_task, a, b, options, ready[a], ready[b], key="hot-map-%d-%d-%s" % (a, b, token), pure=False,
                          retries=_RETRIES)
            for a, b in plan["pairs"]]
    what = {f.key: ("embed", i) for i, f in enumerate(embeds)}
    what.update({f.key: ("refine", i) for i, f in enumerate(refines)})
    what.update({f.key: ("map", p) for p, f in zip(plan["pairs"], maps)})
    try:
        for f in distributed.as_completed(embeds + refines + maps):
            kind, x = what[f.key]
            seconds = f.result()  # (raises the task's hot.Error)
            if kind == "embed":
                progress.embedding_done(x, seconds)
            elif kind == "refine":
                progress.refinement_done(x, seconds)
            else:
                progress.map_done(x[0], x[1], seconds)
        return client.submit(_merge_task, options, *maps, key="hot-merge-" + token, pure=False,
                             retries=_RETRIES).result()
    except distributed.KilledWorker as e:
        client.cancel(embeds + refines + maps)
        kind, x = what.get(getattr(e, "task", None) or (e.args[0] if e.args else None), ("task", "?"))
        raise RuntimeError("the Dask workers running the %s task of %s died too often: %s (out_dir/.parts keeps the finished"
                           " parts: run the collection again to resume)" % (kind, x, e)) from e
    except BaseException:
        client.cancel(embeds + refines + maps)
        raise


def collection(manifest, out_dir, all_pairs=False, client=None, cone_orders=None, repair=False, max_hole=None,
               largest_component=False, snap_landmarks=False, threads=None, progress=True, refine=0):
    """collection(manifest, out_dir, all_pairs=False, client=None, ...) -> dict (report.json)

    Embeds every mesh of `manifest` (lines `mesh_path cones_path`, relative paths against the
    manifest's folder; landmark i of every mesh is the same feature) into one orbifold with one
    cone order (the paper's tour on the first mesh), maps the meshes onto each other, measures
    the cycle consistency, and writes the command line's `collection` files into `out_dir`:
    <i>_<name>.obj per mesh, with all_pairs <a>_to_<b>.map.txt per ordered pair, and
    report.json, which it returns as a dict.

    Each mesh is embedded once, by one task that writes its OBJ file; each map is a task that
    reads the two stored embeddings (no embedding again); a last task measures the cycle
    consistency and writes report.json. They run in `threads` threads of this process
    (default: one per core; the computations release the GIL), or, given a
    dask.distributed.Client, as tasks of its cluster (local or on a batch scheduler or
    Kubernetes): out_dir must then be a folder every worker sees (a shared file system), the
    manifest's files too, and the workers must import this package. The files are the same,
    byte for byte, as the command line's (report.json apart from its times).

    cone_orders: the order p of every landmark's cone (angle 2 pi/p), in the manifest's
    landmark order (default: 2 for all); repair, max_hole, largest_component, snap_landmarks:
    the command line's --repair options (max_hole=None: as without --max-hole, a limit of 0.5
    bounding box diagonals, none when the landmarks are inside the surface). refine: at most this many
    iterations fitting every mesh's embedding to mesh 0's metric (the command line's --refine; 0:
    none), one task per mesh after the embeddings; the maps stay compositions through the one
    orbifold (cycle consistent). progress: a line on stderr per mesh embedded (and refined) and
    every 5% of the maps. A failure raises hot.Error (the first one, naming the mesh), and the
    files this call wrote are removed. Faults: every file is renamed into place only when
    complete, and each task's part in out_dir/.parts marks it done, so a call interrupted (the
    process killed) and made again with the same arguments resumes: it skips what is done, keeps
    the parts if it fails again, and gives the files of an uninterrupted call. On Dask, a task
    whose worker dies is run again on another (retries=2 for tasks that raise); a task whose
    workers die too often raises RuntimeError naming it. out_dir is locked for the call (flock):
    another collection into it raises RuntimeError.

    Example:
        >>> # list.txt: "cat0.off cat.cones\ncat1.off cat.cones\ncat2.off cat.cones\n"
        >>> report = hot.collection("list.txt", "out", all_pairs=True, refine=20)
        >>> report["cycle_consistency_max_rel_error"]  # composed maps against the direct ones
        >>> from dask.distributed import Client
        >>> report = hot.collection("list.txt", "/shared/out", client=Client("scheduler:8786"))
    """
    options = _options(manifest, out_dir, all_pairs, cone_orders, repair, max_hole, largest_component, snap_landmarks, refine)
    plan = _core.collection_plan(**options)
    out = options["out_dir"]
    before = set(_os.listdir(out)) if _os.path.isdir(out) else None
    resuming = _os.path.isdir(_os.path.join(out, ".parts"))
    report = _Progress(progress, plan["meshes"], plan["pairs"])
    _os.makedirs(out, exist_ok=True)
    lock = _lock_folder(out)
    try:
        try:
            if client is None:
                _run_in_threads(plan, options, threads, report)
            else:
                _run_on_dask(plan, options, client, report)
        except BaseException:
            if not resuming:
                _remove_new_files(out, before)
            raise
    finally:
        _os.close(lock)
    with open(_os.path.join(out, "report.json")) as f:
        return _json.load(f)


def _lock_folder(out):
    """out's lock, as the command line's collection takes it (flock on the folder itself,
    exclusive; released when the process ends, killed or not): a second collection into the same
    folder, or a command-line run or stage job, refuses while this one runs"""
    import fcntl
    fd = _os.open(out, _os.O_RDONLY)
    try:
        fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
    except BlockingIOError:
        _os.close(fd)
        raise RuntimeError("'%s' is in use by another collection run (it holds its lock): wait for it to end, or use another"
                           " out_dir" % out) from None
    return fd


def _remove_new_files(out, before):
    """the files a failed collection wrote (none is left half-written: each is renamed when complete)"""
    if not _os.path.isdir(out):
        return
    if before is None:
        _shutil.rmtree(out, ignore_errors=True)
        return
    for name in set(_os.listdir(out)) - before:
        path = _os.path.join(out, name)
        if _os.path.isdir(path):
            _shutil.rmtree(path, ignore_errors=True)
        else:
            try:
                _os.remove(path)
            except OSError:
                pass
    _shutil.rmtree(_os.path.join(out, ".parts"), ignore_errors=True)
