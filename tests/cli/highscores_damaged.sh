#!/usr/bin/env bash
# play with a damaged high-score file: the file is kept aside byte for byte as
# highscores.toml.bad-DATE, its valid entries are written back at once, and the run says so.
# An old one-table file (format 1) is read without complaint and nothing is moved.
set -euo pipefail
bin=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export BEAMZONE_PREF_DIR=$work/pref SDL_VIDEODRIVER=offscreen SDL_AUDIODRIVER=dummy
mkdir -p "$work/pref"
fail() { echo "FAIL: $*"; cat "$work/err"; exit 1; }

printf 'beamzone-highscores 2\nlevel 0000000000000abc Classic\nAAA 900\nB\033B 800\nCCC 700\nend\n' \
  >"$work/pref/highscores.toml"
cp "$work/pref/highscores.toml" "$work/damaged"
"$bin" play --headless-test --frames 5 >"$work/out" 2>"$work/err" || fail "play exit $?"
aside=$(ls "$work/pref" | grep '^highscores\.toml\.bad-' || true)
[ -n "$aside" ] || fail "the damaged file was not kept aside"
cmp -s "$work/damaged" "$work/pref/$aside" || fail "the kept file differs from the damaged one"
grep -qx "AAA 900" "$work/pref/highscores.toml" && grep -qx "CCC 700" "$work/pref/highscores.toml" \
  || fail "valid entries lost: $(cat "$work/pref/highscores.toml")"
grep -qF "highscores.toml:4:2: error: initials must be A-Z, 0-9 or space, not 'B\\eB'" "$work/err" \
  || fail "no escaped, positioned message"
grep -qF "kept as $aside; its 2 valid entries are kept" "$work/err" || fail "no summary"
echo "ok damaged file kept aside as $aside, 2 valid entries kept"

rm -f "$work/pref/"highscores.toml*
printf 'beamzone-highscores 1\nOLD 1234\nend\n' >"$work/pref/highscores.toml"
"$bin" play --headless-test --frames 5 >"$work/out" 2>"$work/err" || fail "play exit $?"
! grep -q "warn.*highscores" "$work/err" || fail "an old file was reported"
[ -z "$(ls "$work/pref" | grep '\.bad-' || true)" ] || fail "an old file was moved aside"
echo "ok an old one-table file is read as it is"
echo "2 passed, 0 failed"
