#!/usr/bin/env bash
# The terminal pendant (robotsim teach --tui) in a real terminal: tmux runs
# it in an 80x24 pseudo-terminal with its own terminal emulator behind it,
# the test types keys into it (send-keys) and reads the rendered screen
# (capture-pane). It checks the screen after each step, the program file
# written against a golden file byte for byte, and that the terminal is
# given back as it was (same stty modes, the full-screen mode left, the
# cursor shown) after q, SIGTERM, SIGINT and a crash (SIGSEGV), and when
# the pendant cannot start; with --device, against robotsim emulate on a
# pseudo-terminal, that a jog moves the controller's motor and a serial
# fault stops everything and shows.
#
#   bash tests/tui/test_tui.sh ROBOTSIM_BINARY WORK_DIR
set -euo pipefail
bin=$(realpath "$1")
work=$2
here=$(cd "$(dirname "$0")" && pwd)
command -v tmux >/dev/null || { echo "FAIL: tmux is not installed (bash scripts/setup.sh test)"; exit 1; }

rm -rf "$work"
mkdir -p "$work"
# A fresh tmux server (its own socket) for each session: a server that is
# still shutting down after kill-server cannot be reached by the next one.
sessions=0
sock="$work/tmux0.sock"
tm() { tmux -S "$sock" "$@"; }
emu=""
trap 'tm kill-server 2>/dev/null || true; [ -n "$emu" ] && kill -INT "$emu" 2>/dev/null || true' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

screen() { tm capture-pane -p -t t; }
# Waits (up to 10 s) until the screen holds TEXT.
expect_screen() {
  for _ in $(seq 100); do
    screen | grep -qF -- "$1" && return 0
    sleep 0.1
  done
  fail "the screen never showed '$1'; it shows:"
  screen
  return 0
}
keys() { tm send-keys -t t "$@"; }
typed() { tm send-keys -t t -l "$1"; }

# Starts the pendant in a fresh 80x24 terminal. The pane's shell notes the
# terminal modes, runs robotsim (its pid in $work/pid), then notes its exit
# code and the modes again.
start() {
  sessions=$((sessions + 1))
  sock="$work/tmux$sessions.sock"
  rm -f "$work"/{pid,code,before,after}
  tm -f /dev/null new-session -d -x 80 -y 24 -s t \
    "cd '$work' && ulimit -c 0 && stty -g > before; sh -c 'echo \$\$ > pid; exec \"$bin\" teach $*'; echo \$? > code; stty -g > after; echo PANE-DONE; exec sleep 600"
}
# Waits until robotsim has exited and the pane's shell has taken notes.
finished() {
  for _ in $(seq 100); do
    [ -s "$work/after" ] && return 0
    sleep 0.1
  done
  fail "robotsim did not exit"
}
# The terminal as it was before: modes, the normal screen, a cursor.
check_restored() {
  local what=$1
  cmp -s "$work/before" "$work/after" || fail "$what: stty modes differ: $(cat "$work/before") / $(cat "$work/after")"
  [ "$(tm display -p -t t '#{alternate_on}')" = 0 ] || fail "$what: the terminal is still in full-screen mode"
  [ "$(tm display -p -t t '#{cursor_flag}')" = 1 ] || fail "$what: the cursor is hidden"
}

# --- 1. A session: jog, teach, re-teach, rename, delete, go to, an input.
cp "$here/pick.rsp" "$work/pick.rsp"
start "pick.rsp --cell scara-pick --tui"
expect_screen "robotsim teach  pick.rsp  on scara-pick  (simulation)"
# Motors with letter, type, value and range; the TCP at home (-225, 840, 0)
# from the cell's description (stdlib/workcells/scara-pick.rsd).
expect_screen " > E revolute        0  -1000..1000"
expect_screen "   C prismatic       0  -350..350"
expect_screen "   A gripper         0  0..120  open"
expect_screen "x -225  y 840  z 0"
expect_screen "> HOME"
[ "$(tm display -p -t t '#{alternate_on}')" = 1 ] || fail "the pendant does not use the full screen"

