# Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
# SPDX-License-Identifier: GPL-3.0-or-later
"""No copies where numpy views do: arrays returned by the module own C++ buffers (or view the
embedding's memory), and input arrays already C-contiguous float64 / int64 are read in place.

How the input side is checked: numpy reports its allocations to tracemalloc, so a conversion
copy of V (or F) made on the way into the module shows in tracemalloc's peak as at least
V.nbytes. The same call with a Fortran-ordered or float32 V (which must be converted) shows
that the measure sees such a copy."""

import gc
import tracemalloc

import numpy as np
import pytest

import hyperbolic_orbifold_tutte as hot


def base_chain(a):
    chain = []
    while a is not None:
        chain.append(a)
        a = getattr(a, "base", None)
    return chain


def test_uv_is_a_view_of_the_embedding(bear):
    e = bear[3]
    a, b = e.uv, e.uv
    assert a is not b and np.shares_memory(a, b)
    assert not a.flags.owndata and not a.flags.writeable and a.flags.c_contiguous
    assert any(isinstance(x, hot.Embedding) for x in base_chain(a))
    for view in (e.V, e.F):
        assert not view.flags.owndata and not view.flags.writeable
        assert any(isinstance(x, hot.Embedding) for x in base_chain(view))
    assert np.shares_memory(e.V, e.V) and np.shares_memory(e.F, e.F)
    assert np.array_equal(e.V, bear[0]) and np.array_equal(e.F, bear[1])


def test_views_keep_the_embedding_alive(bear):
    V, F, lm, _ = bear
    e = hot.embed(V, F, lm)
    uv, expected = e.uv, e.uv.copy()
    del e
    gc.collect()
    junk = [np.random.rand(1000) for _ in range(100)]  # reuse freed memory, if any were freed
    assert np.array_equal(uv, expected)
    del junk


def test_returned_arrays_own_cpp_buffers(bear):
    V, F, lm, e = bear
    for a in (V, F, lm) + hot.map(e, e):
        assert not a.flags.owndata  # a view of a C++ buffer (its base a capsule)
        assert type(a.base).__name__ == "PyCapsule"


def traced_peak(fn):
    """the peak of memory traced (numpy's allocations included) while fn runs, above the start"""
    gc.collect()
    tracemalloc.start()
    try:
        tracemalloc.reset_peak()
        before = tracemalloc.get_traced_memory()[0]
        fn()
        return tracemalloc.get_traced_memory()[1] - before
    finally:
        tracemalloc.stop()


def test_contiguous_inputs_are_not_copied(bear):
    V, F, lm, _ = bear
    assert V.flags.c_contiguous and V.dtype == np.float64 and F.dtype == np.int64
    fortran, single = np.asfortranarray(V), V.astype(np.float32)
    F32 = F.astype(np.int32)
    # the measure sees a conversion copy ...
    assert traced_peak(lambda: hot.select_landmarks(fortran, F, 7)) >= V.nbytes
    assert traced_peak(lambda: hot.select_landmarks(single, F, 7)) >= V.nbytes
    assert traced_peak(lambda: hot.select_landmarks(V, F32, 7)) >= F.nbytes
    # ... and there is none for C-contiguous float64 V and int64 F
    peak = traced_peak(lambda: hot.select_landmarks(V, F, 7))
    print("select_landmarks: peak %d bytes traced (V %d, F %d bytes)" % (peak, V.nbytes, F.nbytes))
    assert peak < V.nbytes / 4
    peak = traced_peak(lambda: hot.embed(V, F, lm))
    print("embed: peak %d bytes traced (V %d, F %d bytes)" % (peak, V.nbytes, F.nbytes))
    assert peak < V.nbytes / 4
    assert traced_peak(lambda: hot.embed(fortran, F, lm)) >= V.nbytes
    # views into larger arrays are read in place too when contiguous
    big = np.concatenate([V, V])
    assert traced_peak(lambda: hot.select_landmarks(big[: len(V)], F, 7)) < V.nbytes / 4
