#!/usr/bin/env bash
# Levels naming hostile or broken model files: `check` imports every model through the same
# importer and limits as `play`, so both refuse the same levels, quickly, with one positioned
# line per model, and neither hangs nor grows without bound. Classes: header declaring 1.5e9
# vertices, .glb with a DAG of nodes, zip bomb (.3mf declaring gigabytes), FIFO as a model's
# mtllib, glTF buffer uri and mtllib escaping the level folder, garbage bytes.
set -uo pipefail
bin=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export BEAMZONE_PREF_DIR=$work/pref SDL_VIDEODRIVER=offscreen SDL_AUDIODRIVER=dummy
fail() { echo "FAIL: $*"; echo "--- stdout"; cat "$work/out"; echo "--- stderr"; cat "$work/err"; exit 1; }

mkdir -p "$work/lv" "$work/outside"
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n' >"$work/outside/secret.mtl"
level() {  # level NAME MODEL: a level in lv/ with one model obstacle
  cat >"$work/lv/$1.toml" <<LVL
version = 1
name = "$1"
[[obstacle]]
kind = "model"
model = "$2"
position = [0, 0, -30]
radius = 2
LVL
}
# run SECONDS COMMAND...: sets rc and the elapsed seconds; a run past the limit is a hang.
run() {
  local limit=$1
  shift
  local start=$SECONDS
  timeout -k 5 "$limit" "$bin" "$@" >"$work/out" 2>"$work/err"
  rc=$?
  took=$((SECONDS - start))
  [ $rc -ne 124 ] && [ $rc -ne 137 ] || fail "$* hung (over ${limit}s)"
}

# The good case first: a model in the level's folder loads in check and in play.
printf 'mtllib tri.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n' >"$work/lv/tri.obj"
printf 'newmtl m\nKd 0 1 0\n' >"$work/lv/tri.mtl"
level good tri.obj
run 60 check "$work/lv/good.toml"
[ $rc -eq 0 ] || fail "good level: check exit $rc"
run 120 play "$work/lv/good.toml" --headless-test --frames 3
[ $rc -eq 0 ] || fail "good level: play exit $rc"
echo "ok: a model in the level's folder loads in check and play"

# One hostile model per class: check and play both refuse it with the level's position.
printf 'ply\nformat ascii 1.0\nelement vertex 1500000000\nproperty float x\nproperty float y\nproperty float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n3 0 0 0\n' >"$work/lv/huge.ply"
printf 'not a model at all\n\x01\x02\x03' >"$work/lv/garbage.obj"
printf 'mtllib ../outside/secret.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n' >"$work/lv/escape.obj"
printf 'mtllib ../../../../../../../../../etc/passwd\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n' >"$work/lv/passwd.obj"
mkfifo "$work/lv/pipe.mtl"
printf 'mtllib pipe.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n' >"$work/lv/fifo_mtl.obj"
mkfifo "$work/lv/pipe.bin"
gltf() {  # gltf URI: a one-triangle glTF whose buffer is URI
  printf '{"asset":{"version":"2.0"},"buffers":[{"uri":"%s","byteLength":42}],"bufferViews":[{"buffer":0,"byteLength":36},{"buffer":0,"byteOffset":36,"byteLength":6}],"accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[1,1,0]},{"bufferView":1,"componentType":5123,"count":3,"type":"SCALAR"}],"meshes":[{"primitives":[{"attributes":{"POSITION":0},"indices":1}]}],"nodes":[{"mesh":0}],"scenes":[{"nodes":[0]}],"scene":0}' "$1"
}
gltf pipe.bin >"$work/lv/fifo_uri.gltf"
gltf ../outside/secret.mtl >"$work/lv/escape_uri.gltf"
# A DAG: 40 levels of two nodes, each sharing both nodes of the next level (2^41 paths).
{
  printf '{"asset":{"version":"2.0"},"nodes":['
  for i in $(seq 0 39); do
    for k in 0 1; do
      [ "$i$k" = "00" ] || printf ','
      if [ "$i" -lt 39 ]; then printf '{"children":[%d,%d]}' $((2 * i + 2)) $((2 * i + 3)); else printf '{}'; fi
    done
  done
  printf '],"scenes":[{"nodes":[0,1]}],"scene":0}'
} >"$work/lv/dag.gltf"

