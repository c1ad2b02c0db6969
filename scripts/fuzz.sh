#!/usr/bin/env bash
# A long fuzzing campaign: builds the libFuzzer targets of tests/fuzz
# optimised (clang, RelWithDebInfo, AddressSanitizer + UBSan) in
# build-fuzz/, then runs each for RUNS inputs (default 10 million), one
# after the other, and prints a line of figures per target. Findings stop
# that target with libFuzzer's report; the input is kept in
# build-fuzz/campaign/<target>/ and the script exits non-zero at the end.
#   bash scripts/fuzz.sh [--runs N] [--seconds S] [TARGET ...] [-- LIBFUZZER-OPTION ...]
# (default: every target). --seconds stops each target after S seconds if
# it has not run N inputs; options after -- go to each target (-max_len=1024).
# docs/reliability.md shows the figures of one campaign.
set -euo pipefail
cd "$(dirname "$0")/.."
runs=10000000
seconds=0
targets=()
extra=()
while [ $# -gt 0 ]; do
  case "$1" in
    --runs) runs=$2; shift 2 ;;
    --seconds) seconds=$2; shift 2 ;;
    -h | --help) sed -n '2,11p' "$0"; exit 0 ;;
    --) shift; extra=("$@"); break ;;
    *) targets+=("$1"); shift ;;
  esac
done
dir=build-fuzz
CC=clang CXX=clang++ cmake -S . -B "$dir" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DROBOTSIM_SANITIZE=ON \
  -DROBOTSIM_FUZZ=ON -DROBOTSIM_WERROR=ON >/dev/null
cmake --build "$dir" -j "$(nproc)" --target robotsim_fuzzers
[ ${#targets[@]} -gt 0 ] || targets=($(cd "$dir/tests/fuzz" && ls fuzz_* | grep -v '\.'))
failed=0
for t in "${targets[@]}"; do
  start=$(date +%s)
  log="$dir/campaign/$t.log"
  mkdir -p "$dir/campaign"
  # The message readers' inputs stay short: every state of the framing and
  # of the reading is reached within 256 bytes (chunked_frames.h refuses
  # bodies over 64 bytes in half of them), and longer inputs, mostly whole
  # sessions from the seeds, cost five times the rate.
  opts=()
  case "$t" in *_reader) opts=(-max_len=256) ;; esac
  if bash tests/fuzz/run.sh --fuzzer "$dir/tests/fuzz/$t" --robotsim "$dir/robotsim" --work "$dir/campaign" \
       --runs "$runs" -- -max_total_time="$seconds" "${opts[@]}" "${extra[@]}" >"$log" 2>&1; then verdict="no finding"; else verdict="FINDING (see $log)"; failed=1; fi
  secs=$(( $(date +%s) - start ))
  execs=$(grep -o 'number_of_executed_units: [0-9]*' "$log" | tail -1 | grep -o '[0-9]*$' || echo "?")
  cov=$(grep -o 'cov: [0-9]*' "$log" | tail -1 | grep -o '[0-9]*$' || echo "?")
  corpus=$(ls "$dir/campaign/$t" | wc -l)
  echo "fuzz: $t: $execs inputs in ${secs}s, coverage $cov edges, $corpus new corpus inputs: $verdict"
done
exit $failed
