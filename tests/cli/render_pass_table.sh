#!/usr/bin/env bash
# render --repeat prints a table of passes, one "NAME  MEAN_MS" line each, and then the frame's
# counts. Tools read the table by each line's first word (the seed's compare.sh takes "prepass",
# "lines", "bloom", "composite" and "total" with awk's $1 and $2), so any other line that starts
# with a pass's name breaks them: every line whose first word names a pass must carry its time.
set -uo pipefail
bin=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }
export SDL_VIDEODRIVER=offscreen SDL_AUDIODRIVER=dummy BEAMZONE_PREF_DIR=$work/pref
export BEAMZONE_CACHE_DIR=$work/cache
expect_seconds=120
source "$(dirname "$0")/lib/expect.bash"

# Both beams and both line methods, so every optional line of counts is printed somewhere.
for args in "--beam mame --line-method compute" "--beam classic --line-method geometry_shader"; do
  # shellcheck disable=SC2086
  expect 0 "^total " render builtin:sphere --copies 8 --size 160x120 --repeat 2 $args \
    --out "$work/frame.png" --overwrite
  table=$(awk '$1 ~ /^(pass|total)$/ || NF == 2' "$work/out")
  [ -n "$table" ] || fail "no pass table: $(cat "$work/out")"
  # The names the table used, from its own rows.
  names=$(awk 'NF == 2 && $2 ~ /^[0-9]+\.[0-9]+$/ {print $1}' "$work/out" | sort -u)
  for name in $names bloom blur; do
    while read -r line; do
      second=$(awk '{print $2}' <<<"$line")
      [[ $second =~ ^[0-9]+\.[0-9]+$ ]] ||
        fail "render $args: a line starts with the pass name '$name' but is not its row: '$line'"
    done < <(awk -v n="$name" '$1 == n' "$work/out")
  done
done
echo "render pass table ok"
