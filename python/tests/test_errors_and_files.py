"""Bad input raises ValueError and unreadable files OSError, with the library's message;
files written from Python read back the same."""

import numpy as np
import pytest

import sscc
from conftest import MODES, uv_sphere

TRIANGLE = np.array([[0.0, 0, 0], [1, 0, 0], [0, 1, 0]])


def test_mesh_input():
    with pytest.raises(ValueError, match=r"TriangleMesh: triangle 0 has vertex index 5 outside \[0, 3\)"):
        sscc.TriangleMesh(TRIANGLE, [[0, 1, 5]])
    with pytest.raises(ValueError, match="TriangleMesh: triangle 1 repeats a vertex"):
        sscc.TriangleMesh(TRIANGLE, [[0, 1, 2], [0, 0, 2]])
    with pytest.raises(ValueError, match="TriangleMesh: vertex 2 has a non-finite coordinate"):
        sscc.TriangleMesh(np.array([[0.0, 0, 0], [1, 0, 0], [0, np.nan, 0]]), [[0, 1, 2]])
    with pytest.raises(ValueError, match="triangles: expected an array of integers"):
        sscc.TriangleMesh(TRIANGLE, [[0.0, 1.0, 2.0]])
    with pytest.raises(ValueError, match=r"vertices: expected an \(n, 3\) array, got shape \(3, 2\)"):
        sscc.TriangleMesh(TRIANGLE[:, :2], [[0, 1, 2]])
    with pytest.raises(ValueError, match="does not fit a 32-bit int"):
        sscc.TriangleMesh(TRIANGLE, np.array([[0, 1, 2**40]]))
    mesh = sscc.TriangleMesh(TRIANGLE, np.array([[0, 1, 2]], dtype=np.uint16))
    assert mesh.triangles.dtype == np.int32 and mesh.triangles.tolist() == [[0, 1, 2]]
    assert not mesh.vertices.flags.writeable


def test_model_and_query_input(sphere, sphere_bvh, sphere_certificates):
    basis = sscc.polynomial_basis(sphere, MODES)
    with pytest.raises(ValueError, match="SubspaceModel: the basis has 3 rows, but the mesh's 86 vertices need 258"):
        sscc.SubspaceModel(sphere, basis[:3], np.ones(MODES))
    with pytest.raises(ValueError, match="SubspaceModel: weight 2 is not a positive finite number"):
        sscc.SubspaceModel(sphere, basis, np.array([1, 1, -1, 1, 1, 1, 1, 1, 1.0]))
    with pytest.raises(ValueError, match="SubspaceModel: 2 weights for 9 modes"):
        sscc.SubspaceModel(sphere, basis, np.ones(2))
    with pytest.raises(ValueError, match="polynomial_basis: 28"):
        sscc.polynomial_basis(sphere, 28)
    detector = sscc.SelfCcd(sphere_bvh, sphere_certificates)
    with pytest.raises(ValueError, match="SubspaceModel: q has 3 coordinates, the model has 9 modes"):
        detector.query(np.zeros(3), np.zeros(3))
    q = np.zeros(MODES)
    bad = q.copy()
    bad[4] = np.inf
    with pytest.raises(ValueError, match=r"SubspaceModel: q\[4\] is not finite"):
        detector.query(q, bad)
    with pytest.raises(ValueError, match=r"q0: expected a 1-D array, got shape \(3, 3\)"):
        detector.query(np.zeros((3, 3)), q)
    with pytest.raises(ValueError, match="mode: expected 'all', 'earliest' or 'any', got 'first'"):
        detector.query(q, q, mode="first")
    with pytest.raises(ValueError, match="bounds: expected 'hybrid', 'refit' or 'subspace'"):
        detector.query(q, q, bounds="tight")
    with pytest.raises(ValueError, match="SelfCcd::query_positions"):
        detector.query_positions(np.zeros((3, 3)), np.zeros((3, 3)))
    other = sscc.SubspaceBvh(sphere_bvh.model, seed=2)
    with pytest.raises(ValueError, match="computed for another mesh, basis, weights or hierarchy"):
        sscc.SelfCcd(other, sphere_certificates)
    with pytest.raises(ValueError, match=r"certificates: epsilon must lie in \(0, 1\)"):
        sscc.Certificates.precompute(sphere_bvh, epsilon=2.0)


