#!/usr/bin/env bash
# The real binary writing to standard output that cannot take it: /dev/full
# (a full device) and a pipe whose reader has gone. Every command must end
# with exit code 1 and "standard output: a write failed" on stderr, never
# exit 0 with the output cut short, nor die silently by SIGPIPE; and the
# files it was asked to write beside standard output are not written.
# Usage: test-broken-outputs.sh AAPAT_BINARY (ctest Cli.StandardOutputThatCannotBeWritten).
set -uo pipefail
aapat=$1
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
status=0
commands=(
  "list"
  "limits --json"
  "show msaa-4"
  "eval msaa-8 aapat-8 --json"
  "generate jittered --n 99856"
  "optimize --family P(1,1,2) --starts 1 --json -o $tmp/side.json"
  "render disc --pattern msaa-4 --size 16 --reference-samples 4 --no-cache --json"
)
fail() { echo "FAIL: $*"; status=1; }
if [ -w /dev/full ]; then
  for c in "${commands[@]}"; do
    # shellcheck disable=SC2086
    $aapat $c >/dev/full 2>"$tmp/err"
    rc=$?
    [ "$rc" -eq 1 ] || fail "'$c' > /dev/full: exit $rc, expected 1"
    grep -q "standard output: a write failed" "$tmp/err" || fail "'$c' > /dev/full: no message ($(head -c 200 "$tmp/err"))"
  done
  [ ! -e "$tmp/side.json" ] || fail "optimize -o was written though standard output failed"
else
  echo "no writable /dev/full here: the full-device cases are skipped"
fi
# A reader that closes at once: the writer sees EPIPE (SIGPIPE is ignored).
# Only outputs larger than a pipe's buffer (64 KiB): a smaller one is all
# written before the reader goes, and that is not the writer's failure.
for c in "generate jittered --n 99856" "generate halton --n 400000 --seed 3"; do
  # shellcheck disable=SC2086
  { $aapat $c 2>"$tmp/err"; echo $? >"$tmp/rc"; } | head -c 1 >/dev/null
  rc=$(cat "$tmp/rc")
  [ "$rc" -eq 1 ] || fail "'$c' | head -c 1: exit $rc, expected 1"
  grep -q "standard output: a write failed" "$tmp/err" || fail "'$c' | head -c 1: no message"
done
[ "$status" -eq 0 ] && echo "every write to a full device or a closed pipe failed the command with a message"
exit "$status"
