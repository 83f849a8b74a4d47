#!/usr/bin/env bash
# ctest-labels: slow
# The showcase through the real binary, at a tiny preview (128x72, a frame
# every 4 s of story): the three sequences rendered, encoded and joined
# behind title cards, checked with ffprobe (codec, pixel format, frame
# counts, durations exactly frames/fps, faststart); the frames checked
# against the storyboard (the dihole's first frame has no shadow, later ones
# do; the disk's last frame, M = 0, is an undistorted projection while a
# lensed one is not); a second run resumes without redoing anything; under
# mpirun the frames come out byte-identical; --thermal adds the fourth
# sequence; --motion-blur renders the film blurred; bad flags are refused.
source "$(dirname "$0")/lib.sh"
e2e_begin "$@"
use_mpirun
CHECK="$TOOLS/storyboard_check"
ARGS=(--size 128x72 --rate 0.25 --progress 0)

# --- Ctrl-C while the first sequence renders: the render stores what it
# holds, says how far it got, and the showcase exits 130; the next run
# resumes (its frames are compared with an uninterrupted run under mpirun
# below).  The test hook LIGHTCONE_TEST_PAUSE_AFTER holds the render after
# 100 working sets (a frame is 72), so the Ctrl-C lands mid-render.
LIGHTCONE_TEST_PAUSE_AFTER=100 "$LIGHTCONE" showcase "${ARGS[@]}" --threads 2 --out sc 2>stop.log &
pid=$!
for _ in $(seq 1 1200); do
  grep -q "test pause" stop.log && grep -q '^frame=' sc/frames/kerr_accrDisk/kerr_accrDisk.journal 2>/dev/null && break
  kill -0 "$pid" 2>/dev/null || break
  sleep 0.05
done
kill -INT "$pid" || fail "the showcase ended before its Ctrl-C: $(cat stop.log)"
rc=0
wait "$pid" || rc=$?
[ "$rc" -eq 130 ] || fail "showcase after Ctrl-C: exit $rc, want 130: $(cat stop.log)"
grep -q "render: interrupted by Ctrl-C (SIGINT): 1 of 8 frames done (1 in this run); run the same command again to resume" \
  stop.log || fail "no render message: $(cat stop.log)"
grep -q "showcase: stopped; the same command resumes" stop.log || fail "no showcase message: $(cat stop.log)"
[ -z "$(find sc -name '*.tmp-*')" ] || fail "temporaries left after Ctrl-C: $(find sc -name '*.tmp-*')"

"$LIGHTCONE" showcase "${ARGS[@]}" --out sc 2>sc.log || fail "showcase: $(cat sc.log)"
grep -q "showcase: done" sc.log || fail "no summary: $(cat sc.log)"
grep -q "resuming: 1 of 8 frames already finished" sc.log || fail "the interrupted render was not resumed: $(cat sc.log)"

# --- videos: 8 + 14 + 18 frames (4 per 16 s of story, first and last
# included) and four 4-frame title cards, all at 0.25 fps ----------------
check_probe sc/showcase.mp4 codec_name=h264 pix_fmt=yuv420p width=128 height=72 nb_read_frames=56 \
  avg_frame_rate=1/4 duration=224.000000
[ "$(atoms sc/showcase.mp4)" = "ftyp moov free mdat" ] || fail "showcase.mp4 not faststart: $(atoms sc/showcase.mp4)"
check_probe sc/kerr_accrDisk.mp4 nb_read_frames=8 duration=32.000000
check_probe sc/kerr_passing.mp4 nb_read_frames=14 duration=56.000000
check_probe sc/dihole.mp4 nb_read_frames=18 duration=72.000000
for c in opening kerr_accrDisk kerr_passing dihole; do
  check_probe "sc/cards/$c.mp4" nb_read_frames=4 width=128 height=72
done
for s in kerr_accrDisk kerr_passing dihole; do
  [ -s "sc/$s.sheet.png" ] || fail "no contact sheet for $s"
done
[ -z "$(find sc -name '*.tmp-*')" ] || fail "temporaries left: $(find sc -name '*.tmp-*')"

# --- the storyboard ---------------------------------------------------------
F=sc/frames
"$CHECK" no-shadow $F/dihole/dihole.0000.exr || fail "dihole frame 0 (masses 0) should show no shadow"
"$CHECK" shadow $F/dihole/dihole.0247.exr || fail "dihole frame 247 (masses 0.4) should show the holes' shadows"
"$CHECK" flat-disk $F/kerr_accrDisk/kerr_accrDisk.0899.exr || fail "kerr_accrDisk's last frame (M = 0) is not undistorted"
# The check can fail: at frame 385 (edge on, M = 1) the disk is lensed.
if "$CHECK" flat-disk $F/kerr_accrDisk/kerr_accrDisk.0385.exr >/dev/null 2>&1; then
  fail "flat-disk passed a lensed frame"
