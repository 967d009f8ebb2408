"""Long calls release the GIL: Python code in another thread runs while they work."""

import math
import threading
import time

import numpy as np
import pytest

import sscc
from conftest import uv_sphere

MODES = 9


def python_time_during(call):
    """(how long Python code in this thread ran during the call, the call's seconds): the
    span between this thread's first and last loop iterations inside the call. With the GIL
    held for the call, that span is at most one switch interval (5 ms) before the call
    began; released, it is about the whole call."""
    window = []

    def worker():
        window.append(time.perf_counter())
        call()
        window.append(time.perf_counter())

    thread = threading.Thread(target=worker)
    thread.start()
    first = last = None
    while thread.is_alive():
        now = time.perf_counter()
        if len(window) == 1 and now > window[0]:
            first = now if first is None else first
            last = now
    thread.join()
    span = 0.0 if first is None else min(last, window[1]) - first
    return span, window[1] - window[0]


def sphere_bvh(rings, segments):
    mesh = sscc.TriangleMesh(*uv_sphere(rings, segments))
    return mesh, sscc.SubspaceBvh(sscc.SubspaceModel(mesh, sscc.polynomial_basis(mesh, MODES), np.ones(MODES)))


def kernel_queries():
    rng = np.random.default_rng(5)
    start = rng.uniform(-1, 1, (300_000, 4, 3))
    end = start + rng.uniform(-1, 1, (300_000, 4, 3))
    return lambda: sscc.vertex_face_ccd_many(start, end)


def exhaustive_query():
    detector = sscc.SelfCcd(sphere_bvh(24, 36)[1])
    return lambda: detector.query_exhaustive(np.zeros(MODES), np.full(MODES, 0.3))


def precomputation():
    bvh = sphere_bvh(8, 12)[1]
    return lambda: sscc.Certificates.precompute(bvh)


def modal_analysis():
    mesh = sscc.TriangleMesh(*uv_sphere(10, 16))
    return lambda: sscc.modal_basis(mesh, modes=10)


def repeated(call, seconds=0.25):
    """The call repeated so that it runs for about `seconds` whatever the machine's speed (a
    call shorter than a few switch intervals could not tell released from held)."""
    start = time.perf_counter()
    call()
    once = time.perf_counter() - start
    repeats = max(1, math.ceil(seconds / max(once, 1e-6)))

    def run():
        for _ in range(repeats):
            call()

    return run


@pytest.mark.parametrize("make_call", [kernel_queries, exhaustive_query, precomputation, modal_analysis])
def test_long_calls_release_the_gil(make_call):
    name = make_call.__name__
    span, seconds = python_time_during(repeated(make_call()))
    assert seconds > 0.05, f"{name} took {seconds:.3f} s: too short to tell"
    assert span > 0.5 * seconds, f"Python ran {span:.3f} s of the {seconds:.3f} s of {name}"


def test_the_measure_sees_a_call_that_holds_the_gil():
    data = np.random.default_rng(1).random(1_000_000).tolist()
    span, seconds = python_time_during(lambda: sorted(data))  # C code that keeps the GIL
    assert seconds > 0.05 and span < 0.5 * seconds
