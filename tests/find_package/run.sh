#!/usr/bin/env bash
# Installs the build tree's sscc into a scratch prefix, then builds and runs two consumers:
# one that uses everything (find_package(sscc), sscc::sscc) and a CCD-only one that asks for
# the core component with TetGen and Spectra made unfindable, and checks that none of their
# headers went into its build.
set -euo pipefail
build_dir=$1
source_dir=$(cd "$(dirname "$0")" && pwd)
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
cmake --install "$build_dir" --prefix "$scratch/prefix" > /dev/null

cmake -S "$source_dir/full" -B "$scratch/full" -DCMAKE_PREFIX_PATH="$scratch/prefix" > /dev/null
cmake --build "$scratch/full" > /dev/null
"$scratch/full/consumer"

cmake -S "$source_dir/core" -B "$scratch/core" -DCMAKE_PREFIX_PATH="$scratch/prefix" \
  -DCMAKE_DISABLE_FIND_PACKAGE_TetGen=ON -DCMAKE_DISABLE_FIND_PACKAGE_Spectra=ON > /dev/null
cmake --build "$scratch/core" > /dev/null
if grep -rlE 'tetgen\.h|Spectra/' "$scratch/core/CMakeFiles" --include='*.d' --include='*.make' > /dev/null; then
  echo "the core consumer's build included TetGen or Spectra headers" >&2
  exit 1
fi
"$scratch/core/core_consumer"
