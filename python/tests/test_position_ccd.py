"""PositionCcd from Python (simulators without a subspace: positions per step) against
SelfCcd.query_positions on the same mesh and an independent brute force over every triangle
pair through the vectorised kernels; with and without excluded pairs."""

import numpy as np
import pytest

import sscc
from conftest import MODES, random_q, uv_sphere
from geometry_checks import check_geometry


def brute_force_self(mesh, x0, x1, excluded=None):
    """Every triangle pair sharing no vertex (and not excluded), all 15 features through the
    vectorised kernels: the colliding pairs (a < b) with their earliest toi."""
    triangles = np.asarray(mesh.triangles)
    a, b = np.triu_indices(len(triangles), k=1)
    shared = (triangles[a][:, :, None] == triangles[b][:, None, :]).any(axis=(1, 2))
    keep = ~shared
    if excluded is not None:
        keep &= np.array([not excluded.contains(i, j) for i, j in zip(a, b)])
    a, b = a[keep], b[keep]
    ta, tb = triangles[a], triangles[b]
    toi = np.full(len(a), np.inf)

    def run(kernel, rows_a, rows_b):
        start = np.concatenate([x0[rows_a], x0[rows_b]], axis=1)
        end = np.concatenate([x1[rows_a], x1[rows_b]], axis=1)
        hit, t = kernel(start, end)
        np.minimum.at(toi, np.nonzero(hit)[0], t[hit])

    for k in range(3):
        run(sscc.vertex_face_ccd_many, ta[:, [k]], tb)
        run(sscc.vertex_face_ccd_many, tb[:, [k]], ta)
        for j in range(3):
            run(sscc.edge_edge_ccd_many, ta[:, [k, (k + 1) % 3]], tb[:, [j, (j + 1) % 3]])
    hit = np.isfinite(toi)
    return np.stack([a[hit], b[hit]], axis=1), toi[hit]


def crushed_sphere_steps(mesh, count, seed):
    """Steps that squash the sphere flat, or through itself, with per-vertex noise: no basis
    holds them."""
    rng = np.random.default_rng(seed)
    x = np.asarray(mesh.vertices)
    steps = []
    for k in range(count):
        x0 = x + 0.01 * rng.standard_normal(x.shape)
        flatten = (-0.4, 0.05, -0.1, 0.6)[k % 4]  # below 0 the caps pass through each other
        x1 = x * np.array([1.0, 1.0, flatten]) + 0.05 * rng.standard_normal(x.shape)
        steps.append((x0, x1))
    return steps


def test_position_ccd_equals_brute_force_and_query_positions(sphere, sphere_bvh):
    ccd = sscc.PositionCcd(sphere)
    assert ccd.mesh.triangle_count == sphere.triangle_count and len(ccd.excluded_pairs) == 0
    detector = sscc.SelfCcd(sphere_bvh)
    colliding = 0
    for x0, x1 in crushed_sphere_steps(sphere, 4, seed=3):
        report = ccd.query(x0, x1)
        pairs, toi = brute_force_self(sphere, x0, x1)
        np.testing.assert_array_equal(report.pairs, pairs)
        np.testing.assert_allclose(report.toi, toi, atol=2 * sscc.DEFAULT_TOI_TOLERANCE)
        # The subspace detector's positions query is the same traversal: the same report.
        same = detector.query_positions(x0, x1)
        np.testing.assert_array_equal(same.pairs, report.pairs)
        np.testing.assert_array_equal(same.toi, report.toi)
        for got, expected in zip(same.features, report.features):
            np.testing.assert_array_equal(got, expected)
        plain = ccd.query(x0, x1, use_normal_cones=False)
        np.testing.assert_array_equal(plain.pairs, report.pairs)
        if report.collided:
            colliding += 1
            assert report.earliest_toi == report.toi.min()
            earliest = ccd.query(x0, x1, mode="earliest")
            assert earliest.earliest_toi == report.earliest_toi
            assert ccd.query(x0, x1, mode="any").collided
    assert colliding >= 2


def test_position_ccd_with_excluded_pairs(sphere):
    ccd = sscc.PositionCcd(sphere)
    x0, x1 = crushed_sphere_steps(sphere, 3, seed=9)[0]
    full = ccd.query(x0, x1)
    assert len(full.pairs) > 4
    # Exclude every other colliding pair: exactly those disappear, the rest keep their toi.
    excluded = sscc.ExcludedPairs(sphere.triangle_count, full.pairs[::2])
    assert len(excluded) == len(full.pairs[::2])
    partial = sscc.PositionCcd(sphere, excluded)
    assert len(partial.excluded_pairs) == len(excluded)
    report = partial.query(x0, x1)
    keep = np.array([not excluded.contains(a, b) for a, b in full.pairs])
    np.testing.assert_array_equal(report.pairs, full.pairs[keep])
    np.testing.assert_array_equal(report.toi, full.toi[keep])
    pairs, toi = brute_force_self(sphere, x0, x1, excluded)
    np.testing.assert_array_equal(report.pairs, pairs)
    with pytest.raises(ValueError, match="triangle"):
        sscc.PositionCcd(sscc.TriangleMesh(*uv_sphere(4, 6)), excluded)


def test_position_ccd_geometry(sphere):
    ccd = sscc.PositionCcd(sphere)
    counts = np.zeros(2, dtype=int)
    for x0, x1 in crushed_sphere_steps(sphere, 3, seed=4):
        report = ccd.query(x0, x1)
        counts += check_geometry(report.features, report.geometry, lambda row: (sphere, sphere),
                                 lambda row, i, v: (x0[v], x1[v]))
    assert counts[0] > 10 and counts[1] > 10


def test_position_ccd_bad_input(sphere):
    ccd = sscc.PositionCcd(sphere)
    x = np.asarray(sphere.vertices)
    with pytest.raises(ValueError):
        ccd.query(x[:-1], x[:-1])
    bad = x.copy()
    bad[3, 1] = np.nan
    with pytest.raises(ValueError):
        ccd.query(x, bad)
    with pytest.raises(ValueError, match="mode"):
        ccd.query(x, x, mode="first")
