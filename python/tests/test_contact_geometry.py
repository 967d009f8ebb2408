"""Contact geometry from Python: every report's feature contacts come with their vertices,
barycentric weights, contact points and normals, checked in NumPy against the positions of
the step (SelfCcd, and Scene in each object's frame and between objects in the world)."""

import numpy as np
import pytest

import sscc
from conftest import MODES, random_q
from geometry_checks import check_geometry, rotation


@pytest.fixture(scope="module")
def detector(sphere_bvh):
    return sscc.SelfCcd(sphere_bvh)


def test_self_ccd_geometry(detector):
    model = detector.bvh.model
    mesh = model.mesh
    rng = np.random.default_rng(23)
    counts = np.zeros(2, dtype=int)
    for amplitude in (0.8, 1.2, 1.6):
        q0 = random_q(rng, amplitude)
        q1 = q0 + random_q(rng, amplitude)
        x0, x1 = model.deformed_positions(q0), model.deformed_positions(q1)
        report = detector.query(q0, q1)
        counts += check_geometry(report.features, report.geometry, lambda row: (mesh, mesh),
                                 lambda row, i, v: (x0[v], x1[v]))
        # The exhaustive reference and the positions query carry the same geometry.
        for other in (detector.query_exhaustive(q0, q1), detector.query_positions(x0, x1)):
            np.testing.assert_array_equal(other.geometry.vertices, report.geometry.vertices)
            np.testing.assert_allclose(other.geometry.normals, report.geometry.normals, atol=1e-12)
    assert counts[0] > 10 and counts[1] > 10
    quiet = detector.query(np.zeros(MODES), np.zeros(MODES))
    assert len(quiet.geometry) == 0 and quiet.geometry.normals.shape == (0, 3)
    assert not quiet.geometry.points.flags.writeable


def test_geometry_outlives_its_report(detector):
    rng = np.random.default_rng(23)
    q0 = random_q(rng, 1.2)
    report = detector.query(q0, q0 + random_q(rng, 1.2))
    geometry = report.geometry
    normals = geometry.normals.copy()
    del report
    np.testing.assert_array_equal(geometry.normals, normals)


def test_scene_geometry(detector):
    model = detector.bvh.model
    mesh = model.mesh
    rng = np.random.default_rng(29)
    scene = sscc.Scene()
    scene.add_object(detector)
    scene.add_object(detector)
    world_linear = sscc.Scene()
    world_linear.add_object(detector, self_motion="world_linear")
    world_linear.add_object(detector, self_motion="world_linear")
    self_counts, inter_counts = np.zeros(2, dtype=int), np.zeros(2, dtype=int)
    for trial in range(4):
        q0 = [random_q(rng, 1.0) for _ in range(2)]
        q1 = [q + random_q(rng, 1.0) for q in q0]
        frames0 = [(np.eye(3), np.zeros(3)), (rotation((1, 1, 0), 0.3), np.array([2.6, 0, 0]))]
        frames1 = [(rotation((0, 0, 1), 0.2), np.array([0.2, 0, 0])),
                   (rotation((1, 1, 0), 0.4), np.array([1.9 - 0.1 * trial, 0.05, 0]))]
        local = [(model.deformed_positions(a), model.deformed_positions(b)) for a, b in zip(q0, q1)]
        world = [(x0 @ f0[0].T + f0[1], x1 @ f1[0].T + f1[1]) for (x0, x1), f0, f1 in zip(local, frames0, frames1)]
        for current, frame in ((scene, local), (world_linear, world)):
            report = current.step(q0, q1, frames0, frames1)
            for o, result in enumerate(report.objects):
                self_counts += check_geometry(result.report.features, result.report.geometry,
                                              lambda row: (mesh, mesh),
                                              lambda row, i, v, o=o: (frame[o][0][v], frame[o][1][v]))
        report = scene.step(q0, q1, frames0, frames1)
        kind, indices, toi = report.features

        def ends(row, i, v):
            side = 1 if kind[row] == sscc.VERTEX_FACE else 2
            o = indices[row][0] if i < side else indices[row][2]
            return world[o][0][v], world[o][1][v]

        inter_counts += check_geometry(report.features, report.geometry, lambda row: (mesh, mesh), ends)
    assert self_counts.sum() > 10
    assert inter_counts[0] > 5 and inter_counts[1] > 5
