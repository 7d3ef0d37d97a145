#!/usr/bin/env bash
# Every output option of every command against one table of hostile targets. Each target is
# refused before any work with a message naming it and a non-zero exit (never a hang, never a
# crash), and is left exactly as it was: the command's own input (a hard link and a symbolic
# link to it, so paths differ but the inode is the same), a character device, a FIFO, a folder,
# a file of another kind carrying the output's name, a read-only folder and a missing folder.
# --overwrite lets a file of another kind be replaced, and nothing else. A replaced output
# keeps its mode.
set -uo pipefail
bin=$1
work=$(mktemp -d)
trap 'chmod -R u+w "$work" 2>/dev/null; rm -rf "$work"' EXIT
export BEAMZONE_PREF_DIR=$work/pref SDL_VIDEODRIVER=offscreen SDL_AUDIODRIVER=dummy
cd "$work"
passed=0
fail() { echo "FAIL: $*"; cat "$work/err" 2>/dev/null; exit 1; }

printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\nf 1 3 4\nf 1 4 2\nf 2 4 3\n' >tet.obj
printf 'version = 1\nname = "Mine"\n' >mine.toml
cp tet.obj tet.orig
cp mine.toml mine.orig

# name | input the command reads | target, relative to the case folder | command (@T: target,
# @D: the folder bench fills). One row per output option; bench has a row per file it writes.
rows=(
  "render --out|tet.obj|out.png|render tet.obj --size 32x24 --out @T"
  "render --mask|tet.obj|out.png|render tet.obj --size 32x24 --out @T.ok.png --mask @T"
  "reference --mask|tet.obj|out.png|reference tet.obj --size 32x24 --mask @T"
  "render --svg|tet.obj|out.svg|render tet.obj --size 32x24 --out @T.ok.png --svg @T"
  "reference --svg|tet.obj|out.svg|reference tet.obj --size 32x24 --mask @T.ok.png --svg @T"
  "difficulty --json|mine.toml|out.json|difficulty mine.toml --seeds 1 --seconds 1 --json @T"
  "play --record|mine.toml|out.replay|play mine.toml --headless-test --frames 5 --record @T"
  "replay --record-demo|mine.toml|out.replay|replay @T --record-demo 1 --level mine.toml"
  "bench summary.json|mine.toml|out/summary.json|bench mine.toml --frames 2 --warmup 0 --size 64x48 --out @D"
  "bench frames.csv|mine.toml|out/frames.csv|bench mine.toml --frames 2 --warmup 0 --size 64x48 --out @D"
  "bench frametime.png|mine.toml|out/frametime.png|bench mine.toml --frames 2 --warmup 0 --size 64x48 --out @D"
  "bench masks/|mine.toml|out/masks/r.png|bench mine.toml --sweep --frames 2 --samples 1 --warmup 0 --rounds 1 --size 64x48 --out @D"
)
targets=(input-hardlink input-symlink char-device fifo folder other-kind)
can_mknod=0
if mknod "$work/probe-dev" c 1 3 2>/dev/null; then can_mknod=1; rm -f "$work/probe-dev"; fi

