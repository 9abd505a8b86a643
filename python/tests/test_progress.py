# Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
# SPDX-License-Identifier: GPL-3.0-or-later
"""progress= of hot.embed() and hot.map_meshes(): the library's phases in order (map_meshes(): the
refinement's last), each from 0 to 1, the same phases as the command line's `embed --progress` lines, the same result bit for
bit with or without the callable, and an exception of the callable raised by the call."""

import subprocess

import numpy as np
import pytest

import hyperbolic_orbifold_tutte as hot
from hot_testing import write_cones, write_off

PHASES = ["input", "cut", "initialization", "optimization", "certificate"]


def phases_of(calls):
    """the phases in the order first told"""
    seen = []
    for phase, _ in calls:
        if phase not in seen:
            seen.append(phase)
    return seen


def check_phases(calls, phases):
    assert phases_of(calls) == phases, calls
    for phase in phases:
        fractions = [f for p, f in calls if p == phase]
        assert all(0.0 <= f <= 1.0 for f in fractions), (phase, fractions)
        assert fractions == sorted(fractions), (phase, fractions)  # never back
        assert fractions[0] == 0.0 and fractions[-1] == 1.0, (phase, fractions)
    # one phase after the other: a phase is not told again once the next one started
    starts = [next(i for i, (p, _) in enumerate(calls) if p == phase) for phase in phases]
    ends = [max(i for i, (p, _) in enumerate(calls) if p == phase) for phase in phases]
    assert all(ends[i] < starts[i + 1] for i in range(len(phases) - 1)), calls


def test_embed_tells_the_phases_and_gives_the_same_bits(bear):
    V, F, lm, plain = bear
    calls = []
    e = hot.embed(V, F, lm, progress=lambda phase, f: calls.append((phase, f)))
    check_phases(calls, PHASES)
    assert all(isinstance(p, str) and isinstance(f, float) for p, f in calls)
    assert np.array_equal(e.uv, plain.uv), "the embedding differs with a progress callable"
    assert e.certified


def test_the_phases_are_the_command_lines(bear, cli, tmp_path):
    # the command line's --progress lines "embed: PHASE NN%" name the same phases (its own
    # reading and writing apart)
    V, F, lm, _ = bear
    write_off(tmp_path / "bear.off", V, F)
    write_cones(tmp_path / "bear.cones", lm)
    out = subprocess.run([cli, "embed", "--mesh", str(tmp_path / "bear.off"), "--cones", str(tmp_path / "bear.cones"),
                          "--out", str(tmp_path / "bear.obj"), "--progress"], capture_output=True, text=True)
    assert out.returncode == 0, out.stderr
    lines = [line.split(":", 1)[1].split()[0] for line in out.stderr.splitlines() if line.startswith("embed: ")]
    cli_phases = [p for p in dict.fromkeys(lines) if p not in ("read", "write")]
    assert cli_phases == PHASES, out.stderr


def test_map_meshes_names_the_two_embeddings(bear):
    V, F, lm, _ = bear
    calls = []
    r = hot.map_meshes(V, F, lm, V + 1.0, F, lm, progress=lambda phase, f: calls.append((phase, f)))
    check_phases(calls, ["source: " + p for p in PHASES] + ["target: " + p for p in PHASES])
    plain = hot.map_meshes(V, F, lm, V + 1.0, F, lm)
    assert np.array_equal(r["faces"], plain["faces"]) and np.array_equal(r["bary"], plain["bary"])


def test_map_meshes_tells_the_refinement_after_the_embeddings(bear):
    # refine=N: the phase "refinement" last, 0 when it starts, i / N after iteration i, 1 at its
    # end (refine_orbifold_map()'s progress); the same map as without the callable. The target
    # is the bear stretched along y, so that the harmonic map is not the refined one.
    V, F, lm, _ = bear
    W = V * np.array([1.0, 1.3, 1.0])
    N = 3
    calls = []
    r = hot.map_meshes(V, F, lm, W, F, lm, refine=N, progress=lambda phase, f: calls.append((phase, f)))
    check_phases(calls, ["source: " + p for p in PHASES] + ["target: " + p for p in PHASES] + ["refinement"])
    told = [f for p, f in calls if p == "refinement"]
    assert 3 <= len(told) <= N + 2 and told[1:-1] == [k / N for k in range(1, len(told) - 1)], told
    plain = hot.map_meshes(V, F, lm, W, F, lm, refine=N)
    assert np.array_equal(r["faces"], plain["faces"]) and np.array_equal(r["bary"], plain["bary"])


class Stop(Exception):
    pass


def test_an_exception_of_the_callable_is_raised(bear):
    V, F, lm, _ = bear
    calls = []

    def progress(phase, f):
        calls.append(phase)
        if phase == "cut":
            raise Stop("enough")

    with pytest.raises(Stop, match="enough"):
        hot.embed(V, F, lm, progress=progress)
    assert calls[-1] == "cut" and calls.count("cut") == 1, "the callable was told more after it raised"
    # a bad input's error still wins over nothing: too few landmarks, the callable fine
    with pytest.raises(hot.InputError):
        hot.embed(V, F, lm[:2], progress=lambda p, f: None)


def test_a_progress_that_is_not_callable_is_refused(bear):
    V, F, lm, _ = bear
    with pytest.raises(hot.InputError, match="progress"):
        hot.embed(V, F, lm, progress=3)
