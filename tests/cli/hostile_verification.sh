#!/usr/bin/env bash
# Verification that cannot be emptied: every way of making a replay prove less (its state
# hashes stripped, thinned or cut at the end, its commands edited) against every command that
# checks a replay. `replay --verify` refuses a replay that lacks a hash at any hash interval or
# at its last tick unless --inputs-only asks for input-only checking; a replay that diverges
# is an error (exit 1) in `replay --verify`, `play --replay` and `bench --replay` alike.
set -uo pipefail
bin=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export BEAMZONE_PREF_DIR=$work/pref SDL_VIDEODRIVER=offscreen SDL_AUDIODRIVER=dummy
fail() { echo "FAIL: $*" >&2; exit 1; }
expect_seconds=120
source "$(dirname "$0")/lib/expect.bash"
level=$(cd "$(dirname "$0")/../../levels" && pwd)/classic.toml
cd "$work"

expect 0 "recorded" replay demo.replay --record-demo 6 --seed 5 --level "$level"
grep -q '^h ' demo.replay || fail "the recording holds no state hashes"

# Variants of the recording. The tampered ones flip the first command's left tread.
tamper() { awk 'BEGIN{d=0} /^c /&&!d{ $3 = ($3 == 127 ? -127 : 127); d=1 } {print}'; }
cp demo.replay intact.replay
tamper <demo.replay >tampered.replay
grep -v '^h ' demo.replay >stripped.replay
tamper <stripped.replay >tampered-stripped.replay
awk '/^h /{ if (n++ % 2) next } {print}' demo.replay >thinned.replay
awk '/^h /{ last = NR } { line[NR] = $0 } END { for (i = 1; i <= NR; i++) if (i != last) print line[i] }' \
  demo.replay >no-last.replay
sed 's/^hash-interval .*/hash-interval 1/' demo.replay >interval.replay
for f in tampered stripped thinned no-last interval; do
  cmp -s demo.replay $f.replay && fail "the $f variant is the same as the recording"
done

# variant | replay --verify | --verify --inputs-only | play --replay | bench --replay
# (- : not run; a replay the game cannot tell from a good one, with no hash to compare)
table=(
  "intact            | 0 | 0 | 0 | 0"
  "tampered          | 1 | 1 | 1 | 1"
  "stripped          | 1 | 0 | - | -"
  "tampered-stripped | 1 | 0 | - | -"
  "thinned           | 1 | 0 | 0 | 0"
  "no-last           | 1 | 0 | 0 | 0"
  "interval          | 1 | 0 | - | -"
)
passed=0
for row in "${table[@]}"; do
  IFS='|' read -r v verify inputs play bench <<<"${row// /}"
  f=$v.replay
  expect "$verify" "" replay "$f" --verify
  [ "$verify" = 0 ] || grep -qE "cannot verify|mismatch|error" err || fail "$v: no message"
  [ "$verify" = 0 ] || [ "$v" = tampered ] || grep -q "cannot verify" err ||
    fail "$v --verify: $(cat err)"
  expect "$inputs" "" replay "$f" --verify --inputs-only
  if [ "$play" != - ]; then
    expect "$play" "" play --headless-test --frames 100000 --replay "$f"
    [ "$play" = 0 ] || grep -q "diverged" err || fail "$v: play says nothing of the divergence"
  fi
  if [ "$bench" != - ]; then
    expect "$bench" "" bench "$level" --replay "$f" --frames 5 --warmup 0 --size 64x48 \
      --out "bench-$v"
    [ "$bench" = 0 ] || grep -q "diverged" err || fail "$v: bench says nothing of the divergence"
    [ "$bench" = 0 ] || [ ! -e "bench-$v/summary.json" ] || fail "$v: bench timed a diverged replay"
  fi
  echo "ok $v: verify $verify, inputs-only $inputs, play $play, bench $bench"
  passed=$((passed + 1))
done
expect 2 "--inputs-only needs --verify" replay demo.replay --inputs-only
echo "$passed passed, 0 failed"
