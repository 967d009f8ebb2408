#!/usr/bin/env bash
# Sets up, builds and runs every test: the Release build in build/ (its tests include the
# README's commands and the API reference without Doxygen warnings), the Python package
# installed with pip into a fresh virtual environment and tested there
# (scripts/python_package.sh), then the same tests
# under AddressSanitizer and UndefinedBehaviorSanitizer in build-sanitize/ (without the
# Python module: an instrumented extension would need the sanitizer runtime preloaded), then
# the tests of what runs on several threads under ThreadSanitizer in build-tsan/
# (scripts/tsan.sh), then every fuzz target for a few seconds from its seed corpus
# (scripts/fuzz.sh: clang with ASan and UBSan in build-fuzz/, building only the fuzz targets
# and what they link). Warnings are errors in the Release build (the sanitizer build only
# reports them: GCC's instrumented -O2 code gives spurious maybe-uninitialized and stringop
# warnings).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
# Where the data beside the repository is present, the tests that need it must find it: a
# missing file fails them instead of skipping them (tests/support/shared_data.hpp).
if [ -d ../shared ]; then export SSCC_REQUIRE_SHARED_DATA=1; fi
# The Release build goes through ccache (depend mode: no extra preprocessor run on a miss), so
# that the Python package's own CMake build (pip install ., the same flags) finds its objects.
export CCACHE_DEPEND=1
bash scripts/build.sh -DSSCC_WARNINGS_AS_ERRORS=ON -DCMAKE_CXX_COMPILER_LAUNCHER=ccache
export SSCC_REQUIRE_DASK=1  # setup.sh installed Dask: its tests run (python/tests/test_dask.py)
(cd build && ctest --output-on-failure -j "$(nproc)")
SSCC_CMAKE_ARGS="-DSSCC_WARNINGS_AS_ERRORS=ON -DCMAKE_CXX_COMPILER_LAUNCHER=ccache" bash scripts/python_package.sh
cmake -S . -B build-sanitize -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSSCC_SANITIZE=ON \
  -DSSCC_BUILD_VALIDATION=OFF -DSSCC_BUILD_PYTHON=OFF
cmake --build build-sanitize -j "$(nproc)"
(cd build-sanitize && ctest --output-on-failure -j "$(nproc)")
bash scripts/tsan.sh
# Seconds per fuzz target in CI: enough to run the seed corpora and a few thousand
# mutations of each, so that a reader or loader that starts crashing on its seeds is caught.
bash scripts/fuzz.sh 5
