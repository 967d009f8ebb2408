#!/usr/bin/env bash
# Builds the libFuzzer targets with clang (AddressSanitizer and UndefinedBehaviorSanitizer
# on) in build-fuzz/ and runs each for SECONDS (default 60) from its seed corpus in
# fuzz/corpus/. Exits non-zero on any finding (a crash, a sanitizer report, a failed check).
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-60}
CC=clang CXX=clang++ cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSSCC_SANITIZE=ON \
  -DSSCC_BUILD_FUZZERS=ON -DSSCC_BUILD_TESTS=OFF -DSSCC_BUILD_VALIDATION=OFF -DSSCC_BUILD_PYTHON=OFF > /dev/null
targets=(fuzz_mesh_off fuzz_mesh_obj fuzz_mesh_ply fuzz_vega_basis fuzz_certificate_file fuzz_kernels fuzz_cli_model
         fuzz_write_off fuzz_tetgen)
cmake --build build-fuzz -j "$(nproc)" --target "${targets[@]}"
status=0
for target in "${targets[@]}"; do
  corpus=fuzz/corpus/${target#fuzz_}
  work=$(mktemp -d)
  cp -r "$corpus"/. "$work"/ 2>/dev/null || true
  echo "fuzz: $target for ${seconds} s"
  if ! build-fuzz/bin/"$target" -max_total_time="$seconds" -timeout=30 -rss_limit_mb=4096 \
       -artifact_prefix=build-fuzz/"$target"- "$work" > build-fuzz/"$target".log 2>&1; then
    echo "fuzz: $target FOUND A PROBLEM (build-fuzz/$target.log, artifacts build-fuzz/$target-*)"
    tail -20 build-fuzz/"$target".log
    status=1
  else
    grep -E "^(#[0-9]+).*(DONE|pulse)" build-fuzz/"$target".log | tail -1 || true
  fi
  rm -rf "$work"
done
exit $status
