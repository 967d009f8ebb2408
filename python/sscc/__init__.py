"""Continuous collision detection for deformable triangle meshes with Subspace
Self-Collision Culling (Barbic and James, SIGGRAPH 2010).

A reduced deformable object moves as x = p + U q. Per time step, give the detector the
step's start and end coordinates q0 -> q1; it reports the non-adjacent triangle pairs that
come into contact during the step, their vertex-face and edge-edge features and the
earliest time of impact, never missing one. Precomputed certificates prove most steps
free of self-collisions in O(r).

    import numpy as np, sscc
    mesh = sscc.read_mesh("data/bunny15k.off")
    U = sscc.polynomial_basis(mesh, 27)
    bvh = sscc.SubspaceBvh(sscc.SubspaceModel(mesh, U, np.ones(27)))
    detector = sscc.SelfCcd(bvh, sscc.Certificates.precompute(bvh))
    report = detector.query(q0, q1)   # report.pairs, report.toi, report.features, report.stats

Objects keep alive what they refer to: drop the mesh, model or hierarchy whenever you like.
Long calls release the GIL. Bad input raises ValueError, unreadable files OSError.
"""

import sys as _sys

from . import _build_info

if _sys.version_info[:2] != _build_info.BUILD_PYTHON_VERSION:
    raise ImportError(
        "sscc was built for Python %d.%d (%s); this is Python %d.%d"
        % (*_build_info.BUILD_PYTHON_VERSION, _build_info.BUILD_PYTHON, *_sys.version_info[:2]))

try:
    import numpy as _numpy  # noqa: F401 (the compiled module needs it)
except ImportError:
    # The compiled module loads in any interpreter of the version it was built for, but
    # needs NumPy. Another interpreter than the build one (a pyenv or virtual-environment
    # python3 first on PATH) may have none, while the distribution's NumPy, built for this
    # same version, sits in the build interpreter's site directory: borrow it, appended
    # last so that it shadows nothing the interpreter has of its own.
    if not _build_info.NUMPY_SITE or _build_info.NUMPY_SITE in _sys.path:
        raise
    _sys.path.append(_build_info.NUMPY_SITE)
    import numpy as _numpy  # noqa: F401

from . import _sscc
from ._sscc import *  # noqa: F401,F403 (the public API is the compiled module's)

__all__ = [name for name in dir(_sscc) if not name.startswith("_")]
