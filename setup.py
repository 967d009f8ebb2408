"""Builds the compiled part of the Python package (sscc._sscc) with CMake, for `pip install .`.

Only the library and the module are built (tests, validation programs and FCL off), in
build-pip/ (kept between runs, so a second install recompiles only what changed). The
metadata is in pyproject.toml. Environment:
  SSCC_CMAKE_ARGS            extra arguments for CMake's configure step (split on spaces),
                             e.g. "-DCMAKE_CXX_COMPILER_LAUNCHER=ccache"
  CMAKE_BUILD_PARALLEL_LEVEL parallel compile jobs (default: every core)
"""

import os
import pathlib
import shutil
import subprocess
import sys

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = pathlib.Path(__file__).resolve().parent


class CMakeExtension(Extension):
    def __init__(self, name):
        super().__init__(name, sources=[])


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        # One place however pip is run (kept between installs). With ccache and the CMake build's
        # flags (SSCC_CMAKE_ARGS), the objects of that build come from the cache: without -g, ccache
        # does not hash the directory a compiler runs in.
        build = ROOT / "build-pip" / "cmake"
        build.mkdir(parents=True, exist_ok=True)
        configure = [
            "cmake", "-S", str(ROOT), "-B", str(build),
            "-DCMAKE_BUILD_TYPE=Release",
            "-DSSCC_BUILD_TESTS=OFF",
            "-DSSCC_BUILD_VALIDATION=OFF",
            "-DSSCC_WITH_FCL=OFF",
            "-DSSCC_BUILD_PYTHON=ON",
            f"-DPython3_EXECUTABLE={sys.executable}",
        ] + os.environ.get("SSCC_CMAKE_ARGS", "").split()
        subprocess.run(configure, check=True)
        compile_ = ["cmake", "--build", str(build), "--target", "sscc_python"]
        if "CMAKE_BUILD_PARALLEL_LEVEL" not in os.environ:
            compile_ += ["-j", str(os.cpu_count() or 1)]
        subprocess.run(compile_, check=True)
        # The module and the build's facts (_build_info.py) go where setuptools packs the package.
        built = build / "python" / "sscc"
        module = next(built.glob("_sscc*" + (".pyd" if os.name == "nt" else ".so")))
        target = pathlib.Path(self.get_ext_fullpath(ext.name))
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(module, target)
        shutil.copyfile(built / "_build_info.py", target.parent / "_build_info.py")


# setuptools' own build directories (and the egg-info it writes) in build-pip/ too, beside CMake's
# build/ rather than inside it.
(ROOT / "build-pip").mkdir(exist_ok=True)
setup(
    ext_modules=[CMakeExtension("sscc._sscc")],
    cmdclass={"build_ext": CMakeBuild},
    options={"build": {"build_base": str(ROOT / "build-pip")}, "egg_info": {"egg_base": str(ROOT / "build-pip")}},
)
