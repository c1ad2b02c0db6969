#!/usr/bin/env bash
# docs/testing.md's "Grading on several machines" recipe, run as it stands
# there: the first ```sh block under that heading, in a copy of
# examples/tests/grading/. Two "machines", lab01 and lab02, are one sshd
# (Debian's openssh-server) that this script starts on two free loopback
# ports: its own host key, a key-only login (no password, no keyboard
# interaction) with a key made here, nothing of the user's ~/.ssh read or
# written (ssh runs with its own config through PARALLEL_SSH); the
# sessions' PATH starts with a folder holding the built robotsim, which
# plays the installed package, and their HOME is a folder of the test's.
# Checks: the merged CSV equals one robotsim test run on the same folder,
# the merged JUnit file holds that run's test suites, both machines graded,
# and the machines' job folders are gone.
# Usage: test_grading_ssh.sh ROBOTSIM_BINARY SOURCE_DIR WORK_DIR
# Exit 77 (skipped) when parallel or sshd is not installed.
set -euo pipefail
binary=$1 source=$2 work=$3
for program in parallel /usr/sbin/sshd ssh ssh-keygen; do
  command -v "$program" >/dev/null 2>&1 || { echo "test_grading_ssh: $program is not installed: skipped" >&2; exit 77; }
done
fail() { echo "test_grading_ssh: FAILED: $*" >&2; exit 1; }

rm -rf "$work" && mkdir -p "$work"/{ssh,bin,remote-home,local-home}
work=$(cd "$work" && pwd)
ln -s "$(cd "$(dirname "$binary")" && pwd)/$(basename "$binary")" "$work/bin/robotsim"
ssh-keygen -q -t ed25519 -N '' -C robotsim-test-host -f "$work/ssh/host_key"
ssh-keygen -q -t ed25519 -N '' -C robotsim-test-user -f "$work/ssh/user_key"
cp "$work/ssh/user_key.pub" "$work/ssh/authorized_keys"
# sshd as root (as here) separates privileges into /run/sshd, which
# Debian's service makes when it starts (its systemd unit's
# RuntimeDirectory); without that service, make the same empty folder.
if [ "$(id -u)" = 0 ] && [ ! -d /run/sshd ]; then mkdir -m 0755 /run/sshd; fi

