#!/usr/bin/env bash
# Hot reload while playing: a broken save is reported (file:line:col, in the log and on screen)
# while the last good level keeps running; fixing the file brings the new level in. SIGTERM
# then ends the game cleanly (SDL turns it into a quit event).
set -euo pipefail
bin=$1
work=$(mktemp -d)
pid=""
cleanup() {
  if [ -n "$pid" ] && kill -0 "$pid" 2>/dev/null; then kill -KILL "$pid"; fi
  rm -rf "$work"
}
trap cleanup EXIT
export BEAMZONE_PREF_DIR=$work/pref SDL_VIDEODRIVER=offscreen SDL_AUDIODRIVER=dummy
log=$work/pref/beamzone.log
level=$work/level.toml

write_level() {  # atomically, as editors save
  printf '%s' "$1" >"$level.tmp" && mv "$level.tmp" "$level"
}
wait_for() {  # pattern, what
  for _ in $(seq 1 600); do
    if grep -qF -- "$1" "$log" 2>/dev/null; then return 0; fi
    if ! kill -0 "$pid" 2>/dev/null; then echo "FAIL: play exited while waiting for $2"; cat "$work/err"; exit 1; fi
    sleep 0.1
  done
  echo "FAIL: timed out waiting for $2"; cat "$log"; exit 1
}

write_level 'version = 1
name = "Good"
[[obstacle]]
kind = "cube"
position = [0, 0, -30]
'
"$bin" play "$level" --headless-test --frames 1000000 --seed 1 >"$work/out" 2>"$work/err" &
pid=$!
wait_for "level: $level" "the first load"

write_level 'version = 1
name = "Broken"
[[obstacle]]
kind = "cube"
position = [0, 0, -30
'
wait_for "$level:5:" "the error of the broken save"
grep -F "$level:5:" "$log" | head -1
kill -0 "$pid" || { echo "FAIL: play died on a broken level"; exit 1; }
echo "ok broken save reported, game still running"

write_level 'version = 1
name = "Fixed"
[[obstacle]]
kind = "pyramid"
position = [10, 0, -30]
'
wait_for "level reloaded: $level" "the fixed level"
echo "ok fixed level reloaded"

kill -TERM "$pid"
set +e
wait "$pid"
rc=$?
set -e
pid=""
[ $rc -eq 0 ] || { echo "FAIL: exit $rc after SIGTERM"; cat "$work/err"; exit 1; }
grep -q " 0 GL errors$" "$work/out" || { echo "FAIL: $(cat "$work/out")"; exit 1; }
echo "ok clean exit on SIGTERM: $(cat "$work/out")"
echo "3 passed, 0 failed"
