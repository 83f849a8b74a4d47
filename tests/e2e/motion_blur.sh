#!/usr/bin/env bash
# ctest-labels: slow
# Motion blur through the whole pipeline (docs/motion_blur.md): a blurred
# sequence is byte-identical whether rendered on 1 thread, on 2 with other
# stripes, under mpirun, or killed and resumed; with and without the reuse
# of a still scene's rays; a scene that does not change renders the same
# with the shutter open; the EXR says it is blurred and the journal how;
# bad shutters are refused naming the flag, the field or the fractional
# frame, and a render with another shutter does not resume into old frames.
source "$(dirname "$0")/lib.sh"
e2e_begin "$@"

use_mpirun  # lib.sh: Open MPI settings for a test, and `mpi N CMD...`
ORBIT="$SRC/tests/data/farm/farm_orbit.lua"  # point stars; the observer rises 2.8 degrees a frame
DATA="$SRC/tests/data/blur"
BLUR=(--shutter 0.5 --time-samples 4 --progress 0)

# --- Determinism: 1 thread, 2 threads with other stripes, mpirun -n 3.
"$LIGHTCONE" render "$ORBIT" --out one --threads 1 "${BLUR[@]}" 2>one.log || fail "1 thread: $(cat one.log)"
"$LIGHTCONE" render "$ORBIT" --out two --threads 2 --stripes 7 "${BLUR[@]}" 2>two.log || fail "2 threads: $(cat two.log)"
same_frames one two farm_orbit
mpi 3 "$LIGHTCONE" render "$ORBIT" --out mpi "${BLUR[@]}" 2>mpi.log || fail "mpirun -n 3: $(cat mpi.log)"
same_frames one mpi farm_orbit

# ... and killed mid-render (after 30 working sets: the test hook holds
# them, so the kill lands mid-job), then resumed.
LIGHTCONE_TEST_PAUSE_AFTER=30 "$LIGHTCONE" render "$ORBIT" --out resumed --threads 2 "${BLUR[@]}" 2>kill.log &
pid=$!
wait_for_pause kill.log "$pid" || true
kill -9 "$pid" 2>/dev/null || true
wait "$pid" 2>/dev/null || true
"$LIGHTCONE" render "$ORBIT" --out resumed --threads 2 "${BLUR[@]}" 2>resume.log || fail "resume: $(cat resume.log)"
same_frames one resumed farm_orbit

# The blurred frames are not the sharp ones, say so in their header, and
# the journal records the flags.
"$LIGHTCONE" render "$ORBIT" --out sharp --frames 4 --progress 0 2>sharp.log || fail "sharp: $(cat sharp.log)"
cmp -s sharp/farm_orbit.0004.png one/farm_orbit.0004.png && fail "the blurred frame 4 is the sharp one"
iinfo -v one/farm_orbit.0004.exr | grep -q 'lightcone/shutter: "shutter 0.5 (centre, 4 instants)"' \
  || fail "no lightcone/shutter in the blurred EXR: $(iinfo -v one/farm_orbit.0004.exr)"
iinfo -v sharp/farm_orbit.0004.exr | grep -q 'lightcone/shutter' && fail "a sharp frame's EXR names a shutter"
grep -q ' shutter=0.5 time_samples=4 ' one/farm_orbit.journal || fail "journal: $(cat one/farm_orbit.journal)"
# Its stars streak: the blurred frame has light where the sharp one has none
# and the same light in all (within 3%: the stars' light is conserved, the
# rest of the sky is dark).
$PY - sharp/farm_orbit.0004.exr one/farm_orbit.0004.exr <<'PY' || fail "the blurred frame's light"
import sys, OpenImageIO as oiio
a = oiio.ImageBuf(sys.argv[1]).get_pixels(oiio.FLOAT)
b = oiio.ImageBuf(sys.argv[2]).get_pixels(oiio.FLOAT)
lit_a, lit_b = (a[..., :3].sum(axis=2) > 1e-4).sum(), (b[..., :3].sum(axis=2) > 1e-4).sum()
sa, sb = a[..., :3].sum(), b[..., :3].sum()
print("lit pixels", lit_a, lit_b, "light", sa, sb)
assert lit_b > lit_a and abs(sb - sa) < 0.03 * sa
PY

# A different shutter does not resume into these frames.
expect_error resume_other_shutter "this render asks for" -- \
  "$LIGHTCONE" render "$ORBIT" --out one --threads 2 --shutter 0.25 --time-samples 4 --progress 0

# --- A still scene: the shutter open changes nothing, to the bit.
"$LIGHTCONE" render "$DATA/still.lua" --out still_closed --progress 0 2>still.log || fail "still: $(cat still.log)"
"$LIGHTCONE" render "$DATA/still.lua" --out still_open --shutter 1 --progress 0 2>still_open.log \
  || fail "still, shutter open: $(cat still_open.log)"
