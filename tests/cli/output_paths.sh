#!/usr/bin/env bash
# Output options given carelessly: a missing or empty value, an option where the value should
# be, a folder that does not exist, a path that names an input or a file of another kind, a
# place nothing can be written (/proc) and a full disk. Each is refused with a message and a
# non-zero exit; no file is created, replaced or left half-written, and no folder is created.
set -uo pipefail
bin=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export BEAMZONE_PREF_DIR=$work/pref SDL_VIDEODRIVER=offscreen SDL_AUDIODRIVER=dummy
cd "$work"
passed=0
fail() { echo "FAIL: $*"; cat "$work/err" 2>/dev/null; exit 1; }
# expect RC NEEDLE CMD...: runs CMD, checks the exit status and that stderr holds NEEDLE.
expect() {
  local want=$1 needle=$2
  shift 2
  "$@" >"$work/out" 2>"$work/err"
  local rc=$?
  [ "$rc" -eq "$want" ] || fail "$* -> exit $rc, expected $want"
  [ -z "$needle" ] || grep -qF -- "$needle" "$work/err" || fail "$* -> stderr lacks '$needle'"
  echo "ok $*: exit $rc"
  passed=$((passed + 1))
}

printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\nf 1 3 4\nf 1 4 2\nf 2 4 3\n' >tet.obj
cp tet.obj tet.orig
printf 'version = 1\nname = "Mine"\n' >mine.toml
cp mine.toml mine.orig

# A missing value never swallows the next option, and an empty one is a usage error.
expect 2 "--mask needs a value, but the next word is the option --out" \
  "$bin" render builtin:cube --mask --out
[ ! -e ./--out ] || fail "a file named --out was written"
expect 2 "--out needs a value" "$bin" render builtin:cube --out
expect 2 "--out needs a value, not an empty string" "$bin" render builtin:cube --out ''
expect 2 "--record needs a value" "$bin" play --headless-test --record --frames 5
expect 2 "--out needs a value" "$bin" bench mine.toml --out --frames 3
expect 2 "--level needs a value" "$bin" replay x.replay --level --verify
# Negative numbers are values, not options.
expect 0 "" "$bin" render builtin:cube --eye -4,3,-5 --size 32x24 --out neg.png

# Missing folders are never created.
expect 1 "does not exist" "$bin" render builtin:cube --size 32x24 --out new/dir/f.png
[ ! -e new ] || fail "render created a folder"
expect 1 "does not exist" "$bin" play --headless-test --frames 5 --record new/dir/r.replay
[ ! -e new ] || fail "play created a folder"
expect 1 "does not exist" "$bin" replay new/dir/d.replay --record-demo 1
[ ! -e new ] || fail "replay --record-demo created a folder"
expect 1 "does not exist" "$bin" bench mine.toml --frames 2 --warmup 0 --out new/dir
[ ! -e new ] || fail "bench created a folder"

# An input, or an existing file of another kind, is never replaced.
expect 1 "that is an input" "$bin" render tet.obj --size 32x24 --out tet.obj
expect 1 "that is an input" "$bin" render tet.obj --size 32x24 --out ./tet.obj --mask m.png
expect 1 "not a PNG image" "$bin" render builtin:cube --size 32x24 --out mine.toml
expect 1 "not a PNG image" "$bin" render builtin:cube --size 32x24 --mask tet.obj
expect 2 "name the same file" "$bin" render builtin:cube --out a.png --mask a.png
expect 1 "that is an input" "$bin" play mine.toml --headless-test --frames 5 --record mine.toml
expect 1 "not a beamzone replay" "$bin" play --headless-test --frames 5 --record tet.obj
expect 1 "not a beamzone replay" "$bin" replay mine.toml --record-demo 1
expect 1 "that is a folder" "$bin" render builtin:cube --size 32x24 --out pref
expect 1 "not a PNG image" "$bin" reference builtin:cube --size 32x24 --mask mine.toml
cmp -s tet.obj tet.orig || fail "the model was replaced"
cmp -s mine.toml mine.orig || fail "the level was replaced"
# Writing over an earlier output of the same kind is fine.
expect 0 "" "$bin" render builtin:cube --size 32x24 --out neg.png

# Nowhere to write: refused before the game starts.
expect 1 "cannot create files in '/proc'" "$bin" play --headless-test --frames 5 --record /proc/r.replay

# A full disk (a file size limit of 0 makes every write fail with EFBIG): the recording cannot
# be saved, which is an error with a message and a non-zero exit.
# (The messages go through a pipe: the size limit would stop them reaching a file.)
(ulimit -f 0; trap '' XFSZ; exec "$bin" play --headless-test --frames 5 --seed 3 --record full.replay) \
  2>&1 | cat >"$work/err"
rc=${PIPESTATUS[0]}
[ $rc -eq 1 ] || fail "play --record onto a full disk -> exit $rc"
grep -qF "cannot save the recording" "$work/err" || fail "no message for the failed save"
[ ! -s full.replay ] || fail "a partial recording was left"
echo "ok play --record onto a full disk: exit $rc, $(grep -F 'cannot save' "$work/err" | head -1)"
passed=$((passed + 1))
echo "$passed passed, 0 failed"
