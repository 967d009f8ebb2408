#!/usr/bin/env bash
# Fails when a C++ file of the repository differs from what clang-format (the repository's
# .clang-format) makes of it; prints the files. Run from the repository root.
set -euo pipefail
clang_format=${1:-clang-format}
if git rev-parse --is-inside-work-tree > /dev/null 2>&1; then
  files=$(git ls-files '*.cpp' '*.hpp')
else
  files=$(find . -path ./build -prune -o \( -name '*.cpp' -o -name '*.hpp' \) -print)
fi
unformatted=()
for f in $files; do
  "$clang_format" --style=file --dry-run --Werror "$f" > /dev/null 2>&1 || unformatted+=("$f")
done
if [ ${#unformatted[@]} -gt 0 ]; then
  echo "not formatted (clang-format -i FILE): ${unformatted[*]}"
  exit 1
fi
echo "format: $(echo "$files" | wc -w) files formatted"
