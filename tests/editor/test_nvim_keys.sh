#!/usr/bin/env bash
# docs/editors.md's Neovim setup used as a person uses it: the first ```lua
# block of its "## Neovim" section copied verbatim into a fresh
# configuration (its own XDG folders, nothing else), the built robotsim
# first on PATH, a real Neovim (Debian's, 0.7) running on a program, and
# the keys a user presses sent to it as typed input (`nvim --server S
# --remote-send`: they go through Neovim's own input, mappings and all),
# never vim.lsp.buf calls. What the screen would show is read back with
# --remote-expr:
#   K         a floating window with the server's hover of MOVE
#   gd        the cursor on the label the GOSUB names
#   Ctrl-X Ctrl-O (insert mode) the server's completions, one taken
# Usage: test_nvim_keys.sh ROBOTSIM_BINARY SOURCE_DIR WORK_DIR
set -euo pipefail
binary=$1 source=$2 work=$3
rm -rf "$work" && mkdir -p "$work/config/nvim" "$work/data" "$work/state" "$work/bin" "$work/project"

awk '/^## Neovim$/ { in_section = 1; next }
     in_section && /^## / { exit }
     in_section && /^```lua$/ { in_block = 1; next }
     in_block && /^```$/ { exit }
     in_block { print }' "$source/docs/editors.md" > "$work/config/nvim/init.lua"
if ! grep -q "robotsim" "$work/config/nvim/init.lua"; then
  echo "test_nvim_keys: no lua block under '## Neovim' in docs/editors.md" >&2
  exit 1
fi
ln -s "$binary" "$work/bin/robotsim"

# Line 2 calls pick (defined on line 5); line 5's MOVE is what K explains.
printf '; keys\n        GOSUB pick\n        END\n\npick:   MOVE 0 0 -150 0 0\n        RETURN\n' > "$work/project/keys.rsp"

cd "$work/project"
export XDG_CONFIG_HOME=$work/config XDG_DATA_HOME=$work/data XDG_STATE_HOME=$work/state
export PATH="$work/bin:$PATH"
socket=$work/nvim.sock
nvim --headless --listen "$socket" keys.rsp > "$work/nvim.log" 2>&1 &
nvim_pid=$!
trap 'kill "$nvim_pid" 2>/dev/null || true' EXIT

fail() {
  echo "test_nvim_keys: FAILED: $*" >&2
  exit 1
}
# (the client prints the value on its standard error)
expr() { timeout 10 nvim --server "$socket" --remote-expr "$1" 2>&1; }
# (the client may complain on its way out that the server closed the channel: not ours to check)
keys() { timeout 10 nvim --server "$socket" --remote-send "$1" 2>/dev/null || true; }
# Polls an expression until it prints what is expected (within $3 s).
wait_for() {
  local want=$1 what=$2 seconds=${3:-20} got=
  for ((i = 0; i < seconds * 10; ++i)); do
    got=$(expr "$what" || true)
    [ "$got" = "$want" ] && return 0
    sleep 0.1
  done
  fail "$what is '$got', not '$want'"
}

for ((i = 0; i < 100; ++i)); do [ -S "$socket" ] && break; sleep 0.1; done
[ -S "$socket" ] || fail "Neovim did not start (log: $(cat "$work/nvim.log"))"
wait_for robotsim '&filetype'
wait_for 1 'luaeval("#vim.lsp.buf_get_clients(0)")'
# The server has answered initialize (on_attach has run): the buffer's keys are there.
wait_for 1 'luaeval("vim.lsp.buf_get_clients(0)[1].initialized and 1 or 0")'
wait_for 'v:lua.vim.lsp.omnifunc' '&omnifunc'

# K on MOVE (line 5, column 9): a floating window with the hover.
keys '<Esc>5G0fM'
wait_for '5 9' 'line(".") . " " . col(".")'
keys 'K'
floats='luaeval("(function() local t = {} for _, w in ipairs(vim.api.nvim_list_wins()) do if vim.api.nvim_win_get_config(w).relative ~= \"\" then table.insert(t, table.concat(vim.api.nvim_buf_get_lines(vim.api.nvim_win_get_buf(w), 0, -1, false), \"\\n\")) end end return table.concat(t, \"\\n\") end)()")'
shown=
for ((i = 0; i < 200; ++i)); do
  shown=$(expr "$floats" || true)
  [ -n "$shown" ] && break
  sleep 0.1
done
[ -n "$shown" ] || fail "K showed no hover window"
case $shown in
  *MOVE*) ;;
  *) fail "the hover window says: $shown" ;;
esac
case $shown in
  *relative*|*motor*) ;;
  *) fail "the hover window does not explain MOVE: $shown" ;;
esac

# gd on pick in "GOSUB pick" (line 2): to line 5, where pick: is.
keys '<Esc>2G0fp'
wait_for '2 15' 'line(".") . " " . col(".")'
keys 'gd'
wait_for '5 1' 'line(".") . " " . col(".")'

# Completion: a new line, MOVET typed, Ctrl-X Ctrl-O: the server's MOVETO,
# taken with Ctrl-Y.
keys 'GoMOVET<C-x><C-o>'
wait_for 1 'complete_info(["items"]).items->len() > 0 ? 1 : 0'
items=$(expr 'join(map(complete_info(["items"]).items, "v:val.word"), " ")')
case " $items " in
  *" MOVETO "*) ;;
  *) fail "completion offered: $items" ;;
esac
keys '<C-y><Esc>'
wait_for MOVETO 'trim(getline("."))'
wait_for n 'mode()'

keys '<Esc>:qall!<CR>'
for ((i = 0; i < 50; ++i)); do kill -0 "$nvim_pid" 2>/dev/null || break; sleep 0.1; done
echo "test_nvim_keys: K, gd and completion work through the keys"
