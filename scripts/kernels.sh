#!/usr/bin/env bash
# The kernel validation report: the public query set against FCL and the exact reference,
# random and near-degenerate queries, run time against error (CSV and plots in
# validation-output/). Needs ../shared for the query set (skipped, with a note, without).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
bash scripts/build.sh
queries=../shared/data/ccd-sample-queries
args=(--random 100000 --seed 1 --output validation-output)
if [ -d "$queries" ]; then
  args+=(--queries "$queries")
else
  echo "kernels: $queries is absent: the query-set report is skipped" >&2
fi
build/bin/sscc kernels "${args[@]}"
