#!/usr/bin/env bash
# The Python package as a user installs it: a fresh virtual environment (Debian's interpreter,
# seeing the system's NumPy and pytest), `pip install .` from this checkout, the README's import
# line, then the pytest suite against the installed package. Offline: pip takes its build
# requirements (setuptools, wheel) from Debian's wheels in /usr/share/python-wheels. The CMake
# build of the module lands in build-pip/ (kept between runs).
#
#   bash scripts/python_package.sh [VENV_DIR]     (default build-venv)
set -euo pipefail
cd "$(dirname "$0")/.."
venv=$(realpath -m "${1:-build-venv}")
start=$SECONDS
rm -rf "$venv"
/usr/bin/python3 -m venv --system-site-packages "$venv"
export PIP_NO_INDEX=1 PIP_FIND_LINKS=/usr/share/python-wheels PIP_DISABLE_PIP_VERSION_CHECK=1
"$venv/bin/pip" install --quiet .
echo "python_package: installed in $((SECONDS - start)) s"
# From elsewhere than the checkout, so that nothing but the installed package can be imported.
(cd /tmp && "$venv/bin/python" -c "import sscc; print(sscc.PositionCcd, sscc.Scene)")
# The suite imports the installed package (the checkout's python/sscc has no compiled part).
"$venv/bin/python" -c "import sscc, sys; sys.exit(not sscc.__file__.startswith('$venv'))"
# The README's one-line example is run by the CMake build's test of the same suite; here its
# 40 s (certificates of the 15k-triangle bunny) would repeat it.
"$venv/bin/python" -m pytest -q -p no:cacheprovider python/tests \
  --deselect python/tests/test_package.py::test_readme_one_liner_runs_with_the_python3_on_path
echo "python_package: installed and tested in $((SECONDS - start)) s"
