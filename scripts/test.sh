#!/usr/bin/env bash
# Sets up, builds and runs every test: the Release build in build/, then the same tests
# under AddressSanitizer and UndefinedBehaviorSanitizer in build-sanitize/, then the tests of
# what runs on several threads under ThreadSanitizer in build-tsan/ (scripts/tsan.sh).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
bash scripts/build.sh
(cd build && ctest --output-on-failure -j "$(nproc)")
cmake -S . -B build-sanitize -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSSCC_SANITIZE=ON \
  -DSSCC_BUILD_VALIDATION=OFF
cmake --build build-sanitize -j "$(nproc)"
(cd build-sanitize && ctest --output-on-failure -j "$(nproc)")
bash scripts/tsan.sh
