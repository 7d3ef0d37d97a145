#!/usr/bin/env bash
# The difficulty setting end to end: --difficulty, else the settings file, else the level's
# own; bad values are usage errors; replays record it; `beamzone difficulty` prints its table
# and writes its JSON.
set -uo pipefail
bin=$1
root=$(cd "$(dirname "$0")/../.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export BEAMZONE_PREF_DIR=$work/pref SDL_VIDEODRIVER=offscreen SDL_AUDIODRIVER=dummy
fail() { echo "FAIL: $*" >&2; cat "$work/err" >&2 2>/dev/null; exit 1; }
ok() { echo "ok $*"; }
play() { "$bin" play --headless-test --frames 2 --seed 5 "$@" >"$work/out" 2>"$work/err"; }

play "$root/levels/classic.toml" || fail "classic exited $?"
grep -q "normal difficulty" "$work/err" || fail "classic should play at its own default, normal"
grep -q '^difficulty = "level"' "$work/pref/settings.toml" || fail "settings file lacks difficulty = \"level\""
play "$root/levels/tutorial.toml" || fail "tutorial exited $?"
grep -q "easy difficulty" "$work/err" || fail "the tutorial's own default is easy"
ok "level default"

sed -i 's/^difficulty = "level"/difficulty = "arcade"/' "$work/pref/settings.toml"
play "$root/levels/tutorial.toml" || fail "exited $?"
grep -q "arcade difficulty" "$work/err" || fail "the settings file should win over the level"
play "$root/levels/tutorial.toml" --difficulty normal || fail "exited $?"
grep -q "normal difficulty" "$work/err" || fail "--difficulty should win over the settings file"
ok "settings file and --difficulty"

play --difficulty brutal
[ $? -eq 2 ] || fail "a bad --difficulty should be a usage error"
grep -q "expected easy, normal or arcade, not 'brutal'" "$work/err" || fail "bad --difficulty message"
ok "bad value"

"$bin" replay "$work/demo.bzr" --record-demo 5 --difficulty arcade --level "$root/levels/classic.toml" \
  >"$work/out" 2>"$work/err" || fail "record-demo exited $?"
grep -q "^difficulty arcade$" "$work/demo.bzr" || fail "the replay does not record its difficulty"
"$bin" replay "$work/demo.bzr" --verify >"$work/out" 2>"$work/err" || fail "verify exited $?"
ok "replays keep the difficulty"

"$bin" difficulty "$root/levels/classic.toml" --seeds 2 --seconds 30 --difficulty normal \
  --json "$work/table.json" >"$work/out" 2>"$work/err" || fail "difficulty exited $?"
grep -q "^| Classic | normal | " "$work/out" || fail "no table row: $(cat "$work/out")"
python3 - "$work/table.json" <<'PY' || fail "table JSON: $(cat "$work/table.json")"
import json, sys
doc = json.load(open(sys.argv[1]))
row = doc["rows"][0]
assert doc["seeds"] == 2 and row["difficulty"] == "normal", doc
assert row["idle"]["games"] == 2 and row["autopilot"]["games"] == 2, row
assert 0 < row["idle"]["mean_first_death_s"] <= 30, row
PY
ok "difficulty table"
