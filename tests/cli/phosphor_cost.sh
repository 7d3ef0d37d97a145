#!/usr/bin/env bash
# tools/phosphor_cost: bench with and without the phosphor, interleaved; one table row per
# round with the costs as the differences of its runs, then the medians; bad arguments and a
# missing binary are refused with a message.
set -euo pipefail
bin=$1
tool=$(cd "$(dirname "$0")/../.." && pwd)/tools/phosphor_cost
out=$("$tool" --bin "$bin" --rounds 2 --frames 3 --size 160x96)
echo "$out"
rows=$(grep -cE '^\| [12] \| [0-9.]+-[0-9.]+ \| [0-9.]+ / [0-9.]+ \| [0-9.]+ / [0-9.]+ \| -?[0-9.]+ \| -?[0-9.]+ \|$' <<<"$out")
[ "$rows" = 2 ] || { echo "FAIL: expected 2 round rows, found $rows"; exit 1; }
# Each row's costs are the differences of its own on / off columns (to the rounding of the three
# printed figures).
while IFS='|' read -r _ round _ passes p50 cost_passes cost_p50 _; do
    awk -v p="$passes" -v c="$cost_passes" -v q="$p50" -v d="$cost_p50" 'BEGIN {
        split(p, a, " / "); split(q, b, " / ");
        e = a[1] - a[2] - c; f = b[1] - b[2] - d;
        exit !(e * e <= 0.0151 ^ 2 && f * f <= 0.0151 ^ 2) }' ||
        { echo "FAIL: round$round: costs are not the differences"; exit 1; }
done < <(grep -E '^\| [12] \|' <<<"$out")
grep -qE '^median phosphor cost: -?[0-9.]+ ms by bloom \+ tiles \+ composite, -?[0-9.]+ ms by p50 frame time \(2 rounds\)$' <<<"$out" ||
    { echo "FAIL: no median line"; exit 1; }
echo "ok two rounds and their medians"
for bad in 0 x -1; do
    if err=$("$tool" --bin "$bin" --rounds "$bad" 2>&1); then echo "FAIL: --rounds $bad accepted"; exit 1; fi
    grep -q "positive whole number" <<<"$err" || { echo "FAIL: --rounds $bad: $err"; exit 1; }
done
echo "ok bad round counts refused"
if err=$("$tool" --bin /nonexistent/beamzone 2>&1); then echo "FAIL: missing binary accepted"; exit 1; fi
grep -q "no beamzone binary" <<<"$err" || { echo "FAIL: missing binary: $err"; exit 1; }
echo "ok missing binary refused"
