#!/usr/bin/env bash
# `beamzone play` on a machine with no display: exactly one line pointing at `beamzone render`,
# exit 1, no crash, whichever way the display is missing.
set -euo pipefail
bin=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export BEAMZONE_PREF_DIR=$work/pref
unset BEAMZONE_ALLOW_OFFSCREEN

check() {
  local label=$1
  shift
  set +e
  env "$@" "$bin" play --frames 3 >"$work/out" 2>"$work/err"
  local rc=$?
  set -e
  if [ $rc -ne 1 ]; then
    echo "FAIL ($label): exit $rc, expected 1"; cat "$work/err"; exit 1
  fi
  if [ "$(wc -l <"$work/err")" -ne 1 ] || [ -s "$work/out" ]; then
    echo "FAIL ($label): expected one line on stderr and nothing on stdout"; cat "$work/out" "$work/err"; exit 1
  fi
  grep -q "^beamzone: no display available (.*); try \`beamzone render\` for headless images$" "$work/err" || {
    echo "FAIL ($label): unexpected message: $(cat "$work/err")"; exit 1; }
  echo "ok ($label): $(cat "$work/err")"
}

check "offscreen driver" SDL_VIDEODRIVER=offscreen DISPLAY=:0
check "dummy driver" SDL_VIDEODRIVER=dummy
check "no DISPLAY" -u DISPLAY -u WAYLAND_DISPLAY -u SDL_VIDEODRIVER

# DISPLAY names a display nobody serves: SDL falls back to its invisible offscreen driver, and
# play must not run unseen. (Wayland's probe may print its own line first, so only the hint is
# checked here, not the line count.)
set +e
env -u SDL_VIDEODRIVER -u WAYLAND_DISPLAY DISPLAY=:7391 timeout 60 "$bin" play >"$work/out" 2>"$work/err"
rc=$?
set -e
if [ $rc -ne 1 ] || [ -s "$work/out" ] || ! grep -q "^beamzone: no display available (.*); try \`beamzone render\` for headless images$" "$work/err"; then
  echo "FAIL (unreachable DISPLAY): exit $rc"; cat "$work/out" "$work/err"; exit 1
fi
echo "ok (unreachable DISPLAY): $(grep '^beamzone:' "$work/err")"
echo "4 passed, 0 failed"
