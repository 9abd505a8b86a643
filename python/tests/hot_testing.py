# Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Helpers of the Python module's tests: the command-line program, awk scripts, and readers
of its files written here (not by the module), as outside references."""

import os
import re
import subprocess

import numpy as np
import pytest


def run_cli(cli, *args):
    """runs the command-line program; its stdout, or the test fails with its stderr"""
    r = subprocess.run([cli] + [str(a) for a in args], capture_output=True, text=True)
    if r.returncode != 0:
        pytest.fail("%s %s failed (%d): %s" % (cli, " ".join(map(str, args)), r.returncode, r.stderr))
    return r.stdout


def run_awk(script, src, dst, **variables):
    """awk -v K=V ... -f script src > dst"""
    cmd = ["awk"]
    for k, v in variables.items():
        cmd += ["-v", "%s=%s" % (k, v)]
    cmd += ["-f", script, str(src)]
    with open(dst, "w") as out:
        subprocess.run(cmd, stdout=out, check=True)
    return dst


def read_off(path):
    """an OFF file's vertices and faces, parsed here (not by the module): an outside reference"""
    tokens = []
    with open(path) as f:
        for line in f:
            line = line.split("#", 1)[0]
            tokens += line.split()
    assert tokens[0] == "OFF"
    nv, nf = int(tokens[1]), int(tokens[2])
    pos = 4
    V = np.array([float(t) for t in tokens[pos:pos + 3 * nv]]).reshape(nv, 3)
    pos += 3 * nv
    faces = []
    for _ in range(nf):
        k = int(tokens[pos])
        faces.append([int(t) for t in tokens[pos + 1:pos + 1 + k]])
        pos += 1 + k
    return V, np.array(faces, dtype=np.int64)


def read_obj_embedding(path):
    """the vt points and the f lines (vertex, vt per corner, 0-based) of an embedding's OBJ file"""
    vt, fv, ft = [], [], []
    with open(path) as f:
        for line in f:
            if line.startswith("vt "):
                _, x, y = line.split()
                vt.append((float(x), float(y)))
            elif line.startswith("f "):
                corners = [c.split("/") for c in line.split()[1:]]
                fv.append([int(c[0]) - 1 for c in corners])
                ft.append([int(c[1]) - 1 for c in corners])
    return np.array(vt), np.array(fv, dtype=np.int64), np.array(ft, dtype=np.int64)


def read_map(path):
    """MAP.txt: one line 'face b0 b1 b2' per source vertex"""
    faces, bary = [], []
    with open(path) as f:
        for line in f:
            t = line.split()
            faces.append(int(t[0]))
            bary.append([float(x) for x in t[1:4]])
    return np.array(faces, dtype=np.int64), np.array(bary)


def write_cones(path, landmarks):
    with open(path, "w") as f:
        f.write(" ".join(str(int(i)) for i in landmarks) + "\n")
    return path


def read_cones(path):
    with open(path) as f:
        return np.array([int(t) for t in f.read().split()], dtype=np.int64)


def diagonal(V):
    return float(np.linalg.norm(V.max(axis=0) - V.min(axis=0)))


def flat_disk(rings=12, radius=2.0):
    """a triangulated flat disk in the plane x = 0 (centre, then rings of 6i vertices): its
    bend by bend.awk (about the z axis) is an isometry, so a map onto the bent copy should be
    close to the identity (vertex i <-> vertex i)"""
    V = [(0.0, 0.0, 0.0)]
    start = [0]
    for i in range(1, rings + 1):
        start.append(len(V))
        r = radius * i / rings
        for j in range(6 * i):
            a = 2 * np.pi * j / (6 * i)
            V.append((0.0, r * np.cos(a), r * np.sin(a)))
    F = []
    for j in range(6):  # the centre's fan
        F.append((0, start[1] + j, start[1] + (j + 1) % 6))
    for i in range(2, rings + 1):  # the strip between rings i - 1 and i, zipped by angle
        n_in, n_out = 6 * (i - 1), 6 * i
        a = b = 0
        while a < n_in or b < n_out:
            if b < n_out and (a == n_in or (b + 1) / n_out <= (a + 1) / n_in):
                F.append((start[i - 1] + a % n_in, start[i] + b, start[i] + (b + 1) % n_out))
                b += 1
            else:
                F.append((start[i - 1] + a, start[i] + b % n_out, start[i - 1] + (a + 1) % n_in))
                a += 1
    return np.array(V), np.array(F, dtype=np.int64)


def write_off(path, V, F):
    with open(path, "w") as f:
        f.write("OFF\n%d %d 0\n" % (len(V), len(F)))
        for p in V:
            f.write("%.17g %.17g %.17g\n" % tuple(p))
        for t in F:
            f.write("%d %s\n" % (len(t), " ".join(str(int(i)) for i in t)))
    return path


def without_times(text):
    """a report.json's text with its times replaced by T"""
    return re.sub(r'"(embedding_seconds|map_seconds|seconds|seconds_certificate)": [0-9.e+-]+', r'"\1": T', text)


def assert_same_files(cli_dir, dir2):
    """the same file names and bytes as the command line's folder (report.json apart from its times)"""
    names = sorted(os.listdir(cli_dir))
    assert names == sorted(os.listdir(dir2)), "other files than the command line's"
    for name in names:
        a = open(os.path.join(cli_dir, name), "rb").read()
        b = open(os.path.join(dir2, name), "rb").read()
        if name == "report.json":
            assert without_times(a.decode()) == without_times(b.decode()), "report.json differs beyond its times"
        else:
            assert a == b, "%s differs from the command line's" % name


def make_hands(d, meshes, cli):
    """hand.off and three smooth deformations of it (same triangulation, same 9 landmarks) in
    folder d, their manifest d/list.txt, and the command line's collection of them with all
    pairs in d/cli; returns (manifest, number of vertices)"""
    V, F = read_off(os.path.join(meshes, "hand.off"))
    x, y, z = V[:, 0], V[:, 1], V[:, 2]
    shapes = {
        "a": V,
        "b": np.stack([x + 0.1 * np.sin(3 * y), y, 1.2 * z], axis=1),
        "c": np.stack([0.9 * x, y + 0.05 * np.cos(4 * 0.9 * x), z], axis=1),
        "e": np.stack([x, 1.1 * y, z + 0.05 * np.sin(2 * x)], axis=1),
    }
    for name, W in shapes.items():
        write_off(d / ("hand_%s.off" % name), W, F)
    run_cli(cli, "landmarks", "--mesh", d / "hand_a.off", "--count", 9, "--out", d / "cones.txt")
    manifest = d / "list.txt"
    manifest.write_text("".join("hand_%s.off cones.txt\n" % n for n in shapes))
    run_cli(cli, "collection", "--manifest", manifest, "--out", d / "cli", "--all-pairs")
    return manifest, len(V)