keys 3 Right Right                       # step 100: E = 200
expect_screen " > E revolute      200"
keys Down 2 Left Left Left               # D, step 10: D = -30
expect_screen " > D revolute      -30"
keys t
expect_screen "name of the new point"
typed ABOVE
keys Enter                               # ABOVE = 200 -30 0 0 0
expect_screen "taught ABOVE"
keys Down 3 Right                        # C, step 100: C = 100
expect_screen " > C prismatic     100"
keys t
typed LOW
keys Enter                               # LOW = 200 -30 100 0 0
expect_screen "taught LOW"
keys Down 2 Right Right                  # B, step 10: B = 20
expect_screen " > B revolute       20"
# The tool centre point by hand (tests/models/test_where_cell.cpp's planar
# arm): t1 = 200 x 0.1175 = 23.5, t2 = -30 x 0.2233 = -6.699 degrees;
# x = -(105 cos t1 + 120 cos(t1 + t2)) = -211.16904, y = 840 - 100 x 0.12
# = 828, z = 105 sin t1 + 120 sin(t1 + t2) = 76.55448; B turns no position.
expect_screen "x -211.169  y 828  z 76.5545"
keys PPage r                             # ABOVE selected (LOW was): re-teach asks
expect_screen "re-teach ABOVE with the current pose? (y/n)"
keys y                                   # ABOVE = 200 -30 100 20 0
expect_screen "re-taught ABOVE"
keys NPage n                             # LOW selected: rename to PICK
expect_screen "new name for LOW"
typed PICK
keys Enter
expect_screen "> PICK"
keys t
typed SPARE
keys Enter
expect_screen "taught SPARE"
keys x                                   # SPARE is selected: delete asks
expect_screen "delete SPARE? (y/n)"
keys n                                   # no: nothing happens
expect_screen "cancelled"
keys x y
expect_screen "deleted SPARE"
keys PPage PPage PPage g                 # HOME: every motor back to 0
expect_screen "went to HOME"
expect_screen "x -225  y 840  z 0"
keys i 3                                 # input 3 on
expect_screen "INPUTS   . . # . . . . ."
keys '?'                                 # the key help, from the shared key map
expect_screen " Left Right - + jog the selected motor or axis by -step / +step"
keys '?'
# Too small a terminal gets a request, then the panel again.
tm resize-window -t t -x 70 -y 20
expect_screen "robotsim teach needs 80x24"
tm resize-window -t t -x 80 -y 24
expect_screen "TOOL CENTRE POINT (world)"
# Jog modes (docs/teach.md, "Jog modes"): from ABOVE (200 -30 100 20 0,
# the tool centre point worked out above), m switches to world: the axes
# of a SCARA with a roll joint, X +10 moves the point 10 along the cell's
# X (the message gives the exact pose, the panel the counts' rounding);
# then tool: Z +10 goes 10 further along the approach, which points down
# (y falls by 10); Z +100 in world leaves the arm's reach (225 from its
# axis): refused, and nothing moves; m (twice) goes back to joint.
keys NPage g
expect_screen "went to ABOVE"
keys m
expect_screen "mode world (m: joint, world, tool)"
expect_screen " WORLD AXES"
expect_screen "RY      about the world's Y, the heading"
keys 2 Right
expect_screen "world jog X +10 length units: tool centre point at -201.169 828 76.5545"
# The panel's point is forward kinematics of the whole counts: within 1 length unit (E turns 0.1175
# degrees a count, D 0.2233: about 0.45 at most at this reach).
x=$(screen | sed -n 's/^   x \(-\{0,1\}[0-9.]*\)  y .*/\1/p' | head -1)
awk -v x="$x" 'BEGIN { exit !(x != "" && x + 201.169 < 1 && x + 201.169 > -1) }' ||
  fail "after world X +10 the tool centre point's x is '$x', not within 1 of -201.169"
