# Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
# SPDX-License-Identifier: GPL-3.0-or-later
"""hot.view(obj, out_dir): the folder of the command line's `view` job (index.html, data.js,
viewer.js, three.min.js). Its data against the command line's view of the same embedding
(embed's OBJ file), and against map_meshes()' own result; bad arguments raise. (The page itself
is tested in a browser by test/test_view.sh, label viewer.)"""

import json
import os

import numpy as np
import pytest

import hyperbolic_orbifold_tutte as hot
from hot_testing import run_cli, write_cones


def page_data(folder):
    """data.js of a view folder as a dict (window.HOT_VIEW = {...};)"""
    with open(os.path.join(folder, "data.js")) as f:
        text = f.read()
    return json.loads(text[text.index("window.HOT_VIEW = ") + len("window.HOT_VIEW = "):].rstrip().rstrip(";"))


def test_embedding_view_is_the_command_lines(bear, cli, tmp_path):
    V, F, lm, e = bear
    hot.view(e, tmp_path / "py")
    assert sorted(os.listdir(tmp_path / "py")) == ["data.js", "index.html", "three.min.js", "viewer.js"]
    # the command line: the same embedding (embed's numbers are the module's), viewed from its OBJ file
    write_cones(tmp_path / "c.txt", lm)
    run_cli(cli, "embed", "--mesh", os.path.join(os.environ["HOT_DATA_DIR"], "meshes", "bear.off"), "--cones", tmp_path / "c.txt",
            "--out", tmp_path / "a.obj")
    run_cli(cli, "view", "--embedding", tmp_path / "a.obj", "--out", tmp_path / "cli")
    a, b = page_data(tmp_path / "py"), page_data(tmp_path / "cli")
    sa, sb = a["shapes"][0], b["shapes"][0]
    for key in ("positions", "faces", "uv", "cut", "cut_uv", "fold", "landmark_numbers", "landmark_vertices"):
        assert sa[key] == sb[key], key
    assert np.allclose(np.array(sa["positions"]).reshape(-1, 3), V, rtol=0, atol=1e-8 * np.abs(V).max())
    assert sorted(sa["landmark_vertices"]) == sorted(int(i) for i in lm)
    for f in ("index.html", "viewer.js", "three.min.js"):
        with open(tmp_path / "py" / f, "rb") as x, open(tmp_path / "cli" / f, "rb") as y:
            assert x.read() == y.read(), f


def test_map_view_holds_the_map(bear, tmp_path):
    V, F, lm, _ = bear
    W = V * np.array([1.0, 1.3, 0.8])  # a stretched copy, the same triangulation
    r = hot.map_meshes(V, F, lm, W, F, lm)
    hot.view(r, tmp_path / "m")
    d = page_data(tmp_path / "m")
    assert d["kind"] == "map" and len(d["shapes"]) == 2
    m = [x for x in d["maps"] if x["from"] == 0 and x["to"] == 1][0]
    assert m["face"] == r["faces"].tolist()
    assert np.array_equal(np.array(m["bary"]).reshape(-1, 3), r["bary"])
    # the colours of B: A's colour field carried back; landmark i of B gets landmark i of A's colour
    ca, cb = np.array(d["shapes"][0]["colors"]).reshape(-1, 3), np.array(d["shapes"][1]["colors"]).reshape(-1, 3)
    for i in lm:
        assert np.abs(ca[i] - cb[i]).max() < 1e-3
    # a pair of embeddings as map() takes them: the same page data
    hot.view((r["source"], r["target"]), tmp_path / "pair")
    assert page_data(tmp_path / "pair")["maps"] == d["maps"]


def test_bad_arguments_raise(bear, tmp_path):
    _, _, _, e = bear
    with pytest.raises(hot.InputError):
        hot.view(3, tmp_path / "x")
    with pytest.raises(hot.InputError):
        hot.view([e], tmp_path / "x")
    (tmp_path / "other").mkdir()
    (tmp_path / "other" / "notes.txt").write_text("keep")
    with pytest.raises(hot.ComputationError):
        hot.view(e, tmp_path / "other")
    assert os.listdir(tmp_path / "other") == ["notes.txt"]
    assert not os.path.exists(tmp_path / "x") and not os.path.exists(tmp_path / "other.tmp")
