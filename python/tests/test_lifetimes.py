"""Objects outlive whatever owned them, and nothing is held twice: a detector shares the
hierarchy and certificates it was built with (C++ shared ownership, no copy), a hierarchy
shares its model's data, a scene shares its detectors'. Python references can be dropped
in any order; what the library holds lives as long as something refers to it."""

import gc
import weakref

import numpy as np

import sscc
from conftest import MODES, random_q, uv_sphere


def build_detector():
    """A detector whose mesh, model, hierarchy and certificates exist only inside it."""
    vertices, triangles = uv_sphere(8, 12)
    mesh = sscc.TriangleMesh(vertices, triangles)
    model = sscc.SubspaceModel(mesh, sscc.polynomial_basis(mesh, MODES), np.ones(MODES))
    bvh = sscc.SubspaceBvh(model)
    certificates = sscc.Certificates.precompute(bvh)
    detector = sscc.SelfCcd(bvh, certificates)
    return detector, [weakref.ref(model), weakref.ref(bvh), weakref.ref(certificates)]


def steps():
    rng = np.random.default_rng(13)
    result = []
    for _ in range(8):
        q0 = random_q(rng, 1.2)
        result.append((q0, q0 + random_q(rng, 1.2)))
    return result


def test_detector_shares_its_hierarchy_and_certificates():
    """The detector holds the very hierarchy and certificates it was given, not copies: the
    objects it returns are the Python objects passed in, and two detectors share them."""
    vertices, triangles = uv_sphere(8, 12)
    mesh = sscc.TriangleMesh(vertices, triangles)
    bvh = sscc.SubspaceBvh(sscc.SubspaceModel(mesh, sscc.polynomial_basis(mesh, MODES), np.ones(MODES)))
    certificates = sscc.Certificates.precompute(bvh)
    detector = sscc.SelfCcd(bvh, certificates)
    assert detector.bvh is bvh and detector.certificates is certificates
    other = sscc.SelfCcd(bvh)
    assert other.bvh is bvh and other.certificates is None
    scene = sscc.Scene()
    scene.add_object(detector)
    scene.add_object(other)
    assert scene.detector(0).bvh is bvh and scene.detector(1).bvh is bvh
    assert scene.detector(0).certificates is certificates


def test_detector_outlives_mesh_model_hierarchy_and_certificates():
    detector, owned = build_detector()
    gc.collect()
    # The Python objects go with their last Python reference; their C++ parts live on in the
    # detector, which shares them.
    assert all(ref() is None for ref in owned)
    reports = [detector.query(q0, q1) for q0, q1 in steps()]
    assert any(r.collided for r in reports)
    # The detector's view of its parts still works.
    assert detector.bvh.model.mesh.triangle_count == 168
    assert detector.certificates.root_radius > 0
    # Rebuilt from scratch, the answers are the same: nothing read freed memory.
    again, _ = build_detector()
    for (q0, q1), report in zip(steps(), reports):
        np.testing.assert_array_equal(again.query(q0, q1).pairs, report.pairs)


def test_parts_reached_through_others_outlive_them():
    detector, _ = build_detector()
    bvh = detector.bvh
    model = bvh.model
    mesh = model.mesh
    vertices = mesh.vertices
    weights = model.weights
    del detector, bvh, model
    gc.collect()
    assert mesh.vertex_count == len(vertices) == 86
    np.testing.assert_allclose(np.linalg.norm(vertices, axis=1), 1.0)
    np.testing.assert_array_equal(weights, np.ones(MODES))


def test_arrays_outlive_their_reports_and_meshes():
    detector, _ = build_detector()
    q0, q1 = next((a, b) for a, b in steps() if detector.query(a, b).collided)
    report = detector.query(q0, q1)
    pairs, toi, features = report.pairs.copy(), report.toi.copy(), [f.copy() for f in report.features]
    views = report.pairs, report.toi, report.features
    del report
    gc.collect()
    np.testing.assert_array_equal(views[0], pairs)
    np.testing.assert_array_equal(views[1], toi)
    for got, expected in zip(views[2], features):
        np.testing.assert_array_equal(got, expected)
    mesh = sscc.TriangleMesh(*uv_sphere(4, 6))
    triangles, expected = mesh.triangles, mesh.triangles.copy()
    del mesh
    gc.collect()
    np.testing.assert_array_equal(triangles, expected)


def test_scene_outlives_its_detectors():
    scene = sscc.Scene()
    detector, owned = build_detector()
    ref = weakref.ref(detector)
    scene.add_object(detector)
    scene.add_object(detector)
    del detector
    gc.collect()
    assert ref() is None  # the scene holds copies of the detector, which share its parts
    q = np.zeros(MODES)
    report = scene.step([q, q], [q, q], [None, None], [None, (np.eye(3), (0.1, 0, 0))])
    assert [o.outcome for o in report.objects] == ["static", "certified"]
    assert report.collided  # two coincident spheres, one moving: their triangles meet
    objects = report.objects
    del scene, report
    gc.collect()
    assert objects[1].outcome == "certified"
    assert len(objects[0].report.geometry) == 0
