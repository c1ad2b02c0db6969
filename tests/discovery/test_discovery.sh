#!/usr/bin/env bash
# Every Catch2 test case must be its own CTest test: a test name that CMake
# cannot hold in a list (an unmatched ']' or a ';') silently glues the test
# cases after it into one, which then runs nothing. Compares the two counts.
#   test_discovery.sh TESTS_BINARY CTEST_BUILD_DIR
set -euo pipefail
# Catch2 v2 exits with the number of tests it listed: not an error here.
names=$("$1" --list-test-names-only || true)
cases=$(grep -c . <<<"$names")
registered=$(cd "$2" && ctest -N -L catch | grep -c '^  Test *#')
if [ "$cases" -ne "$registered" ]; then
  echo "Catch2 lists $cases test cases, CTest has $registered: a test name CMake cannot hold (']' or ';'?)" >&2
  exit 1
fi
echo "$cases test cases, each a CTest test"
