#!/usr/bin/env bash
# Every library robot exported as URDF (robotsim export ROBOT --urdf) passes
# check_urdf, urdfdom's own checker (Debian's liburdfdom-tools), and so do
# the hand-written files of tests/urdf/data. Skipped (exit 77), saying so,
# when check_urdf is not installed.
#   test_check_urdf.sh ROBOTSIM SOURCE_DIR WORK_DIR
set -euo pipefail
robotsim=$1 source=$2 work=$3
if ! command -v check_urdf >/dev/null 2>&1; then
  echo "SKIPPED: check_urdf is not installed (Debian's liburdfdom-tools; bash scripts/setup.sh test installs it)"
  exit 77
fi
rm -rf "$work" && mkdir -p "$work"
count=0
for rsd in "$source"/stdlib/robots/*.rsd; do
  name=$(basename "$rsd" .rsd)
  "$robotsim" export "$name" --urdf -o "$work/$name.urdf" >/dev/null
  if ! check_urdf "$work/$name.urdf" >"$work/$name.check" 2>&1; then
    echo "FAIL: check_urdf refuses the export of $name:"; cat "$work/$name.check"; exit 1
  fi
  # The tree it prints ends at tool0, under the last arm link.
  grep -q 'child([0-9]*):  *tool0$' "$work/$name.check" || { echo "FAIL: $name has no tool0"; cat "$work/$name.check"; exit 1; }
  count=$((count + 1))
done
[ "$count" -eq 10 ] || { echo "FAIL: expected the library's 10 robots, exported $count"; exit 1; }
for urdf in "$source"/tests/urdf/data/*.urdf; do
  check_urdf "$urdf" >"$work/check.out" 2>&1 || { echo "FAIL: check_urdf refuses $urdf:"; cat "$work/check.out"; exit 1; }
done
echo "check_urdf: the 10 library robots' exports and the hand-written files pass"