def test_mesh_files(tmp_path):
    with pytest.raises(OSError, match="cannot open the file"):
        sscc.read_mesh(str(tmp_path / "missing.off"))
    bad = tmp_path / "bad.off"
    bad.write_text("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n")
    with pytest.raises(OSError, match="bad.off.*vertex index 7"):
        sscc.read_mesh(str(bad))
    good = tmp_path / "quad.off"
    good.write_text("OFF\n4 1 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n")
    mesh = sscc.read_mesh(str(good))
    assert mesh.triangle_count == 2 and mesh.vertices.shape == (4, 3)


def test_basis_files(tmp_path, sphere):
    basis = sscc.polynomial_basis(sphere, MODES)
    path = str(tmp_path / "sphere.U")
    sscc.write_basis(path, basis)
    np.testing.assert_array_equal(sscc.read_basis(path), basis)
    sscc.write_basis(path, np.ascontiguousarray(basis))  # either memory order
    np.testing.assert_array_equal(sscc.read_basis(path), basis)
    with pytest.raises(ValueError, match="the name must end in .U"):
        sscc.write_basis(str(tmp_path / "sphere.txt"), basis)
    with pytest.raises(OSError, match="missing.U"):
        sscc.read_basis(str(tmp_path / "missing.U"))
    with pytest.raises(OSError):
        sscc.write_basis(str(tmp_path / "no" / "such" / "dir.U"), basis)


def test_certificate_files(tmp_path, sphere_bvh, sphere_certificates):
    path = str(tmp_path / "sphere.sscc")
    sphere_certificates.write(path)
    read = sscc.Certificates.read(path, sphere_bvh)
    assert read.root_radius == sphere_certificates.root_radius
    assert read.key == sphere_certificates.key
    assert [read.node_radius(n) for n in range(read.node_count)] == \
        [sphere_certificates.node_radius(n) for n in range(read.node_count)]
    with pytest.raises(IndexError):
        read.node_radius(read.node_count)
    with pytest.raises(OSError, match="certificate file .*missing.sscc: cannot open"):
        sscc.Certificates.read(str(tmp_path / "missing.sscc"), sphere_bvh)
    other = sscc.SubspaceBvh(sphere_bvh.model, seed=2)
    with pytest.raises(OSError, match="certificate file"):
        sscc.Certificates.read(path, other)
    with open(path, "r+b") as f:
        f.seek(40)
        byte = f.read(1)
        f.seek(40)
        f.write(bytes([byte[0] ^ 0xFF]))
    with pytest.raises(OSError, match="certificate file"):
        sscc.Certificates.read(path, sphere_bvh)
    with pytest.raises(OSError, match="cannot open for writing"):
        sphere_certificates.write(str(tmp_path / "no" / "such.sscc"))


def test_precompute_progress(sphere_bvh):
    calls = []
    certificates = sscc.Certificates.precompute(sphere_bvh, progress=lambda done, total: calls.append((done, total)))
    levels = calls[-1][1]
    assert calls == [(done, levels) for done in range(1, levels + 1)]
    assert certificates.stats["seconds"] > 0 and certificates.parameters["epsilon"] == 0.1

    class Stop(Exception):
        pass

    def stop(done, total):
        raise Stop(f"stopped at {done} of {total}")

    with pytest.raises(Stop, match="stopped at 1 of"):
        sscc.Certificates.precompute(sphere_bvh, progress=stop)


def test_modal_basis():
    mesh = sscc.TriangleMesh(*uv_sphere(6, 10, radius=0.1))
    U, weights = sscc.modal_basis(mesh, modes=6, youngs=1e6, poisson=0.4, density=1000)
    assert U.shape == (3 * mesh.vertex_count, 6) and weights.shape == (6,)
    assert np.all(weights > 0) and np.all(np.diff(weights) >= 0)
    model = sscc.SubspaceModel(mesh, U, weights)
    assert model.mode_count == 6
    with pytest.raises(ValueError, match="voxel.*tetgen|tetgen.*voxel|volume"):
        sscc.modal_basis(mesh, volume="cubes")
