"""The kernels from Python: known answers, the vectorised forms against the scalar ones,
arrays without copies, and the cost of the language boundary."""

import statistics
import time
import tracemalloc

import numpy as np
import pytest

import sscc

# A vertex falling straight through the middle of a resting triangle: contact at t = 1/2.
VERTEX_THROUGH_FACE = [(0.25, 0.25, 1.0), (0, 0, 0), (1, 0, 0), (0, 1, 0),
                       (0.25, 0.25, -1.0), (0, 0, 0), (1, 0, 0), (0, 1, 0)]
# The same vertex passing beside the triangle (x + y > 1 all the way).
VERTEX_BESIDE_FACE = [(0.75, 0.75, 1.0), (0, 0, 0), (1, 0, 0), (0, 1, 0),
                      (0.75, 0.75, -1.0), (0, 0, 0), (1, 0, 0), (0, 1, 0)]
# Two crossing edges, one moving down onto the other: contact at t = 3/4.
EDGES_CROSSING = [(-1, 0, 1), (1, 0, 1), (0, -1, 0), (0, 1, 0),
                  (-1, 0, -1 / 3), (1, 0, -1 / 3), (0, -1, 0), (0, 1, 0)]


def test_vertex_face_hit_and_toi():
    hit, toi = sscc.vertex_face_ccd(*VERTEX_THROUGH_FACE)
    assert hit
    # Never later than the true contact, within the tolerance of it.
    assert 0.5 - sscc.DEFAULT_TOI_TOLERANCE <= toi <= 0.5
    hit, toi = sscc.vertex_face_ccd(*VERTEX_THROUGH_FACE, toi_tolerance=1e-12)
    assert 0.5 - 1e-12 <= toi <= 0.5
    assert sscc.vertex_face_ccd(*VERTEX_BESIDE_FACE) == (False, 1.0)


def test_edge_edge_hit_and_toi():
    hit, toi = sscc.edge_edge_ccd(*EDGES_CROSSING)
    assert hit
    assert 0.75 - sscc.DEFAULT_TOI_TOLERANCE <= toi <= 0.75


def test_minimum_separation_reports_a_near_miss():
    # Passing 0.05 beside the triangle's hypotenuse (distance 0.05 / sqrt 2 from the edge x + y = 1).
    near = [(0.55, 0.5, 1.0)] + VERTEX_BESIDE_FACE[1:4] + [(0.55, 0.5, -1.0)] + VERTEX_BESIDE_FACE[5:]
    assert not sscc.vertex_face_ccd(*near)[0]
    assert sscc.vertex_face_ccd(*near, minimum_separation=0.1)[0]


def test_triangles_intersect():
    base = [(0, 0, 0), (1, 0, 0), (0, 1, 0)]
    assert sscc.triangles_intersect(*base, (0.2, 0.2, -1), (0.2, 0.2, 1), (2, 2, 0))
    assert not sscc.triangles_intersect(*base, (0.2, 0.2, 0.5), (0.3, 0.2, 1), (0.2, 0.3, 1))


def random_queries(rng, n):
    """Primitives of unit size moving by about their size: roughly a tenth of them touch."""
    start = rng.uniform(-1.0, 1.0, (n, 4, 3))
    end = start + rng.uniform(-1.0, 1.0, (n, 4, 3))
    return start, end


def test_vectorised_forms_equal_the_scalar_ones():
    rng = np.random.default_rng(7)
    start, end = random_queries(rng, 400)
    for many, one in ((sscc.vertex_face_ccd_many, sscc.vertex_face_ccd),
                      (sscc.edge_edge_ccd_many, sscc.edge_edge_ccd)):
        hit, toi = many(start, end)
        assert hit.dtype == np.bool_ and toi.dtype == np.float64 and hit.shape == toi.shape == (400,)
        expected = [one(*start[i], *end[i]) for i in range(400)]
        assert hit.tolist() == [h for h, _ in expected]
        assert toi.tolist() == [t for _, t in expected]
        assert 10 < hit.sum() < 390


