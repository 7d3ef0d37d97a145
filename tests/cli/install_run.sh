#!/usr/bin/env bash
# `cmake --install` to a scratch prefix, then the installed binary works on its own: the tree
# is moved after installing (so nothing may point back into the prefix), BEAMZONE_ROOT is
# unset and the working folder is elsewhere, and render, check, bench and play all run from
# the installed data. With the installed data taken away it fails naming the installed
# location, which shows it never reaches back into the source tree.
set -uo pipefail
bin=$1
build=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; cat "$work/err" >&2 2>/dev/null; exit 1; }
ok() { echo "ok $*"; }

cmake --install "$build" --prefix "$work/prefix" >"$work/install.log" 2>"$work/err" ||
  fail "cmake --install exited $?"
mv "$work/prefix" "$work/moved"
p=$work/moved
for f in bin/beamzone share/beamzone/shaders/lines/lines.geom share/beamzone/data/fonts/futural.jhf \
  share/beamzone/data/models/pylon.obj share/beamzone/data/gamecontrollerdb/gamecontrollerdb.txt \
  share/beamzone/levels/classic.toml share/beamzone/levels/README.md \
  share/applications/org.beamzone.Beamzone.desktop share/metainfo/org.beamzone.Beamzone.metainfo.xml \
  share/icons/hicolor/scalable/apps/org.beamzone.Beamzone.svg \
  share/icons/hicolor/256x256/apps/org.beamzone.Beamzone.png share/man/man6/beamzone.6; do
  [ -s "$p/$f" ] || fail "the install lacks $f"
done
[ -x "$p/bin/beamzone" ] || fail "bin/beamzone is not executable"
for f in share/beamzone/data/frames share/beamzone/data/screenshots share/beamzone/levels/generate.py; do
  [ ! -e "$p/$f" ] || fail "the install should leave out $f"
done
grep -q "^Exec=beamzone play$" "$p/share/applications/org.beamzone.Beamzone.desktop" || fail "desktop Exec line"
grep -q "<launchable type=\"desktop-id\">org.beamzone.Beamzone.desktop</launchable>" \
  "$p/share/metainfo/org.beamzone.Beamzone.metainfo.xml" || fail "metainfo launchable"
if command -v appstreamcli >/dev/null; then
  appstreamcli validate --no-net "$p/share/metainfo/org.beamzone.Beamzone.metainfo.xml" >"$work/err" 2>&1 ||
    fail "appstreamcli validate"
fi
ok "installed files"

run() {
  (cd "$work" && env -u BEAMZONE_ROOT BEAMZONE_PREF_DIR="$work/pref" SDL_VIDEODRIVER=offscreen \
    SDL_AUDIODRIVER=dummy timeout 300 "$p/bin/beamzone" "$@") >"$work/out" 2>"$work/err"
}
run render builtin:cube --size 96x64 --out "$work/cube.png" || fail "render exited $?"
[ -s "$work/cube.png" ] || fail "render wrote no PNG"
ok "render"
run check "$p/share/beamzone/levels/classic.toml" "$p/share/beamzone/levels/volcano_night.toml" ||
  fail "check exited $?"
ok "check"
run bench "$p/share/beamzone/levels/classic.toml" --frames 5 --warmup 1 --size 96x64 --out "$work/bench" ||
  fail "bench exited $?"
[ -s "$work/bench/summary.json" ] || fail "bench wrote no summary.json"
ok "bench --frames 5"
run play --headless-test --frames 5 || fail "play exited $?"
grep -q "^play: 5 frames, 5 ticks, 0 GL errors$" "$work/out" || fail "play summary: $(cat "$work/out")"
grep -q "level: $p/share/beamzone/levels/classic.toml" "$work/err" ||
  fail "play did not take the installed default level"
grep -q "data: $p/share/beamzone (installed)" "$work/err" || fail "play did not log its installed data folder"
ok "play --headless-test --frames 5"

# Without its data the installed binary stops with a message naming where the data belongs.
mv "$p/share/beamzone" "$p/share/beamzone-aside"
run render builtin:cube --size 96x64 --out "$work/cube2.png"
rc=$?
[ "$rc" -eq 1 ] || fail "render without data exited $rc, wanted 1"
grep -q "$p/share/beamzone/shaders" "$work/err" || fail "the message should name the installed shaders folder: $(cat "$work/err")"
ok "no fallback to the source tree"
