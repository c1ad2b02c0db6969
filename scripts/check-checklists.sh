#!/usr/bin/env bash
# Checks docs/architecture.md's checklists against the tree, so that they
# cannot go stale: every file the "Adding an instruction", "Adding an
# operand shape" and "Adding a library robot" sections name exists (a
# NAME in a path stands for the new thing and is not looked for), and
# every source file with a `switch` over vm::Op or vm::Format (a case label
# of either) is named in the first two.
#
#   scripts/check-checklists.sh [ROOT]     (ROOT defaults to this checkout)
#
# Prints one `docs/architecture.md: error:` per problem and exits 1 if
# there is any; exits 0 and prints a one-line summary otherwise.
set -euo pipefail
root=${1:-"$(cd "$(dirname "$0")/.." && pwd)"}
cd "$root"
doc=docs/architecture.md

section() {  # HEADING: the lines of one "## HEADING" section
  awk -v h="## $1" '$0 == h { on = 1; next } on && /^## / { exit } on' "$doc"
}
paths() {  # the backquoted paths of stdin: a folder, then a file with an extension
  grep -oE '`[A-Za-z0-9_./-]+`' | tr -d '`' | grep -E '^[a-z][A-Za-z0-9_-]*/([A-Za-z0-9_./-]*)$' |
    grep -E '/$|\.[a-z]+$' | LC_ALL=C sort -u
}

bad=0
instruction=$(section "Adding an instruction"; section "Adding an operand shape")
robot=$(section "Adding a library robot")
for heading in "Adding an instruction" "Adding an operand shape" "Adding a library robot"; do
  if [ -z "$(section "$heading")" ]; then
    echo "$doc: error: no section \"## $heading\""; bad=1
  fi
done

named=$( (paths <<<"$instruction"; paths <<<"$robot") | LC_ALL=C sort -u)
count=0
while IFS= read -r p; do
  [ -n "$p" ] || continue
  count=$((count + 1))
  case "$p" in *NAME*) continue ;; esac
  if [ ! -e "$p" ]; then
    echo "$doc: error: the checklists name $p, which is not in the tree"; bad=1
  fi
done <<<"$named"

# Every file that switches over an opcode or a format: a case label of one.
enum_names() { sed -n "/^enum class $1\b/,/^};/p" vm/opcodes.h | grep -oE '^[[:space:]]+[A-Z][A-Za-z0-9]*' |
  tr -d ' \t' | paste -sd'|'; }
ops=$(enum_names Op); formats=$(enum_names Format)
case_re="\bcase[[:space:]]+((rs::)?vm::)?(Op::($ops)|Format::($formats))\b"
switching=$(find base diag model vm stdlib compiler runtime launch tools bench \
  \( -name '*.h' -o -name '*.cpp' \) -type f -print 2>/dev/null | LC_ALL=C sort | xargs grep -lE "$case_re" || true)
listed=$(paths <<<"$instruction")
while IFS= read -r f; do
  [ -n "$f" ] || continue
  if ! grep -qxF "$f" <<<"$listed"; then
    echo "$doc: error: $f has a switch over vm::Op or vm::Format, but \"Adding an instruction\" and" \
      "\"Adding an operand shape\" do not name it"
    bad=1
  fi
done <<<"$switching"
if [ "$bad" -ne 0 ]; then exit 1; fi
echo "checklists: $count paths named, all in the tree; $(grep -c . <<<"$switching") files switch over Op or Format," \
  "all named"
