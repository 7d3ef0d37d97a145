# Sourced by the tests/cli scripts that drive `play` (not itself a test: CTest registers only
# tests/cli/*.sh). Sets bin (the binary, the script's first argument) and a scratch folder
# work (removed on exit) that also holds the preference folder; runs headless under SDL's
# offscreen and dummy drivers; ok NAME counts a passed check, fail NAME stops with the last
# command's stderr ($work/err).
bin=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export BEAMZONE_PREF_DIR=$work/pref SDL_VIDEODRIVER=offscreen SDL_AUDIODRIVER=dummy
pass=0
ok() { echo "ok $1"; pass=$((pass + 1)); }
fail() { echo "FAIL $1"; cat "$work/err" 2>/dev/null || true; exit 1; }
