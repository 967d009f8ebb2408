#!/usr/bin/env bash
# Sets up, builds and runs the main job: the kernel validation report (the public query
# set against FCL and the exact reference, random and near-degenerate queries, run time
# against error with CSV and plots in validation-output/).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
bash scripts/build.sh
queries=../shared/data/ccd-sample-queries
args=(--random 100000 --seed 1 --output validation-output)
if [ -d "$queries" ]; then
  args+=(--queries "$queries")
else
  echo "main: $queries is absent: the query-set report is skipped" >&2
fi
build/bin/sscc kernels "${args[@]}"
