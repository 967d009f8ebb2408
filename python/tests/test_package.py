"""The package as shipped: the stub matches the module, everything has a docstring, the
one-line example of the README runs with the python3 on PATH, and the installed package
imports."""

import ast
import os
import pathlib
import re
import shutil
import subprocess
import sys

import pytest

import sscc
from conftest import REPOSITORY

PACKAGE = pathlib.Path(sscc.__file__).resolve().parent
STUB = ast.parse((pathlib.Path(__file__).resolve().parents[1] / "sscc" / "__init__.pyi").read_text())


def stub_definitions(body):
    """Public names defined in a stub body: name -> its ast node."""
    names = {}
    for node in body:
        if isinstance(node, (ast.FunctionDef, ast.ClassDef)):
            names[node.name] = node
        elif isinstance(node, ast.AnnAssign) and isinstance(node.target, ast.Name):
            names[node.target.id] = node
    return {name: node for name, node in names.items() if not name.startswith("_")}


def runtime_parameters(function):
    """Parameter names from pybind11's signature line, e.g. 'f(self: X, q0: object, *, mode: str = ...)'."""
    signature = function.__doc__.splitlines()[0]
    inside = signature[signature.index("(") + 1:signature.rindex(") ->")]
    return [name for name in re.findall(r"(?:^|, )(\w+):", inside) if name != "self"]


def stub_parameters(node):
    arguments = node.args.args + node.args.kwonlyargs
    return [a.arg for a in arguments if a.arg != "self"]


def test_stub_lists_exactly_the_public_api():
    compiled = {name for name in dir(sscc._sscc) if not name.startswith("_")}
    assert set(stub_definitions(STUB.body)) == compiled
    assert all(getattr(sscc, name) is getattr(sscc._sscc, name) for name in compiled)


def test_stub_members_and_parameters_match_the_module():
    for name, node in stub_definitions(STUB.body).items():
        runtime = getattr(sscc, name)
        if isinstance(node, ast.FunctionDef):
            assert stub_parameters(node) == runtime_parameters(runtime), name
        elif isinstance(node, ast.ClassDef):
            stubbed = stub_definitions(node.body)
            public = {m for m in dir(runtime) if not m.startswith("_")}
            assert set(stubbed) == public, name
            for member, definition in stubbed.items():
                attribute = getattr(runtime, member)
                if isinstance(definition, ast.FunctionDef) and not isinstance(attribute, property):
                    assert stub_parameters(definition) == runtime_parameters(attribute), f"{name}.{member}"
            init = next((n for n in node.body if isinstance(n, ast.FunctionDef) and n.name == "__init__"), None)
            if init is not None:
                assert stub_parameters(init) == runtime_parameters(runtime.__init__), f"{name}.__init__"


def documentation(attribute):
    """The user-written part of a docstring (pybind11 puts the signature on the first line)."""
    doc = attribute.__doc__ or ""
    if callable(attribute) and not isinstance(attribute, type):
        doc = "\n".join(doc.splitlines()[1:])
    return doc.strip()


def test_everything_public_has_a_docstring():
    undocumented = []
    for name in sscc.__all__:
        attribute = getattr(sscc, name)
        if isinstance(attribute, (int, float)):
            continue
        if not documentation(attribute):
            undocumented.append(name)
        if isinstance(attribute, type):
            for member in dir(attribute):
                if member.startswith("_") and member != "__init__":
                    continue
                if member == "__init__" and name in ("Certificates", "ContactGeometry", "CertificateShard", "Features",
                                                     "SceneObjectResult", "SceneReport", "SelfCcdReport"):
                    continue  # made by the library only (certificates by precompute or read)
                if not documentation(getattr(attribute, member)):
                    undocumented.append(f"{name}.{member}")
    assert not undocumented
    assert len(sscc.__doc__) > 200


def test_readme_one_liner_runs_with_the_python3_on_path():
    """The line of the README, as written, run from the repository root."""
    python3 = shutil.which("python3")
    assert python3 is not None
    version = subprocess.run([python3, "-c", "import sys; print(*sys.version_info[:2])"],
                             capture_output=True, text=True, check=True).stdout.split()
    if tuple(map(int, version)) != sys.version_info[:2]:
        pytest.skip(f"python3 on PATH ({python3}) is {'.'.join(version)}, the module was built for "
                    f"{sys.version_info[0]}.{sys.version_info[1]}")
    line = ("import sscc, numpy as np; m = sscc.read_mesh('data/bunny15k.off'); U = sscc.polynomial_basis(m, 27); "
            "b = sscc.SubspaceBvh(sscc.SubspaceModel(m, U, np.ones(27))); c = sscc.Certificates.precompute(b); "
            "d = sscc.SelfCcd(b, c); r = d.query(np.zeros(27), np.zeros(27)); "
            "print(r.pairs.shape, r.stats['root_certified'])")
    readme = (REPOSITORY / "README.md").read_text()
    assert line in readme
    environment = dict(os.environ, PYTHONPATH=str(PACKAGE.parent))
    result = subprocess.run([python3, "-c", line], cwd=REPOSITORY, env=environment, capture_output=True, text=True)
    assert result.returncode == 0, result.stderr
    assert result.stdout == "(0, 2) True\n"


def cache_value(build, name):
    for line in (build / "CMakeCache.txt").read_text().splitlines():
        if line.startswith(name + ":"):
            return line.split("=", 1)[1]
    return None


def test_installed_package_imports(tmp_path):
    build = pathlib.Path(os.environ.get("SSCC_BUILD_DIR", PACKAGE.parents[1]))
    cmake = shutil.which("cmake")
    if cmake is None or not (build / "CMakeCache.txt").exists():
        pytest.skip("needs cmake and the build directory (SSCC_BUILD_DIR)")
    subprocess.run([cmake, "--install", str(build), "--component", "python", "--prefix", str(tmp_path)],
                   check=True, capture_output=True)
    site = tmp_path / cache_value(build, "SSCC_PYTHON_INSTALL_DIR")
    assert (site / "sscc" / "__init__.pyi").exists() and (site / "sscc" / "py.typed").exists()
    check = ("import sscc; assert sscc.__file__.startswith(%r); "
             "print(sscc.vertex_face_ccd((0.25, 0.25, 1), (0, 0, 0), (1, 0, 0), (0, 1, 0), "
             "(0.25, 0.25, -1), (0, 0, 0), (1, 0, 0), (0, 1, 0))[0])" % str(site))
    result = subprocess.run([sys.executable, "-c", check], cwd=tmp_path, capture_output=True, text=True,
                            env=dict(os.environ, PYTHONPATH=str(site)))
    assert result.returncode == 0, result.stderr
    assert result.stdout == "True\n"
