#!/usr/bin/env bash
# Installs the Debian packages datomsim needs, only those missing. Quick when all are there.
# Non-interactive; runs apt-get as root, or through sudo otherwise.
set -euo pipefail

packages=(
  build-essential cmake pkg-config git time
  libgtest-dev libgmock-dev libbenchmark-dev
  libcli11-dev nlohmann-json3-dev libtinyxml2-dev libfmt-dev libcairo2-dev
  # The load model's sparse solvers (docs/mechanics.md).
  libeigen3-dev
  # The studio's local server: Boost.Beast's HTTP and WebSocket over Boost.Asio (docs/studio.md).
  libboost-dev
  clang-format cmake-format
  # The fuzz harnesses (scripts/fuzz.sh): Clang and its libFuzzer and sanitizer runtimes.
  clang libclang-rt-dev
  # The Python package (docs/python.md): its module, and what its tests and users import.
  pybind11-dev python3-dev python3-numpy python3-pytest
  # Hypothesis: the Python package's fuzzing (python/tests/test_fuzz.py, scripts/fuzz.sh).
  python3-hypothesis
  # Sweeps on a Dask cluster, their progress bar and their plots.
  python3-distributed python3-tqdm python3-matplotlib
  # Shell completion is tested in both shells it is made for (docs/shell-completion.md).
  bash-completion zsh
)
# The browser viewer and its end-to-end test (docs/viewer.md).
# Node.js may come from another source than Debian's packages (with its own npm): the commands
# count, not the package names.
if [[ "${DATOMSIM_SKIP_BROWSER:-0}" != 1 ]]; then
  # chromium draws the viewer; ffmpeg encodes its frames into videos (datomsim video).
  packages+=(chromium ffmpeg)
  if ! command -v node >/dev/null || ! command -v npm >/dev/null; then
    packages+=(nodejs npm)
  fi
fi

missing=()
for package in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$package")
  fi
done

if ((${#missing[@]} > 0)); then
  echo "install-deps: installing ${missing[*]}"
  run_as_root=()
  if [[ "$(id -u)" != 0 ]]; then
    if ! command -v sudo >/dev/null; then
      echo "install-deps: need root or sudo to install: ${missing[*]}" >&2
      exit 1
    fi
    run_as_root=(sudo)
  fi
  export DEBIAN_FRONTEND=noninteractive
  "${run_as_root[@]}" apt-get update -qq
  "${run_as_root[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

# The browser viewer's packages (three.js, esbuild), pinned by viewer/package-lock.json; only
# when missing or older than the lock file.
viewer="$(dirname "$0")/../viewer"
if [[ "${DATOMSIM_SKIP_BROWSER:-0}" != 1 ]]; then
  if [[ ! -d "$viewer/node_modules" || "$viewer/package-lock.json" -nt "$viewer/node_modules" ]]; then
    echo "install-deps: installing the viewer's npm packages"
    npm --prefix "$viewer" ci --no-audit --no-fund --loglevel=error
    touch "$viewer/node_modules"
  fi
fi
