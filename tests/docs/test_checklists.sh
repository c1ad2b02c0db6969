#!/usr/bin/env bash
# docs/architecture.md's checklists against the tree
# (scripts/check-checklists.sh): pass on the tree, and fail on copies of
# it with a named file gone, a switch over vm::Format in a file the
# checklist does not name, or a file dropped from the checklist, each
# time naming the file.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
check="$root/scripts/check-checklists.sh"
bash "$check" "$root"

copied=(base diag model vm stdlib compiler runtime launch tools bench docs examples
        editors/vscode/syntaxes scripts tests -path tests/browser/node_modules -prune -o -type f)
source "$root/tests/support/planted_tree.sh"
copy
rm "$work/tree/tools/lsp/features/completion.cpp"
expect_refused "a named file gone" "the checklists name tools/lsp/features/completion.cpp, which is not in the tree"
copy
printf 'int planted(rs::vm::Format f) {\n  switch (f) {\n    case rs::vm::Format::None: return 0;\n    default: return 1;\n  }\n}\n' \
  >> "$work/tree/runtime/run/trace.cpp"
expect_refused "a switch over Format in runtime/run/trace.cpp" \
  "runtime/run/trace.cpp has a switch over vm::Op or vm::Format, but"
copy
sed -i 's|`compiler/program/codegen.cpp` (encoding), ||' "$work/tree/docs/architecture.md"
expect_refused "codegen.cpp dropped from the checklist" \
  "compiler/program/codegen.cpp has a switch over vm::Op or vm::Format, but"
copy
sed -i 's|^## Adding an operand shape$|## Adding a shape|' "$work/tree/docs/architecture.md"
expect_refused "a checklist section renamed" 'no section "## Adding an operand shape"'
echo "checklists: every planted staleness was caught"
