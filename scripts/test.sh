#!/usr/bin/env bash
# Builds datomsim and runs every check: formatting, the unit and scenario tests (release build,
# warnings as errors), the examples/ built against the installed package, the same tests under
# AddressSanitizer and UndefinedBehaviorSanitizer (Clang), a determinism check across compilers
# and optimisation levels, 30 s of fuzzing of every reader of user input, a smoke run of the
# benchmarks, and the viewer's tests (unit, then end to end in headless Chromium;
# DATOMSIM_SKIP_BROWSER=1 skips them).
# Exits non-zero on the first failure.
set -euo pipefail
cd "$(dirname "$0")/.."

# Each step says when it starts, to show in a CI log where the time goes.
step() {
  printf '== %s (at %d min %02d s)\n' "$1" $((SECONDS / 60)) $((SECONDS % 60))
}

scripts/install-deps.sh
scripts/check-format.sh

step "release build and tests"
scripts/build.sh release
ctest --test-dir build/release --output-on-failure -j "$(nproc)"

step "examples: installed to a temporary prefix, built and run outside the tree"
scripts/test-examples.sh

step "sanitizer build (Clang, with the fuzz harnesses) and tests"
scripts/build.sh sanitize
ctest --test-dir build/sanitize --output-on-failure -j "$(nproc)"

step "determinism: the same run built by Clang at -O1 (sanitize) and by GCC at -O2 (release)"
scratch="$(mktemp -d)"
trap 'rm -rf "$scratch"' EXIT
for flavour in release sanitize; do
  "build/$flavour/bin/datomsim" generate arch --hole 1 -o "$scratch/arch.json" 2> /dev/null
  "build/$flavour/bin/datomsim" run "$scratch/arch.json" --program follow-gradient \
    --goal 6,5,2 --start 0,0,2 --seed 3 --jitter-ms 5 --trace "$scratch/$flavour.jsonl" \
    --out "$scratch/$flavour.json"
done
for flavour in release sanitize; do
  "build/$flavour/bin/datomsim" run scenes/walkers.json --program walkers --seed 5 \
    --trace "$scratch/$flavour-walkers.jsonl" --out "$scratch/$flavour-walkers.json"
  "build/$flavour/bin/datomsim" run scenes/reshape-heap.json --program reconfigure --seed 7 \
    --trace "$scratch/$flavour-heap.jsonl" --out "$scratch/$flavour-heap.json"
  "build/$flavour/bin/datomsim" run scenes/reshape-heap.json --program reconfigure --seed 7 \
    --module catom3d --trace "$scratch/$flavour-catoms.jsonl" --out "$scratch/$flavour-catoms.json"
done
for run in "" -walkers -heap -catoms; do
  cmp "$scratch/release$run.jsonl" "$scratch/sanitize$run.jsonl"
  cmp "$scratch/release$run.json" "$scratch/sanitize$run.json"
done
echo "traces identical ($(wc -l < "$scratch/release.jsonl"), " \
  "$(wc -l < "$scratch/release-walkers.jsonl"), $(wc -l < "$scratch/release-heap.jsonl") and" \
  "$(wc -l < "$scratch/release-catoms.jsonl") lines)"

step "fuzzing: each reader of user input for 30 s (scripts/fuzz.sh)"
scripts/fuzz.sh 30

step "benchmarks (smoke run)"
scripts/bench.sh --smoke

if [[ "${DATOMSIM_SKIP_BROWSER:-0}" != 1 ]]; then
  step "viewer: unit tests, then end to end in headless Chromium"
  npm --prefix viewer test
  node viewer/e2e/view.e2e.mjs --datomsim build/release/bin/datomsim --shots build/viewer-shots
  node viewer/e2e/colours.e2e.mjs --datomsim build/release/bin/datomsim --shots build/viewer-shots
  node viewer/e2e/studio.e2e.mjs --datomsim build/release/bin/datomsim --shots build/viewer-shots
fi
step "all checks passed"
