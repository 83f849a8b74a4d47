#!/usr/bin/env bash
# The files lightcone keeps in a render's folder (the lock, the journal,
# the event log, the meter, frames, previews) are its own: a link planted
# under one of their names is never followed (a `lightcone.lock` link made
# render and develop truncate its target, a `<shot>.events` link had event
# lines appended to its target, a frame's link had its target replaced), and
# a FIFO there never hangs a render that holds the folder's lock (issue 43).
# Every command here runs under `timeout`, so a hang fails instead of
# stalling the suite.
source "$(dirname "$0")/lib.sh"
e2e_begin "$@"

cat >tiny.lua <<'LUA'
local lc = require "lightcone"
return {
  name = "tiny", frames = 2, width = 16, height = 8, auto_exposure = 1,
  frame = function(i) return {
    spacetime = lc.kerr{mass = 1, spin = 0.9}, observer = lc.static_observer{r = 30, theta = 80, phi = i},
  } end,
}
LUA
T=(timeout -s KILL 20)
echo "not lightcone's" >outside.txt
cp outside.txt keep.txt
# outside_unchanged NAME: the file outside every folder is as it was.
outside_unchanged() {
  cmp -s outside.txt keep.txt || fail "$1: the link's target outside the folder was written ($(stat -c %s outside.txt) bytes)"
  cp keep.txt outside.txt
}

# A rendered folder to develop, and a journal elsewhere to plant a link to.
"${T[@]}" "$LIGHTCONE" render tiny.lua --out done --progress 0 2>done.log || fail "render: $(cat done.log)"
cp done/tiny.journal journal_before

# --- Links: refused where the file is kept open (the lock, the journal), and
# written around (a warning) where it is only a view (the event log); a
# frame's, the meter's or a preview's name is replaced, never followed.
mkdir -p lock_link && ln -s "$WORK/outside.txt" lock_link/lightcone.lock
expect_error render_lock_link "lock_link/lightcone.lock: it is a symbolic link" -- "${T[@]}" "$LIGHTCONE" render tiny.lua --out lock_link
outside_unchanged render_lock_link
ln -s "$WORK/outside.txt" done/lightcone.lock
expect_error develop_lock_link "done/lightcone.lock: it is a symbolic link" -- "${T[@]}" "$LIGHTCONE" develop done --exposure-shift 1
outside_unchanged develop_lock_link
rm -f done/lightcone.lock

mkdir -p journal_link && ln -s "$WORK/done/tiny.journal" journal_link/tiny.journal
expect_error render_journal_link "journal_link/tiny.journal: it is a symbolic link" -- "${T[@]}" "$LIGHTCONE" render tiny.lua --out journal_link
cmp -s done/tiny.journal journal_before || fail "a render appended to another folder's journal through a link"
[ -z "$(ls journal_link/*.png 2>/dev/null)" ] || fail "a refused render wrote frames: $(ls journal_link)"

mkdir -p events_link && ln -s "$WORK/outside.txt" events_link/tiny.events
"${T[@]}" "$LIGHTCONE" render tiny.lua --out events_link --progress 0 2>events_link.log || fail "events link: $(cat events_link.log)"
outside_unchanged events_link
grep -qF "events_link/tiny.events: it is a symbolic link" events_link.log || fail "no warning names the event log's link: $(cat events_link.log)"
[ -f events_link/tiny.0001.png ] || fail "a linked event log stopped the render"

mkdir -p frame_link && ln -s "$WORK/outside.txt" frame_link/tiny.0000.png && ln -s "$WORK/outside.txt" frame_link/tiny.meter
"${T[@]}" "$LIGHTCONE" render tiny.lua --out frame_link --progress 0 2>frame_link.log || fail "frame link: $(cat frame_link.log)"
outside_unchanged frame_link
[ -f frame_link/tiny.0000.png ] && [ ! -L frame_link/tiny.0000.png ] || fail "the frame's link was not replaced by the frame"
[ -f frame_link/tiny.meter ] && [ ! -L frame_link/tiny.meter ] || fail "the meter's link was not replaced by the meter"
cmp -s frame_link/tiny.0000.png done/tiny.0000.png || fail "the frame written in place of a link differs"
# develop replaces a frame's link the same way.
rm done/tiny.0001.png && ln -s "$WORK/outside.txt" done/tiny.0001.png
"${T[@]}" "$LIGHTCONE" develop done 2>develop_link.log || fail "develop over a link: $(cat develop_link.log)"
outside_unchanged develop_frame_link
cmp -s frame_link/tiny.0001.png done/tiny.0001.png || fail "develop's frame in place of a link differs"

mkdir -p outside_dir preview_link && ln -s "$WORK/outside_dir" preview_link/preview
expect_error preview_link "preview_link/preview: it is a symbolic link" -- \
  "${T[@]}" "$LIGHTCONE" render tiny.lua --out preview_link --preview 2 --size 16x16
[ -z "$(ls -A outside_dir)" ] || fail "previews were written through a link: $(ls outside_dir)"

