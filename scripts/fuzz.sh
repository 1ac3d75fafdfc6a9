#!/usr/bin/env bash
# Builds the fuzz harnesses (fuzz/) with Clang's libFuzzer, AddressSanitizer and
# UndefinedBehaviorSanitizer, in the sanitized build (scripts/build.sh sanitize), and runs each
# for SECONDS (default 30), as many at once as there are cores, from its corpus in fuzz/corpus
# (copied: new inputs stay in build/fuzz).
# A crash, a sanitizer report or a broken property stops the script with the input that caused it
# (build/fuzz/crashes/). Then (or when FUZZER is "python") hypothesis over the Python package's
# public functions, python/tests/test_fuzz.py, with DATOMSIM_FUZZ_EXAMPLES examples each (default
# 2000), when the release build has the package.
#   scripts/fuzz.sh [SECONDS] [FUZZER...]
set -euo pipefail
cd "$(dirname "$0")/.."

seconds="${1:-30}"
shift || true
fuzzers=("$@")
python_fuzz=0
if ((${#fuzzers[@]} == 0)); then
  fuzzers=(json_scene_fuzzer xml_scene_fuzzer trace_fuzzer arguments_fuzzer actuator_design_fuzzer
    csg_target_fuzzer)
  python_fuzz=1
elif [[ " ${fuzzers[*]} " == *" python "* ]]; then
  python_fuzz=1
  read -r -a fuzzers <<< "$(printf '%s ' "${fuzzers[@]}" | sed 's/\bpython\b//g')"
fi

# Hypothesis over the Python package (docs/limits.md, "Fuzzing").
fuzz_python() {
  if [[ ! -d build/release/python/datomsim ]]; then
    echo "python: not fuzzed (build/release has no Python package: scripts/build.sh release)"
    return
  fi
  local examples="${DATOMSIM_FUZZ_EXAMPLES:-2000}"
  if ! PYTHONPATH=build/release/python DATOMSIM_FUZZ_EXAMPLES="$examples" /usr/bin/python3 -m pytest \
    -q -p no:cacheprovider python/tests/test_fuzz.py > build/fuzz/python.log 2>&1; then
    tail -60 build/fuzz/python.log >&2
    echo "fuzz.sh: the Python package failed its fuzzing (build/fuzz/python.log)" >&2
    exit 1
  fi
  echo "python: $examples examples per function, no crash ($(tail -1 build/fuzz/python.log))"
}
if ((${#fuzzers[@]} == 0)); then
  mkdir -p build/fuzz
  fuzz_python
  exit 0
fi

# The harnesses are part of the sanitized build (scripts/build.sh sanitize); their inputs, logs
# and crashes are kept in build/fuzz.
scripts/build.sh sanitize "${fuzzers[@]}"

mkdir -p build/fuzz/crashes
# One fuzzer runs on one core: as many run at once as there are cores (each its SECONDS), and
# their results are told in the order given.
fuzz_one() {
  local fuzzer="$1" corpus="build/fuzz/corpus/${1%_fuzzer}"
  mkdir -p "$corpus"
  cp -n "fuzz/corpus/${fuzzer%_fuzzer}"/* "$corpus"/ 2> /dev/null || true
  # One process, no leak reports from the tools' own caches; a crash leaves its input.
  if "build/sanitize/fuzz/$fuzzer" -max_total_time="$seconds" -print_final_stats=1 \
    -artifact_prefix="build/fuzz/crashes/$fuzzer-" "$corpus" > "build/fuzz/$fuzzer.log" 2>&1; then
    echo 0 > "build/fuzz/$fuzzer.status"
  else
    echo 1 > "build/fuzz/$fuzzer.status"
  fi
}
cores="$(nproc)"
for fuzzer in "${fuzzers[@]}"; do
  rm -f "build/fuzz/$fuzzer.status"
  while (($(jobs -rp | wc -l) >= cores)); do wait -n || true; done
  fuzz_one "$fuzzer" &
done
wait
for fuzzer in "${fuzzers[@]}"; do
  if [[ "$(cat "build/fuzz/$fuzzer.status" 2> /dev/null)" != 0 ]]; then
    tail -40 "build/fuzz/$fuzzer.log" >&2
    echo "fuzz.sh: $fuzzer failed; the input is in build/fuzz/crashes/" >&2
    exit 1
  fi
  corpus="build/fuzz/corpus/${fuzzer%_fuzzer}"
  runs=$(grep -o "stat::number_of_executed_units: *[0-9]*" "build/fuzz/$fuzzer.log" | grep -o "[0-9]*$")
  echo "$fuzzer: $runs runs in ${seconds} s, no crash ($(ls "$corpus" | wc -l) inputs in its corpus)"
done
((python_fuzz == 0)) || fuzz_python
