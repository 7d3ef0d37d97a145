#!/usr/bin/env bash
# Without a usable sound device, what the audio libraries print on stderr (ALSA's "ALSA lib
# ..." lines) goes to the log, and the terminal shows only the game's own one-line warning.
# On a machine whose ALSA finds a device, or without ALSA, there is nothing to hide: the
# check then only requires that no library line reached the terminal.
set -euo pipefail
source "$(dirname "$0")/lib/harness.bash"
SDL_AUDIODRIVER=alsa "$bin" play --headless-test --frames 3 >"$work/out" 2>"$work/err" ||
    fail "play exit $?"
if grep -q "ALSA lib" "$work/err"; then fail "library noise on the terminal"; fi
ok "no ALSA library lines on the terminal"
if grep -q "audio libraries said: ALSA lib" "$work/pref/beamzone.log"; then
    grep -q "warn: .*playing silently" "$work/err" || fail "the game's own warning is missing"
    [ "$(grep -c "playing silently" "$work/err")" -eq 1 ] || fail "more than one warning line"
    ok "the library lines are in the log, the terminal has one warning"
fi
echo "$pass passed, 0 failed"
