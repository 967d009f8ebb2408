#!/usr/bin/env bash
# Regenerates the README's tables: runs the commands written beside them and prints the tables
# in the README's form (scripts/readme_tables.py), to paste over the README's. Each command's
# output goes to reproduce-output/ (demo_bunnies.md, bench.md, bench_self_ccd.md); copy them
# into docs/ with the README, which keeps the outputs behind its current tables.
#
#   bash scripts/reproduce.sh                    # build, then all three (see below)
#   bash scripts/reproduce.sh demo paper fcl     # some of them: the others' outputs are taken from docs/
#   bash scripts/reproduce.sh --tables-only DIR  # no run: the tables from the outputs in DIR
#
#   demo   build/bin/sscc demo: sixteen bunnies, 300 steps (about 80 s with demo-cache/; the
#          modal basis and certificates take about 20 s more the first time)
#   paper  build/bin/sscc bench: the paper's Table 1 (about 6 minutes)
#   fcl    build/bin/sscc bench --only self-ccd --table-steps 5 --threads 1 --cache bench-cache:
#          every mesh of ../shared/data/meshes against FCL (about 75 s with bench-cache/;
#          5 to 11 minutes the first time)
# Run on a machine otherwise idle: the tables are timings.
set -euo pipefail
cd "$(dirname "$0")/.."
if [ "${1:-}" = "--tables-only" ]; then
  python3 scripts/readme_tables.py "${2:?a folder with demo_bunnies.md, bench.md and bench_self_ccd.md}"
  exit 0
fi
parts=("$@")
[ ${#parts[@]} -gt 0 ] || parts=(demo paper fcl)
out=reproduce-output
mkdir -p "$out"
for f in demo_bunnies.md bench.md bench_self_ccd.md; do [ -f "$out/$f" ] || cp "docs/$f" "$out/$f"; done
bash scripts/build.sh > "$out/build.log"
for part in "${parts[@]}"; do
  case "$part" in
    demo) build/bin/sscc demo | tee "$out/demo_bunnies.md" ;;
    paper)
      build/bin/sscc bench --output "$out/bench"
      cp "$out/bench/bench.md" "$out/bench.md" ;;
    fcl)
      build/bin/sscc bench --only self-ccd --table-steps 5 --threads 1 --cache bench-cache --output "$out/bench-fcl"
      cp "$out/bench-fcl/bench_self_ccd.md" "$out/bench_self_ccd.md" ;;
    *) echo "reproduce: unknown part $part (demo, paper, fcl)" >&2; exit 2 ;;
  esac
done
echo
echo "reproduce: the README's tables (outputs in $out/):"
python3 scripts/readme_tables.py "$out"