def test_vectorised_known_cases():
    start = np.array([VERTEX_THROUGH_FACE[:4], VERTEX_BESIDE_FACE[:4]], dtype=float)
    end = np.array([VERTEX_THROUGH_FACE[4:], VERTEX_BESIDE_FACE[4:]], dtype=float)
    hit, toi = sscc.vertex_face_ccd_many(start, end)
    assert hit.tolist() == [True, False]
    assert 0.5 - sscc.DEFAULT_TOI_TOLERANCE <= toi[0] <= 0.5 and toi[1] == 1.0
    # Any float dtype and layout is accepted (converted once).
    hit32, _ = sscc.vertex_face_ccd_many(start.astype(np.float32), np.asfortranarray(end))
    assert hit32.tolist() == [True, False]
    empty_hit, empty_toi = sscc.vertex_face_ccd_many(np.zeros((0, 4, 3)), np.zeros((0, 4, 3)))
    assert empty_hit.shape == empty_toi.shape == (0,)


def test_vectorised_bad_input():
    with pytest.raises(ValueError, match=r"start: expected an \(n, 4, 3\) array, got shape \(5, 3\)"):
        sscc.vertex_face_ccd_many(np.zeros((5, 3)), np.zeros((5, 4, 3)))
    with pytest.raises(ValueError, match="start and end: 2 and 3 queries"):
        sscc.edge_edge_ccd_many(np.zeros((2, 4, 3)), np.zeros((3, 4, 3)))
    start, end = random_queries(np.random.default_rng(1), 10)
    start[6, 2, 1] = np.nan
    with pytest.raises(ValueError, match="query 6: .*(finite|NaN)"):
        sscc.vertex_face_ccd_many(start, end)


def test_scalar_bad_input():
    with pytest.raises(ValueError, match=r"f1: expected 3 coordinates, got shape \(2,\)"):
        sscc.vertex_face_ccd((0, 0, 1), (0, 0, 0), (1, 0), (0, 1, 0), (0, 0, -1), (0, 0, 0), (1, 0, 0), (0, 1, 0))
    with pytest.raises(ValueError, match="(finite|NaN)"):
        sscc.edge_edge_ccd((np.inf, 0, 1), *EDGES_CROSSING[1:])


def test_vectorised_call_copies_nothing_it_does_not_need():
    # 10^5 queries: 9.6 MB in each input array, 0.9 MB of output. A copy of an input would
    # show in NumPy's traced allocations.
    start, end = random_queries(np.random.default_rng(3), 100_000)
    tracemalloc.start()
    try:
        sscc.vertex_face_ccd_many(start, end)
        _, peak = tracemalloc.get_traced_memory()
    finally:
        tracemalloc.stop()
    assert peak < start.nbytes / 4, f"peak {peak} bytes for {start.nbytes}-byte inputs"


def test_boundary_cost_of_a_million_queries(record_property):
    """The vectorised call against the same loop in C++ on data already in C++ containers:
    median of interleaved repeats. The figure is printed; the bound is generous because the
    machine is shared."""
    start, end = random_queries(np.random.default_rng(11), 1_000_000)
    python_seconds, native_seconds = [], []
    for _ in range(5):
        begin = time.perf_counter()
        sscc.vertex_face_ccd_many(start, end)
        python_seconds.append(time.perf_counter() - begin)
        native_seconds.append(sscc._sscc._native_kernel_loop_seconds("vertex_face", start, end))
    ratio = statistics.median(python_seconds) / statistics.median(native_seconds)
    record_property("vectorised_over_native", ratio)
    print(f"\n10^6 vertex-face queries: vectorised {statistics.median(python_seconds) * 1e3:.1f} ms, "
          f"C++ loop {statistics.median(native_seconds) * 1e3:.1f} ms, ratio {ratio:.3f}")
    assert ratio < 1.5
