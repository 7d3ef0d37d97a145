#!/usr/bin/env bash
# render --svg and reference --svg: the SVG parses as valid SVG structure with a real XML
# parser, and rasterised by a real SVG rasteriser (rsvg-convert) at the frame's size its lines
# score F1 >= 0.99 against the exact reference mask on real models; a level frame, the styles
# and bad outputs go through too.
set -uo pipefail
bin=$1
root=$(cd "$(dirname "$0")/../.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }
py=/usr/bin/python3
lines="$(dirname "$0")/lib/svg_lines.py"
command -v rsvg-convert >/dev/null || fail "rsvg-convert missing (tools/install-deps installs librsvg2-bin)"

expect_seconds=300
source "$(dirname "$0")/lib/expect.bash"

# score NAME W H: rasterise $work/NAME.svg as hairlines and score it against $work/NAME-ref.png.
score() {
  local name=$1 w=$2 h=$3
  "$py" "$lines" check "$work/$name.svg" "$w" "$h" >"$work/check" || fail "$name: invalid SVG"
  "$py" "$lines" hairline "$work/$name.svg" "$work/$name-hair.svg" || fail "$name: hairline"
  rsvg-convert "$work/$name-hair.svg" -o "$work/$name-raster.png" || fail "$name: rsvg-convert"
  "$py" "$lines" mask "$work/$name-raster.png" "$work/$name-svgmask.png" || fail "$name: mask"
  expect 0 "f1" compare "$work/$name-svgmask.png" "$work/$name-ref.png"
  local f1
  f1=$(grep -oE 'f1 [0-9.]+' "$work/out" | cut -d' ' -f2)
  echo "$name: $(cat "$work/check"); $(cat "$work/out")"
  awk -v f="$f1" 'BEGIN { exit !(f >= 0.99) }' || fail "$name: F1 $f1 < 0.99"
}

models=/usr/share/assimp/models
for m in PLY/Wuson.ply OBJ/spider.obj glTF/CesiumMilkTruck/CesiumMilkTruck.gltf 3DS/fels.3ds \
         Collada/duck.dae; do
  [ -f "$models/$m" ] || fail "missing test model $models/$m (assimp-testmodels)"
  name=$(basename "$m" | tr . _)
  expect 0 "paths after chaining; pen-up travel" render "$models/$m" --size 320x240 \
    --out "$work/$name.png" --svg "$work/$name.svg"
  expect 0 "lit pixels" reference "$models/$m" --size 320x240 --mask "$work/$name-ref.png"
  score "$name" 320 240
done

# Material lines: a cube whose faces come in three materials, one face split along its
# diagonal; the edges between materials go to a group of their own and still match the
# reference that draws them too. Without --material-lines that group stays empty.
cube_mat=$models/OBJ/cube_usemtl.obj
expect 0 "" render "$cube_mat" --size 320x240 --material-lines --out "$work/m.png" \
  --svg "$work/material.svg"
expect 0 "" reference "$cube_mat" --size 320x240 --material-lines --mask "$work/material-ref.png"
score material 320 240
grep -A1 '<g id="material"' "$work/material.svg" | grep -q '<path' ||
  fail "material SVG has no path in its material group"
expect 0 "" render "$cube_mat" --size 320x240 --out "$work/m.png" --svg "$work/plain.svg"
if grep -A1 '<g id="material"' "$work/plain.svg" | grep -q '<path'; then
  fail "material lines drawn without --material-lines"
fi

# Intersection lines: the intersections level turns them on itself ([render]
# intersection_lines); its crossings go to a group of their own, and the SVG still matches the
# mask of the same frame. Copies of a cube overlapping (--copy-step below 1) get them from
# --intersection-lines, and none without it.
expect 0 "" reference --level "$root/levels/intersections.toml" --time 3 --size 320x240 \
  --mask "$work/intersection-ref.png" --svg "$work/intersection.svg"
score intersection 320 240
grep -A1 '<g id="intersection"' "$work/intersection.svg" | grep -q '<path' ||
  fail "intersection SVG has no path in its intersection group"
expect 0 "" render builtin:cube --copies 4 --copy-step 0.7 --intersection-lines --size 320x240 \
  --out "$work/i.png" --svg "$work/copies.svg"
grep -A1 '<g id="intersection"' "$work/copies.svg" | grep -q '<path' ||
  fail "overlapping copies have no intersection lines"
expect 0 "" render builtin:cube --copies 4 --copy-step 0.7 --size 320x240 --out "$work/i.png" \
  --svg "$work/copies-plain.svg"
if grep -A1 '<g id="intersection"' "$work/copies-plain.svg" | grep -q '<path'; then
  fail "intersection lines drawn without --intersection-lines"
fi

# Another view, another style: the x-ray style hides nothing, in the SVG as in the mask.
expect 0 "" render builtin:sphere --size 200x150 --eye 0,1,4 --style vector-xray \
  --out "$work/x.png" --svg "$work/xray.svg"
expect 0 "" reference builtin:sphere --size 200x150 --eye 0,1,4 --style vector-xray \
  --mask "$work/xray-ref.png"
score xray 200 150
# A paper style strokes in its ink over its paper.
expect 0 "" render builtin:cube --size 160x120 --style toon --out "$work/t.png" --svg "$work/toon.svg"
grep -q 'fill="#c7dbed"' "$work/toon.svg" || fail "toon SVG lacks its paper background"
grep -q '<g id="silhouette"[^>]*stroke="#050508" stroke-width="3"' "$work/toon.svg" ||
  fail "toon SVG lacks its ink and width: $(grep '<g' "$work/toon.svg")"

# The technical style: the cube's three hidden edges, dashed and anchored, in hidden-1; its
# visible lines still match the reference.
expect 0 "" render builtin:cube --size 320x240 --style technical --out "$work/t.png" \
  --svg "$work/tech.svg"
expect 0 "" reference builtin:cube --size 320x240 --style technical --mask "$work/tech-ref.png"
score tech 320 240
grep -q "hidden-1=3" "$work/check" || fail "technical cube: $(cat "$work/check")"
grep -q 'stroke-dasharray="6 4"' "$work/tech.svg" || fail "technical cube: no dashes"

# A level frame, from reference (the level's benchmark camera).
expect 0 "paths after chaining" reference --level "$root/levels/classic.toml" --time 2 \
  --size 320x180 --mask "$work/level-ref.png" --svg "$work/level.svg"
score level 320 180

# The play key: Shift+F12 writes screenshot-0001.svg into the pref folder, F12 still the PNG.
mkdir -p "$work/pref"
BEAMZONE_PREF_DIR="$work/pref" timeout 120 "$bin" play --headless-test --frames 40 --size 320x180 \
  --press 2:Return,30:Shift+F12,35:F12 >"$work/out" 2>&1 || fail "play exit $?: $(tail -3 "$work/out")"
grep -q "vector screenshot saved: .*paths after chaining" "$work/out" || fail "no vector screenshot log"
[ -f "$work/pref/screenshots/screenshot-0001.png" ] || fail "F12 wrote no PNG"
"$py" "$lines" check "$work/pref/screenshots/screenshot-0001.svg" 320 180 >"$work/check" ||
  fail "the play SVG is invalid"
grep -q "hud=" "$work/check" || fail "the play SVG lacks the HUD: $(cat "$work/check")"

# Outputs: an existing non-SVG file is not replaced; an SVG is; usage errors exit 2.
printf 'keep me' >"$work/keep.svg"
expect 1 "not a SVG document" render builtin:cube --out "$work/c.png" --svg "$work/keep.svg"
[ "$(cat "$work/keep.svg")" = "keep me" ] || fail "keep.svg was overwritten"
expect 0 "" render builtin:cube --size 64x48 --out "$work/c.png" --svg "$work/xray.svg"
expect 2 "same file" render builtin:cube --out "$work/c.png" --svg "$work/c.png"
expect 2 "same file" reference builtin:cube --mask "$work/r.svg" --svg "$work/r.svg"
expect 1 "folder" render builtin:cube --out "$work/c.png" --svg "$work/no/such/dir/x.svg"
echo "svg export ok"
