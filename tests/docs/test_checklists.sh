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

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
copy() {
  rm -rf "$work/tree" && mkdir -p "$work/tree"
  (cd "$root" && find base diag model vm stdlib compiler runtime launch teach testrun wire lsp debug dap cli bench \
     docs examples editors/vscode/syntaxes tests -path tests/browser/node_modules -prune -o -type f -print |
     tar cf - -T -) | tar xf - -C "$work/tree"
}
expect_failure() {  # WHAT EXPECTED-TEXT (the tree at $work/tree already changed)
  if out=$(bash "$check" "$work/tree" 2>&1); then
    echo "FAIL: the check passed with $1" >&2; exit 1
  fi
  if ! grep -qF "$2" <<<"$out"; then
    echo "FAIL: expected '$2' in:" >&2; echo "$out" >&2; exit 1
  fi
  echo "ok: $1 is refused"
}
copy
rm "$work/tree/lsp/features/completion.cpp"
expect_failure "a named file gone" "the checklists name lsp/features/completion.cpp, which is not in the tree"
copy
printf 'int planted(rs::vm::Format f) {\n  switch (f) {\n    case rs::vm::Format::None: return 0;\n    default: return 1;\n  }\n}\n' \
  >> "$work/tree/runtime/run/trace.cpp"
expect_failure "a switch over Format in runtime/run/trace.cpp" \
  "runtime/run/trace.cpp has a switch over vm::Op or vm::Format, but"
copy
sed -i 's|`compiler/program/codegen.cpp` (encoding), ||' "$work/tree/docs/architecture.md"
expect_failure "codegen.cpp dropped from the checklist" \
  "compiler/program/codegen.cpp has a switch over vm::Op or vm::Format, but"
copy
sed -i 's|^## Adding an operand shape$|## Adding a shape|' "$work/tree/docs/architecture.md"
expect_failure "a checklist section renamed" 'no section "## Adding an operand shape"'
echo "checklists: every planted staleness was caught"