fi

# --- resume: nothing is redone ---------------------------------------------
"$LIGHTCONE" showcase "${ARGS[@]}" --out sc 2>again.log || fail "second run: $(cat again.log)"
[ "$(grep -c 'nothing to render' again.log)" -eq 3 ] || fail "second run rendered again: $(cat again.log)"
[ "$(grep -c 'newer than its frames; kept' again.log)" -eq 3 ] || fail "second run re-encoded: $(cat again.log)"
check_probe sc/showcase.mp4 nb_read_frames=56

# --- under mpirun (a master and two workers): the same frames ----------------
mpi 3 "$LIGHTCONE" showcase "${ARGS[@]}" --out mpi 2>mpi.log || fail "mpirun showcase: $(cat mpi.log)"
n=0
for f in sc/frames/*/*.exr sc/frames/*/*.png; do
  n=$((n + 1))
  cmp -s "$f" "mpi/${f#sc/}" || fail "$f differs under mpirun"
done
[ "$n" -eq 80 ] || fail "expected 80 frame files, found $n"
check_probe mpi/showcase.mp4 nb_read_frames=56

# --- --thermal adds the fourth sequence and keeps the three -------------------
"$LIGHTCONE" showcase "${ARGS[@]}" --thermal --out sc 2>thermal.log || fail "showcase --thermal: $(cat thermal.log)"
[ "$(grep -c 'nothing to render' thermal.log)" -eq 3 ] || fail "--thermal rendered the three again: $(cat thermal.log)"
check_probe sc/kerr_accrDisk_thermal.mp4 nb_read_frames=8 duration=32.000000
check_probe sc/cards/kerr_accrDisk_thermal.mp4 nb_read_frames=4
check_probe sc/showcase.mp4 nb_read_frames=68 duration=272.000000

# --- --motion-blur: the same film with every shot's shutter at 0.5, in a folder
# of its own by default; its frames are blurred (their EXRs say so) and differ
# from the sharp film's where anything moves.
mkdir blur && (cd blur && "$LIGHTCONE" showcase "${ARGS[@]}" --motion-blur 2>../blur.log) \
  || fail "showcase --motion-blur: $(cat blur.log)"
check_probe blur/out/showcase/preview-blur/showcase.mp4 nb_read_frames=56 duration=224.000000
for shot in kerr_accrDisk kerr_passing dihole; do
  grep -q ' shutter=0.5 ' blur/out/showcase/preview-blur/frames/$shot/$shot.journal \
    || fail "$shot: not rendered with the shutter open"
done
iinfo -v blur/out/showcase/preview-blur/frames/kerr_passing/kerr_passing.0915.exr | grep -q 'lightcone/shutter: "shutter 0.5' \
  || fail "kerr_passing's frame 915 is not blurred"
cmp -s blur/out/showcase/preview-blur/frames/kerr_passing/kerr_passing.0915.png sc/frames/kerr_passing/kerr_passing.0915.png \
  && fail "the blurred kerr_passing frame 915 is the sharp one"

# --- bad flags -----------------------------------------------------------------
expect_error quality "--quality 'draft': choose preview or production" -- "$LIGHTCONE" showcase --quality draft --out bad
expect_error rate "--rate goes with --quality preview" -- "$LIGHTCONE" showcase --quality production --rate 2 --out bad
expect_error size "--size '12': expected WxH" -- "$LIGHTCONE" showcase --size 12 --out bad
mkdir empty
expect_error shots "empty/kerr_accrDisk.lua not found" -- "$LIGHTCONE" showcase --shots empty --out bad
expect_error rate_range "--rate -1: must be between 0.01 and 240" -- "$LIGHTCONE" showcase --rate -1 --out bad
mkdir broken
cp "$SRC"/shots/kerr_accrDisk.lua "$SRC"/shots/dihole.lua broken/
echo 'error("broken on purpose")' >broken/kerr_passing.lua
expect_error broken_shot "broken/kerr_passing.lua:1: broken on purpose" -- "$LIGHTCONE" showcase --shots broken --out bad
[ ! -e bad ] || fail "a refused showcase left bad/ behind"
touch a_file
expect_error out_is_file "a_file/frames/kerr_accrDisk: cannot create the output directory" -- \
  "$LIGHTCONE" showcase "${ARGS[@]}" --out a_file

e2e_end
