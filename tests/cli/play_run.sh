#!/usr/bin/env bash
# The whole play loop, headless: a hidden window under SDL's offscreen driver runs N frames
# (one 60 Hz tick each) of the game and of the --edit viewer, with screenshots, the settings
# file and the log in a scratch pref folder.
set -euo pipefail
source "$(dirname "$0")/lib/harness.bash"

cat >"$work/level.toml" <<'LVL'
version = 1
name = "CLI test"
[[obstacle]]
kind = "pyramid"
position = [0, 0, -30]
LVL

# Game on the built-in level: a project root with shaders and data but no levels/ folder.
src=${BEAMZONE_ROOT:-$(cd "$(dirname "$0")/../.." && pwd)}
mkdir "$work/root"
ln -s "$src/shaders" "$work/root/shaders"
ln -s "$src/data" "$work/root/data"
BEAMZONE_ROOT=$work/root "$bin" play --headless-test --frames 30 --seed 7 --screenshot-at 20 >"$work/out" 2>"$work/err" || fail "game run exit $?"
grep -q "^play: 30 frames, 30 ticks, 0 GL errors$" "$work/out" || fail "game run summary: $(cat "$work/out")"
[ -s "$work/pref/screenshots/screenshot-0001.png" ] || fail "no screenshot"
grep -q "screenshot saved: $work/pref/screenshots/screenshot-0001.png" "$work/pref/beamzone.log" || fail "screenshot not logged"
grep -q "settings: $work/pref/settings.toml" "$work/err" || fail "settings path not printed at start"
grep -q "high scores: $work/pref/highscores.toml" "$work/err" || fail "high-score path not printed at start"
[ -s "$work/pref/settings.toml" ] || fail "no settings file written on first start"
grep -q "playing the built-in level" "$work/err" || fail "did not fall back to the built-in level"
ok "game on the built-in level"

# The default level, levels/classic.toml.
"$bin" play --headless-test --frames 5 >"$work/out" 2>"$work/err" || fail "default level run exit $?"
grep -q "level: .*levels/classic.toml" "$work/err" || fail "default level not levels/classic.toml"
ok "game on levels/classic.toml"

# Through the environment switch, on a level file, arcade style; a second screenshot.
BEAMZONE_ALLOW_OFFSCREEN=1 "$bin" play "$work/level.toml" --frames 10 --style arcade --preset fast \
  --screenshot-at 5 >"$work/out" 2>"$work/err" || fail "level run exit $?"
grep -q "0 GL errors" "$work/out" || fail "level run: $(cat "$work/out")"
[ -s "$work/pref/screenshots/screenshot-0002.png" ] || fail "second screenshot not numbered 0002"
ok "game on a level file (BEAMZONE_ALLOW_OFFSCREEN=1)"

"$bin" play "$work/level.toml" --edit --headless-test --frames 10 >"$work/out" 2>"$work/err" || fail "edit run exit $?"
grep -q "^play: 10 frames, 10 ticks, 0 GL errors$" "$work/out" || fail "edit run: $(cat "$work/out")"
ok "--edit viewer"

# A settings file with a bad value: a positioned warning, defaults for that key, file kept.
printf 'volume = 7\nvsync = "off"\n' >"$work/pref/settings.toml"
cp "$work/pref/settings.toml" "$work/settings.before"
"$bin" play --headless-test --frames 3 >"$work/out" 2>"$work/err" || fail "bad settings made play fail"
grep -qF "$work/pref/settings.toml:1:10: error: volume must be a number from 0 to 1" "$work/err" || fail "bad setting not reported"
cmp -s "$work/settings.before" "$work/pref/settings.toml" || fail "a settings file with errors was overwritten"
ok "bad settings value reported, file untouched"

# A level with errors at start: every error as file:line:col, exit 1, no window needed.
printf 'version = 1\nname = "bad"\n[[obstacle]]\nkind = "cubee"\nposition = [50, 0, 0]\n' >"$work/bad.toml"
set +e
"$bin" play "$work/bad.toml" --headless-test --frames 3 >"$work/out" 2>"$work/err"
rc=$?
set -e
[ $rc -eq 1 ] || fail "broken level: exit $rc"
grep -qF "$work/bad.toml:4:8: error:" "$work/err" || fail "broken level error not positioned"
ok "broken level at start"

set +e
"$bin" play "$work/missing.toml" --headless-test --frames 3 >"$work/out" 2>"$work/err"
rc=$?
set -e
[ $rc -eq 1 ] && grep -qF "$work/missing.toml" "$work/err" || fail "missing level: exit $rc"
ok "missing level file"
echo "$pass passed, 0 failed"