# Two free loopback ports: bound once by the kernel's choice, then given to sshd.
read -r port1 port2 < <(python3 -c '
import socket
s = [socket.socket() for _ in range(2)]
for x in s: x.bind(("127.0.0.1", 0))
print(*(x.getsockname()[1] for x in s))')
cat > "$work/ssh/sshd_config" <<CONFIG
ListenAddress 127.0.0.1:$port1
ListenAddress 127.0.0.1:$port2
HostKey $work/ssh/host_key
PidFile $work/ssh/sshd.pid
AuthorizedKeysFile $work/ssh/authorized_keys
AuthenticationMethods publickey
PasswordAuthentication no
KbdInteractiveAuthentication no
UsePAM no
StrictModes no
AllowUsers $(id -un)
SetEnv PATH=$work/bin:/usr/local/bin:/usr/bin:/bin HOME=$work/remote-home
CONFIG
cat > "$work/ssh/ssh_config" <<CONFIG
Host lab01
  Port $port1
Host lab02
  Port $port2
Host *
  HostName 127.0.0.1
  User $(id -un)
  IdentityFile $work/ssh/user_key
  IdentitiesOnly yes
  UserKnownHostsFile $work/ssh/known_hosts
  StrictHostKeyChecking accept-new
  BatchMode yes
  LogLevel ERROR
CONFIG

/usr/sbin/sshd -D -e -f "$work/ssh/sshd_config" 2> "$work/ssh/sshd.log" &
sshd_pid=$!
trap 'kill "$sshd_pid" 2>/dev/null || true' EXIT
for _ in $(seq 50); do
  ssh -F "$work/ssh/ssh_config" lab01 true 2>/dev/null && ssh -F "$work/ssh/ssh_config" lab02 true 2>/dev/null && break
  kill -0 "$sshd_pid" 2>/dev/null || fail "sshd did not start: $(cat "$work/ssh/sshd.log")"
  sleep 0.2
done
[ "$(ssh -F "$work/ssh/ssh_config" lab02 'command -v robotsim')" = "$work/bin/robotsim" ] ||
  fail "the sessions do not find the built robotsim"
# Key-only: sshd's effective settings, and a login without the key refused.
/usr/sbin/sshd -T -f "$work/ssh/sshd_config" -C user="$(id -un)",host=localhost,addr=127.0.0.1 |
  grep -x 'passwordauthentication no' >/dev/null || fail "sshd allows passwords"
ssh -F /dev/null -o BatchMode=yes -o IdentitiesOnly=yes -o IdentityFile=none -o StrictHostKeyChecking=no \
  -o UserKnownHostsFile="$work/ssh/known_hosts" -p "$port1" "$(id -un)@127.0.0.1" true 2>/dev/null &&
  fail "a login without the key was accepted"

# The recipe, verbatim.
awk '/^### Grading on several machines/ { in_section = 1; next }
     in_section && /^#/ && !/^# / { exit }
     in_section && /^```sh$/ { in_block = 1; next }
     in_block && /^```$/ { exit }
     in_block { print }' "$source/docs/testing.md" > "$work/recipe.sh"
grep -q -- '--sshlogin' "$work/recipe.sh" || fail "no recipe under '### Grading on several machines' in docs/testing.md"
cp -r "$source/examples/tests/grading" "$work/grading"
(cd "$work/grading" && HOME=$work/local-home PARALLEL_SSH="ssh -F $work/ssh/ssh_config" PATH="$work/bin:$PATH" \
   bash -e "$work/recipe.sh") > "$work/recipe.out" 2>&1 || fail "the recipe failed: $(cat "$work/recipe.out")"
grep -q "not graded" "$work/recipe.out" && fail "the recipe said: $(cat "$work/recipe.out")"

cd "$work/grading"
# One machine's view of the same folder: the reference.
set +e
LC_ALL=C "$binary" test --spec assignment.rstest submissions --format csv --junit "$work/one-machine.xml" > "$work/one-machine.csv"
code=$?
set -e
[ "$code" -le 1 ] || fail "robotsim test on one machine exited $code"
[ "$(wc -l < "$work/one-machine.csv")" -ge 3 ] || fail "the one-machine table is short: $(cat "$work/one-machine.csv")"
diff -u "$work/one-machine.csv" grades.csv || fail "the merged CSV differs from one machine's"

# The JUnit file: well-formed, and the same test suites and test cases,
# failures and errors as the one-machine run (times left out: wall time).
python3 - "$work/one-machine.xml" grades.xml <<'PY' || fail "the merged JUnit file differs from one machine's"
import sys, xml.etree.ElementTree as ET
def cases(path):
    root = ET.parse(path).getroot()
    suites = root.iter("testsuite")
    out = []
    for s in suites:
        for c in s.iter("testcase"):
            out.append((s.get("name"), c.get("name"), c.find("failure") is not None, c.find("error") is not None))
    return sorted(out)
one, merged = cases(sys.argv[1]), cases(sys.argv[2])
if one != merged or len(one) < 4:
    print("one machine:", one, "\nmerged:", merged, file=sys.stderr)
    sys.exit(1)
PY

# Both machines graded (the job log's Host column), every job ended 0.
grep -q lab01 results/joblog || fail "lab01 graded nothing: $(cat results/joblog)"
grep -q lab02 results/joblog || fail "lab02 graded nothing: $(cat results/joblog)"
awk -F '\t' 'NR > 1 && $7 != 0 { bad = 1 } END { exit bad }' results/joblog || fail "a job failed: $(cat results/joblog)"
[ "$(awk 'NR > 1' results/joblog | wc -l)" = "$(ls submissions/*.rsp | wc -l)" ] || fail "not one job per submission"
# Nothing left on the machines.
leftover=$(find "$work/remote-home" -type f | head -n 5)
[ -z "$leftover" ] || fail "left on the machines: $leftover"
echo "test_grading_ssh: ok ($(awk 'NR > 1' results/joblog | wc -l) submissions on lab01 and lab02)"
