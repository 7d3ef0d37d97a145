#!/usr/bin/env bash
# `play --record` writes a replay of the game it plays; `play --replay` plays it back through
# the same loop, stops at its end, and every recorded state hash matches (exit 0); the
# headless `beamzone replay --verify` agrees. A bad replay file is one error line, exit 1.
set -euo pipefail
bin=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export BEAMZONE_PREF_DIR=$work/pref SDL_VIDEODRIVER=offscreen SDL_AUDIODRIVER=dummy

"$bin" play --headless-test --frames 90 --seed 11 --record "$work/game.replay" >"$work/out" 2>"$work/err" \
  || { echo "FAIL: record run"; cat "$work/err"; exit 1; }
grep -q "^ticks 90$" "$work/game.replay" || { echo "FAIL: replay file"; head "$work/game.replay"; exit 1; }
echo "ok recorded 90 ticks"

"$bin" play --headless-test --frames 100000 --replay "$work/game.replay" >"$work/out" 2>"$work/err" \
  || { echo "FAIL: replay run"; cat "$work/err"; exit 1; }
grep -q "^play: 90 frames, 90 ticks, 0 GL errors$" "$work/out" || { echo "FAIL: $(cat "$work/out")"; exit 1; }
grep -q "every recorded state hash matched" "$work/err" || { echo "FAIL: no match report"; cat "$work/err"; exit 1; }
echo "ok replayed in the play loop and stopped at its end"

"$bin" replay "$work/game.replay" --verify >"$work/out" || { echo "FAIL: replay --verify"; exit 1; }
echo "ok beamzone replay --verify: $(cat "$work/out")"

printf 'beamzone-replay 1\nseed x\n' >"$work/bad.replay"
set +e
"$bin" play --headless-test --frames 10 --replay "$work/bad.replay" >"$work/out" 2>"$work/err"
rc=$?
set -e
[ $rc -eq 1 ] && grep -q "bad.replay:2" "$work/err" || { echo "FAIL: bad replay: exit $rc"; cat "$work/err"; exit 1; }
grep -c "error" "$work/err" | grep -qx 1 || { echo "FAIL: expected one error line"; cat "$work/err"; exit 1; }
echo "ok bad replay file: $(grep error "$work/err")"
echo "4 passed, 0 failed"
