# Shared helpers for the end-to-end tests (sourced; tests/CMakeLists.txt
# excludes this file from the tests it registers).
# Usage in a test:  source "$(dirname "$0")/lib.sh"; e2e_begin "$@"
set -euo pipefail

e2e_begin() {
  LIGHTCONE="$1"
  SRC="$2"
  WORK="$3"
  TOOLS="${4:-}"
  rm -rf "$WORK"
  mkdir -p "$WORK"
  cd "$WORK"
  FAILURES=0
  CHECKS=0
  # Debian's interpreter for the tests that read results back: python3-openimageio
  # installs its module for it (a python3 earlier on PATH, e.g. pyenv's, would not see it).
  PY=python3
  [ -x /usr/bin/python3 ] && PY=/usr/bin/python3
  # A command that stops the script under `set -e` says which, where: else
  # ctest shows a failed test with no output at all.
  trap 'e2e_status=$?; echo "FAIL: stopped at line $LINENO of ${0##*/}: \`$BASH_COMMAND\` exited with status $e2e_status" >&2' ERR
  return 0
}

fail() {
  echo "FAIL: $*" >&2
  FAILURES=$((FAILURES + 1))
}

# expect_error NAME EXPECTED_SUBSTRING -- command...
# The command must exit non-zero (not by a signal) and print the substring on stderr.
expect_error() {
  local name="$1" want="$2"
  shift 3
  CHECKS=$((CHECKS + 1))
  local rc=0
  "$@" >"$WORK/$name.out" 2>"$WORK/$name.err" || rc=$?
  if [ "$rc" -eq 0 ]; then
    fail "$name: exit 0, expected an error"
  elif [ "$rc" -gt 128 ]; then
    fail "$name: died with signal $((rc - 128))"
  elif ! grep -qF -- "$want" "$WORK/$name.err"; then
    fail "$name: stderr lacks '$want'; got: $(cat "$WORK/$name.err")"
  fi
}

# ffprobe's view of a video, one key=value per line.
probe() {
  ffprobe -v error -count_frames -show_entries \
    stream=codec_name,pix_fmt,nb_read_frames,avg_frame_rate,width,height:format=duration -of default=nw=1 "$1"
}
# check_probe FILE KEY=VALUE...: every pair must be in probe's output.
check_probe() {
  local file="$1" p
  shift
  p=$(probe "$file" 2>&1) || { fail "ffprobe $file: $p"; return; }
  for kv in "$@"; do
    grep -qx -- "$kv" <<<"$p" || fail "$file: want $kv; ffprobe says: $(tr '\n' ' ' <<<"$p")"
  done
}
# The top-level MP4 atoms in file order ("ftyp moov free mdat").
atoms() {
  python3 - "$1" <<'PY'
import struct, sys
d = open(sys.argv[1], 'rb').read()
i, out = 0, []
while i + 8 <= len(d):
    n, t = struct.unpack('>I4s', d[i:i + 8])
    if n == 1: n = struct.unpack('>Q', d[i + 8:i + 16])[0]
    out.append(t.decode('latin-1'))
    if n < 8: break
    i += n
print(' '.join(out))
PY
}
# For tests that launch mpirun: Open MPI refuses root without these, needs
# no rsh agent on one node, no cross-memory attach (often forbidden in
# containers), no core binding (the master sleeps; its core is for the
# workers).  `mpi N CMD...` runs CMD on N ranks, killed after 120 s.
use_mpirun() {
  export OMPI_MCA_plm_rsh_agent=
  export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
  export OMPI_MCA_btl_vader_single_copy_mechanism=none
  export OMPI_MCA_rmaps_base_oversubscribe=1
  mpi() {
    local n="$1"
    shift
    timeout 120 mpirun --oversubscribe --bind-to none -n "$n" "$@"
  }
}

# wait_for_pause LOG PID: until LOG shows that the test hook
# (LIGHTCONE_TEST_PAUSE_AFTER) paused a render; fails (returning 1) if
# process PID ends first or no pause comes in 60 s.
wait_for_pause() {
  local log="$1" pid="$2"
  for _ in $(seq 1 1200); do
    grep -q 'test pause: pid' "$log" 2>/dev/null && return 0
    kill -0 "$pid" 2>/dev/null || break
    sleep 0.05
  done
  grep -q 'test pause: pid' "$log" 2>/dev/null && return 0
  fail "$log: the render never paused: $(cat "$log")"
  return 1
}

# same_frames A B NAME (frames of shot NAME in folders A and B): every EXR and PNG of A equals B's, byte for byte.
same_frames() {
  local n=0
  for f in "$1"/"$3".*.exr "$1"/"$3".*.png; do
    [ -e "$f" ] || continue
    n=$((n + 1))
    cmp -s "$f" "$2/$(basename "$f")" || fail "$2: $(basename "$f") differs from $1's"
  done
  [ "$n" -gt 0 ] || fail "$1: no frames"
}

# start_monitor DIR... : starts `lightcone monitor DIR... --port 0` in the
# background (its log monitor.log), sets MONITOR (its pid) and URL, and
# kills it when the test ends.  A monitor that does not start fails the
# test and ends it.
start_monitor() {
  "$LIGHTCONE" monitor "$@" --port 0 2>monitor.log &
  MONITOR=$!
  trap 'kill "$MONITOR" 2>/dev/null || true' EXIT
  for _ in $(seq 1 100); do grep -q "http://127.0.0.1:" monitor.log && break; sleep 0.05; done
  URL=$(grep -o "http://127.0.0.1:[0-9]*" monitor.log) || { fail "the monitor did not start: $(cat monitor.log)"; e2e_end; exit 1; }
}

# tiny_fall_render DIR: one 32x18 frame of shots/kerr_fall.lua in DIR, for
# a journal and event log to copy.
tiny_fall_render() {
  mkdir -p "$1"
  "$LIGHTCONE" render "$SRC/shots/kerr_fall.lua" --out "$1" --size 32x18 --supersample 1 --progress 0 --frames 0:0 \
    2>"$1.render.log" || fail "render: $(cat "$1.render.log")"
}

# The shot NAME.lua, written here, is refused at its line LINE with a
# message holding PART, and leaves no files.
expect_refused_at() {  # name, line, part
  CHECKS=$((CHECKS + 1))
  "$LIGHTCONE" render "$1.lua" --out "$1" --size 8x8 >"$1.out" 2>"$1.err" && fail "$1 was accepted"
  grep -qF "$1.lua:$2:" "$1.err" || fail "$1: not at the shot's line: $(cat "$1.err")"
  grep -qF "$3" "$1.err" || fail "$1: $(cat "$1.err")"
  [ ! -e "$1" ] || [ -z "$(ls -A "$1")" ] || fail "$1: a refused shot left files: $(ls "$1")"
}

# A one-frame shot NAME.lua whose frame returns the scene fields FIELDS, all
# on line 3, is refused there with a message holding PART.
refused_scene() {  # name, scene fields, part
  cat >"$1.lua" <<LUA
local lc = require "lightcone"
return {name = "$1", frames = 1, width = 8, height = 8, frame = function()
  return {$2} end}
LUA
  expect_refused_at "$1" 3 "$3"
}

e2e_end() {
  echo "$CHECKS error checks; $FAILURES failures"
  [ "$FAILURES" -eq 0 ]
}
