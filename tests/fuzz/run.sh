#!/usr/bin/env bash
# Runs one libFuzzer target of tests/fuzz on its seed corpus: the hand-made
# seeds in tests/fuzz/corpus/<reader>/ plus the project's own files of that
# kind (examples/, stdlib/, tests/golden/; images are compiled from the
# examples first). New inputs go to a work directory, emptied first, so a
# run with the same --runs is the same run (libFuzzer -seed=1).
#   bash tests/fuzz/run.sh --fuzzer BIN --robotsim BIN --work DIR --runs N [-- libFuzzer options]
# A finding (crash, leak, UB, timeout) stops the run with libFuzzer's report
# and a non-zero exit; the input that did it is left in DIR/<target>/.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
fuzzer="" robotsim="" work="" runs=10000 extra=()
while [ $# -gt 0 ]; do
  case "$1" in
    --fuzzer) fuzzer=$2; shift 2 ;;
    --robotsim) robotsim=$2; shift 2 ;;
    --work) work=$2; shift 2 ;;
    --runs) runs=$2; shift 2 ;;
    --) shift; extra=("$@"); break ;;
    *) echo "run.sh: unknown argument '$1' (see the comment at the top)" >&2; exit 2 ;;
  esac
done
[ -x "$fuzzer" ] && [ -n "$work" ] || { echo "run.sh: --fuzzer BIN and --work DIR are required" >&2; exit 2; }
name=$(basename "$fuzzer")
reader=${name#fuzz_}
reader=${reader%_fixed}
reader=${reader%_reader}
reader=${reader%_arms}
out="$work/$name"
rm -rf "$out" && mkdir -p "$out"

seeds=()
[ -d "$here/corpus/$reader" ] && seeds+=("$here/corpus/$reader")
# Scenario files of cells of several robots: program LABEL FILE, test: robot, LABEL. expectations.
[ "$reader" = test_file ] && seeds+=("$root/examples/two_robots" "$root/examples/tests/grading_cell")
case "$reader" in
  program | stimuli | test_file | points)
    seeds+=("$root/examples" "$root/examples/tests/passing" "$root/examples/tests/failing"
            "$root/examples/tests/grading" "$root/tests/golden") ;;
  urdf)
    seeds+=("$root/tests/urdf/data_read") ;;
  description)
    seeds+=("$root/stdlib/robots" "$root/stdlib/workcells" "$root/stdlib/grippers" "$root/stdlib/objects") ;;
  image)
    [ -x "$robotsim" ] || { echo "run.sh: the image seeds need --robotsim BIN" >&2; exit 2; }
    mkdir -p "$work/seeds-image"
    for f in "$root"/examples/*.rsp "$root"/tests/golden/*.rsp; do
      "$robotsim" compile "$f" -o "$work/seeds-image/$(basename "$f" .rsp).rsb" >/dev/null 2>&1 || true
    done
    # Images that carry a cell: geometry, and a cell with devices (section version 3).
    "$robotsim" compile "$root/examples/gantry_pick.rsp" --cell gantry-cell -o "$work/seeds-image/gantry_cell.rsb" >/dev/null 2>&1 || true
    "$robotsim" compile "$root/examples/adept_production.rsp" --cell adept-cell -o "$work/seeds-image/adept_cell.rsb" >/dev/null 2>&1 || true
    seeds+=("$work/seeds-image") ;;
esac

# A reader's keywords, when it has a dictionary (description.dict).
# The device run's inputs are a WORKCELL's lines: the description's words.
dict=$reader
[ "$reader" = device_run ] && dict=description
[ -f "$here/$dict.dict" ] && extra+=("-dict=$here/$dict.dict")

# The debug adapter's seeds launch examples/ programs by relative paths:
# it runs from the top of the tree (its own paths made absolute first).
if [ "$reader" = dap ]; then
  fuzzer=$(realpath "$fuzzer") out=$(realpath "$out")
  cd "$root"
fi

echo "fuzz: $name, $runs inputs, seeds from ${#seeds[@]} directories" >&2
# -rss_limit_mb: the readers' own limits keep far below it; -timeout: ten
# seconds for one input, under the sanitizers (every reader is linear in
# its input's size, and inputs here stay under a few KiB).
exec "$fuzzer" -seed=1 -runs="$runs" -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 -artifact_prefix="$out/" \
  "${extra[@]}" "$out" "${seeds[@]}"
