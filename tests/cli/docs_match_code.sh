#!/usr/bin/env bash
# The docs cannot drift silently: every command, flag and style that README.md, CONTRIBUTING.md
# and docs/ name in code exists in `beamzone --help` / `beamzone CMD --help`, every repository
# path they name exists, and every settings key they name is one the settings file the game
# writes on first start holds (tests/cli/lib/docs_check.py says exactly what is read). Then
# the checker itself must catch a bogus flag, command, style, path and settings key.
set -uo pipefail
bin=$1
root=$(cd "$(dirname "$0")/../.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export SDL_VIDEODRIVER=offscreen SDL_AUDIODRIVER=dummy
fail() { echo "FAIL: $*" >&2; exit 1; }
check=(python3 "$root/tests/cli/lib/docs_check.py" "$bin" "$root" "$work/pref/settings.toml")

# The settings file, every key in it, as the game writes it on first start.
BEAMZONE_PREF_DIR=$work/pref "$bin" play --headless-test --frames 1 --seed 1 >"$work/out" 2>&1 \
  || fail "play to write the settings file: $(cat "$work/out")"
[ -s "$work/pref/settings.toml" ] || fail "play wrote no settings file"

"${check[@]}" || fail "the docs name things the code does not have (above)"
echo "ok the docs match the code"

# A bogus name of every kind must be caught and named: one doc holds them all (the checker
# starts the binary nine times, so one run instead of ten), each on its own line.
bogus=(
  "a bogus flag on a command|Run \`beamzone render x.obj --bogus-flag 3\`.|'render --bogus-flag'"
  "a bogus flag in a synopsis|    build/beamzone bench LEVEL [--frames N] [--no-such-thing]|'bench --no-such-thing'"
  "a lone bogus flag|The \`--frobnicate\` option.|'--frobnicate'"
  "a bogus command|Run \`build/beamzone explode levels/classic.toml\`.|'beamzone explode'"
  "a bogus choice|Run \`beamzone play --preset fast|turbo\`.|'turbo'"
  "a bogus style|Run \`beamzone render x.obj --style watercolour\`.|'--style watercolour'"
  "a bogus path|See \`src/render/no_such_pass.cpp\`.|'src/render/no_such_pass.cpp'"
  "a bogus file name|See \`pass_nothing.cpp\`.|'pass_nothing.cpp'"
  "a bogus link|See [this](no/such/file.md).|no/such/file.md"
  "a bogus settings key|Set \`turbo_mode = true\` in the settings file.|'turbo_mode'"
)
printf '# Test\n' >"$work/bogus.md"
for b in "${bogus[@]}"; do
  text=${b#*|}
  printf '\n%s\n' "${text%|*}" >>"$work/bogus.md"
done
"${check[@]}" "$work/bogus.md" >"$work/bogus.out" 2>&1 && fail "a doc full of bogus names passed"
for b in "${bogus[@]}"; do
  what=${b%%|*}
  expect=${b##*|}
  grep -qF -- "$expect" "$work/bogus.out" || fail "$what: no \"$expect\" in: $(cat "$work/bogus.out")"
  echo "ok catches $what"
done
problems=$(grep -c 'bogus.md:[0-9]*: ' "$work/bogus.out")
[ "$problems" -eq ${#bogus[@]} ] || fail "expected ${#bogus[@]} problems, got $problems: $(cat "$work/bogus.out")"
echo "ok ${#bogus[@]} bogus names, ${#bogus[@]} problems"
