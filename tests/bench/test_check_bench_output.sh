#!/usr/bin/env bash
# The bench-smoke checker must fail on what a rotten benchmark prints: a
# NaN (as ik_bench --help once did), an infinity, a missing figure, a wrong
# exit code, a JSON file not written or holding null; and pass on good
# output. Each case runs check_bench_output.sh on a planted output.
set -uo pipefail
check="$(dirname "$0")/check_bench_output.sh"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
expect() {  # expect EXIT DESCRIPTION -- CHECKER ARGUMENTS...
  local want=$1 what=$2
  shift 3
  bash "$check" "$@" >"$work/out" 2>&1
  local got=$?
  if [ "$got" -ne "$want" ]; then
    echo "FAILED: $what: the checker exited $got, expected $want"
    cat "$work/out"
    failures=$((failures + 1))
  fi
}
expect 0 "good output" -- --expect "[0-9.]+ ns per call" -- printf '12.5 ns per call\n'
expect 1 "-nan" -- --expect "ns per call" -- printf -- '-nan ns per call\n'
expect 1 "inf" -- --expect "ratio" -- printf 'ratio inf\n'
expect 1 "a missing figure" -- --expect "[0-9.]+ ns per call" -- printf 'ns per call\n'
expect 1 "a failed program" -- -- false
expect 0 "an expected exit code" -- --exit 2 -- sh -c 'exit 2'
printf '{\n  "ratio": 0.5\n}\n' >"$work/good.json"
expect 0 "good JSON" -- --json "$work/written.json" --json-expect '"ratio": 0' -- cp "$work/good.json" "$work/written.json"
expect 1 "JSON not written" -- --json "$work/never.json" -- true
printf '{\n  "ratio": null\n}\n' >"$work/null.json"
expect 1 "null in the JSON" -- --json "$work/written.json" -- cp "$work/null.json" "$work/written.json"
expect 1 "a JSON key missing" -- --json "$work/written.json" --json-expect '"dispatch"' -- cp "$work/good.json" "$work/written.json"
if [ "$failures" -gt 0 ]; then
  echo "$failures case(s) failed"
  exit 1
fi
echo "check_bench_output.sh: 10 cases as expected"
