#!/usr/bin/env bash
# Sets up, builds and runs the main job: `sscc demo`, sixteen modal bunnies dropped and
# struck, their continuous collision detection run every step with certificates (SSCC) and
# without (traditional), FCL on a few steps; a table, plots in demo-output/, and the line
# 'demo: ... speedup=X agree=yes|no'. The first run computes the bunny's modal basis and
# certificates and caches them in demo-cache/.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
bash scripts/build.sh
build/bin/sscc demo "$@"
