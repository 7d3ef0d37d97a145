#!/usr/bin/env bash
# Every kind of file beamzone reads, through every command that reads it, replaced by a FIFO
# and by a file one byte over its kind's size cap (core/budgets.h; sparse, so it costs no disk).
# Each read goes through the one reader: regular files only, opened without blocking, a size cap
# per kind, a message naming the file. Nothing may hang (each run has a time limit) or crash;
# a file the command needs is an error (exit 1) naming it; a file the game can do without
# (settings, high scores, controller mappings, the log) is reported or skipped and play goes on.
set -uo pipefail
bin=$1
src=$(cd "$(dirname "$0")/../.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export BEAMZONE_PREF_DIR=$work/pref SDL_VIDEODRIVER=offscreen SDL_AUDIODRIVER=dummy
cd "$work"
passed=0
fail() { echo "FAIL: $*"; cat "$work/err" 2>/dev/null | head -20; exit 1; }
MiB=$((1 << 20))

printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n' >tri.obj
"$bin" render builtin:cube --size 16x12 --out ok.png >/dev/null 2>&1 || fail "render ok.png"
"$bin" replay demo.replay --record-demo 1 >/dev/null 2>&1 || fail "record a replay"
mkdir -p pref

# kind | cap in bytes | file name | command (@F: the file; run in $work) | needed (1) or not (0)
rows=(
  "level|$MiB|bad.toml|check @F|1"
  "level|$MiB|bad.toml|play @F --headless-test --frames 2|1"
  "level|$MiB|bad.toml|difficulty @F --seeds 1 --seconds 1|1"
  "level|$MiB|bad.toml|bench @F --frames 1 --warmup 0 --size 32x24 --out b|1"
  "level|$MiB|bad.toml|replay demo.replay --verify --level @F|1"
  "model|$((512 * MiB))|bad.obj|render @F --size 16x12 --out m.png|1"
  "model|$((512 * MiB))|bad.obj|reference @F --size 16x12 --mask r.png|1"
  "replay|$((256 * MiB))|bad.replay|replay @F --verify|1"
  "replay|$((256 * MiB))|bad.replay|play --headless-test --frames 2 --replay @F|1"
  "PNG|$((256 * MiB))|bad.png|compare @F ok.png|1"
  "PNG|$((256 * MiB))|bad.png|compare ok.png @F|1"
  "settings|$MiB|pref/settings.toml|play --headless-test --frames 2|0"
  "high scores|$MiB|pref/highscores.toml|play --headless-test --frames 2|0"
  "controller mappings|$((4 * MiB))|pref/gamecontrollerdb.txt|play --headless-test --frames 2|0"
  "log|0|pref/beamzone.log|play --headless-test --frames 2|0"
  "shader|$MiB|root/shaders/lines/lines.geom|render builtin:cube --size 16x12 --out s.png|1"
)

for row in "${rows[@]}"; do
  IFS='|' read -r kind cap file template needed <<<"$row"
  if [ -n "${only:-}" ] && [ "$kind" != "$only" ]; then continue; fi
  for form in fifo oversize; do
    [ "$kind" = log ] && [ $form = oversize ] && continue  # a log is appended to, never read
    rm -rf "$work/root" "$file" b
    env_root=()
    if [ "$kind" = shader ]; then
      mkdir -p root && cp -r "$src/shaders" "$src/data" root/
      env_root=(BEAMZONE_ROOT="$work/root")
    fi
    [ -e "$file" ] && rm -f "$file"
    if [ $form = fifo ]; then mkfifo "$file"; else truncate -s $((cap + 1)) "$file"; fi
    cmd=${template//@F/$file}
    # shellcheck disable=SC2086
    env "${env_root[@]}" timeout 60 "$bin" $cmd >"$work/out" 2>"$work/err" </dev/null
    rc=$?
    label="$kind as a $form: $cmd"
    [ $rc -ne 124 ] || fail "$label: hung (killed after 60 s)"
    [ $rc -lt 128 ] || fail "$label: crashed (exit $rc)"
    base=$(basename "$file")
    if [ "$needed" = 1 ]; then
      [ $rc -eq 1 ] || fail "$label: exit $rc, expected 1"
      grep -qF "$base" "$work/err" || fail "$label: the message does not name $base"
      if [ $form = fifo ]; then grep -qi "not a regular file\|FIFO" "$work/err" || fail "$label: no reason"
      else grep -qi "limit\|bytes" "$work/err" || fail "$label: no reason"; fi
    else
      [ $rc -eq 0 ] || fail "$label: exit $rc, expected 0 (play goes on without it)"
      [ "$kind" = log ] || grep -qF "$base" "$work/err" || fail "$label: no warning naming $base"
    fi
    # The FIFO is never replaced: it stays, or (high scores) is kept aside under a .bad- name.
    if [ $form = fifo ]; then
      kept=0
      for f in "$file" "$file".bad-*; do [ -p "$f" ] && kept=1; done
      [ $kept = 1 ] || fail "$label: the FIFO is gone"
    fi
    echo "ok $label: exit $rc, $(grep -m1 -F "$base" "$work/err" | cut -c1-150)"
    passed=$((passed + 1))
    rm -rf "$file" "$file".bad-*
  done
done
echo "$passed passed, 0 failed"
