#!/usr/bin/env bash
# Configures and builds robotsim into build/ (Release, warnings as errors:
# the demo and the tests use the same flags, so the tests reuse the demo's
# build). Arguments are targets; none builds everything.
#   bash scripts/build.sh robotsim     the command only (the demo)
#   bash scripts/build.sh              everything: tests, benchmarks
# ROBOTSIM_SETUP=test installs the test tools too.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh "${ROBOTSIM_SETUP:-build}"
dir=${ROBOTSIM_BUILD_DIR:-build}
cmake -S . -B "$dir" -DCMAKE_BUILD_TYPE=Release -DROBOTSIM_WERROR=ON >/dev/null
targets=()
for t in "$@"; do targets+=(--target "$t"); done
cmake --build "$dir" -j "$(nproc)" "${targets[@]}"
