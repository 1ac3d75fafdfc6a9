#!/usr/bin/env bash
# Configures and builds one flavour of datomsim into build/<flavour>: release (default, GCC -O2)
# or sanitize (Clang -O1 with AddressSanitizer and UndefinedBehaviorSanitizer, and the fuzz
# harnesses of fuzz/: one sanitized build serves the tests and the fuzzers). Warnings are errors.
# With targets after the flavour, builds only those.
#   scripts/build.sh [release|sanitize] [TARGET...]
set -euo pipefail
cd "$(dirname "$0")/.."

flavour="${1:-release}"
shift || true
case "$flavour" in
  release) options=(-DCMAKE_BUILD_TYPE=Release) ;;
  # -O1: the sanitizers' own advice, and several times faster than -O0 on the scenario tests.
  sanitize)
    options=(-DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=Debug "-DCMAKE_CXX_FLAGS_DEBUG=-O1 -g"
      -DDATOMSIM_SANITIZE=ON -DDATOMSIM_FUZZ=ON -DDATOMSIM_BUILD_BENCHMARKS=OFF)
    ;;
  *) echo "build.sh: unknown flavour '$flavour' (release or sanitize)" >&2; exit 2 ;;
esac
targets=()
(($# > 0)) && targets=(--target "$@")

# The compiler's chatter goes to a log; only errors are shown.
mkdir -p build
log="build/$flavour.log"
# Unity builds: the sources of a target compiled eight to a file. Each file's own templates (CLI11,
# fmt's format checks, gtest) are then instantiated once for eight: the command line compiles in a
# third of the time, the whole build in about half.
cmake -S . -B "build/$flavour" -DDATOMSIM_WERROR=ON -DCMAKE_UNITY_BUILD=ON \
  -DCMAKE_UNITY_BUILD_BATCH_SIZE=8 "${options[@]}" > "$log" 2>&1 ||
  { cat "$log" >&2; exit 1; }
cmake --build "build/$flavour" -j "$(nproc)" "${targets[@]}" >> "$log" 2>&1 ||
  { grep -E "error|Error" -A5 "$log" | head -60 >&2; echo "build.sh: full log in $log" >&2; exit 1; }
