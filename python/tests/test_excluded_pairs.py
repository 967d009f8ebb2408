"""Exclusion sets from Python: ExcludedPairs, the pairs touching at rest against an exact
brute force, and a model excluding them through certificates and queries."""

import numpy as np
import pytest

import sscc
from conftest import MODES, random_q, uv_sphere


def two_spheres(offset=(1.8713, 0.0371, 0.0237)):
    """Two unit spheres that cut each other in a small circle: a mesh touching itself at rest."""
    v, t = uv_sphere(6, 9)
    return sscc.TriangleMesh(np.vstack([v, v + np.asarray(offset)]), np.vstack([t, t + len(v)]))


def touching_by_brute_force(mesh):
    x = np.asarray(mesh.vertices)
    triangles = np.asarray(mesh.triangles)
    pairs = []
    for a in range(len(triangles)):
        for b in range(a + 1, len(triangles)):
            if mesh.adjacent(a, b):
                continue
            if sscc.triangles_intersect(*x[triangles[a]], *x[triangles[b]]):
                pairs.append((a, b))
    return np.array(pairs, dtype=np.int32).reshape(-1, 2)


def test_excluded_pairs_construction():
    excluded = sscc.ExcludedPairs(10, [(3, 1), (1, 3), (2, 7), (0, 9)])
    np.testing.assert_array_equal(excluded.pairs, [[0, 9], [1, 3], [2, 7]])
    assert excluded.pairs.dtype == np.int32 and not excluded.pairs.flags.writeable
    assert len(excluded) == 3 and excluded.triangle_count == 10
    assert excluded.contains(3, 1) and excluded.contains(1, 3) and not excluded.contains(1, 2)
    empty = sscc.ExcludedPairs(5, np.zeros((0, 2), dtype=int))
    assert len(empty) == 0 and empty.pairs.shape == (0, 2)
    with pytest.raises(ValueError):
        sscc.ExcludedPairs(10, [(4, 4)])
    with pytest.raises(ValueError, match="out of range"):
        sscc.ExcludedPairs(10, [(4, 10)])
    with pytest.raises(ValueError, match="integers"):
        sscc.ExcludedPairs(10, [(0.5, 2.0)])
    with pytest.raises(IndexError):
        excluded.contains(10, 0)


def test_touching_at_rest_equals_brute_force():
    mesh = two_spheres()
    excluded = sscc.ExcludedPairs.touching_at_rest(mesh)
    expected = touching_by_brute_force(mesh)
    assert len(expected) > 0
    np.testing.assert_array_equal(excluded.pairs, expected)
    apart = sscc.TriangleMesh(*uv_sphere(6, 9))
    assert len(sscc.ExcludedPairs.touching_at_rest(apart)) == 0


def test_model_excluding_rest_contacts():
    mesh = two_spheres()
    model = sscc.SubspaceModel(mesh, sscc.polynomial_basis(mesh, MODES), np.ones(MODES))
    assert len(model.excluded_pairs) == 0
    excluding = model.excluding_rest_contacts()
    explicit = model.excluding(sscc.ExcludedPairs.touching_at_rest(mesh))
    np.testing.assert_array_equal(excluding.excluded_pairs.pairs, explicit.excluded_pairs.pairs)
    a, b = excluding.excluded_pairs.pairs[0]
    assert model.considers(a, b) and not excluding.considers(a, b)
    assert not excluding.considers(0, 1)  # adjacent
    with pytest.raises(IndexError):
        excluding.considers(0, mesh.triangle_count)
    # The shared basis: no copy.
    np.testing.assert_array_equal(excluding.scaled_basis, model.scaled_basis)
    # Certificates: 0 where the resting pairs are; positive once they are excluded. A file
    # computed with the set is refused by the model without it.
    plain_bvh, bvh = sscc.SubspaceBvh(model), sscc.SubspaceBvh(excluding)
    assert sscc.Certificates.precompute(plain_bvh).root_radius == 0
    certificates = sscc.Certificates.precompute(bvh)
    assert certificates.root_radius > 0
    with pytest.raises(ValueError):
        sscc.SelfCcd(plain_bvh, certificates)
    detector = sscc.SelfCcd(bvh, certificates)
    rng = np.random.default_rng(6)
    colliding = 0
    for amplitude in (0.1, 0.5, 1.0):
        q0 = random_q(rng, amplitude)
        q1 = q0 + random_q(rng, amplitude)
        report = detector.query(q0, q1)
        reference = detector.query_exhaustive(q0, q1)
        np.testing.assert_array_equal(report.pairs, reference.pairs)
        np.testing.assert_array_equal(report.toi, reference.toi)
        assert not any(excluding.excluded_pairs.contains(a, b) for a, b in report.pairs)
        colliding += report.collided
    assert colliding >= 1
    with pytest.raises(ValueError):
        model.excluding(sscc.ExcludedPairs(3, [(0, 2)]))
