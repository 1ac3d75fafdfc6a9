#!/usr/bin/env bash
# Fails when a C++ file differs from what clang-format (the project's .clang-format) would write,
# or a CMake file from what cmake-format (.cmake-format.yaml) would write.
set -euo pipefail
cd "$(dirname "$0")/.."

mkdir -p build
mapfile -t files < <(git ls-files '*.cpp' '*.h')
if ! clang-format --dry-run --Werror "${files[@]}" 2> build/format.log; then
  grep -E "^[^ ].*(warning|error)" build/format.log | head -20 >&2
  rm -f build/format.log
  echo "check-format: run clang-format -i on the files above" >&2
  exit 1
fi
rm -f build/format.log

mapfile -t cmake_files < <(git ls-files 'CMakeLists.txt' '*/CMakeLists.txt' '*.cmake')
unformatted=()
for file in "${cmake_files[@]}"; do
  cmake-format --check "$file" > /dev/null 2>&1 || unformatted+=("$file")
  # A C++ formatter run on a CMake file glues "#" to the comment and spaces out paths
  # ("docs / x.md"); cmake-format leaves comments alone, so look for it here.
  if grep -qE '^\s*#[^ #!]|[a-z] / [a-z]' "$file"; then unformatted+=("$file (comments)"); fi
done
if ((${#unformatted[@]} > 0)); then
  printf '  %s\n' "${unformatted[@]}" >&2
  echo "check-format: run cmake-format -i on the files above" >&2
  exit 1
fi
echo "check-format: ${#files[@]} C++ files and ${#cmake_files[@]} CMake files formatted"
