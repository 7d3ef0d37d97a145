#!/usr/bin/env bash
# beamzone bench: a short run writes every file with the documented columns and keys, the
# sweep and scaling modes write theirs, and bad input or usage gets exit 1 or 2.
set -uo pipefail
bin=$1
root=$(cd "$(dirname "$0")/../.." && pwd)
level=$root/levels/stress.toml
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

expect_seconds=300
source "$(dirname "$0")/lib/expect.bash"

# A short single-preset run.
expect 0 "p50" bench "$level" --frames 6 --warmup 2 --size 192x108 --preset fast --out "$work/one"
for f in summary.json frames.csv frametime.png; do [ -s "$work/one/$f" ] || fail "bench wrote no $f"; done
# The compute line method (the presets' default) times its edge extraction before the lines.
head -1 "$work/one/frames.csv" | grep -Eq "^Config,Frame,TimeInSeconds,MsBetweenPresents,MsCPUBusy,MsPass_prepass,(MsPass_edges,(MsPass_visibility,)?)?MsPass_lines" ||
  fail "frames.csv header: $(head -1 "$work/one/frames.csv")"
[ "$(wc -l <"$work/one/frames.csv")" -eq 7 ] || fail "frames.csv should have a header and 6 rows"
for key in '"p50"' '"p99"' '"low_1pct"' '"timing_method": "cpu_finish"' '"triangles_submitted_mean"' '"feature_edges_mean"'; do
  grep -q "$key" "$work/one/summary.json" || fail "summary.json lacks $key"
done
# Timer queries can be forced (llvmpipe has them, they just miss geometry work).
expect 0 "gpu_queries" bench "$level" --frames 4 --warmup 6 --size 96x54 --timing gpu --out "$work/gpu"
grep -q "MsPass_lines" "$work/gpu/frames.csv" || fail "gpu_queries run lost its pass columns"
# Query results arrive frames late; every timed frame must still get its own.
awk -F, 'NR > 1 && ($6 == "" || $7 == "") { bad = 1 } END { exit bad }' "$work/gpu/frames.csv" ||
  fail "a frame has no pass times: $(cat "$work/gpu/frames.csv")"

# --no-phosphor: the same look with its phosphor off, recorded in the run's settings.
expect 0 "p50" bench "$level" --beam mame --frames 3 --warmup 1 --size 192x108 --preset fast --out "$work/mame"
grep -q '"phosphor": "exponential"' "$work/mame/summary.json" || fail "mame run: phosphor not exponential"
# Its mip-chain bloom says how it went past level 0 (drawn or walked: render/beam/pass_bloom.cpp).
grep -q '"levels_walked"' "$work/mame/summary.json" || fail "mame run: summary.json lacks bloom_chain"
# And how often its first downsample read the whole beam image (RenderSettings::first_downsample).
grep -qE '"whole_image_first_downsample_share": [0-9.e+-]+' "$work/mame/summary.json" ||
  fail "mame run: summary.json lacks whole_image_first_downsample_share"
expect 0 "p50" bench "$level" --beam mame --no-phosphor --frames 3 --warmup 1 --size 192x108 --preset fast --out "$work/nophos"
grep -q '"phosphor": "off"' "$work/nophos/summary.json" || fail "--no-phosphor run: phosphor not off"
grep -q '"beam": "mame"' "$work/nophos/summary.json" || fail "--no-phosphor changed the look"

# The sweep: every configuration, a score for each, the goals judged.
expect 0 "goal high: mean F1" bench "$level" --sweep --frames 4 --warmup 2 --rounds 2 --samples 2 --size 192x108 --out "$work/sweep"
for f in sweep.json tradeoff.png summary.json frames.csv frametime.png masks/reference_frame0001.png; do
  [ -s "$work/sweep/$f" ] || fail "sweep wrote no $f"
done
for cfg in fast balanced high fast-compute balanced-compute high-compute fast-geometry-shader balanced-geometry-shader high-geometry-shader balanced-per-fragment image-outline balanced-no-culling balanced-no-lod balanced-no-instancing balanced-material-lines balanced-material-lines-compute balanced-material-lines-geometry-shader balanced-intersection-lines balanced-intersection-lines-compute balanced-intersection-lines-geometry-shader; do
  grep -q "\"label\": \"$cfg\"" "$work/sweep/sweep.json" || fail "sweep.json lacks $cfg"
done

grep -q '"scored_frame_times_s"' "$work/sweep/sweep.json" || fail "sweep.json lacks the scored frames' times"
# A scored frame is reproducible: timed frame 1 after 2 warm-up frames is tick 4, t = 4/60 s.
expect 0 "" reference --level "$level" --time 0.0667 --size 192x108 --mask "$work/again.png"
cmp -s "$work/again.png" "$work/sweep/masks/reference_frame0001.png" || fail "reference --level --time differs from the sweep's"

# Scaling on two frames.
expect 0 "ms per 100k triangles" bench "$level" --scaling --frames 2 --warmup 1 --size 96x54 --series-max 30000 --out "$work/scale"
grep -q '"model_series"' "$work/scale/scaling.json" || fail "scaling.json has no model series"
grep -q '"edges_pass_ms_mean"' "$work/scale/scaling.json" || fail "scaling.json has no edges pass"
[ -s "$work/scale/scaling.png" ] && [ -s "$work/scale/scaling.json" ] || fail "scaling files missing"

# Bad input: exit 1 with the file named.
expect 1 "missing.toml" bench "$work/missing.toml" --frames 2
printf 'version = 1\n[field]\nsize = -3\n' >"$work/bad.toml"
expect 1 "bad.toml:[0-9]+:[0-9]+: error" bench "$work/bad.toml" --frames 2
printf 'junk\n' >"$work/junk.bzr"
expect 1 "junk.bzr" bench "$level" --replay "$work/junk.bzr" --frames 2
# Usage: exit 2.
expect 2 "no LEVEL" bench
expect 2 "unknown option" bench "$level" --bogus
expect 2 "unknown preset" bench "$level" --preset ultra
expect 2 "exclude each other" bench "$level" --sweep --preset fast
expect 2 "exclude each other" bench "$level" --sweep --scaling
expect 2 "--frames" bench "$level" --frames 0
expect 2 "exclude each other" bench "$level" --sweep --no-phosphor
expect 2 "--timing" bench "$level" --timing sometimes
expect 0 "usage: beamzone bench" bench --help
echo "bench CLI ok"
