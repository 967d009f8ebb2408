#!/usr/bin/env bash
# ThreadSanitizer job: the library and the tests of what runs on several threads (self
# queries, scene steps, concurrent callers: sscc_thread_tests) built with clang and
# -fsanitize=thread in build-tsan/, then run on several threads. OpenMP is clang's libomp,
# which loads its archer tool under ThreadSanitizer so that the runtime's own
# synchronisation is seen; ignore_noninstrumented_modules keeps the uninstrumented runtime
# from reporting on itself. A race in the library or the tests fails the job. The build is
# clang's, so its -Wuninitialized is an error here (a field used in a constructor before it
# is initialised, as StepContext's statistics once were).
set -euo pipefail
cd "$(dirname "$0")/.."
cmake -S . -B build-tsan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++ \
  -DSSCC_THREAD_SANITIZE=ON -DSSCC_BUILD_VALIDATION=OFF -DSSCC_WITH_FCL=OFF -DSSCC_BUILD_PYTHON=OFF \
  -DCMAKE_CXX_FLAGS=-Werror=uninitialized
cmake --build build-tsan -j "$(nproc)" --target sscc_thread_tests
export TSAN_OPTIONS="ignore_noninstrumented_modules=1 halt_on_error=1 exitcode=66"
export OMP_NUM_THREADS=4  # more threads than this machine's cores: more interleavings
build-tsan/bin/sscc_thread_tests
