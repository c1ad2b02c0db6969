#!/usr/bin/env bash
# Installs what testing needs too, builds the rest of the tree in the demo's
# build/ (same flags: nothing is built twice), and runs the whole test suite
# once in Release (with the browser test of the animation page), then the
# unit tests again and the fuzz targets under AddressSanitizer and
# UndefinedBehaviorSanitizer.
set -euo pipefail
cd "$(dirname "$0")/.."
ROBOTSIM_SETUP=test bash scripts/build.sh
(cd build && ctest -j "$(nproc)" --output-on-failure)

echo "== unit tests and fuzz targets under AddressSanitizer + UndefinedBehaviorSanitizer (clang)"
# One clang build serves both: the libraries carry libFuzzer's coverage
# hooks (harmless to the unit tests), and each fuzz target runs a short,
# fixed number of inputs as a CTest test (label fuzz; docs/reliability.md).
# The language server's million-line document runs in Release only (50x
# slower here, and the same code), and so do the peak memory of
# `robotsim test` on 100,000,000 instructions and of the readers on 20 MB
# inputs and of `animate` and `plot` of a MOVES loop at their default limits (the sanitizers' shadow memory
# is no measure of robotsim's, and the runs take minutes here) and the tests
# labelled slow (the collision differential test: tests/CMakeLists.txt), and
# the checks of the tree and its docs (labels layers and docs: scripts
# reading files, the same in both builds).
# Ninja as for build/ (scripts/build.sh says why); a build-asan/ already
# configured keeps its generator.
generator=()
[ ! -f build-asan/CMakeCache.txt ] && command -v ninja >/dev/null 2>&1 && generator=(-G Ninja)
# The test files are not instrumented (tests/CMakeLists.txt): this build
# links the ones build/ compiled rather than compiling them again.
CC=clang CXX=clang++ cmake -S . -B build-asan "${generator[@]}" -DCMAKE_BUILD_TYPE=Debug -DROBOTSIM_SANITIZE=ON -DROBOTSIM_FUZZ=ON \
  -DROBOTSIM_WERROR=ON -DROBOTSIM_TEST_OBJECTS_FROM="$PWD/build" >/dev/null
cmake --build build-asan -j "$(nproc)" --target robotsim_tests robotsim_fuzzers
(cd build-asan && ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
  ctest -j "$(nproc)" --output-on-failure -LE 'browser|vscode|slow|layers|docs' -E '1,000,000-line|100,000,000-instruction|MOVES loop at the default limits|peak memory')
