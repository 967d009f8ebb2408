"""Self-CCD from Python: certified steps, the traversal against the exhaustive reference,
modes, the other queries and the report's arrays."""

import numpy as np
import pytest

import sscc
from conftest import MODES, random_q


def test_small_step_is_certified_by_the_root(sphere_bvh, sphere_certificates):
    detector = sscc.SelfCcd(sphere_bvh, sphere_certificates)
    radius = sphere_certificates.root_radius
    assert 0 < radius <= sphere_certificates.global_radius
    direction = np.random.default_rng(2).standard_normal(MODES)
    q1 = 0.9 * radius * direction / np.linalg.norm(direction)  # weights are ones: ||q||_M = ||q||
    report = detector.query(np.zeros(MODES), q1)
    assert report.stats["root_certified"]
    assert report.stats["kernel_calls"] == 0
    assert not report.collided and report.pairs.shape == (0, 2)
    # The same step without certificates does the work and finds the same nothing.
    traditional = detector.query(np.zeros(MODES), q1, use_certificates=False, use_normal_cones=False,
                                 use_displacement_bounds=False)
    assert not traditional.stats["root_certified"] and traditional.stats["kernel_calls"] > 0
    assert not traditional.collided


def test_normal_cones_on_and_off(sphere_bvh):
    # The cones (on by default) cull patches of the sphere; switched off they cull nothing.
    # Both report what the exhaustive reference does, on q and on explicit positions.
    detector = sscc.SelfCcd(sphere_bvh)
    detector.prepare()  # the cones' radii built before the queries
    model = sphere_bvh.model
    rng = np.random.default_rng(8)
    culled = 0
    for amplitude in (0.01, 0.4, 1.2):
        q0 = random_q(rng, amplitude)
        q1 = q0 + random_q(rng, amplitude)
        reference = detector.query_exhaustive(q0, q1)
        x0, x1 = model.deformed_positions(q0), model.deformed_positions(q1)
        cones = detector.query(q0, q1, use_certificates=False, use_displacement_bounds=False)
        plain = detector.query(q0, q1, use_certificates=False, use_normal_cones=False,
                               use_displacement_bounds=False)
        positions = detector.query_positions(x0, x1)
        plain_positions = detector.query_positions(x0, x1, use_normal_cones=False)
        for report in (cones, plain, positions, plain_positions):
            np.testing.assert_array_equal(report.pairs, reference.pairs)
            np.testing.assert_array_equal(report.toi, reference.toi)
        assert plain.stats["cone_culled"] == 0 and plain_positions.stats["cone_culled"] == 0
        assert plain.stats["plane_culled"] == 0 and plain_positions.stats["plane_culled"] == 0
        culled += cones.stats["cone_culled"] + positions.stats["cone_culled"]
    assert culled > 0


def test_displacement_bounds_without_certificates(sphere_bvh):
    # Without certificates the query culls by the step's displacements; switched off, it is
    # the traditional query. Both report what the exhaustive reference does.
    detector = sscc.SelfCcd(sphere_bvh)
    rng = np.random.default_rng(5)
    culled = 0
    for amplitude in (0.01, 0.05, 0.4, 1.2):
        q0 = random_q(rng, amplitude)
        q1 = q0 + random_q(rng, amplitude)
        reference = detector.query_exhaustive(q0, q1)
        bounded = detector.query(q0, q1, use_certificates=False)
        plain = detector.query(q0, q1, use_certificates=False, use_normal_cones=False,
                               use_displacement_bounds=False)
        for report in (bounded, plain):
            np.testing.assert_array_equal(report.pairs, reference.pairs)
            np.testing.assert_array_equal(report.toi, reference.toi)
        assert plain.stats["displacement_culled"] == 0
        culled += bounded.stats["displacement_culled"]
    assert culled > 0


def test_query_equals_exhaustive(sphere_bvh, sphere_certificates):
    detector = sscc.SelfCcd(sphere_bvh, sphere_certificates)
    rng = np.random.default_rng(21)
    colliding = quiet = 0
    for amplitude in (0.02, 0.15, 0.4, 0.8, 1.2):
        for _ in range(6):
            q0 = random_q(rng, amplitude)
            q1 = q0 + random_q(rng, amplitude)
            fast = detector.query(q0, q1)
            reference = detector.query_exhaustive(q0, q1)
            np.testing.assert_array_equal(fast.pairs, reference.pairs)
            np.testing.assert_array_equal(fast.toi, reference.toi)
            for got, expected in zip(fast.features, reference.features):
                np.testing.assert_array_equal(got, expected)
            assert fast.earliest_toi == reference.earliest_toi
            positions = detector.query_positions(sphere_bvh.model.deformed_positions(q0),
                                                 sphere_bvh.model.deformed_positions(q1))
            np.testing.assert_array_equal(positions.pairs, reference.pairs)
            if fast.collided:
                colliding += 1
                assert fast.earliest_toi == fast.toi.min()
                assert fast.stats["kernel_calls"] > 0
            else:
                quiet += 1
    assert colliding >= 3 and quiet >= 3


