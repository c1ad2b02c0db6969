#!/usr/bin/env bash
# Installs what testing needs too, builds the rest of the tree in the demo's
# build/ (same flags: nothing is built twice), and runs the whole test suite
# once in Release (with the browser test of the animation page), then the
# unit tests again under AddressSanitizer and UndefinedBehaviorSanitizer.
set -euo pipefail
cd "$(dirname "$0")/.."
ROBOTSIM_SETUP=test bash scripts/build.sh
(cd build && ctest --output-on-failure)

echo "== unit tests under AddressSanitizer + UndefinedBehaviorSanitizer"
cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=Debug -DROBOTSIM_SANITIZE=ON -DROBOTSIM_WERROR=ON >/dev/null
cmake --build build-asan -j "$(nproc)" --target robotsim_tests
(cd build-asan && ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
  ctest --output-on-failure -LE 'browser|vscode')
