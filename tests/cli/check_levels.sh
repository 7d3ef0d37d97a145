#!/usr/bin/env bash
# `beamzone check`: every shipped level is clean (exit 0); broken files give exit 1 and one
# `file:line:col: error: ...` line per problem; usage errors give exit 2.
set -euo pipefail
bin=$1
root=$(cd "$(dirname "$0")/../.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

fail() { echo "FAIL: $*"; echo "--- stdout"; cat "$work/out"; echo "--- stderr"; cat "$work/err"; exit 1; }
run() {  # run ARGS...: sets $rc, output in $work/out and $work/err
  set +e
  "$bin" check "$@" >"$work/out" 2>"$work/err"
  rc=$?
  set -e
}

# Every shipped level passes, and there are at least six of them.
levels=("$root"/levels/*.toml)
[ ${#levels[@]} -ge 6 ] || { echo "FAIL: only ${#levels[@]} levels shipped"; exit 1; }
run "${levels[@]}"
[ $rc -eq 0 ] || fail "shipped levels: exit $rc"
[ ! -s "$work/err" ] || fail "shipped levels printed errors"
grep -q "^checked ${#levels[@]} files: ${#levels[@]} clean, 0 with errors$" "$work/out" || fail "summary line"
[ -f "$root/levels/classic.toml" ] || { echo "FAIL: no levels/classic.toml"; exit 1; }
echo "ok: ${#levels[@]} shipped levels clean"

# No window, no GL: the checker works where no video driver can start.
set +e
env -u DISPLAY -u WAYLAND_DISPLAY SDL_VIDEODRIVER=no-such-driver "$bin" check "$root/levels/classic.toml" >"$work/out" 2>"$work/err"
rc=$?
set -e
[ $rc -eq 0 ] || fail "check without a video driver: exit $rc"
echo "ok: no video driver needed"

# A broken file: every error, each with its position, in file order.
cat >"$work/bad.toml" <<'TOML'
version = 1
name = "Broken"
[field]
size = nan
wrapp = true
[[obstacle]]
kind = "cubee"
position = [0, 0, 0]
[[obstacle]]
kind = "model"
model = "../../../etc/passwd"
position = [50, 0, 0]
TOML
run "$work/bad.toml"
[ $rc -eq 1 ] || fail "broken file: exit $rc, expected 1"
cat >"$work/expected" <<EXPECTED
$work/bad.toml:4:8: error: 'size' must be a finite number, not nan
$work/bad.toml:5:1: error: unknown key 'wrapp' in [field]; did you mean 'wrap'?
$work/bad.toml:7:8: error: unknown kind 'cubee'; did you mean 'cube'? (one of: cube, pyramid, tall_box, short_box, wall, arcade_wide_pyramid, arcade_narrow_pyramid, arcade_tall_box, arcade_short_box, model)
$work/bad.toml:11:9: error: model path '../../../etc/passwd' leads outside the level's folder and the project's data/ folder
EXPECTED
diff "$work/expected" "$work/err" >"$work/diff" || { cat "$work/diff"; fail "broken file messages"; }
[ ! -s "$work/out" ] || fail "broken file printed to stdout"
echo "ok: broken file -> exit 1, 4 positioned errors"

# Syntax errors: all of them, not only the first.
printf 'version = 1\nname = "x"\n[field]\nsize = 40O\nwrap = tru\n' >"$work/syntax.toml"
run "$work/syntax.toml"
[ $rc -eq 1 ] || fail "syntax file: exit $rc"
[ "$(wc -l <"$work/err")" -eq 2 ] || fail "expected 2 syntax errors"
grep -q "^$work/syntax.toml:4:10: error: syntax error" "$work/err" || fail "first syntax error position"
grep -q "^$work/syntax.toml:5:11: error: syntax error in boolean" "$work/err" || fail "second syntax error position"
echo "ok: syntax errors -> 2 positioned errors"

# A good and a bad file together: still exit 1, the good one is reported ok.
run "$root/levels/classic.toml" "$work/bad.toml"
[ $rc -eq 1 ] || fail "mixed: exit $rc"
grep -q "classic.toml: ok" "$work/out" || fail "mixed: classic not ok"
grep -q "^checked 2 files: 1 clean, 1 with errors$" "$work/out" || fail "mixed: summary"
echo "ok: mixed -> exit 1"

# A missing file is an error of that file, not a usage error.
run "$work/nope.toml"
[ $rc -eq 1 ] || fail "missing file: exit $rc"
grep -qx "$work/nope.toml:1:1: error: file not found" "$work/err" || fail "missing file message"
echo "ok: missing file -> exit 1"

# --quiet prints nothing for clean files.
run --quiet "$root/levels/classic.toml"
{ [ $rc -eq 0 ] && [ ! -s "$work/out" ] && [ ! -s "$work/err" ]; } || fail "--quiet"
echo "ok: --quiet"

# Usage errors.
run
[ $rc -eq 2 ] || fail "no arguments: exit $rc, expected 2"
grep -q "no level files given" "$work/err" || fail "no arguments message"
run --frobnicate "$root/levels/classic.toml"
[ $rc -eq 2 ] || fail "unknown option: exit $rc, expected 2"
grep -q "unknown option '--frobnicate'" "$work/err" || fail "unknown option message"
run --help
{ [ $rc -eq 0 ] && grep -q "^usage: beamzone check" "$work/out"; } || fail "--help"
echo "ok: usage errors -> exit 2"
echo "check_levels: all passed"