same_frames still_closed still_open still

# --- Reuse of a still scene's rays: a static observer watching a moving
# sphere shares rays between frames; blurred frames neither take nor keep
# them (frame 3 closes its own shutter and may), and the frames are the
# same with reuse off.
"$LIGHTCONE" render "$DATA/moving_sphere.lua" --out reuse --threads 2 --progress 0 2>reuse.log \
  || fail "moving sphere: $(cat reuse.log)"
"$LIGHTCONE" render "$DATA/moving_sphere.lua" --out no_reuse --threads 2 --no-reuse --progress 0 2>no_reuse.log \
  || fail "moving sphere, --no-reuse: $(cat no_reuse.log)"
same_frames reuse no_reuse moving_sphere
iinfo -v reuse/moving_sphere.0003.exr | grep -q 'lightcone/shutter' && fail "frame 3 closed its shutter"
iinfo -v reuse/moving_sphere.0002.exr | grep -q 'lightcone/shutter' || fail "frame 2 is blurred"

# --- Bad input.
expect_error shutter_too_long "--shutter 1.5: must be between 0 (closed) and 1" -- \
  "$LIGHTCONE" render "$DATA/still.lua" --out bad --shutter 1.5
expect_error shutter_negative "--shutter -0.1: must be between 0" -- \
  "$LIGHTCONE" render "$DATA/still.lua" --out bad --shutter -0.1
expect_error no_time_samples "--time-samples 0: must be between 1 and 64" -- \
  "$LIGHTCONE" render "$DATA/still.lua" --out bad --time-samples 0
expect_error absurd_time_samples "--time-samples 1000: must be between 1 and 64" -- \
  "$LIGHTCONE" render "$DATA/still.lua" --out bad --time-samples 1000
expect_error shutter_position "--shutter-position middle: expected centre, start or end" -- \
  "$LIGHTCONE" render "$DATA/still.lua" --out bad --shutter-position middle
sed 's/supersample = 2,/supersample = 2, shutter = 2,/' "$DATA/still.lua" >shot_shutter.lua
expect_error shot_shutter "shot_shutter.lua: field 'shutter' must be between 0 and 1" -- \
  "$LIGHTCONE" render shot_shutter.lua --out bad
sed 's/sky = lc.starfield{},/sky = lc.starfield{}, shutter = -1,/' "$DATA/still.lua" >frame_shutter.lua
expect_error frame_shutter "frame_shutter.lua: frame 0: field 'shutter' must be between 0 and 1" -- \
  "$LIGHTCONE" render frame_shutter.lua --out bad
expect_error whole_frames "whole_frames.lua: frame 0 at 0.125: " -- \
  "$LIGHTCONE" render "$DATA/whole_frames.lua" --out bad --shutter 0.5 --shutter-position start --time-samples 2
grep -q "frame(i) is also called at fractional i" whole_frames.err || fail "no hint: $(cat whole_frames.err)"
# A cut between cameras within a shutter: a mono picture blended with a
# stereo pair (frame 2's shutter reaches back to frame 1.5), or a flat
# picture with a sphere.
sed 's/camera = lc.camera{fov = 40},/camera = (i < 2) and lc.camera{fov = 40} or lc.camera{fov = 40, stereo = "side-by-side"},/' \
  "$DATA/still.lua" >stereo_cut.lua
expect_error stereo_cut "stereo_cut.lua: frame 2: the camera is lc.camera (flat, side-by-side) at the frame but lc.camera (flat, mono) at 1.75, within its shutter" -- \
  "$LIGHTCONE" render stereo_cut.lua --out bad --shutter 1 --time-samples 2
expect_error stereo_cut_region "close it for this frame" -- \
  "$LIGHTCONE" render stereo_cut.lua --out bad --shutter 1 --time-samples 2 --region 0,0,8,8
sed 's/camera = lc.camera{fov = 40},/camera = (i < 1) and lc.equirect{} or lc.equirect{longitude = 180},/' \
  "$DATA/still.lua" >projection_cut.lua
expect_error projection_cut "frame 1: the camera is lc.equirect (flat, mono) at the frame but lc.equirect (equirectangular, mono) at 0.75" -- \
  "$LIGHTCONE" render projection_cut.lua --out bad --shutter 1 --time-samples 2
# ... a closed shutter renders the cut.
"$LIGHTCONE" render stereo_cut.lua --out cut_closed --progress 0 2>cut_closed.log || fail "a cut, shutter closed: $(cat cut_closed.log)"
[ ! -e bad ] || fail "a refused render left files: $(ls bad)"
e2e_end
