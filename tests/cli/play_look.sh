#!/usr/bin/env bash
# Which look `play` uses, as its "look:" log line states it. Style: --style, else the level's
# [render] style, else the settings file. Preset: --preset, else the settings file, else the
# level's preset. The level's line width, crease angle and bloom strength always apply.
set -euo pipefail
source "$(dirname "$0")/lib/harness.bash"

cat >"$work/styled.toml" <<'LVL'
version = 1
name = "Arcade, high, wide lines"
[render]
style = "arcade"
preset = "high"
line_width = 3
LVL
cat >"$work/plain.toml" <<'LVL'
version = 1
name = "No render section"
LVL
cat >"$work/preset_only.toml" <<'LVL'
version = 1
name = "Only a preset"
[render]
preset = "fast"
LVL

# look PREF_DIR ARGS...: runs a few frames and prints the look line.
look() {
  local pref=$1
  shift
  BEAMZONE_PREF_DIR=$pref "$bin" play --headless-test --frames 3 --seed 1 "$@" >"$work/out" 2>"$work/err" \
    || fail "play $* exited $?"
  grep -q "^play: 3 frames, 3 ticks, 0 GL errors$" "$work/out" || fail "play $*: $(cat "$work/out")"
  grep "look: " "$work/err" | sed 's/.*look: //'
}
expect() {  # what, wanted, got
  [ "$3" = "$2" ] || fail "$1: wanted '$2', got '$3'"
  ok "$1: $3"
}

# First start: the settings file is written with the defaults and counts as the player's.
got=$(look "$work/fresh" "$work/styled.toml")
expect "level style over the settings file, settings preset over the level's" \
  "style vector-xray (level), preset balanced (settings file), beam mame (settings file), line width 3 px (level)" "$got"
grep -q '^beam = "mame"' "$work/fresh/settings.toml" || fail "settings file without the beam"
grep -q '^preset = "balanced"' "$work/fresh/settings.toml" || fail "settings file not written"

got=$(look "$work/fresh" "$work/styled.toml" --style occluded --preset fast --beam classic)
expect "command line over both" \
  "style vector (command line), preset fast (command line), beam classic (command line), line width 3 px (level)" "$got"
grep -q '^preset = "balanced"' "$work/fresh/settings.toml" || fail "--preset was written into the settings file"

# A settings file that names a style but no preset: the level's preset fills in.
mkdir -p "$work/partial"
printf 'style = "arcade"\n' >"$work/partial/settings.toml"
got=$(look "$work/partial" "$work/preset_only.toml")
expect "settings style where the level names none, level preset where the settings name none" \
  "style vector-xray (settings file), preset fast (level), beam mame (default)" "$got"
got=$(look "$work/partial" "$work/plain.toml")
expect "neither names a preset" "style vector-xray (settings file), preset balanced (default), beam mame (default)" "$got"

echo "$pass passed, 0 failed"
