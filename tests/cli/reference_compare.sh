#!/usr/bin/env bash
# beamzone reference and compare: the CPU reference agrees with the GPU mask of a model,
# scores are printed, a level frame works, and bad input or usage gets exit 1 or 2 with a
# message, never a crash.
set -uo pipefail
bin=$1
root=$(cd "$(dirname "$0")/../.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

expect_seconds=120
source "$(dirname "$0")/lib/expect.bash"

# The GPU mask of a cube and the exact reference: same camera options, a perfect score.
expect 0 "" render builtin:cube --size 200x150 --out "$work/c.png" --mask "$work/gpu.png"
expect 0 "lit pixels; 12 feature edges" reference builtin:cube --size 200x150 --mask "$work/ref.png"
expect 0 "precision 1.0000 recall 1.0000 f1 1.0000" compare "$work/gpu.png" "$work/ref.png"
# An explicit camera, arcade style and another crease angle go through too.
expect 0 "" render builtin:sphere --size 160x120 --eye 0,1,4 --fov 40 --style arcade --out "$work/s.png" --mask "$work/sg.png"
expect 0 "" reference builtin:sphere --size 160x120 --eye 0,1,4 --fov 40 --style arcade --mask "$work/sr.png"
expect 0 "f1 (0\.9[5-9]|1\.0)" compare "$work/sg.png" "$work/sr.png"
expect 0 "" reference builtin:cube --size 64x48 --crease 95 --mask "$work/outline.png"
# Tolerance: a mask against an empty one scores 0; --tol 0 is allowed.
"$bin" reference builtin:cube --size 200x150 --eye 100,0,0 --target 0,0,-1000 --mask "$work/empty.png" >/dev/null 2>&1 ||
  fail "empty-view reference failed"
expect 0 "f1 0.0000" compare "$work/gpu.png" "$work/empty.png" --tol 0

# A level frame on the benchmark path.
expect 0 "lit pixels" reference --level "$root/levels/stress.toml" --time 1.5 --size 160x90 --mask "$work/lv.png"
[ -s "$work/lv.png" ] || fail "no level reference written"

# Bad input: exit 1 with one line naming the problem.
expect 1 "missing.obj" reference "$work/missing.obj" --mask "$work/x.png"
printf 'not a png' >"$work/bad.png"
expect 1 "bad.png" compare "$work/bad.png" "$work/ref.png"
expect 1 "must have the same size" compare "$work/gpu.png" "$work/lv.png"
expect 1 "nope.png" compare "$work/nope.png" "$work/ref.png"
printf 'version = 1\nname = 3\n' >"$work/broken.toml"
expect 1 "broken.toml:[0-9]+:[0-9]+: error" reference --level "$work/broken.toml" --time 1
# Usage: exit 2.
expect 2 "no INPUT" reference
expect 2 "unknown option" reference builtin:cube --bogus
expect 2 "needs --time" reference --level "$root/levels/stress.toml"
expect 2 "only --size applies" reference --level "$root/levels/stress.toml" --time 1 --eye 1,2,3
expect 2 "--fov must be" reference builtin:cube --fov 0
expect 2 "need TEST.png and REF.png" compare "$work/gpu.png"
expect 2 "--tol" compare "$work/gpu.png" "$work/ref.png" --tol -1
expect 2 "third" compare a.png b.png c.png
expect 0 "usage: beamzone compare" compare --help
expect 0 "usage: beamzone reference" reference --help
echo "reference/compare CLI ok"
