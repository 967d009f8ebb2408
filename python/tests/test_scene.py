"""Scenes from Python: frames as 4x4 matrices or (R, t) pairs, and contacts between
objects against a brute force over every triangle pair through the vectorised kernels."""


import numpy as np
import pytest

import sscc
from conftest import MODES, random_q


def rotation(axis, angle):
    axis = np.asarray(axis, dtype=float) / np.linalg.norm(axis)
    k = np.array([[0, -axis[2], axis[1]], [axis[2], 0, -axis[0]], [-axis[1], axis[0], 0]])
    return np.eye(3) + np.sin(angle) * k + (1 - np.cos(angle)) * k @ k


def homogeneous(R, t):
    matrix = np.eye(4)
    matrix[:3, :3], matrix[:3, 3] = R, t
    return matrix


def world(model, q, frame):
    R, t = frame
    return model.deformed_positions(q) @ R.T + t


def brute_force_pairs(model, x0, x1):
    """Every triangle pair of two objects (positions x0[k] -> x1[k] of object k), all 15
    features through the vectorised kernels; the colliding pairs with their first toi."""
    triangles = np.asarray(model.mesh.triangles)
    m = len(triangles)
    a, b = np.meshgrid(np.arange(m), np.arange(m), indexing="ij")
    a, b = a.ravel(), b.ravel()
    toi = np.full(len(a), np.inf)
    ta, tb = triangles[a], triangles[b]

    def run(kernel, rows_a, rows_b, first, second):
        # rows_* pick corner columns of each triangle: object `first` supplies rows_a.
        start = np.concatenate([x0[first][rows_a], x0[second][rows_b]], axis=1)
        end = np.concatenate([x1[first][rows_a], x1[second][rows_b]], axis=1)
        hit, t = kernel(start, end)
        np.minimum.at(toi, np.nonzero(hit)[0], t[hit])

    for k in range(3):
        run(sscc.vertex_face_ccd_many, ta[:, [k]], tb, 0, 1)
        run(sscc.vertex_face_ccd_many, tb[:, [k]], ta, 1, 0)
        for j in range(3):
            run(sscc.edge_edge_ccd_many, ta[:, [k, (k + 1) % 3]], tb[:, [j, (j + 1) % 3]], 0, 1)
    hit = np.isfinite(toi)
    return np.stack([a[hit], b[hit]], axis=1), toi[hit]


@pytest.fixture(scope="module")
def detector(sphere_bvh, sphere_certificates):
    return sscc.SelfCcd(sphere_bvh, sphere_certificates)


def test_inter_object_contacts_equal_brute_force(detector):
    model = detector.bvh.model
    rng = np.random.default_rng(17)
    colliding = 0
    for trial in range(6):
        scene = sscc.Scene()
        scene.add_object(detector)
        scene.add_object(detector)
        q0 = [random_q(rng, 0.2) for _ in range(2)]
        q1 = [q + random_q(rng, 0.2) for q in q0]
        # Two unit spheres 2.6 apart closing by 0.4 to 1.0 while turning.
        gap = 2.6 - 0.4 - 0.12 * trial
        frames0 = [(rotation((0, 0, 1), 0.0), np.zeros(3)), (rotation((1, 1, 0), 0.3), np.array([2.6, 0, 0]))]
        frames1 = [(rotation((0, 0, 1), 0.2), np.array([0.2, 0, 0])),
                   (rotation((1, 1, 0), 0.5), np.array([0.2 + gap, 0.05, 0]))]
        report = scene.step(q0, q1, frames0, frames1)
        as_matrices = scene.step(np.array(q0), np.array(q1), [homogeneous(*f) for f in frames0],
                                 [homogeneous(*f) for f in frames1])
        np.testing.assert_array_equal(as_matrices.pairs, report.pairs)
        x0 = [world(model, q, f) for q, f in zip(q0, frames0)]
        x1 = [world(model, q, f) for q, f in zip(q1, frames1)]
        pairs, toi = brute_force_pairs(model, x0, x1)
        assert report.pairs.shape[1] == 4
        assert np.all(report.pairs[:, 0] == 0) and np.all(report.pairs[:, 2] == 1)
        np.testing.assert_array_equal(report.pairs[:, [1, 3]], pairs)
        np.testing.assert_allclose(report.toi, toi, atol=2 * sscc.DEFAULT_TOI_TOLERANCE)
        if len(pairs):
            colliding += 1
            assert report.collided and report.earliest_toi == report.toi.min()
            kind, indices, feature_toi = report.features
            assert indices.shape[1] == 4 and len(kind) == len(feature_toi) > 0
        for obj in report.objects:
            assert obj.outcome in ("certified", "traversed")
    assert 2 <= colliding < 6


def test_static_switched_off_and_counts(detector):
    scene = sscc.Scene()
    assert scene.add_object(detector) == 0
    assert scene.add_object(detector, self_collision=False) == 1
    assert scene.object_count == 2
    q = np.zeros(MODES)
    far = (np.eye(3), (10.0, 0, 0))
    report = scene.step([q, q], [q, q], [None, far], [None, far])
    assert [o.outcome for o in report.objects] == ["static", "switched_off"]
    assert not report.collided and report.pairs.shape == (0, 4)
    assert report.stats["objects_static"] == 1 and report.stats["object_pairs_culled"] == 1
    moving = scene.step([q, q], [0.01 * np.ones(MODES), q], [None, far], [None, far])
    assert [o.outcome for o in moving.objects] == ["certified", "switched_off"]
    assert moving.objects[0].report.pairs.shape == (0, 2)


def test_scene_bad_input(detector):
    scene = sscc.Scene()
    scene.add_object(detector)
    q = np.zeros(MODES)
    with pytest.raises(ValueError, match="q1: 2 entries for 1 objects"):
        scene.step([q], [q, q])
    with pytest.raises(ValueError, match=r"frames1\[0\]: expected a 4x4 matrix or a pair \(R, t\)"):
        scene.step([q], [q], None, [np.eye(3)])
    with pytest.raises(ValueError, match=r"frames0\[0\]: the last row of a 4x4 frame must be \(0, 0, 0, 1\)"):
        scene.step([q], [q], [np.ones((4, 4))])
    sheared = np.eye(3)
    sheared[0, 1] = 0.5
    with pytest.raises(ValueError, match="rigid|rotation|orthonormal"):
        scene.step([q], [q], [(sheared, np.zeros(3))])


def test_scene_self_motion_half_turn(detector):
    """A half-turn with q fixed: refused for the object-frame self test, certified when told
    the object turns rigidly, and the world-linear paths collapse the mesh onto the axis."""
    q = np.zeros(MODES)
    half_turn = (np.diag([-1.0, -1.0, 1.0]), np.zeros(3))
    still = (np.eye(3), np.zeros(3))
    object_frame = sscc.Scene()
    object_frame.add_object(detector)
    with pytest.raises(ValueError, match="max_object_frame_rotation"):
        object_frame.step([q], [q], [still], [half_turn])
    rigid = object_frame.step([q], [q], [still], [half_turn], max_object_frame_rotation=np.inf)
    assert not rigid.collided
    world = sscc.Scene()
    world.add_object(detector, self_motion="world_linear")
    collapsed = world.step([q], [q], [still], [half_turn])
    assert collapsed.collided
    assert collapsed.earliest_toi <= 0.5
    with pytest.raises(ValueError, match="self_motion"):
        world.add_object(detector, self_motion="rigid")
