#!/usr/bin/env bash
# Degenerate cameras, one table through every command that makes a picture and through `check`:
# the up vector along the view, the eye at the target, near >= far after framing, coordinates
# beyond float range (given, or a model's). Each gets one clear message and a non-zero exit:
# never an empty picture with exit 0, never an internal error, never a written file.
set -uo pipefail
bin=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export BEAMZONE_PREF_DIR=$work/pref SDL_VIDEODRIVER=offscreen SDL_AUDIODRIVER=dummy
cd "$work"
passed=0
fail() { echo "FAIL: $*"; cat "$work/err"; exit 1; }

printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\nf 1 3 4\nf 1 4 2\nf 2 4 3\n' >tet.obj
printf 'v 0 0 0\nv 1e30 0 0\nv 0 1e30 0\nv 0 0 1e30\nf 1 2 3\nf 1 3 4\nf 1 4 2\nf 2 4 3\n' >huge.obj
printf 'v 1e38 1e38 1e38\nv -1e38 0 0\nv 0 -1e38 0\nf 1 2 3\n' >edge.obj

# model | camera options | what the message says
cameras=(
  "tet.obj|--eye 0,10,0 --target 0,0,0|parallel to the up vector"
  "tet.obj|--eye 0,-3,0 --target 0,2,0|parallel to the up vector"
  "tet.obj|--eye 1,1,1 --target 0,0,0 --up 2,2,2|parallel to the up vector"
  "tet.obj|--eye 0.5,10,0.5|parallel to the up vector"
  "tet.obj|--eye 1,1,1 --target 1,1,1|must differ"
  "tet.obj|--eye 0,0,5 --near 50|not before the far plane"
  "tet.obj|--eye 0,0,5 --far 0.001|not before the far plane"
  "tet.obj|--eye 1e300,0,0 --target 0,0,0|not a finite point"
  "tet.obj|--up 0,0,0|--up must not be zero"
  "huge.obj||beyond"
  "huge.obj|--eye 5,5,5|beyond"
  "edge.obj||beyond"
)
for row in "${cameras[@]}"; do
  IFS='|' read -r model options needle <<<"$row"
  for cmd in "render $model --size 32x24 --out pic.png --mask m.png" \
    "reference $model --size 32x24 --mask pic.png"; do
    rm -f pic.png m.png
    # shellcheck disable=SC2086
    timeout 120 "$bin" $cmd $options >"$work/out" 2>"$work/err"
    rc=$?
    label="${cmd%% *} $model $options"
    [ $rc -eq 1 ] || [ $rc -eq 2 ] || fail "$label: exit $rc"
    grep -qF -- "$needle" "$work/err" || fail "$label: the message lacks '$needle'"
    grep -q "internal error" "$work/err" && fail "$label: an internal error"
    [ ! -e pic.png ] && [ ! -e m.png ] || fail "$label: a picture was written"
    echo "ok $label: exit $rc, $(grep -m1 -F -- "$needle" "$work/err" | cut -c1-140)"
    passed=$((passed + 1))
  done
done

# Levels: a camera key straight down is an error at its line in `check` and wherever the level
# loads; keys that are fine alone but pass straight over the target between them are refused
# by the commands that follow the path, at the time it happens.
cat >down.toml <<'T'
version = 1
name = "Down"

[[camera_key]]
time = 0
eye = [0, 40, 0]
target = [0, 0, 0]

[[camera_key]]
time = 4
eye = [10, 40, 0]
target = [0, 0, 0]
T
cat >over.toml <<'T'
version = 1
name = "Over"

[[camera_key]]
time = 0
eye = [-10, 40, 0]
target = [0, 0, 0]

[[camera_key]]
time = 2
eye = [10, 40, 0]
target = [0, 0, 0]
T
for cmd in "check down.toml" "bench down.toml --frames 2 --warmup 0 --size 32x24 --out b1" \
  "reference --level down.toml --time 0.5 --size 32x24 --mask pic.png" \
  "bench over.toml --frames 120 --warmup 0 --size 32x24 --out b2" \
  "reference --level over.toml --time 1 --size 32x24 --mask pic.png"; do
  rm -f pic.png
  # shellcheck disable=SC2086
  timeout 300 "$bin" $cmd >"$work/out" 2>"$work/err"
  rc=$?
  [ $rc -eq 1 ] || fail "$cmd: exit $rc"
  grep -q "cannot make a picture" "$work/err" || fail "$cmd: no message"
  grep -q "internal error" "$work/err" && fail "$cmd: an internal error"
  [ ! -e pic.png ] && [ ! -e b2/summary.json ] || fail "$cmd: a result was written"
  case $cmd in *down.toml*) grep -q "down.toml:7:" "$work/err" || fail "$cmd: no file:line";; esac
  echo "ok $cmd: $(grep -m1 "cannot make" "$work/err" | cut -c1-160)"
  passed=$((passed + 1))
done
echo "$passed passed, 0 failed"
