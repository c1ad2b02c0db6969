#!/usr/bin/env bash
# The opcode-name check (scripts/check-opcode-names.sh) passes on the tree,
# and fails on copies of it with a match by an opcode's name planted outside
# vm/ (a comparison either way round, a case label, a set, `using enum`),
# naming the file, the line and the opcode; naming an opcode without
# matching it (a default value, an instruction built) and another enum's
# Op (debug's Condition::Op::Eq) pass.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
check="$root/scripts/check-opcode-names.sh"
bash "$check" "$root"

copied=(base diag model vm stdlib compiler runtime launch tools bench
        \( -name '*.h' -o -name '*.cpp' \) -type f)
source "$root/tests/support/planted_tree.sh"
lines=$(wc -l < "$root/tools/testrun/coverage.cpp")
expect_failure tools/testrun/coverage.cpp 'bool b(vm::Op op) { return op == vm::Op::JmpIn; }' \
  "tools/testrun/coverage.cpp:$((lines + 1)): error: opcode Op::JmpIn matched by name outside vm/"
expect_failure runtime/run/profile.cpp 'bool b(vm::Op op) { return rs::vm::Op::Gosub!=op; }' \
  'error: opcode Op::Gosub matched by name outside vm/'
expect_failure tools/lsp/program_index.cpp 'int f(vm::Op op) { switch (op) { case vm::Op::Return: return 1; default: return 0; } }' \
  'error: opcode Op::Return matched by name outside vm/'
expect_failure tools/cli/lib/app.cpp 'const std::set<vm::Op> waits{vm::Op::WaitFor, vm::Op::Delay};' \
  'error: opcode Op::WaitFor matched by name outside vm/'
expect_failure launch/run_diagnostics.cpp 'using enum vm::Op;' \
  'error: opcode using enum vm::Op matched by name outside vm/'
expect_failure bench/generate.cpp 'bool e(Op op) { return op==Op::End; }' \
  'error: opcode Op::End matched by name outside vm/'
expect_pass tools/lsp/program_index.cpp 'struct Planted { vm::Op op = vm::Op::End; };'
expect_pass compiler/program/codegen.cpp 'const vm::Instr planted{vm::Op::MoveTo, 0, 2, 0, 0};'
expect_pass tools/debug/expression.cpp 'bool planted(Condition c) { return c.op == Condition::Op::Eq; }'
echo "opcode names: every planted match by name outside vm/ was caught, every mere naming passed"
