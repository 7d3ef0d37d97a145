#!/usr/bin/env bash
# One escaper and cap for every untrusted string in messages: a table of hostile strings (a
# terminal escape sequence, a newline that fakes a line of output, a bidi override, the 8-bit
# CSI, a 100 KB value) through every place a command echoes one: option values, unknown options
# and commands, file paths, a level's name. Nothing reaches the terminal raw: no ESC byte, no
# U+202E, no C1 control, no line the hostile text started; and the output stays small.
set -uo pipefail
bin=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export BEAMZONE_PREF_DIR=$work/pref SDL_VIDEODRIVER=offscreen SDL_AUDIODRIVER=dummy
cd "$work"
passed=0
fail() { echo "FAIL: $*"; head -c 2000 "$work/all"; exit 1; }

printf 'version = 1\nname = "Mine"\n' >mine.toml
"$bin" render builtin:cube --size 16x12 --out ok.png >/dev/null 2>&1 || fail "render ok.png"

esc=$'\e[2J\e]0;pwned\a'
newline=$'x\nFAKE: all tests passed'
bidi=$'abc\u202egnp.exe'
csi=$'\xc2\x9b31mred'
huge=$(head -c 100000 /dev/zero | tr '\0' 'A')
strings=(esc newline bidi csi huge)

# Where a command echoes a value (@S: the hostile string).
sites=(
  "render builtin:cube --style @S"
  "render builtin:cube --preset @S"
  "render builtin:cube --beam @S"
  "render builtin:cube --line-method @S"
  "render builtin:cube --size @S"
  "render builtin:cube --eye @S"
  "render @S.obj --size 16x12 --out r.png"
  "render builtin:cube --@S"
  "reference builtin:cube --@S"
  "reference @S.obj --size 16x12 --mask r.png"
  "bench mine.toml --style @S"
  "bench mine.toml --timing @S"
  "bench @S.toml --frames 1"
  "bench mine.toml --@S"
  "difficulty --difficulty @S"
  "difficulty @S.toml --seeds 1 --seconds 1"
  "difficulty --@S"
  "replay x.replay --difficulty @S --record-demo 1"
  "replay @S.replay --verify"
  "replay x.replay --@S"
  "compare @S.png ok.png"
  "compare ok.png ok.png --@S"
  "check @S.toml"
  "check --@S"
  "play --headless-test --frames 2 --style @S"
  "play --headless-test --frames 2 --difficulty @S"
  "play --headless-test --frames 2 --line-method @S"
  "play @S.toml --headless-test --frames 2"
  "play --headless-test --@S"
  "@S"
)

for s in "${strings[@]}"; do
  value=${!s}
  for site in "${sites[@]}"; do
    read -r -a words <<<"$site"
    args=()
    for w in "${words[@]}"; do args+=("${w//@S/$value}"); done
    timeout 60 "$bin" "${args[@]}" >"$work/out" 2>"$work/err" </dev/null
    rc=$?
    cat "$work/out" "$work/err" >"$work/all"
    label="$s in '$site'"
    [ $rc -eq 1 ] || [ $rc -eq 2 ] || fail "$label: exit $rc"
    LC_ALL=C grep -q $'\e' "$work/all" && fail "$label: a raw ESC reached the output"
    grep -qF $'\u202e' "$work/all" && fail "$label: a raw U+202E reached the output"
    grep -qF $'\xc2\x9b' "$work/all" && fail "$label: a raw C1 CSI reached the output"
    grep -q '^FAKE' "$work/all" && fail "$label: the value started a line of its own"
    size=$(wc -c <"$work/all")
    [ "$size" -lt 8000 ] || fail "$label: $size bytes of output"
    passed=$((passed + 1))
  done
  echo "ok $s: ${#sites[@]} sites, e.g. $(grep -m1 -E 'pwned|FAKE|gnp|red|AAAA' "$work/all" | cut -c1-140)"
done

# A level's name in `check`'s report.
for s in esc newline bidi csi; do
  value=${!s}
  # As a TOML string: JSON's escapes (\u001b, \n, \") are TOML's too.
  quoted=$(python3 -c 'import json, sys; print(json.dumps(sys.argv[1], ensure_ascii=False))' "$value")
  printf 'version = 1\nname = %s\n' "$quoted" >named.toml
  timeout 60 "$bin" check named.toml >"$work/out" 2>"$work/err"
  rc=$?
  cat "$work/out" "$work/err" >"$work/all"
  [ $rc -le 1 ] || fail "check named.toml with a $s name: exit $rc"
  LC_ALL=C grep -q $'\e' "$work/all" && fail "$s level name: a raw ESC reached the output"
  grep -qF $'\u202e' "$work/all" && fail "$s level name: a raw U+202E reached the output"
  grep -q '^FAKE' "$work/all" && fail "$s level name: the name started a line of its own"
  passed=$((passed + 1))
done
echo "ok level names: $(head -c 160 "$work/all")"
echo "$passed passed, 0 failed"
