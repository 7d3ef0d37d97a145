# Sourced by the tests/cli scripts that check beamzone's exit codes and messages (not itself a
# test: CTest registers only tests/cli/*.sh). Needs bin (the binary), work (a scratch folder)
# and fail MESSAGE from the script; expect_seconds is the time limit of one run.
#
# expect RC PATTERN ARGS...: runs beamzone ARGS, checks that it exits with RC and, unless
# PATTERN is empty, that its stdout or stderr matches the extended regular expression PATTERN.
expect() {
  local want=$1 pattern=$2
  shift 2
  timeout "${expect_seconds:-120}" "$bin" "$@" >"$work/out" 2>"$work/err"
  local rc=$?
  [ "$rc" -eq "$want" ] || fail "beamzone $* exited $rc, wanted $want: $(cat "$work/err")"
  if [ -n "$pattern" ]; then
    grep -qE -e "$pattern" "$work/err" "$work/out" ||
      fail "beamzone $*: output lacks /$pattern/: $(cat "$work/err" "$work/out")"
  fi
}
