#!/usr/bin/env bash
# docs/editors.md's Neovim setup, as written: the first ```lua block of its
# "## Neovim" section copied verbatim into a fresh configuration (its own
# XDG folders, nothing else), the built robotsim first on PATH as the
# snippet's `robotsim`, then a real `nvim --headless` (not --clean: the
# configuration is the point) opens a program with a misspelt instruction
# and must show the server's diagnostic at that line (nvim_setup_check.lua).
# Usage: test_nvim_setup.sh ROBOTSIM_BINARY SOURCE_DIR WORK_DIR
set -euo pipefail
binary=$1 source=$2 work=$3
rm -rf "$work" && mkdir -p "$work/config/nvim" "$work/data" "$work/state" "$work/bin" "$work/project"

awk '/^## Neovim$/ { in_section = 1; next }
     in_section && /^## / { exit }
     in_section && /^```lua$/ { in_block = 1; next }
     in_block && /^```$/ { exit }
     in_block { print }' "$source/docs/editors.md" > "$work/config/nvim/init.lua"
if ! grep -q "robotsim" "$work/config/nvim/init.lua"; then
  echo "test_nvim_setup: no lua block under '## Neovim' in docs/editors.md" >&2
  exit 1
fi
ln -s "$binary" "$work/bin/robotsim"

# A program with a typo on its third line (HRDHOM, no instruction), no
# cell line: checked on the default robot.
printf '; a typo for the editor to show\n        HRDHOME\n        HRDHOM\n        END\n' > "$work/project/typo.rsp"

cd "$work/project"
export XDG_CONFIG_HOME=$work/config XDG_DATA_HOME=$work/data XDG_STATE_HOME=$work/state
export PATH="$work/bin:$PATH"
export NVIM_SETUP_FILE=$work/project/typo.rsp
timeout 60 nvim --headless -c "luafile $source/tests/editor/nvim_setup_check.lua"
