"""Independent checks of a report's contact geometry against the positions of the step, in
NumPy: the features' vertices from the mesh, the two contact points meeting at the time of
impact, barycentric weights in range, unit normals along the triangle's (or the edges')."""

import numpy as np

import sscc


def feature_vertices(first_mesh, second_mesh, kind, first, second):
    if kind == sscc.VERTEX_FACE:
        return [first, *second_mesh.triangles[second]]
    return [*first_mesh.edges[first], *second_mesh.edges[second]]


def check_geometry(features, geometry, meshes, positions):
    """features: a report's Features; meshes(row) -> (first mesh, second mesh); positions(row,
    i, vertex) -> (x at t = 0, x at t = 1) of the feature's i-th vertex. Returns the numbers
    of vertex-face and edge-edge rows checked."""
    kind, indices, toi = features
    assert len(geometry) == len(kind)
    vertices, weights = geometry.vertices, geometry.barycentric
    points, normals = geometry.points, geometry.normals
    assert vertices.shape == (len(kind), 4) and weights.shape == (len(kind), 4)
    assert points.shape == (len(kind), 3) and normals.shape == (len(kind), 3)
    counts = [0, 0]
    for row in range(len(kind)):
        first_mesh, second_mesh = meshes(row)
        first, second = (indices[row][0], indices[row][1]) if len(indices[row]) == 2 else (indices[row][1], indices[row][3])
        expected = feature_vertices(first_mesh, second_mesh, kind[row], first, second)
        np.testing.assert_array_equal(vertices[row], expected)
        ends = [positions(row, i, v) for i, v in enumerate(expected)]
        start = np.array([e[0] for e in ends])
        end = np.array([e[1] for e in ends])
        t = toi[row]
        at = (1 - t) * start + t * end
        w = weights[row]
        motion = np.linalg.norm(end - start, axis=1).max()
        # The two contact points meet at toi (toi is at most the tolerance early).
        assert np.linalg.norm(w @ at) <= 4 * motion * sscc.DEFAULT_TOI_TOLERANCE + 1e-12
        assert abs(np.linalg.norm(normals[row]) - 1) < 1e-12
        # The first side starts on the positive side of the normal.
        assert normals[row] @ (w @ start) >= -1e-12
        side = 1 if kind[row] == sscc.VERTEX_FACE else 2
        np.testing.assert_allclose(points[row], w[:side] @ at[:side], atol=1e-12)
        if kind[row] == sscc.VERTEX_FACE:
            assert w[0] == 1.0 and np.all(w[1:] <= 0) and np.all(w[1:] >= -1)
            assert abs(w[1:].sum() + 1) < 1e-12
            n = np.cross(at[2] - at[1], at[3] - at[1])
        else:
            assert np.all(np.abs(w) <= 1)
            assert abs(w[:2].sum() - 1) < 1e-12 and abs(w[2:].sum() + 1) < 1e-12
            n = np.cross(at[1] - at[0], at[3] - at[2])
        assert abs(abs(n @ normals[row]) / np.linalg.norm(n) - 1) < 1e-9
        counts[int(kind[row])] += 1
    return counts


def rotation(axis, angle):
    axis = np.asarray(axis, dtype=float) / np.linalg.norm(axis)
    k = np.array([[0, -axis[2], axis[1]], [axis[2], 0, -axis[0]], [-axis[1], axis[0], 0]])
    return np.eye(3) + np.sin(angle) * k + (1 - np.cos(angle)) * k @ k
