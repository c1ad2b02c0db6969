#!/usr/bin/env bash
# Runs a benchmark program once and checks what it printed (the test
# suite's bench-smoke tests, bench/CMakeLists.txt): the exit code, a line
# matching each --expect pattern (extended regular expressions, usually
# with the figure's digits in them), no NaN or infinity anywhere, and, with
# --json FILE, that the program wrote FILE with every --json-expect pattern
# in it and no null (what nlohmann-json writes for a NaN).
#
#   check_bench_output.sh [--exit N] [--expect RE]... [--json FILE [--json-expect RE]...] -- COMMAND [ARG]...
set -uo pipefail

expected_exit=0
expects=()
json=""
json_expects=()
while [ $# -gt 0 ]; do
  case "$1" in
    --exit) expected_exit=$2; shift 2 ;;
    --expect) expects+=("$2"); shift 2 ;;
    --json) json=$2; shift 2 ;;
    --json-expect) json_expects+=("$2"); shift 2 ;;
    --) shift; break ;;
    *) echo "check_bench_output.sh: unknown argument '$1'" >&2; exit 2 ;;
  esac
done
if [ $# -eq 0 ]; then
  echo "check_bench_output.sh: no command after --" >&2
  exit 2
fi

output=$(mktemp)
trap 'rm -f "$output"' EXIT
[ -n "$json" ] && rm -f "$json"
"$@" >"$output" 2>&1
code=$?

failed=0
fail() {
  echo "FAILED: $*"
  failed=1
}
[ "$code" -eq "$expected_exit" ] || fail "exit code $code, expected $expected_exit"
for re in "${expects[@]}"; do
  grep -Eq -- "$re" "$output" || fail "no line matches: $re"
done
if grep -Eiwq -- '-?(nan|inf|infinity)' "$output"; then
  fail "NaN or infinity printed: $(grep -Eiw -- '-?(nan|inf|infinity)' "$output" | head -3)"
fi
if [ -n "$json" ]; then
  if [ ! -s "$json" ]; then
    fail "no JSON written to $json"
  else
    for re in "${json_expects[@]}"; do
      grep -Eq -- "$re" "$json" || fail "nothing in $json matches: $re"
    done
    if grep -Eq -- ':[[:space:]]*null' "$json"; then
      fail "null (a NaN?) in $json: $(grep -En -- ':[[:space:]]*null' "$json" | head -3)"
    fi
  fi
fi

echo "== $* (exit $code)"
cat "$output"
exit "$failed"
