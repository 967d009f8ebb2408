#!/usr/bin/env bash
# How the pipeline grows with the mesh: `sscc scale` at each size given (triangles; default
# 10000 100000 1000000), each in its own process under /usr/bin/time -v, then a Markdown table
# of the times, the peak memory (the resident set /usr/bin/time reports, and the process's
# own getrusage figure beside it) and the triangle pairs the precomputation screened. Each size's output and log go to scale-output/.
#
#   bash scripts/scale.sh                 # 10^4, 10^5, 10^6 triangles
#   bash scripts/scale.sh 10000 100000    # those sizes only
#   SSCC_SCALE_ARGS="--threads 2 --steps 100" bash scripts/scale.sh
set -euo pipefail
cd "$(dirname "$0")/.."
sscc=${SSCC:-build/bin/sscc}
output=${SCALE_OUTPUT:-scale-output}
sizes=("$@")
[ ${#sizes[@]} -gt 0 ] || sizes=(10000 100000 1000000)
read -r -a extra <<<"${SSCC_SCALE_ARGS:-}"
[ -x "$sscc" ] || { echo "scale: no $sscc (build first: bash scripts/build.sh)" >&2; exit 1; }
mkdir -p "$output"
timer=()
[ -x /usr/bin/time ] && timer=(/usr/bin/time -v)

field() { sed -n "s/.* $1=\([^ ]*\).*/\1/p" "$2"; }

rows=()
for n in "${sizes[@]}"; do
  echo "scale: $n triangles ..." >&2
  # Progress on the terminal and in the log; the result line in the .txt.
  "${timer[@]}" "$sscc" scale --triangles "$n" "${extra[@]}" >"$output/scale_$n.txt" 2> >(tee "$output/scale_$n.log" >&2)
  wait  # for tee
  line="$output/scale_$n.txt"
  time_kb=$(sed -n 's/.*Maximum resident set size (kbytes): *//p' "$output/scale_$n.log")
  time_mb=$([ -n "$time_kb" ] && awk "BEGIN { printf \"%.0f\", $time_kb / 1024 }" || echo "-")
  rows+=("| $(field triangles "$line") | $(field nodes "$line") | $(field hierarchy_s "$line") | $(field certificates_s "$line") | $(field detector_s "$line") | $(field prepare_s "$line") | $(field query_ms_per_step "$line") | $(field total_s "$line") | $time_mb | $(field peak_rss_mb "$line") | $(field pairs_screened "$line") | $(field screened_per_pair "$line") |")
done
echo "| triangles | nodes | hierarchy s | certificates s | detector s | prepare s | query ms/step | total s | peak MB (time -v) | peak MB (getrusage) | triangle pairs screened | per pair of the mesh |"
echo "|---|---|---|---|---|---|---|---|---|---|---|---|"
printf '%s\n' "${rows[@]}"
