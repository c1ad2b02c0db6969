#!/usr/bin/env bash
# A language server exchange in plain bash, for a root with nothing but
# robotsim in it: starts COMMAND (a `robotsim lsp`), sends initialize,
# initialized and the didOpen of a program whose line 2 is an unknown
# instruction, waits for that file's publishDiagnostics and checks it holds
# the unknown instruction's error on that line (0-based line 1), then shutdown and exit, and
# checks the server's exit status is 0. Every message read goes to LOG.
#
#   bash tests/package/lsp_exchange.sh LOG COMMAND [ARGS...]
set -euo pipefail
export LC_ALL=C  # lengths in bytes, as Content-Length counts
log=$1
shift
: >"$log"
coproc SERVER { "$@" 2>>"$log.stderr"; }
server_pid=$SERVER_PID
# bash unsets SERVER when the server exits, which it may do as soon as it
# reads `exit`: keep the descriptors' numbers.
server_out=${SERVER[0]}
server_in=${SERVER[1]}

send() {
  printf 'Content-Length: %d\r\n\r\n%s' "${#1}" "$1" >&"$server_in"
}
# One message's body into $body; fails after 30 s of silence.
receive() {
  local line length=""
  while IFS= read -r -t 30 line <&"$server_out"; do
    line=${line%$'\r'}
    [ -z "$line" ] && break
    case "$line" in Content-Length:*) length=${line#Content-Length: } ;; esac
  done
  [ -n "$length" ] || { echo "no message header from the server" >>"$log"; return 1; }
  IFS= read -r -t 30 -N "$length" body <&"$server_out"
  printf '%s\n' "$body" >>"$log"
}
# Messages until one matches the pattern (at most 50).
receive_until() {
  local i
  for i in $(seq 50); do
    receive || return 1
    case "$body" in $1) return 0 ;; esac
  done
  echo "no message matched $1" >>"$log"
  return 1
}

uri=file:///home/student/work/bad.rsp
send '{"jsonrpc":"2.0","id":1,"method":"initialize","params":{"processId":null,"rootUri":"file:///home/student/work","capabilities":{}}}'
receive_until '*"id":1*"capabilities"*' || receive_until '*"capabilities"*"id":1*'
send '{"jsonrpc":"2.0","method":"initialized","params":{}}'
send '{"jsonrpc":"2.0","method":"textDocument/didOpen","params":{"textDocument":{"uri":"'"$uri"'","languageId":"robotsim","version":1,"text":"        MOVETO 0 0 0 0 0\n        FROB 3\n        END\n"}}}'
receive_until '*"textDocument/publishDiagnostics"*"'"$uri"'"*'
case "$body" in
  *"unknown instruction 'FROB'"*'"line":1'*'"severity":1'*) ;;
  *) echo "the diagnostics hold no error on line 2: $body" >>"$log"; exit 1 ;;
esac
send '{"jsonrpc":"2.0","id":2,"method":"shutdown"}'
receive_until '*"id":2*'
send '{"jsonrpc":"2.0","method":"exit"}'
eval "exec ${server_in}>&-"
wait "$server_pid"
