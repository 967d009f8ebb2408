#!/usr/bin/env bash
# The API reference: Doxygen over the public headers (docs/Doxyfile) into OUTPUT_DIR/html
# (default build-docs/). Fails on any Doxygen warning, printing them. The CTest test
# `api_reference` runs it (when doxygen is installed: scripts/setup.sh installs it).
#
#   bash scripts/docs.sh [OUTPUT_DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-build-docs}
mkdir -p "$out"
log="$out/doxygen-warnings.log"
# WARN_AS_ERROR = FAIL_ON_WARNINGS makes doxygen's exit status non-zero on a warning; the log
# is checked as well, so that a doxygen that only writes warnings still fails.
if ! (cat docs/Doxyfile; echo "OUTPUT_DIRECTORY = $out"; echo "WARN_LOGFILE = $log") | doxygen - ||
  [ -s "$log" ]; then
  echo "docs: Doxygen warned:" >&2
  cat "$log" >&2
  exit 1
fi
echo "docs: API reference in $out/html/index.html, no warnings"
