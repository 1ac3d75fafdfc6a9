#!/usr/bin/env bash
# Fails when a C++ file differs from what clang-format (the project's .clang-format) would write.
set -euo pipefail
cd "$(dirname "$0")/.."

mapfile -t files < <(git ls-files '*.cpp' '*.h')
if ! clang-format --dry-run --Werror "${files[@]}" 2> format.log; then
  grep -E "^[^ ].*(warning|error)" format.log | head -20 >&2
  rm -f format.log
  echo "check-format: run clang-format -i on the files above" >&2
  exit 1
fi
rm -f format.log
echo "check-format: ${#files[@]} files formatted"