keys m
expect_screen " TOOL AXES"
keys Down Down Right
expect_screen "tool jog Z +10 length units: tool centre point at -201.169 818 76.5545"
tcp_before=$(screen | grep '^   x ')
keys m m 3 Right                         # tool, joint, world: Z still selected
expect_screen "world jog Z +100 length units refused (reach): the point is"
[ "$(screen | grep '^   x ')" = "$tcp_before" ] || fail "a refused jog moved the tool: $(screen | grep '^   x ')"
keys m m
expect_screen "mode joint (m: joint, world, tool)"
expect_screen " MOTORS"
keys q
finished
[ "$(cat "$work/code")" = 0 ] || fail "q exits $(cat "$work/code"), not 0"
check_restored "after q"
# The file, byte for byte: tests/tui/pick.expected.rsp, worked out by hand
# (tests/tui/README.md says how).
cmp "$work/pick.rsp" "$here/pick.expected.rsp" || {
  fail "the program written differs from tests/tui/pick.expected.rsp"
  diff "$here/pick.expected.rsp" "$work/pick.rsp" || true
}
cmp -s "$work/pick.rsp.bak" "$here/pick.rsp" || fail "pick.rsp.bak is not the file as it was loaded"
tm kill-server

# --- 2. Someone edits the file meanwhile: teach refuses and says so in the
# message row; then SIGTERM ends the pendant with the terminal restored.
cp "$here/pick.rsp" "$work/pick.rsp"
start "pick.rsp --cell scara-pick --tui"
expect_screen "> HOME"
echo "; edited in an editor" >> "$work/pick.rsp"
cp "$work/pick.rsp" "$work/edited.rsp"
keys t
typed LATE
keys Enter
expect_screen "changed"
cmp -s "$work/pick.rsp" "$work/edited.rsp" || fail "a refused write changed the file"
keys l                                   # read it again: teaching goes on on top of the edit
expect_screen "read again: 1 points"
keys t
typed LATE
keys Enter
expect_screen "taught LATE"
# The new row goes after the last point (HOME), above the comment the
# editor appended, laid out like HOME (every motor still at 0).
{ cat "$here/pick.rsp"; echo "LATE      0    0    0    0    0"; echo "; edited in an editor"; } > "$work/edited-late.rsp"
cmp -s "$work/pick.rsp" "$work/edited-late.rsp" || fail "after l, LATE is not written on top of the edit: $(tail -3 "$work/pick.rsp")"
kill -TERM "$(cat "$work/pid")"
finished
[ "$(cat "$work/code")" = 143 ] || fail "SIGTERM exits $(cat "$work/code"), not 143 (128 + 15)"
check_restored "after SIGTERM"
tm kill-server

# --- 3. Ctrl-C's SIGINT quits like q, exit 130; a crash (SIGSEGV) still
# gives the terminal back before the process dies of it (no core file).
for sig in INT SEGV; do
  cp "$here/pick.rsp" "$work/pick.rsp"
  start "pick.rsp --cell scara-pick --tui"
  expect_screen "> HOME"
  keys 3 Right                           # a change on screen, none in the file
  expect_screen " > E revolute      100"
  kill -"$sig" "$(cat "$work/pid")"
  finished
  want=130
  [ "$sig" = SEGV ] && want=139          # the shell's 128 + 11: it died of the signal
  [ "$(cat "$work/code")" = "$want" ] || fail "SIG$sig exits $(cat "$work/code"), not $want"
  check_restored "after SIG$sig"
  cmp -s "$work/pick.rsp" "$here/pick.rsp" || fail "SIG$sig: the file changed"
  tm kill-server
done

