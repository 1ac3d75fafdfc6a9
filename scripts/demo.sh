#!/usr/bin/env bash
# The main job: installs what is missing, builds, and runs the paper's experiment, writing its
# pictures, traces and viewers into demo-output/ (or the folder given as the first argument).
set -euo pipefail
cd "$(dirname "$0")/.."

scripts/install-deps.sh
scripts/build.sh release
build/release/bin/datomsim demo --out "${1:-demo-output}"
