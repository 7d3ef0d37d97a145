#!/usr/bin/env bash
# beamzone bench --accuracy: on one small real model it scores every preset and the baseline
# from the four views, writes the JSON, the plot, the masks and the diffs, reuses its cached
# reference masks on a second run, a view is reproducible with `reference`, and bad usage or
# a bad model gets a clear message.
set -uo pipefail
bin=$1
models=${BEAMZONE_MODELS_DIR:-/usr/share/assimp/models}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }
[ -f "$models/PLY/Wuson.ply" ] || { echo "missing $models (install assimp-testmodels)" >&2; exit 1; }

expect_seconds=600
source "$(dirname "$0")/lib/expect.bash"

run() { expect 0 "goal high: mean F1 >= balanced" bench --accuracy --models-dir "$models" --model PLY/Wuson.ply \
  --model Collada/duck.dae --size 160x120 --frames 2 --out "$work/acc"; }
run
for f in accuracy.json accuracy_tradeoff.png masks/Wuson.ply_framed_reference.png \
  masks/duck.dae_above_high.png diffs/Wuson.ply_close_balanced.png; do
  [ -s "$work/acc/$f" ] || fail "accuracy wrote no $f"
done
for cfg in fast balanced high image-outline; do
  grep -q "\"label\": \"$cfg\"" "$work/acc/accuracy.json" || fail "accuracy.json lacks $cfg"
done
for view in framed behind close above; do
  [ "$(grep -c "\"view\": \"$view\"" "$work/acc/accuracy.json")" -ge 2 ] || fail "accuracy.json lacks view $view"
done
for key in '"precision"' '"recall"' '"f1"' '"frame_ms_p50"' '"mean_f1"' '"min_f1"' '"reference_command"'; do
  grep -q "$key" "$work/acc/accuracy.json" || fail "accuracy.json lacks $key"
done
# 2 models x 4 views cached; a second run computes no reference mask.
[ "$(ls "$work/acc/reference-cache" | wc -l)" -eq 8 ] || fail "reference cache: $(ls "$work/acc/reference-cache")"
cp "$work/acc/masks/Wuson.ply_behind_reference.png" "$work/first.png"
run
grep -Eq '"reference_cpu_ms": 0(\.0)?,' "$work/acc/accuracy.json" || fail "second run recomputed references: $(grep reference_cpu "$work/acc/accuracy.json")"
cmp -s "$work/first.png" "$work/acc/masks/Wuson.ply_behind_reference.png" || fail "cached reference differs"
# The JSON's command for a view rebuilds the same reference mask.
cmd=$(grep -m1 -A0 '"reference_command": "reference [^"]*Wuson.ply[^"]*"' "$work/acc/accuracy.json" | sed -n 's/.*"reference_command": "\(.*\)".*/\1/p')
[ -n "$cmd" ] || fail "no reference_command for Wuson"
# shellcheck disable=SC2086
expect 0 "" $cmd --mask "$work/again.png"
cmp -s "$work/again.png" "$work/acc/masks/Wuson.ply_framed_reference.png" || fail "reference_command gives another mask: $cmd"

# Usage errors (exit 2) and a model that cannot be loaded (skipped, named; none left: exit 1).
expect 2 "takes no LEVEL" bench levels/stress.toml --accuracy
expect 2 "exclude each other" bench --accuracy --preset high
expect 2 "--model needs --accuracy" bench levels/stress.toml --model x.ply
printf 'not a model' >"$work/bad.ply"
expect 1 "bad.ply" bench --accuracy --model "$work/bad.ply" --size 64x48 --frames 1 --out "$work/bad"
echo "bench --accuracy: ok"