declare -A reason=(
  [huge.ply]="PLY header declares 1500000000"
  [garbage.obj]="error: model $work/lv/garbage.obj: "
  [escape.obj]="secret.mtl': leads outside"
  [passwd.obj]="etc/passwd': leads outside"
  [fifo_mtl.obj]="pipe.mtl': not a regular file (a FIFO)"
  [fifo_uri.gltf]="pipe.bin': not a regular file (a FIFO)"
  [escape_uri.gltf]="secret.mtl': leads outside"
  [dag.gltf]="node instances"
)
for model in "${!reason[@]}"; do
  name=${model//./_}
  level "$name" "$model"
  run 60 check "$work/lv/$name.toml"
  [ $rc -eq 1 ] || fail "$model: check exit $rc, expected 1"
  [ "$(grep -c . "$work/err")" -eq 1 ] || fail "$model: check printed more than one line"
  grep -q "^$work/lv/$name.toml:3:1: error: model $work/lv/$model: " "$work/err" || fail "$model: check message not positioned"
  grep -qF "${reason[$model]}" "$work/err" || fail "$model: check message lacks '${reason[$model]}'"
  [ $took -le 20 ] || fail "$model: check took ${took}s"
  check_line=$(cat "$work/err")
  run 120 play "$work/lv/$name.toml" --headless-test --frames 3
  [ $rc -eq 1 ] || fail "$model: play exit $rc, expected 1"
  grep -qF "${reason[$model]}" "$work/err" || fail "$model: play message lacks '${reason[$model]}'"
  grep -qF "$check_line" "$work/err" || fail "$model: play and check say different things"
  echo "ok: $model refused by check and play (${took}s): ${reason[$model]}"
done

# A FIFO in the level's folder named as the model itself.
mkfifo "$work/lv/model_pipe.obj"
level model_fifo model_pipe.obj
run 30 check "$work/lv/model_fifo.toml"
[ $rc -eq 1 ] || fail "FIFO model: check exit $rc"
grep -q "is not a regular file" "$work/err" || fail "FIFO model: message"
echo "ok: a FIFO as the model is refused"

# render confines a model to its own folder.
run 60 render "$work/lv/escape.obj" --out "$work/escape.png"
[ $rc -eq 1 ] || fail "render escape: exit $rc"
grep -qF "secret.mtl': leads outside" "$work/err" || fail "render escape: message"
[ ! -e "$work/escape.png" ] || fail "render escape: wrote an image"
echo "ok: render refuses a model reading outside its folder"

# render and a zip bomb: a .3mf whose model entry inflates to 300 MB (over the 256 MB cap) is
# refused from the zip's directory, before anything is inflated.
if command -v python3 >/dev/null; then
  python3 - "$work/bomb.3mf" <<'PY'
import sys, zipfile
with zipfile.ZipFile(sys.argv[1], "w", zipfile.ZIP_DEFLATED, compresslevel=9) as z:
    z.writestr("[Content_Types].xml", "<Types/>")
    with z.open("3D/3dmodel.model", "w", force_zip64=True) as f:
        block = b"\0" * (1 << 20)
        for _ in range(300):
            f.write(block)
PY
  run 60 render "$work/bomb.3mf" --out "$work/bomb.png"
  [ $rc -eq 1 ] || fail "zip bomb: render exit $rc"
  [ "$(grep -c . "$work/err")" -eq 1 ] || fail "zip bomb: more than one line"
  grep -qF "$work/bomb.3mf: error: zip entry '3D/3dmodel.model' inflates to 314572800 bytes" "$work/err" || fail "zip bomb: message"
  echo "ok: render refuses a zip bomb .3mf ($(stat -c %s "$work/bomb.3mf") bytes) in ${took}s"
fi
