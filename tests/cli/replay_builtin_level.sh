#!/usr/bin/env bash
# A replay recorded on the built-in level (`replay --record-demo` without --level) plays back
# with `play --replay` and no LEVEL argument: play takes the level the replay names, even with
# a levels/classic.toml in reach, and every state hash matches. A replay naming a level file
# plays on that file.
set -euo pipefail
bin=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export BEAMZONE_PREF_DIR=$work/pref SDL_VIDEODRIVER=offscreen SDL_AUDIODRIVER=dummy

"$bin" replay "$work/demo.replay" --record-demo 2 --seed 4 >"$work/out"
grep -q "^level builtin:default$" "$work/demo.replay" || { echo "FAIL: not on the built-in level"; exit 1; }
"$bin" play --headless-test --frames 100000 --replay "$work/demo.replay" >"$work/out" 2>"$work/err" \
  || { echo "FAIL: play --replay of a built-in level demo"; cat "$work/err"; exit 1; }
grep -q "every recorded state hash matched" "$work/err" || { echo "FAIL: no match report"; cat "$work/err"; exit 1; }
echo "ok built-in level demo plays with play --replay: $(cat "$work/out")"

printf 'version = 1\nname = "T"\n[field]\nsize = 200\n' >"$work/t.toml"
"$bin" replay "$work/file.replay" --record-demo 1 --level "$work/t.toml" >"$work/out"
"$bin" play --headless-test --frames 100000 --replay "$work/file.replay" >"$work/out" 2>"$work/err" \
  || { echo "FAIL: play --replay of a level-file demo"; cat "$work/err"; exit 1; }
grep -q "every recorded state hash matched" "$work/err" || { echo "FAIL: no match report"; cat "$work/err"; exit 1; }
echo "ok level-file demo plays on the level it names"
echo "2 passed, 0 failed"
