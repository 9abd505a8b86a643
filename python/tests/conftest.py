# Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Fixtures of the Python module's tests.

Run by ctest (label python) with the environment:
  PYTHONPATH    <build>/python (the package hyperbolic_orbifold_tutte)
  HOT_CLI       <build>/bin/hyperbolic_orbifold_tutte (the command-line program compared with)
  HOT_DATA_DIR  <build>/data (libcgal-demo's meshes in meshes/)
  HOT_SOURCE_DIR the source tree (test/bend.awk, test/twist.awk)
By hand: the same variables, then /usr/bin/python3 -m pytest -q python/tests
"""

import os

import pytest


def _env(name):
    value = os.environ.get(name)
    if not value:
        pytest.fail("environment variable %s is not set (see python/tests/conftest.py)" % name, pytrace=False)
    return value


@pytest.fixture(scope="session")
def cli():
    path = _env("HOT_CLI")
    if not os.access(path, os.X_OK):
        pytest.fail("HOT_CLI=%s is not an executable (build the target hyperbolic_orbifold_tutte)" % path, pytrace=False)
    return path


@pytest.fixture(scope="session")
def meshes():
    path = os.path.join(_env("HOT_DATA_DIR"), "meshes")
    if not os.path.exists(os.path.join(path, "bear.off")):
        pytest.fail("%s holds no bear.off (libcgal-demo's meshes)" % path, pytrace=False)
    return path


@pytest.fixture(scope="session")
def source_dir():
    return _env("HOT_SOURCE_DIR")


@pytest.fixture(scope="module")
def bear(meshes):
    """bear.off (libcgal-demo), 7 landmarks of select_landmarks(), its embedding"""
    import hyperbolic_orbifold_tutte as hot
    V, F = hot.read_mesh(os.path.join(meshes, "bear.off"))
    lm = hot.select_landmarks(V, F, 7)
    return V, F, lm, hot.embed(V, F, lm)
