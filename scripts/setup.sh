#!/usr/bin/env bash
# Installs from Debian's packages what robotsim needs, and nothing more:
#   bash scripts/setup.sh         building and running (the demo)
#   bash scripts/setup.sh test    also testing: the browser test's Chromium,
#                                 Node and its pinned packages
# Idempotent: asks apt only for what is missing. Runs as root (or via sudo).
set -euo pipefail
cd "$(dirname "$0")/.."
mode=${1:-build}
case "$mode" in
  build | test) ;;
  *) echo "usage: bash scripts/setup.sh [build|test]" >&2; exit 2 ;;
esac

# libedit-dev: line editing and history at the prompt of robotsim debug;
# libedit (BSD licence) rather than GNU readline, whose GPL would bind the
# whole robotsim binary that links it.
packages=(
  build-essential cmake make ninja-build pkg-config
  antlr4 libantlr4-runtime-dev default-jre-headless
  libeigen3-dev libfmt-dev catch2 libcli11-dev nlohmann-json3-dev
  libcairo2-dev libedit-dev
  libcpp-httplib-dev libncurses-dev
  liburdfdom-dev libtinyxml2-dev libconsole-bridge-dev libassimp-dev
)
# ninja-build: scripts/build.sh builds with Ninja, which keeps both cores
# busy where make's per-library order leaves one idle (docs/performance.md).
# libcpp-httplib-dev: the HTTP server of `robotsim teach`'s live page.
# libncurses-dev: the terminal pendant (robotsim teach --tui) draws with ncurses.
# liburdfdom-dev (with tinyxml2, whose line numbers position its errors,
# and console_bridge, through which it reports) and libassimp-dev (mesh
# files): the URDF reader, linked by the helper robotsim-urdf, which every
# build makes (so in both modes; the .deb's Depends names their runtime
# libraries, computed by dpkg-shlibdeps from the helper).
# Catch2 and the unit tests build with the tree; the browser test drives a
# real Chromium with playwright-core (pinned in tests/browser/package-lock.json);
# lcov's genhtml reads robotsim test's coverage files; lua5.4, luajit and
# libfcl-dev are the benchmarks' peers (the VM's dispatch loop is held to
# LuaJIT's interpreter, `luajit -joff`, and compared with Lua 5.4's;
# collision_bench times libfcl beside robotsim's own GJK; robotsim itself
# links none of them); neovim's built-in LSP client drives the language server
# end to end (the editor_neovim test); clang and its runtime (libFuzzer)
# build the sanitizer and fuzzing build, and llvm's llvm-symbolizer gives
# their reports file:line (without it a sanitized process also warns of the
# missing symbolizer on stderr, which a byte-for-byte test reads); unzip
# lists the VS Code package;
# GNU time reads the peak memory of a one-line compile (robotsim_bench
# --only startup); tmux gives the terminal pendant's test a real terminal (a pseudo-terminal
# with a terminal emulator behind it) whose screen it reads. Orocos KDL is
# the inverse-kinematics benchmark's peer and independent check
# (bench/ik_bench.cpp; the benchmark builds without it); with its URDF
# parser (libkdl-parser-dev, with urdfdom, already in the build list) it reads robotsim's
# URDF exports in the urdf_kdl test, and urdfdom's check_urdf
# (liburdfdom-tools) checks them in urdf_check. zsh and fish test
# the shell completions with their own completion machinery; parallel and
# openssh-server (an sshd the test starts on loopback, no service) and rsync
# (parallel copies files with it) run the
# grading recipe of docs/testing.md over ssh.
[ "$mode" = test ] && packages+=(chromium fonts-liberation lcov lua5.4 luajit libfcl-dev neovim clang libclang-rt-14-dev llvm unzip tmux
  liborocos-kdl-dev libkdl-parser-dev liburdfdom-tools zsh fish parallel openssh-server rsync time)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ "$mode" = test ]; then
  # Node.js may come from elsewhere than Debian's packages (with its own npm,
  # which Debian's npm package conflicts with): ask apt only when a command is missing.
  command -v node >/dev/null 2>&1 || missing+=(nodejs)
  command -v npm >/dev/null 2>&1 || missing+=(npm)
fi

if [ ${#missing[@]} -gt 0 ]; then
  echo "setup: installing ${missing[*]}" >&2
  sudo=""
  [ "$(id -u)" -ne 0 ] && sudo="sudo"
  export DEBIAN_FRONTEND=noninteractive
  $sudo apt-get update -qq
  $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

if [ "$mode" = test ] && [ ! -d tests/browser/node_modules/playwright-core ]; then
  echo "setup: npm ci in tests/browser" >&2
  npm ci --prefix tests/browser --no-audit --no-fund >/dev/null
fi
# The VS Code extension's packages (its client library, vsce, the grammar
# test tool, the DAP test client), pinned in editors/vscode/package-lock.json;
# without install scripts: nothing used here needs one (vsce's optional
# keytar would try to build a native module). A tree installed before the
# last package was added is installed again.
if [ "$mode" = test ] && { [ ! -d editors/vscode/node_modules/@vscode/vsce ] ||
                           [ ! -d editors/vscode/node_modules/@vscode/debugadapter-testsupport ]; }; then
  echo "setup: npm ci in editors/vscode" >&2
  npm ci --prefix editors/vscode --ignore-scripts --no-audit --no-fund >/dev/null
fi
