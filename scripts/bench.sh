#!/usr/bin/env bash
# Runs the benchmarks of build/release. With --smoke, only the small cases, briefly (as CI does);
# otherwise every case, including the 2-million-module box. Extra arguments go to Google Benchmark.
set -euo pipefail
cd "$(dirname "$0")/.."

smoke=()
if [[ "${1:-}" == --smoke ]]; then
  shift
  smoke=(--benchmark_filter=Small --benchmark_min_time=0.01)
fi
for bench in build/release/bench/*_bench; do
  "$bench" "${smoke[@]}" "$@"
done
