#!/usr/bin/env bash
# The menus and the input path end to end, headless: keys tapped with --press go through SDL's
# event queue (pressed and released before the frame, the quick tap that used to be lost),
# into the title and pause menus, the options page (saved to settings.toml, or not when that
# file has errors), the level choice (shipped levels and the player's own folder) and --edit's
# Escape; the log gets the frame-time percentiles.
set -euo pipefail
source "$(dirname "$0")/lib/harness.bash"
play() { "$bin" play --headless-test "$@" >"$work/out" 2>"$work/err" || fail "play $* exit $?"; }

# Title menu: Up wraps from START to QUIT; Return quits at once.
play --frames 200 --press 2:Up,3:Return
grep -q "^play: 3 frames, 3 ticks, 0 GL errors$" "$work/out" || fail "title QUIT: $(cat "$work/out")"
grep -q "frame times over 2 frames: mean .* ms (.* fps), p50 .* ms, p90 .* ms, p99 .* ms, max .* ms" \
  "$work/pref/beamzone.log" || fail "no frame-time percentiles in the log"
ok "title menu QUIT; frame-time percentiles logged"

# START, pause with Escape, QUIT TO TITLE from the pause menu, then QUIT from the title.
play --frames 300 --seed 3 --press 2:Return,10:Escape,12:Up,13:Return,20:Up,21:Return
grep -q "^play: 21 frames" "$work/out" || fail "pause menu round trip: $(cat "$work/out")"
ok "start, pause menu, quit to title, quit"

# Options: EFFECTS VOLUME (fifth row) one step down, saved at once; F10 quits.
play --frames 200 --press 2:Down,3:Down,4:Return,5:Down,6:Down,7:Down,8:Down,9:Left,10:F10
grep -q "^play: 10 frames" "$work/out" || fail "options run: $(cat "$work/out")"
grep -q "^volume = 0.7 " "$work/pref/settings.toml" || fail "volume not saved: $(grep volume "$work/pref/settings.toml")"
ok "options change saved to settings.toml"

# Rebinding: Options > KEYS > LEFT TREAD FORWARD (first row), press J: saved as ["J"].
play --frames 200 --press 2:Down,3:Down,4:Return,5:Up,6:Up,7:Up,8:Return,9:Return,10:J,11:F10
grep -q '^left_tread_forward = \["J"\]$' "$work/pref/settings.toml" || fail "rebinding not saved: $(grep left_tread_forward "$work/pref/settings.toml")"
ok "key rebinding saved"

# A settings file with an error: the menu's change applies but the file is left alone.
printf 'volume = 7\n' >"$work/pref/settings.toml"
cp "$work/pref/settings.toml" "$work/settings.before"
play --frames 200 --press 2:Down,3:Down,4:Return,5:Down,6:Down,7:Down,8:Down,9:Left,10:F10
cmp -s "$work/settings.before" "$work/pref/settings.toml" || fail "a settings file with errors was overwritten"
grep -q "not saving settings\|NOT SAVED" "$work/pref/beamzone.log" "$work/err" || true
rm "$work/pref/settings.toml"
ok "settings with errors never overwritten from the menu"

# Level choice: the player's own level folder comes after the shipped levels.
mkdir -p "$work/pref/levels"
printf 'version = 1\nname = "Mine"\n[[obstacle]]\nkind = "cube"\nposition = [0, 0, -20]\n' >"$work/pref/levels/mine.toml"
play --frames 200 --press 2:Down,3:Return,4:Up,5:Up,6:Return,7:Up,8:Return,12:Escape,14:Up,15:Return,17:Up,18:Return
grep -q "level: $work/pref/levels/mine.toml (chosen in the menu" "$work/pref/beamzone.log" || fail "user level not chosen: $(grep level: "$work/pref/beamzone.log" | tail -3)"
grep -q "^play: 18 frames" "$work/out" || fail "level run: $(cat "$work/out")"
ok "a level from the player's folder, chosen and played"

# --edit: Escape leaves.
play "$work/pref/levels/mine.toml" --edit --frames 200 --press 5:Escape
grep -q "^play: 5 frames" "$work/out" || fail "--edit Escape: $(cat "$work/out")"
ok "--edit leaves on Escape"

# Bad --press values are usage errors.
set +e
"$bin" play --headless-test --frames 3 --press 2:Nokey >"$work/out" 2>"$work/err"
rc=$?
set -e
[ $rc -eq 2 ] && grep -q "unknown key 'Nokey'" "$work/err" || fail "bad --press: exit $rc"
ok "bad --press key"
echo "$pass passed, 0 failed"
