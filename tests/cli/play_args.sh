#!/usr/bin/env bash
# Command line of `beamzone play`: --help names the settings and high-score files; bad options
# are usage errors (exit 2, one line naming the option), checked before any window opens.
set -euo pipefail
bin=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export BEAMZONE_PREF_DIR=$work/pref
export SDL_VIDEODRIVER=offscreen

"$bin" play --help >"$work/help"
grep -q "^usage: beamzone play" "$work/help"
grep -qF "settings:    $work/pref/settings.toml" "$work/help" || { echo "FAIL: --help lacks the settings path"; cat "$work/help"; exit 1; }
grep -qF "high scores: $work/pref/highscores.toml" "$work/help" || { echo "FAIL: --help lacks the high-score path"; exit 1; }
grep -qF -- "--frames N" "$work/help"
echo "ok --help"

passed=1
bad() {
  local needle=$1
  shift
  set +e
  "$bin" play "$@" >"$work/out" 2>"$work/err"
  local rc=$?
  set -e
  if [ $rc -ne 2 ] || [ "$(wc -l <"$work/err")" -ne 1 ] || ! grep -qF -- "$needle" "$work/err"; then
    echo "FAIL: play $* -> exit $rc, stderr:"; cat "$work/err"; exit 1
  fi
  echo "ok $*: $(cat "$work/err")"
  passed=$((passed + 1))
}
bad "--preset" --preset ultra
bad "--style" --style cel
bad "--vsync" --vsync maybe
bad "--frames" --frames 0
bad "--frames" --frames many
bad "--seed" --seed -4
bad "--seed" --seed 99999999999999999999999
bad "needs a value" --record
bad "cannot be used together" --record a --replay b
bad "unknown option --bogus" --bogus
bad "more than one LEVEL" a.toml b.toml
echo "$passed passed, 0 failed"
