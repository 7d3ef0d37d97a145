#!/usr/bin/env bash
# render --lit-share: the share of pixels above 1/255 (the haze figure that tools/haze reports
# for Bernardoni 2018's hallway). A black frame is 0%; a glowing cube lights some but not all pixels,
# and the mame look's thresholded bloom with its black level lights fewer than classic's.
set -euo pipefail
bin=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export SDL_VIDEODRIVER=offscreen SDL_AUDIODRIVER=dummy
share() {  # prints the percentage (a number) of one render
    local line
    line=$("$bin" render "$@" --size 160x120 --lit-share --out "$work/frame.png" | grep '^lit share')
    [[ $line =~ ^lit\ share\ \(brightest\ channel\ above\ 1/255\):\ ([0-9]+\.[0-9]+)%$ ]] ||
        { echo "FAIL: unexpected line '$line'"; exit 1; }
    echo "${BASH_REMATCH[1]}"
}
# The camera looks away from the cube: nothing on screen.
empty=$(share builtin:cube --eye 0,0,5 --target 0,0,10)
[ "$empty" = "0.00" ] || { echo "FAIL: empty view lit $empty%"; exit 1; }
echo "ok empty view: $empty%"
classic=$(share builtin:cube --beam classic)
mame=$(share builtin:cube --beam mame)
awk -v c="$classic" 'BEGIN { exit !(c > 1 && c < 100) }' || { echo "FAIL: cube lit $classic%"; exit 1; }
echo "ok cube, classic: $classic%"
awk -v c="$classic" -v m="$mame" 'BEGIN { exit !(m > 0 && m < c) }' ||
    { echo "FAIL: cube lit $mame% with the mame look, $classic% with classic"; exit 1; }
echo "ok cube, mame: $mame%"
# Without the flag, no such line.
if "$bin" render builtin:cube --size 160x120 --out "$work/frame.png" | grep -q '^lit share'; then
    echo "FAIL: lit share printed without --lit-share"; exit 1
fi
echo "ok no line without the flag"
