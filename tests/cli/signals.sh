#!/usr/bin/env bash
# SIGTERM and SIGINT end every command promptly (exit 128 + signal), and `play` quits as if its
# window were closed (exit 0), saving its recording on the way out: the file it leaves is a
# complete replay.
set -uo pipefail
bin=$1
work=$(mktemp -d)
pids=()
trap 'for p in "${pids[@]}"; do kill -9 "$p" 2>/dev/null; done; rm -rf "$work"' EXIT
export BEAMZONE_PREF_DIR=$work/pref SDL_VIDEODRIVER=offscreen SDL_AUDIODRIVER=dummy
passed=0
fail() { echo "FAIL: $*"; cat "$work/err" 2>/dev/null; exit 1; }

less_than() { awk -v a="$1" -v b="$2" 'BEGIN { exit !(a < b) }'; }

# wait_for FILE TEXT SECONDS: until FILE holds TEXT.
wait_for() {
  local i
  for ((i = 0; i < $3 * 10; i++)); do
    grep -qF -- "$2" "$1" 2>/dev/null && return 0
    sleep 0.1
  done
  return 1
}

# stop_and_time PID SIGNAL: sends it, waits (at most 10 s), sets rc and secs. (Not in a
# subshell: only this shell can wait for its child.)
stop_and_time() {
  local pid=$1 sig=$2 start end
  start=$(date +%s.%N)
  kill -s "$sig" "$pid"
  for ((i = 0; i < 100; i++)); do
    kill -0 "$pid" 2>/dev/null || break
    sleep 0.1
  done
  wait "$pid"
  rc=$?
  end=$(date +%s.%N)
  secs=$(awk -v a="$start" -v b="$end" 'BEGIN { printf "%.2f", b - a }')
}

# play, mid-game: the recording is saved and is a whole replay.
for sig in TERM INT; do
  rm -f "$work/game.replay"
  "$bin" play --headless-test --frames 100000000 --seed 5 --record "$work/game.replay" \
    >"$work/out" 2>"$work/err" &
  pid=$!
  pids+=("$pid")
  wait_for "$work/err" "game seed" 120 || fail "play did not start"
  sleep 1
  stop_and_time "$pid" "$sig"
  [ "$rc" -eq 0 ] || fail "play SIG$sig -> exit $rc, expected 0"
  grep -qF "stopped by a signal" "$work/err" || fail "play SIG$sig: no note"
  less_than "$secs" 5 || fail "play took ${secs}s to stop"
  "$bin" replay "$work/game.replay" --verify >"$work/verify" 2>"$work/err" ||
    fail "the recording left by SIG$sig is not a whole replay"
  echo "ok play SIG$sig: exit $rc after ${secs}s; $(cat "$work/verify")"
  passed=$((passed + 1))
done

# Commands with nothing to save end at once.
# stops_at_once NAME SIGNAL EXIT COMMAND...: runs COMMAND, signals it after 2 s and expects
# exit EXIT within 2 s.
stops_at_once() {
  local name=$1 sig=$2 want=$3
  shift 3
  "$@" >"$work/out" 2>"$work/err" &
  pid=$!
  pids+=("$pid")
  sleep 2
  kill -0 "$pid" 2>/dev/null || fail "$name ended before the signal"
  stop_and_time "$pid" "$sig"
  [ "$rc" -eq "$want" ] || fail "$name SIG$sig -> exit $rc"
  less_than "$secs" 2 || fail "$name took ${secs}s to stop"
}
passes() { echo "ok $1: exit $rc after ${secs}s"; passed=$((passed + 1)); }

stops_at_once render INT 130 "$bin" render builtin:sphere --size 64x48 --repeat 100000 --out "$work/s.png"
grep -qF "beamzone: SIGINT: stopped" "$work/err" || fail "no note on stderr"
passes "render SIGINT"

printf 'version = 1\nname = "S"\n' >"$work/s.toml"
stops_at_once bench TERM 143 "$bin" bench "$work/s.toml" --frames 1000000 --out "$work/bench"
passes "bench SIGTERM"
echo "$passed passed, 0 failed"