# --- 4. With --device: robotsim emulate plays the controller on a
# pseudo-terminal; a jog moves its motor, read position reads it back, and
# a serial fault (the controller falls silent) stops everything and shows
# in the message row.
# The emulator's console is fed through a FIFO on fd 3; its output goes to
# $work/emu.out.
start_emulator() {
  rm -f "$work/emu.in" "$work/emu.out" "$work/rhino"
  mkfifo "$work/emu.in"
  "$bin" emulate --link "$work/rhino" -q "$@" < "$work/emu.in" > "$work/emu.out" 2>&1 &
  emu=$!
  exec 3> "$work/emu.in"
  for _ in $(seq 100); do [ -e "$work/rhino" ] && break; sleep 0.1; done
}
stop_emulator() {
  echo quit >&3
  exec 3>&-
  wait "$emu" || true
  emu=""
}
# The emulator's motor E as its status console reports it.
emulator_e() {
  local before
  before=$(grep -c "motor E: position" "$work/emu.out" || true)
  echo status >&3
  for _ in $(seq 50); do
    [ "$(grep -c "motor E: position" "$work/emu.out" || true)" -gt "$before" ] && break
    sleep 0.1
  done
  grep "motor E: position" "$work/emu.out" | tail -1 | sed 's/.*position \(-\{0,1\}[0-9]*\),.*/\1/'
}
# A Mark IV, which reports its encoder counts (read position needs them).
cp "$here/pick.rsp" "$work/pick.rsp"
start_emulator --dialect mark4
start "pick.rsp --cell scara-pick --tui --device '$work/rhino' --dialect mark4"
expect_screen "(robot on /"
keys 3 Right
expect_screen "moved to 100 0 0 0 0"
[ "$(emulator_e)" = 100 ] || fail "the emulator's motor E is not at 100: $(cat "$work/emu.out")"
keys p
expect_screen "read from the controller: 100 0 0 0 0"
echo "fault silence" >&3
sleep 0.3
keys Right
expect_screen "DEVICE FAULT, every motor stopped:"
keys Right                               # refused: the pose stays, the fault shows
sleep 0.3
expect_screen " > E revolute      100"
expect_screen "DEVICE FAULT, every motor stopped:"
keys q
finished
[ "$(cat "$work/code")" = 0 ] || fail "q after a fault exits $(cat "$work/code"), not 0"
check_restored "after a device fault"
stop_emulator
tm kill-server

# Ctrl-C during a move on the device (a Mark III) stops the robot where it is (the
# serial layer's handler, which the pendant's calls), then quits (130)
# with the terminal given back. The emulator runs at twice the speed: E
# at 800 counts/s.
cp "$here/pick.rsp" "$work/pick.rsp"
start_emulator --speed 2
start "pick.rsp --cell scara-pick --tui --device '$work/rhino'"
expect_screen "(robot on /"
keys 3 Right Right Right Right Right Right Right Right Right Right  # E = 1000
expect_screen " > E revolute     1000"
keys g                                   # HOME: E from 1000 to 0, 1.25 s
for _ in $(seq 100); do
  e=$(emulator_e)
  [ -n "$e" ] && [ "$e" -lt 1000 ] && break
done
kill -INT "$(cat "$work/pid")"
finished
[ "$(cat "$work/code")" = 130 ] || fail "Ctrl-C during a device move exits $(cat "$work/code"), not 130"
check_restored "after Ctrl-C during a device move"
sleep 0.3
e=$(emulator_e)
[ -n "$e" ] && [ "$e" -gt 0 ] && [ "$e" -lt 1000 ] || fail "Ctrl-C did not stop the move: the emulator's E is '$e'"
stop_emulator
tm kill-server

# --- 5. It cannot start without a terminal: an error, exit 2, no file written.
cp "$here/pick.rsp" "$work/pick.rsp"
set +e
"$bin" teach "$work/pick.rsp" --cell scara-pick --tui < /dev/null > "$work/out" 2> "$work/err"
code=$?
set -e
[ "$code" = 2 ] || fail "without a terminal: exit $code, not 2"
grep -qF "needs a terminal" "$work/err" || fail "without a terminal: no message ($(cat "$work/err"))"
cmp -s "$work/pick.rsp" "$here/pick.rsp" || fail "without a terminal the file changed"

if [ "$failures" -gt 0 ]; then
  echo "$failures failure(s)"
  exit 1
fi
echo "terminal pendant: all checks passed"
