#!/usr/bin/env bash
# Configures and builds robotsim into build/ (Release). Extra arguments go
# to CMake, e.g. scripts/build.sh -DCMAKE_BUILD_TYPE=Debug.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
dir=${ROBOTSIM_BUILD_DIR:-build}
cmake -S . -B "$dir" -DCMAKE_BUILD_TYPE=Release "$@" >/dev/null
cmake --build "$dir" -j "$(nproc)"