# make TARGET INPUT PATH: puts a hostile TARGET at PATH.
make_target() {
  case $1 in
    input-hardlink) ln "$work/$2" "$3" ;;
    input-symlink) ln -s "$work/$2" "$3" ;;
    char-device) mknod "$3" c 1 3 ;;
    fifo) mkfifo "$3" ;;
    folder) mkdir "$3" ;;
    other-kind) printf 'notes: not an output\n' >"$3" ;;
  esac
}
# What is at PATH: its type and, for a regular file, its content.
fingerprint() {
  if [ -L "$1" ]; then echo "link $(readlink "$1")"
  elif [ -c "$1" ]; then echo "chardev $(stat -c %t:%T "$1")"
  elif [ -p "$1" ]; then echo fifo
  elif [ -d "$1" ]; then echo "folder $(ls -A "$1" | wc -l)"
  elif [ -f "$1" ]; then echo "file $(md5sum <"$1")"
  else echo missing; fi
}
# run_case CASEDIR CMD...: runs under a timeout; stdout/stderr to $work/out, $work/err.
run_case() {
  timeout 60 "$@" >"$work/out" 2>"$work/err" </dev/null
}
expand() {  # expand TEMPLATE T D
  local s=${1//@T/$2}
  echo "${s//@D/$3}"
}

n=0
for row in "${rows[@]}"; do
  IFS='|' read -r name input rel template <<<"$row"
  for overwrite in "" " --overwrite"; do
    [ -n "$overwrite" ] && [[ $name == play* ]] && continue  # play has no --overwrite
    for t in "${targets[@]}"; do
      [ $t = char-device ] && [ $can_mknod = 0 ] && continue
      n=$((n + 1))
      c=$work/case$n
      mkdir -p "$c/$(dirname "$rel")"
      T=$c/$rel
      D=$c/out
      make_target $t "$input" "$T"
      before=$(fingerprint "$T")
      # shellcheck disable=SC2046
      run_case "$bin" $(expand "$template" "$T" "$D")$overwrite
      rc=$?
      label="$name$overwrite <- $t"
      if [ -n "$overwrite" ] && [ $t = other-kind ]; then
        # The one target --overwrite may replace: the command runs and writes there.
        [ $rc -eq 0 ] || fail "$label: exit $rc, expected 0"
        # (A mask's name depends on the frames sampled: r.png is checked, never written.)
        [[ $rel == */masks/* ]] || [ "$(fingerprint "$T")" != "$before" ] ||
          fail "$label: the file was not replaced"
      else
        [ $rc -eq 1 ] || [ $rc -eq 2 ] || fail "$label: exit $rc, expected a refusal (1 or 2)"
        grep -qF -- "$(basename "$T")" "$work/err" || fail "$label: the message does not name the target"
        [ "$(fingerprint "$T")" = "$before" ] || fail "$label: the target changed"
      fi
      cmp -s tet.obj tet.orig || fail "$label: the model was replaced"
      cmp -s mine.toml mine.orig || fail "$label: the level was replaced"
      echo "ok $label: exit $rc"
      passed=$((passed + 1))
    done
  done
done

# A folder nothing can be written to, and a missing one: refused before any work, nothing made.
for row in "${rows[@]}"; do
  IFS='|' read -r name input rel template <<<"$row"
  # Root may write into a mode-0555 folder; /proc refuses everyone.
  ro=$work/ro
  mkdir -p "$ro"
  chmod 0555 "$ro"
  place=$ro
  [ "$(id -u)" = 0 ] && place=/proc
  for where in "$place" "$work/missing/deeper"; do
    T=$where/$rel
    D=$where/out
    # shellcheck disable=SC2046
    run_case "$bin" $(expand "$template" "$T" "$D")
    rc=$?
    [ $rc -eq 1 ] || [ $rc -eq 2 ] || fail "$name into $where: exit $rc"
    [ ! -e "$work/missing" ] || fail "$name created a folder"
    [ -z "$(ls -A "$ro")" ] || fail "$name wrote into the read-only folder"
    [ ! -e /proc/out ] && [ ! -e /proc/out.png ] || fail "$name wrote into /proc"
    echo "ok $name into $where: exit $rc, $(head -c 160 "$work/err" | head -1)"
    passed=$((passed + 1))
  done
done

# A replaced output keeps its mode (0600 stays 0600).
"$bin" render tet.obj --size 32x24 --out private.png >/dev/null 2>&1 || fail "render private.png"
chmod 0600 private.png
"$bin" render tet.obj --size 32x24 --out private.png >/dev/null 2>"$work/err" || fail "render again"
[ "$(stat -c %a private.png)" = 600 ] || fail "private.png is now $(stat -c %a private.png)"
echo "ok a replaced output keeps mode 0600"
passed=$((passed + 1))
echo "$passed passed, 0 failed"