def colliding_step(detector):
    rng = np.random.default_rng(4)
    while True:
        q0 = random_q(rng, 0.8)
        q1 = q0 + random_q(rng, 0.8)
        report = detector.query(q0, q1)
        if report.collided and len(report.pairs) > 2:
            return q0, q1, report


def test_report_arrays(sphere, sphere_bvh):
    detector = sscc.SelfCcd(sphere_bvh)
    _, _, report = colliding_step(detector)
    pairs, toi = report.pairs, report.toi
    assert pairs.dtype == np.int32 and pairs.ndim == 2 and pairs.shape[1] == 2
    assert toi.dtype == np.float64 and toi.shape == (len(pairs),)
    assert np.all(pairs[:, 0] < pairs[:, 1])
    assert all(not sphere.adjacent(int(a), int(b)) for a, b in pairs)
    assert np.all((toi >= 0) & (toi <= 1))
    kind, indices, feature_toi = report.features
    assert len(report.features) == len(kind) == len(indices) == len(feature_toi) > 0
    assert set(kind.tolist()) <= {sscc.VERTEX_FACE, sscc.EDGE_EDGE}
    assert feature_toi.min() == report.earliest_toi
    # Vertex-face rows are (vertex, triangle); edge-edge rows index mesh.edges.
    vertex_face = indices[kind == sscc.VERTEX_FACE]
    assert np.all(vertex_face[:, 0] < sphere.vertex_count) and np.all(vertex_face[:, 1] < sphere.triangle_count)
    assert np.all(indices[kind == sscc.EDGE_EDGE] < len(sphere.edges))
    # Views into the report: no copy per access, read-only.
    assert np.shares_memory(report.pairs, report.pairs)
    assert report.pairs.base is report and report.toi.base is report and report.features.kind.base is report
    with pytest.raises(ValueError):
        pairs[0, 0] = 1
    assert set(report.stats) >= {"nodes_visited", "box_tests", "triangle_pairs", "kernel_calls",
                                 "vertices_computed", "certified", "root_certified", "seconds"}


def test_modes(sphere_bvh):
    detector = sscc.SelfCcd(sphere_bvh)
    q0, q1, everything = colliding_step(detector)
    earliest = detector.query(q0, q1, mode="earliest")
    assert earliest.earliest_toi == everything.earliest_toi
    assert np.all(earliest.features.toi == earliest.earliest_toi)
    anyhit = detector.query(q0, q1, mode="any")
    assert anyhit.collided and len(anyhit.features) == 1
    everything_set = {tuple(p) for p in everything.pairs.tolist()}
    assert {tuple(p) for p in anyhit.pairs.tolist()} <= everything_set
    for bounds in ("refit", "subspace"):
        np.testing.assert_array_equal(detector.query(q0, q1, bounds=bounds).pairs, everything.pairs)


def test_discrete_query_finds_interpenetration(sphere):
    # Linear modes map the sphere to ellipsoids, which never cross themselves; large
    # quadratic ones fold it through itself.
    modes = 27
    detector = sscc.SelfCcd(sscc.SubspaceBvh(sscc.SubspaceModel(sphere, sscc.polynomial_basis(sphere, modes),
                                                                np.ones(modes))))
    assert not detector.query_discrete(np.zeros(modes)).collided
    rng = np.random.default_rng(9)
    found = 0
    for _ in range(20):
        report = detector.query_discrete(random_q(rng, 3.0, modes))
        if report.collided:
            found += 1
            assert np.all(report.toi == 0.0) and len(report.features) == 0
    assert found > 0


def test_minimum_separation_needs_the_traditional_query(sphere_bvh, sphere_certificates):
    detector = sscc.SelfCcd(sphere_bvh, sphere_certificates)
    with pytest.raises(ValueError, match="certificates bound contact, not a minimum separation"):
        detector.query(np.zeros(MODES), np.zeros(MODES), minimum_separation=0.01)
    thick = detector.query(np.zeros(MODES), np.zeros(MODES), use_certificates=False, minimum_separation=0.3)
    assert thick.collided  # the sphere's non-adjacent triangles lie closer than 0.3


def test_results_are_handed_over_without_copies(sphere, sphere_model):
    """Arrays the library made for the caller are adopted by NumPy (their base is the capsule
    that frees the C++ storage), and arrays the library keeps are views of their owner."""
    U = sscc.polynomial_basis(sphere, MODES)
    positions = sphere_model.deformed_positions(np.zeros(MODES))
    for adopted in (U, positions):
        assert not adopted.flags.owndata and type(adopted.base).__name__ == "PyCapsule"
    assert sphere.vertices.base is sphere and sphere.triangles.base is sphere
    assert sphere_model.scaled_basis.base is sphere_model and sphere_model.weights.base is sphere_model
    np.testing.assert_array_equal(positions, sphere.vertices)
