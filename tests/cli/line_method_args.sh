#!/usr/bin/env bash
# --line-method on render, bench and play: compute, geometry_shader and auto are accepted
# (auto draws each frame with one of the other two and the per-pass times show which), and a
# bad name is a usage error (exit 2) naming the valid ones, before anything is drawn.
set -uo pipefail
bin=$1
root=$(cd "$(dirname "$0")/../.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }
export SDL_VIDEODRIVER=offscreen SDL_AUDIODRIVER=dummy BEAMZONE_PREF_DIR=$work/pref

expect_seconds=300
source "$(dirname "$0")/lib/expect.bash"

# The test's own cache folder: what auto chooses must not hang on a measurement another test
# took under whatever load the run had. Empty, render uses the built-in rule (4,000 triangles).
export BEAMZONE_CACHE_DIR=$work/cache
# A cube is far below it: the geometry shader draws it (no edges pass).
expect 0 "lines" render builtin:cube --size 96x72 --repeat 2 --line-method auto --out "$work/auto.png"
grep -q "^edges " "$work/out" "$work/err" && fail "auto drew a cube with the compute method: $(cat "$work/out")"
expect 0 "lines" render builtin:cube --size 96x72 --repeat 2 --line-method geometry_shader --out "$work/gs.png"
cmp -s "$work/auto.png" "$work/gs.png" || fail "auto's cube differs from the geometry shader's"
# Many copies pass it: the compute method's passes.
expect 0 "^edges " render builtin:sphere --copies 64 --size 96x72 --repeat 2 --line-method auto --out "$work/many.png"

# bench measures the machine and keeps the crossing; render then follows what is kept, not its
# built-in rule: set the kept crossing to never, then to always.
expect 0 "p50" bench "$root/levels/classic.toml" --frames 2 --warmup 1 --size 96x54 --line-method auto --out "$work/calibrate"
kept=$work/cache/line-methods.json
[ -s "$kept" ] || fail "bench kept no line-method measurement in $kept"
grep -q '"compute_from_triangles"' "$kept" || fail "no crossing in $kept: $(cat "$kept")"
sed -i -E 's/"compute_from_triangles": [0-9]+/"compute_from_triangles": 1000000000/' "$kept"
expect 0 "lines" render builtin:sphere --copies 64 --size 96x72 --repeat 2 --line-method auto --out "$work/never.png"
grep -q "^edges " "$work/out" "$work/err" && fail "a kept crossing of 1e9 triangles, yet auto drew 64 spheres with compute"
sed -i -E 's/"compute_from_triangles": [0-9]+/"compute_from_triangles": 0/' "$kept"
expect 0 "^edges " render builtin:cube --size 96x72 --repeat 2 --line-method auto --out "$work/always.png"

expect 2 "unknown line method 'fastest' \(use compute, geometry_shader, auto or image_outline\)" \
  render builtin:cube --size 96x72 --line-method fastest --out "$work/x.png"
[ -e "$work/x.png" ] && fail "render wrote an image for a bad line method"
expect 2 "unknown line method 'fastest'" bench "$root/levels/classic.toml" --frames 2 --line-method fastest
expect 2 "--line-method: expected compute, geometry_shader or auto, not 'fastest'" play --line-method fastest
echo "line method CLI ok"
