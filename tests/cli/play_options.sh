#!/usr/bin/env bash
# Every option in the menus, driven headless with --press through SDL's event queue as a
# player's keys would be: each path changes its setting and the test checks that it was
# saved to settings.toml (a fresh preference folder per option, so nothing carries over).
set -euo pipefail
source "$(dirname "$0")/lib/harness.bash"

# Taps the keys one frame apart from frame 2, then F10 quits; the run must end on that frame.
drive() {
    local presses="" frame=2 key
    for key in "$@"; do
        presses+="${presses:+,}$frame:$key"
        frame=$((frame + 1))
    done
    presses+=",$frame:F10"
    rm -rf "$work/pref"
    "$bin" play --headless-test --frames 400 --press "$presses" >"$work/out" 2>"$work/err" ||
        fail "play --press $presses: exit $?"
    grep -q "^play: $frame frames" "$work/out" || fail "did not quit on frame $frame: $(cat "$work/out")"
}
saved() {  # saved PATTERN NAME: the settings file has a line matching PATTERN
    grep -q "$1" "$work/pref/settings.toml" ||
        fail "$2 not saved: $(grep "${1%% *}" "$work/pref/settings.toml" || echo none)"
    ok "$2"
}
# Title: START, LEVEL, OPTIONS. Options rows: DIFFICULTY, PRESET, STYLE, BEAM, EFFECTS VOLUME,
# FULLSCREEN, VSYNC, SHOW FPS, FRAME RATE CAP, COMFORT AND TEXT, ARCADE SETTINGS, GAMEPAD
# LAYOUT, KEYS ...
options=(Down Down Return)
down() { local i; for ((i = 0; i < $1; i++)); do printf 'Down '; done; }

drive "${options[@]}" Right
saved '^difficulty = "easy"' "difficulty"
drive "${options[@]}" $(down 1) Right
saved '^preset = "high"' "preset"
drive "${options[@]}" $(down 2) Left
saved '^style = "technical"' "style"  # wraps from vector to the table's last
drive "${options[@]}" $(down 3) Right
saved '^beam = "classic"' "beam look"
drive "${options[@]}" $(down 4) Left
saved '^volume = 0.7 ' "effects volume"
drive "${options[@]}" $(down 5) Return
saved '^fullscreen = true' "fullscreen"
drive "${options[@]}" $(down 6) Left
saved '^vsync = "off"' "vsync"
drive "${options[@]}" $(down 7) Return
saved '^show_fps = true' "show fps"
drive "${options[@]}" $(down 8) Right Right
saved '^max_fps = 60 ' "frame rate cap"
drive "${options[@]}" $(down 11) Right
saved '^gamepad = "drive"' "gamepad layout"

# Comfort and text: TEXT SIZE, FLICKER AND FLASHES, COLOUR-SAFE PALETTE.
comfort=("${options[@]}" $(down 9) Return)
drive "${comfort[@]}" Right Right
saved '^ui_scale = 1.5 ' "text size"
drive "${comfort[@]}" Down Right
saved '^flashes = "soft"' "flicker and flashes soft"
drive "${comfort[@]}" Down Left
saved '^flashes = "off"' "flicker and flashes off"
grep -q "no flicker or trails" "$work/pref/beamzone.log" || fail "flashes off not applied: $(grep look: "$work/pref/beamzone.log")"
ok "flashes off reaches the look"
drive "${comfort[@]}" Down Down Return
saved '^colour_safe = true' "colour-safe palette"

# Arcade settings: TANKS, MISSILES FROM, BONUS TANKS (each starts at the level's own).
arcade=("${options[@]}" $(down 10) Return)
drive "${arcade[@]}" Left
saved '^lives = 5 ' "arcade tanks"
drive "${arcade[@]}" Down Right Right Right
saved '^missile_score = 20000 ' "arcade missiles from"
drive "${arcade[@]}" Down Down Right
saved '^bonus_score = 0 ' "arcade bonus tanks (none)"

# A saved setting is read back: start again with that file and the option shows it.
drive "${arcade[@]}" Right
saved '^lives = 2 ' "arcade tanks 2"
cp "$work/pref/settings.toml" "$work/kept.toml"
mkdir -p "$work/pref2"
cp "$work/kept.toml" "$work/pref2/settings.toml"
BEAMZONE_PREF_DIR=$work/pref2 "$bin" play --headless-test --frames 400 --record "$work/r.bzreplay" \
    --press 30:F10 >"$work/out" 2>"$work/err" || fail "record with arcade settings: exit $?"
grep -q "^lives 2$" "$work/r.bzreplay" || fail "replay does not record 2 tanks: $(head -8 "$work/r.bzreplay")"
ok "arcade tanks from the settings file start the game and the replay records them"
echo "$pass passed, 0 failed"
