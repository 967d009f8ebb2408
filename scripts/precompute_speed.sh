#!/usr/bin/env bash
# Precomputation time of two builds in one run, and whether their certificate files are the
# same byte for byte: for each mesh, `sscc precompute --basis polynomial:27` with the first
# binary, then the second, each under /usr/bin/time (wall time, peak resident memory). The
# reference is usually a build of an earlier commit:
#
#   git worktree add /tmp/sscc-old <commit> && bash /tmp/sscc-old/scripts/build.sh
#   bash scripts/precompute_speed.sh /tmp/sscc-old/build/bin/sscc build/bin/sscc \
#       ../shared/data/meshes/bunny00.off ../shared/data/meshes/lion.off
#
# PRECOMPUTE_ARGS adds options to every run (e.g. "--exclude-rest-contacts --threads 2").
# Exits 1 when two files differ.
set -euo pipefail
[ $# -ge 3 ] || { echo "usage: precompute_speed.sh OLD_SSCC NEW_SSCC MESH..." >&2; exit 2; }
old=$1 new=$2
shift 2
read -r -a extra <<<"${PRECOMPUTE_ARGS:-}"
output=${PRECOMPUTE_OUTPUT:-precompute-speed}
mkdir -p "$output"
status=0
printf '| mesh | reference | this build | ratio | peak memory (reference / this) | files |\n|---|---|---|---|---|---|\n'
for mesh in "$@"; do
  name=$(basename "$mesh" .off)
  declare -A seconds=() memory=()
  for which in old new; do
    binary=${!which}
    /usr/bin/time -f "%e %M" -o "$output/$name-$which.time" "$binary" precompute --mesh "$mesh" \
      --basis polynomial:27 "${extra[@]}" --output "$output/$name-$which.sscc" >"$output/$name-$which.log" 2>&1
    read -r seconds[$which] memory[$which] <"$output/$name-$which.time"
  done
  same=identical
  cmp -s "$output/$name-old.sscc" "$output/$name-new.sscc" || { same=DIFFERENT; status=1; }
  ratio=$(awk -v a="${seconds[old]}" -v b="${seconds[new]}" 'BEGIN { printf "%.2fx", a / b }')
  printf '| %s | %s s | %s s | %s | %s / %s MB | %s |\n' "$name" "${seconds[old]}" "${seconds[new]}" "$ratio" \
    "$((memory[old] / 1024))" "$((memory[new] / 1024))" "$same"
done
exit $status
