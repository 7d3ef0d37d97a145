#!/usr/bin/env bash
# Every default key is documented: the man page (dist/beamzone.6) and `play --help` list each
# key the settings file binds by default (F3 and F6 included), and both say where keys are
# rebound in the game, pad buttons included.
set -euo pipefail
source "$(dirname "$0")/lib/harness.bash"
root=$(cd "$(dirname "$0")/../.." && pwd)
man=$root/dist/beamzone.6

# The defaults as the game writes them: change one option so that settings.toml is saved.
"$bin" play --headless-test --frames 50 --press 2:Down,3:Down,4:Return,5:Right,6:F10 \
    >"$work/out" 2>"$work/err" || fail "play exit $?"
"$bin" play --help >"$work/help" 2>&1 || true
sed 's/\\-/-/g' "$man" >"$work/man"
missing=""
while IFS= read -r key; do
    # "Alt+Return" is written that way in both; the man page has "Keypad +" after "M, =, -".
    base=${key#Keypad }
    grep -qiF -- "$base" "$work/man" || missing+=" man:'$key'"
    grep -qiF -- "$key" "$work/help" || missing+=" help:'$key'"
done < <(sed -n '/^\[keys\]/,/^\[buttons\]/p' "$work/pref/settings.toml" | grep -v -e '^\[buttons\]' -e '^#' |
    grep -o '"[^"]*"' | tr -d '"' | sort -u)
[ -z "$missing" ] || fail "keys not documented:$missing"
ok "every default key is in the man page and --help"
grep -q "Options.*Keys" "$work/man" && grep -q "Options > Keys" "$work/help" ||
    fail "in-game rebinding not mentioned"
ok "both name the in-game Keys screen"
grep -q "^\[buttons\]" "$work/pref/settings.toml" || fail "settings.toml has no [buttons]"
grep -qi "pad button" "$work/man" && grep -qi "pad button" "$work/help" ||
    fail "pad button rebinding not mentioned"
ok "the settings file has [buttons]; both say pad buttons are rebound"
echo "$pass passed, 0 failed"
