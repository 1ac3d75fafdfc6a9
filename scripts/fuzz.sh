#!/usr/bin/env bash
# Builds the fuzz harnesses (fuzz/) with Clang's libFuzzer, AddressSanitizer and
# UndefinedBehaviorSanitizer, and runs each for SECONDS (default 30) from its corpus in fuzz/corpus
# (copied: new inputs stay in the build folder). A crash, a sanitizer report or a broken property
# stops the script with the input that caused it (build/fuzz/crashes/).
#   scripts/fuzz.sh [SECONDS] [FUZZER...]
set -euo pipefail
cd "$(dirname "$0")/.."

seconds="${1:-30}"
shift || true
fuzzers=("$@")
((${#fuzzers[@]} > 0)) ||
  fuzzers=(json_scene_fuzzer xml_scene_fuzzer trace_fuzzer arguments_fuzzer actuator_design_fuzzer)

mkdir -p build
log=build/fuzz.log
cmake -S . -B build/fuzz -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DDATOMSIM_FUZZ=ON -DDATOMSIM_BUILD_TESTS=OFF -DDATOMSIM_BUILD_BENCHMARKS=OFF > "$log" 2>&1 ||
  { cat "$log" >&2; exit 1; }
cmake --build build/fuzz -j "$(nproc)" --target "${fuzzers[@]}" >> "$log" 2>&1 ||
  { grep -E "error" -A5 "$log" | head -40 >&2; echo "fuzz.sh: full log in $log" >&2; exit 1; }

mkdir -p build/fuzz/crashes
for fuzzer in "${fuzzers[@]}"; do
  corpus="build/fuzz/corpus/${fuzzer%_fuzzer}"
  mkdir -p "$corpus"
  cp -n "fuzz/corpus/${fuzzer%_fuzzer}"/* "$corpus"/ 2> /dev/null || true
  # One process, no leak reports from the tools' own caches; a crash leaves its input.
  if ! "build/fuzz/fuzz/$fuzzer" -max_total_time="$seconds" -print_final_stats=1 \
    -artifact_prefix="build/fuzz/crashes/$fuzzer-" "$corpus" > "build/fuzz/$fuzzer.log" 2>&1; then
    tail -40 "build/fuzz/$fuzzer.log" >&2
    echo "fuzz.sh: $fuzzer failed; the input is in build/fuzz/crashes/" >&2
    exit 1
  fi
  runs=$(grep -o "stat::number_of_executed_units: *[0-9]*" "build/fuzz/$fuzzer.log" | grep -o "[0-9]*$")
  echo "$fuzzer: $runs runs in ${seconds} s, no crash ($(ls "$corpus" | wc -l) inputs in its corpus)"
done
