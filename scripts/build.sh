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
# Ninja (setup.sh's build list) starts each file as soon as what it needs
# exists; make's generated files wait for every library a library links to
# be archived first, which leaves a core idle for stretches (about 20 s of
# the demo's build on 2 cores; docs/performance.md, "Setup"). A build/
# already configured keeps its generator.
generator=()
[ ! -f "$dir/CMakeCache.txt" ] && command -v ninja >/dev/null 2>&1 && generator=(-G Ninja)
cmake -S . -B "$dir" "${generator[@]}" -DCMAKE_BUILD_TYPE=Release -DROBOTSIM_WERROR=ON >/dev/null
targets=()
for t in "$@"; do targets+=(--target "$t"); done
cmake --build "$dir" -j "$(nproc)" "${targets[@]}"