# --- Temporaries: a frame's or a video's temporary ("<name>.tmp-<pid>") has
# a predictable name, and the image and video libraries were handed that
# name: a link planted there after lightcone cleared it (here planted again
# and again while the command runs) had OpenImageIO and FFmpeg write the
# frame or video into the file it led to. Now they write only a temporary
# lightcone created, through its descriptor: the command either stops
# naming what was planted, or (if the planter was too slow) finishes with
# the right files; the link's target is never written.
cat >plant.py <<'PY'
# plant.py PID DIR VICTIM NAME...: while process PID lives (60 s at most),
# keeps a link to VICTIM at DIR/NAME.tmp-PID for every NAME, made again as
# soon as it is removed, as a hostile user of a shared folder would.
import os, sys, time
pid, d, victim, names = int(sys.argv[1]), sys.argv[2], sys.argv[3], sys.argv[4:]
temps = [os.path.join(d, f"{n}.tmp-{pid}") for n in names]
deadline = time.monotonic() + 60
while time.monotonic() < deadline:
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        break
    for t in temps:
        try:
            os.symlink(victim, t)
        except (FileExistsError, FileNotFoundError):
            pass
    time.sleep(0.0001)
PY
# planted NAME DIR OUTPUT... -- COMMAND...: runs COMMAND (lightcone itself,
# not under `timeout`: the temporaries carry its pid) with links planted at
# the temporaries of DIR/OUTPUT...; it must not write outside.txt, stop (if
# it stops) naming a planted temporary, and leave no link under a final
# name.  The planter gives up after 60 s, and a command still running then
# is killed and fails the test.
planted() {
  local name=$1 dir=$2 rc=0 out
  shift 2
  local outputs=()
  while [ "$1" != -- ]; do outputs+=("$1"); shift; done
  shift
  "$@" >"$name.out" 2>"$name.err" &
  local pid=$!
  "$PY" plant.py "$pid" "$dir" "$WORK/outside.txt" "${outputs[@]}"
  if kill -0 "$pid" 2>/dev/null; then
    kill -KILL "$pid"
    fail "$name: still running after 60 s"
  fi
  wait "$pid" || rc=$?
  outside_unchanged "$name"
  for out in "${outputs[@]}"; do
    [ ! -L "$dir/$out" ] || fail "$name: a planted link became $dir/$out"
    rm -f "$dir/$out.tmp-$pid"
  done
  if [ "$rc" -ne 0 ]; then
    grep -qF "something appeared under its temporary's name" "$name.err" && grep -qF ".tmp-$pid after" "$name.err" ||
      fail "$name: exit $rc without naming the planted temporary: $(cat "$name.err")"
  fi
  PLANTED_RC=$rc
}
mkdir -p tmp_link
planted render_tmp_link tmp_link tiny.0000.exr tiny.0000.png tiny.0001.exr tiny.0001.png -- \
  "$LIGHTCONE" render tiny.lua --out tmp_link --progress 0
if [ "$PLANTED_RC" -eq 0 ]; then
  cmp -s tmp_link/tiny.0001.png done/tiny.0001.png || fail "the frames written beside planted links differ"
fi
planted encode_tmp_link . film.mp4 -- "$LIGHTCONE" encode done -o film.mp4
if [ "$PLANTED_RC" -eq 0 ]; then
  [ -f film.mp4 ] && [ -s film.mp4 ] || fail "encode beside a planted link exited 0 without its video"
fi

# --- FIFOs: refused (the journal, the lock) or written around (the event
# log, the meter), at once.
mkdir -p journal_fifo && mkfifo journal_fifo/tiny.journal
expect_error journal_fifo "journal_fifo/tiny.journal: it is a FIFO" -- "${T[@]}" "$LIGHTCONE" render tiny.lua --out journal_fifo
cp done/tiny.0000.png journal_fifo/
expect_error encode_journal_fifo "journal_fifo/tiny.journal: it is a FIFO" -- "${T[@]}" "$LIGHTCONE" encode journal_fifo -o fifo.mp4
mkdir -p lock_fifo && mkfifo lock_fifo/lightcone.lock
expect_error lock_fifo "lock_fifo/lightcone.lock: it is a FIFO" -- "${T[@]}" "$LIGHTCONE" render tiny.lua --out lock_fifo
mkdir -p events_fifo && mkfifo events_fifo/tiny.events && mkfifo events_fifo/tiny.meter
"${T[@]}" "$LIGHTCONE" render tiny.lua --out events_fifo --progress 0 2>events_fifo.log || fail "events FIFO: $(cat events_fifo.log)"
grep -qF "events_fifo/tiny.events: it is a FIFO" events_fifo.log || fail "no warning names the event log's FIFO: $(cat events_fifo.log)"
[ -p events_fifo/tiny.events ] || fail "the event log's FIFO was replaced"
cmp -s events_fifo/tiny.0001.png done/tiny.0001.png || fail "the render beside a FIFO made another frame"

e2e_end
