#!/usr/bin/env bash
# The layer check (scripts/check-layers.sh) passes on the tree, and fails
# on copies of it with an include planted that points up, or sideways into
# a layer that is not allowed, naming the file, the line and the layers,
# and on a list that allows an edge no include uses; then the opcode-name
# check (test_opcode_names.sh).
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
check="$root/scripts/check-layers.sh"
bash "$check" "$root"

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
copy() {
  rm -rf "$work/tree" && mkdir -p "$work/tree"
  (cd "$root" && find base diag model vm stdlib compiler runtime cli bench tests scripts \
     -path tests/browser/node_modules -prune -o \( -name '*.h' -o -name '*.cpp' -o -name '*.txt' -o -name '*.sh' \) \
     -type f -print | tar cf - -T -) | tar xf - -C "$work/tree"
}
expect_failure() {  # FILE LINE-TO-PLANT EXPECTED-TEXT
  copy
  echo "$2" >> "$work/tree/$1"
  if out=$(bash "$check" "$work/tree" 2>&1); then
    echo "FAIL: the check passed with '$2' planted in $1" >&2; exit 1
  fi
  if ! grep -qF "$3" <<<"$out"; then
    echo "FAIL: expected '$3' in:" >&2; echo "$out" >&2; exit 1
  fi
  echo "ok: '$2' in $1 is refused"
}
expect_failure vm/opcodes.cpp '#include "compiler/program/compiler.h"' \
  'vm/opcodes.cpp:'
expect_failure vm/opcodes.cpp '#include "compiler/program/compiler.h"' \
  'vm includes "compiler/program/compiler.h" of layer compiler/program, which vm may not include'
expect_failure model/kinematics/frame.cpp '#include "model/workcell/model.h"' \
  'model/kinematics includes "model/workcell/model.h" of layer model/workcell'
expect_failure runtime/sim/sim_machine.cpp '#include "runtime/render/scene.h"' \
  'runtime/sim includes "runtime/render/scene.h" of layer runtime/render'
expect_failure diag/diagnostic.cpp '#include "../vm/opcodes.h"' \
  'diag includes "vm/opcodes.h" of layer vm'
expect_failure compiler/program/lexer.cpp '#include "nowhere.h"' \
  'include "nowhere.h" names no file of the tree'
# An edge the list allows and no include uses: refused, naming the edge.
copy
sed -i 's|^teach/tui *: .*|& vm|' "$work/tree/scripts/layers.txt"
if out=$(bash "$check" "$work/tree" 2>&1); then
  echo "FAIL: the check passed with an unused edge teach/tui -> vm in the list" >&2; exit 1
fi
grep -qF 'layer teach/tui may include vm, but no file of it does' <<<"$out" ||
  { echo "FAIL: expected the unused edge named in:" >&2; echo "$out" >&2; exit 1; }
echo "ok: an allowed edge no include uses is refused"
echo "layers: every planted upward include and the unused edge were caught"
# No layer outside vm/ matches an opcode by name (docs/architecture.md).
bash "$(dirname "$0")/test_opcode_names.sh"
