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

# A cube is far below auto's threshold: the geometry shader draws it (no edges pass).
expect 0 "lines" render builtin:cube --size 96x72 --repeat 2 --line-method auto --out "$work/auto.png"
grep -q "^edges " "$work/out" "$work/err" && fail "auto drew a cube with the compute method: $(cat "$work/out")"
expect 0 "lines" render builtin:cube --size 96x72 --repeat 2 --line-method geometry_shader --out "$work/gs.png"
cmp -s "$work/auto.png" "$work/gs.png" || fail "auto's cube differs from the geometry shader's"
# Many copies pass it: the compute method's passes.
expect 0 "^edges " render builtin:sphere --copies 64 --size 96x72 --repeat 2 --line-method auto --out "$work/many.png"

expect 2 "unknown line method 'fastest' \(use compute, geometry_shader, auto or image_outline\)" \
  render builtin:cube --size 96x72 --line-method fastest --out "$work/x.png"
[ -e "$work/x.png" ] && fail "render wrote an image for a bad line method"
expect 2 "unknown line method 'fastest'" bench "$root/levels/classic.toml" --frames 2 --line-method fastest
expect 0 "p50" bench "$root/levels/classic.toml" --frames 3 --warmup 1 --size 96x54 --line-method auto --out "$work/bench"
expect 2 "--line-method: expected compute, geometry_shader or auto, not 'fastest'" play --line-method fastest
echo "line method CLI ok"
