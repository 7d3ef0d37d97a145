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
echo "3 passed, 0 failed"
