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

copied=(base diag model vm stdlib grammar compiler runtime launch tools bench tests scripts
        -path tests/browser/node_modules -prune
        -o \( -name '*.h' -o -name '*.cpp' -o -name '*.txt' -o -name '*.sh' \) -type f)
source "$root/tests/support/planted_tree.sh"
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
sed -i 's|^tools/wire *: .*|& vm|' "$work/tree/scripts/layers.txt"
expect_refused "an unused edge tools/wire -> vm in the list" 'layer tools/wire may include vm, but no file of it does'
echo "layers: every planted upward include and the unused edge were caught"
# No layer outside vm/ matches an opcode by name (docs/architecture.md).
bash "$(dirname "$0")/test_opcode_names.sh"
