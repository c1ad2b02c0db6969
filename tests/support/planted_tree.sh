# Sourced by the tests of the tree's own checks (tests/layers/,
# tests/docs/): each copies the tree, plants one thing in the copy, and
# runs its check there, which must refuse it naming what it found (or,
# for a mere naming, let it pass). Before sourcing, set `root` (the source
# tree), `check` (the script under test, given the tree's folder) and
# `copied` (the arguments to `find` that select the files to copy, less
# the final -print). Makes `$work`, removed on exit.
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# A fresh copy of the selected files in $work/tree.
copy() {
  rm -rf "$work/tree" && mkdir -p "$work/tree"
  (cd "$root" && find "${copied[@]}" -print | tar cf - -T -) | tar xf - -C "$work/tree"
}

# WHAT EXPECTED-TEXT: the check refuses $work/tree (already changed as WHAT
# says) with EXPECTED-TEXT in its output.
expect_refused() {
  local out
  if out=$(bash "$check" "$work/tree" 2>&1); then
    echo "FAIL: the check passed with $1" >&2; exit 1
  fi
  if ! grep -qF "$2" <<<"$out"; then
    echo "FAIL: expected '$2' in:" >&2; echo "$out" >&2; exit 1
  fi
  echo "ok: $1 is refused"
}

# FILE LINE-TO-PLANT EXPECTED-TEXT: a fresh copy with the line appended to
# FILE is refused, with EXPECTED-TEXT in the check's output.
expect_failure() {
  copy
  echo "$2" >> "$work/tree/$1"
  expect_refused "'$2' planted in $1" "$3"
}

# FILE LINE-TO-PLANT: a fresh copy with the line appended to FILE passes.
expect_pass() {
  local out
  copy
  echo "$2" >> "$work/tree/$1"
  if ! out=$(bash "$check" "$work/tree" 2>&1); then
    echo "FAIL: the check refused '$2' in $1:" >&2; echo "$out" >&2; exit 1
  fi
  echo "ok: '$2' in $1 passes"
}

# The copy as it is passes: each refusal that follows is the planted
# thing's, not the copy's (a copy missing a layer would refuse anything).
copy
if ! copy_out=$(bash "$check" "$work/tree" 2>&1); then
  echo "FAIL: the check refuses the unchanged copy:" >&2; echo "$copy_out" >&2; exit 1
fi
