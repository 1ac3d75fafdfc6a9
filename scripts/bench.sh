#!/usr/bin/env bash
# Runs the benchmarks of build/release: the Google Benchmark binaries (inner loops: rule
# evaluation, reach, the event engine), then whole commands as a user runs them against the
# performance goals (scripts/bench-commands.py; docs/performance.md).
#   scripts/bench.sh            every case, including the 2-million-module box
#   scripts/bench.sh --smoke    only the small cases, briefly (as CI does)
#   scripts/bench.sh --large    also scenes of 100 million modules (minutes, 8 GB of disk)
# Other arguments go to Google Benchmark.
set -euo pipefail
cd "$(dirname "$0")/.."

mode=goals
smoke=()
large=()
case "${1:-}" in
  --smoke) shift; mode=smoke; smoke=(--benchmark_filter=Small --benchmark_min_time=0.01) ;;
  --large) shift; large=(--large) ;;
esac
for bench in build/release/bench/*_bench; do
  "$bench" "${smoke[@]}" "$@"
done
echo
scripts/bench-commands.py "$mode" "${large[@]}"
