#!/usr/bin/env bash
# Hot reload while playing: a broken save is reported (file:line:col, in the log and on screen)
# while the last good level keeps running; fixing the file brings the new level into the
# running game (not a new one: its tick count goes on), the level's [render] style follows the
# edit, and the recording in progress ends at the edit and still verifies against the level it
# was made on. SIGTERM then ends the game cleanly (play quits as when its window is closed).
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
[render]
style = "arcade"
'
cp "$level" "$work/good.toml"  # what the recording will be verified against
"$bin" play "$level" --headless-test --frames 1000000 --seed 1 --record "$work/game.replay" \
  >"$work/out" 2>"$work/err" &
pid=$!
wait_for "level: $level" "the first load"
# The game (and the level hash its recording names) exists once the look is chosen.
wait_for "look: style vector-xray (level)" "the level's style"
echo "ok the level's style is used: $(grep -o 'look: .*' "$log" | head -1)"

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

line=$(grep -o "level taken into the running game at tick [0-9]*: score [0-9]*, lives [0-9]*.*" "$log" | head -1)
tick=$(echo "$line" | sed 's/.* at tick \([0-9]*\):.*/\1/')
[ -n "$line" ] && [ "$tick" -gt 0 ] || { echo "FAIL: the game did not go on: '$line'"; cat "$log"; exit 1; }
echo "ok the running game kept going: $line"
grep -q "look: style vector (settings file)" "$log" || { echo "FAIL: the style did not follow the edit"; cat "$log"; exit 1; }
echo "ok the style followed the edit: $(grep -o 'look: .*' "$log" | tail -1)"

grep -q "the recording ends (a replay belongs to one level): [0-9]* ticks saved to $work/game.replay" "$log" \
  || { echo "FAIL: the recording did not end at the edit"; cat "$log"; exit 1; }
"$bin" replay "$work/game.replay" --verify --level "$work/good.toml" >"$work/verify" \
  || { echo "FAIL: the recording made before the edit does not verify"; cat "$work/verify"; exit 1; }
echo "ok the recording ended at the edit and verifies: $(cat "$work/verify")"

kill -TERM "$pid"
set +e
wait "$pid"
rc=$?
set -e
pid=""
[ $rc -eq 0 ] || { echo "FAIL: exit $rc after SIGTERM"; cat "$work/err"; exit 1; }
grep -q " 0 GL errors$" "$work/out" || { echo "FAIL: $(cat "$work/out")"; exit 1; }
echo "ok clean exit on SIGTERM: $(cat "$work/out")"

# The --edit viewer takes edits in the same way (its meshes too: a new skyline).
: >"$log"
"$bin" play "$level" --edit --headless-test --frames 1000000 >"$work/out" 2>"$work/err" &
pid=$!
wait_for "look: " "the viewer to start"
write_level 'version = 1
name = "Edited in the viewer"
[[obstacle]]
kind = "cube"
position = [5, 0, -20]
[backdrop]
mountains = [[0, 3], [120, 8], [240, 4]]
[render]
style = "arcade"
'
wait_for "level reloaded: $level" "the viewer's reload"
grep -q "look: style vector-xray (level)" "$log" || { echo "FAIL: the viewer's style did not follow"; cat "$log"; exit 1; }
kill -TERM "$pid"
set +e
wait "$pid"
rc=$?
set -e
pid=""
[ $rc -eq 0 ] && grep -q " 0 GL errors$" "$work/out" || { echo "FAIL: viewer exit $rc: $(cat "$work/out")"; cat "$work/err"; exit 1; }
echo "ok --edit reloaded the level and its look: $(cat "$work/out")"
echo "8 passed, 0 failed"
