#!/usr/bin/env bash
# beamzone replay: a recorded game verifies headless (exit 0); a tampered one fails at the
# first mismatching tick (exit 1); broken files give one clear line naming file:line, never a
# crash.
set -uo pipefail
bin=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

expect_seconds=60
source "$(dirname "$0")/lib/expect.bash"

expect 0 "recorded" replay "$work/demo.bzr" --record-demo 120 --seed 3
expect 0 "ok: [0-9]+ ticks" replay "$work/demo.bzr" --verify
expect 0 "seed +3" replay "$work/demo.bzr"

# Tamper with the first command run: the next state hash (tick 60 or later) must differ.
awk 'BEGIN{done=0} /^c /&&!done{ $3 = ($3 == 127 ? -127 : 127); done=1 } {print}' \
  "$work/demo.bzr" >"$work/tampered.bzr"
cmp -s "$work/demo.bzr" "$work/tampered.bzr" && fail "tampering changed nothing"
expect 1 "state hash mismatch at tick [0-9]+" replay "$work/tampered.bzr" --verify

# Broken files: one line each, with the file and the line.
printf 'hello\n' >"$work/junk.bzr"
expect 1 "junk.bzr:1:1: error: not a beamzone replay" replay "$work/junk.bzr" --verify
head -c 400 "$work/demo.bzr" >"$work/cut.bzr"
expect 1 "cut.bzr:[0-9]+:[0-9]+: error: " replay "$work/cut.bzr" --verify
sed 's/^ticks .*/ticks 5/' "$work/demo.bzr" >"$work/count.bzr"
expect 1 "count.bzr:[0-9]+:[0-9]+: error: run length [0-9]+ makes more commands than" replay "$work/count.bzr" --verify
expect 1 "file not found" replay "$work/missing.bzr" --verify
expect 1 "not a regular file" replay /dev/zero --verify
head -c 100000 /dev/urandom >"$work/random.bzr"
expect 1 "random.bzr" replay "$work/random.bzr" --verify
expect 2 "no replay FILE" replay
expect 2 "unknown option" replay "$work/demo.bzr" --bogus
echo "replay CLI ok"
