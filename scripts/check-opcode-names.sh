#!/usr/bin/env bash
# Checks that no layer outside vm/ decides by an opcode's name: every fact
# about an instruction (calls, returns, branches, waits, ends, jumps,
# moves, ...) is a flag or the format in vm::kOps, and the other layers ask
# those (docs/architecture.md, "Instruction facts").
#
#   scripts/check-opcode-names.sh [ROOT]     (ROOT defaults to this checkout)
#
# Matching by name is comparing an opcode with a named one (== Op::Gosub,
# Op::Gosub != ...), a case label of one, a list of two or more (a set of
# them), or `using enum vm::Op`. Naming one is not: a default value
# (Op op = Op::End), an instruction built or emitted ({Op::MoveTo, ...}).
# tests/ may name opcodes (a test of GOSUB is about GOSUB). Prints one
# `file:line: error:` per match and exits 1 if there is any; exits 0 and
# prints a one-line summary otherwise.
set -euo pipefail
root=${1:-"$(cd "$(dirname "$0")/.." && pwd)"}
cd "$root"

# The opcode names, from the enum itself.
names=$(sed -n '/^enum class Op\b/,/^};/p' vm/opcodes.h | grep -oE '^[[:space:]]+[A-Z][A-Za-z0-9]*' | tr -d ' \t' |
  paste -sd'|')
[ -n "$names" ] || { echo "vm/opcodes.h: error: no enum class Op found to take the opcode names from" >&2; exit 1; }

q='((rs::)?vm::)?Op::('"$names"')\b'     # a named opcode, qualified or not
b='(^|[^:[:alnum:]_])'                   # not the tail of another enum's Op (Condition::Op::Eq)
pattern="(==|!=)[[:space:]]*$q|$b$q[[:space:]]*(==|!=)|\bcase[[:space:]]+$q|$b$q[[:space:]]*,[[:space:]]*$q"
pattern="$pattern|\busing[[:space:]]+enum[[:space:]]+((rs::)?vm::)?Op\b"

files=$(find base diag model stdlib compiler runtime launch tools bench \
  \( -name '*.h' -o -name '*.cpp' \) -type f -print 2>/dev/null | LC_ALL=C sort)
bad=0
if [ -n "$files" ]; then
  # shellcheck disable=SC2086  # the file names have no blanks (the layer check holds them to folders)
  matches=$(grep -nE "$pattern" $files || true)
  if [ -n "$matches" ]; then
    bad=1
    while IFS= read -r m; do
      file=${m%%:*}; rest=${m#*:}; line=${rest%%:*}
      op=$(grep -oE "Op::($names)\b|using[[:space:]]+enum[[:space:]]+[[:alnum:]_:]*Op" <<<"${rest#*:}" | head -1)
      echo "$file:$line: error: opcode $op matched by name outside vm/: ask its flags or format in vm::kOps" \
        "(vm::has(op, vm::kCalls), ...), see docs/architecture.md, \"Instruction facts\""
    done <<<"$matches"
  fi
fi
if [ "$bad" -ne 0 ]; then exit 1; fi
echo "opcode names: $(wc -l <<<"$files") files outside vm/ decide by flags and formats, none by an opcode's name"
