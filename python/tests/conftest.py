"""Shared fixtures: small meshes built in NumPy and models over them."""

import math
import pathlib

import numpy as np
import pytest

import sscc

REPOSITORY = pathlib.Path(__file__).resolve().parents[2]
MODES = 9


def uv_sphere(rings, segments, radius=1.0, centre=(0.0, 0.0, 0.0)):
    """A closed sphere: two poles and (rings - 1) latitude rings of `segments` vertices."""
    vertices = [(0.0, 0.0, radius)]
    for i in range(1, rings):
        theta = math.pi * i / rings
        for j in range(segments):
            phi = 2.0 * math.pi * j / segments
            vertices.append((radius * math.sin(theta) * math.cos(phi),
                             radius * math.sin(theta) * math.sin(phi),
                             radius * math.cos(theta)))
    vertices.append((0.0, 0.0, -radius))
    south = len(vertices) - 1

    def ring(i, j):
        return 1 + (i - 1) * segments + j % segments

    triangles = [(0, ring(1, j), ring(1, j + 1)) for j in range(segments)]
    for i in range(1, rings - 1):
        for j in range(segments):
            triangles.append((ring(i, j), ring(i + 1, j), ring(i + 1, j + 1)))
            triangles.append((ring(i, j), ring(i + 1, j + 1), ring(i, j + 1)))
    triangles += [(ring(rings - 1, j), south, ring(rings - 1, j + 1)) for j in range(segments)]
    return np.asarray(vertices) + np.asarray(centre), np.asarray(triangles, dtype=np.int32)


@pytest.fixture(scope="module")
def sphere():
    return sscc.TriangleMesh(*uv_sphere(8, 12))


@pytest.fixture(scope="module")
def sphere_model(sphere):
    return sscc.SubspaceModel(sphere, sscc.polynomial_basis(sphere, MODES), np.ones(MODES))


@pytest.fixture(scope="module")
def sphere_bvh(sphere_model):
    return sscc.SubspaceBvh(sphere_model)


@pytest.fixture(scope="module")
def sphere_certificates(sphere_bvh):
    return sscc.Certificates.precompute(sphere_bvh)


def random_q(rng, amplitude, modes=MODES):
    return amplitude * rng.standard_normal(modes) / 3.0
