#!/usr/bin/env bash
# Configures and builds one flavour of datomsim into build/<flavour>: release (default) or
# sanitize (AddressSanitizer and UndefinedBehaviorSanitizer, -O0). Warnings are errors.
set -euo pipefail
cd "$(dirname "$0")/.."

flavour="${1:-release}"
case "$flavour" in
  release) options=(-DCMAKE_BUILD_TYPE=Release) ;;
  sanitize) options=(-DCMAKE_BUILD_TYPE=Debug -DDATOMSIM_SANITIZE=ON -DDATOMSIM_BUILD_BENCHMARKS=OFF) ;;
  *) echo "build.sh: unknown flavour '$flavour' (release or sanitize)" >&2; exit 2 ;;
esac

# The compiler's chatter goes to a log; only errors are shown.
mkdir -p build
log="build/$flavour.log"
cmake -S . -B "build/$flavour" -DDATOMSIM_WERROR=ON "${options[@]}" > "$log" 2>&1 ||
  { cat "$log" >&2; exit 1; }
cmake --build "build/$flavour" -j "$(nproc)" >> "$log" 2>&1 ||
  { grep -E "error|Error" -A5 "$log" | head -60 >&2; echo "build.sh: full log in $log" >&2; exit 1; }
