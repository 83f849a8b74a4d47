#!/usr/bin/env bash
# ctest-labels: slow
# Exposure that follows the light and develop without re-tracing
# (docs/light.md): the fall into a glowing Kerr disk (shots/kerr_fall.lua,
# auto_exposure) keeps its 99th percentile of display luminance in a band
# over the whole fall, and its frames are byte-identical rendered together,
# one alone, under mpirun and killed and resumed; `lightcone develop` makes
# every PNG again to the byte with the recorded look, another look through
# the journal (which encode then takes), and refuses bad input with nothing
# changed.
source "$(dirname "$0")/lib.sh"
e2e_begin "$@"

use_mpirun
FALL="$SRC/shots/kerr_fall.lua"
SMALL=(--size 96x54 --supersample 1 --progress 0)
FRAMES=0:179:30

# --- Automatic exposure: the band, and the same exposure however rendered.
"$LIGHTCONE" render "$FALL" --out all --frames "$FRAMES" "${SMALL[@]}" 2>all.log || fail "render: $(cat all.log)"
"$LIGHTCONE" render "$FALL" --out alone --frames 120 "${SMALL[@]}" 2>alone.log || fail "alone: $(cat alone.log)"
cmp -s alone/kerr_fall.0120.png all/kerr_fall.0120.png || fail "frame 120 rendered alone has another PNG"
# ... and metered only what its smoothing (12 frames: 36 either side) reaches.
grep -q "auto exposure: the readings of frames 84-156 of the shot's 180" alone.log || fail "frame 120's meter: $(cat alone.log)"
grep -q "auto exposure: 0 readings kept from alone/kerr_fall.meter, 73 metered" alone.log || fail "frame 120's meter: $(cat alone.log)"
mpi 3 "$LIGHTCONE" render "$FALL" --out mpi --frames "$FRAMES" "${SMALL[@]}" 2>mpi.log || fail "mpirun -n 3: $(cat mpi.log)"
same_frames all mpi kerr_fall
# The event log (for `lightcone monitor`) names the run's two workers, their node and threads.
[ "$(grep -c " event=rank rank=[12] host=$(hostname) threads=[0-9]" mpi/kerr_fall.events)" = 2 ] \
  || fail "the MPI run's event log lacks its workers: $(cat mpi/kerr_fall.events)"
# Resumed: three frames finished, then a run killed mid-job (the test hook
# holds its working sets), then the rest.
"$LIGHTCONE" render "$FALL" --out resumed --frames 0:60:30 "${SMALL[@]}" 2>first.log || fail "first: $(cat first.log)"
LIGHTCONE_TEST_PAUSE_AFTER=30 "$LIGHTCONE" render "$FALL" --out resumed --frames "$FRAMES" --threads 2 "${SMALL[@]}" \
  2>kill.log &
pid=$!
wait_for_pause kill.log "$pid" || true
kill -9 "$pid" 2>/dev/null || true
wait "$pid" 2>/dev/null || true
"$LIGHTCONE" render "$FALL" --out resumed --frames "$FRAMES" "${SMALL[@]}" 2>resume.log || fail "resume: $(cat resume.log)"
grep -q "3 more were finished before" resume.log || fail "the resume did not resume: $(cat resume.log)"
same_frames all resumed kerr_fall
# The last frame of the fall, from the readings the first run kept.
"$LIGHTCONE" render "$FALL" --out all --frames 179 "${SMALL[@]}" 2>last.log || fail "render 179: $(cat last.log)"
grep -q "auto exposure: 0 readings kept from all/kerr_fall.meter, 180 metered" all.log || fail "no meter pass: $(cat all.log)"
grep -q "auto exposure: 37 readings kept from all/kerr_fall.meter, 0 metered" last.log \
  || fail "the second run metered again: $(cat last.log)"
# The light climbs ~3 stops over the fall (the EXR's 99th percentile); the
# PNG's stays within 0.70 to 0.90 of the display's white (linear), where a
# fixed exposure goes from 0.73 to 0.96, the last third washed out.
$PY - all/kerr_fall.*.exr <<'PY' || fail "auto exposure: the display's 99th percentile left its band"
import sys, numpy as np, OpenImageIO as oiio
def p99(path, srgb):
    a = oiio.ImageBuf(path).get_pixels(oiio.FLOAT)[..., :3].astype(np.float64)
    if srgb: a = np.where(a <= 0.04045, a / 12.92, ((a + 0.055) / 1.055) ** 2.4)
    return np.percentile(a @ np.array([0.2126, 0.7152, 0.0722]), 99)
light = [p99(f, False) for f in sys.argv[1:]]
shown = [p99(f[:-3] + "png", True) for f in sys.argv[1:]]
print("light:", " ".join("%.3g" % v for v in light))
print("shown:", " ".join("%.3f" % v for v in shown))
assert light[-1] / light[0] > 6, "the fall's light should climb more than 2.5 stops"
assert all(0.70 <= v <= 0.90 for v in shown), shown
PY
# A meter file that is not whole is metered again, not trusted.
mkdir -p cut
head -c 100 all/kerr_fall.meter >cut/kerr_fall.meter
"$LIGHTCONE" render "$FALL" --out cut --frames 120 "${SMALL[@]}" 2>cut.log || fail "cut meter: $(cat cut.log)"
grep -q "0 readings kept from cut/kerr_fall.meter, 73 metered" cut.log || fail "a cut meter file was trusted: $(cat cut.log)"
cmp -s cut/kerr_fall.0120.png all/kerr_fall.0120.png || fail "after a cut meter file, frame 120 differs"
# The journal records each frame's look, with its metered exposure.
grep -q ' look=exposure:-3[0-9.]*,view:gamut_safe,white_balance:5000' all/kerr_fall.journal \
  || fail "journal lacks the look: $(cat all/kerr_fall.journal)"

# --- develop: the recorded look gives every PNG back, to the byte.
cp -r all original
"$LIGHTCONE" develop all 2>develop.log || fail "develop: $(cat develop.log)"
grep -q "develop: done: 7 frames" develop.log || fail "develop's summary: $(cat develop.log)"
same_frames original all kerr_fall
ls all | grep -q tmp && fail "temporary files left by develop"
# Another look: a stop brighter in the filmic view changes every PNG and
# no EXR; the journal records it, encode takes the frames as current; the
# recorded view back gives the original PNGs.
"$LIGHTCONE" develop all --exposure-shift 1 --view filmic --bloom 0 2>brighter.log || fail "develop brighter: $(cat brighter.log)"
for f in original/kerr_fall.*.png; do cmp -s "$f" "all/$(basename "$f")" && fail "develop left $(basename "$f") as it was"; done
for f in original/kerr_fall.*.exr; do cmp -s "$f" "all/$(basename "$f")" || fail "develop changed $(basename "$f")"; done
grep -q ' look=exposure:-3[0-9.]*,view:filmic,white_balance:5000,saturation:1.2 ' all/kerr_fall.journal \
  || fail "journal lacks the developed look: $(tail -2 all/kerr_fall.journal)"
"$LIGHTCONE" encode all -o developed.mp4 2>encode.log || fail "encode after develop: $(cat encode.log)"
check_probe developed.mp4 nb_read_frames=7
# The shift is from the render's own exposure, which the journal keeps
# beside the developed look: a shift of 0 with the render's view and bloom
# gives the original PNG back.
grep -q ' look=exposure:-3[0-9.]*,view:filmic,.* render_look=exposure:-3[0-9.]*,view:gamut_safe,white_balance:5000,saturation:1.2,bloom:0.2 #' \
  all/kerr_fall.journal || fail "journal lacks the render's own look: $(tail -1 all/kerr_fall.journal)"
"$LIGHTCONE" develop all --exposure-shift 0 --view gamut_safe --bloom 0.2 --frames 120 2>back.log || fail "back: $(cat back.log)"
cmp -s all/kerr_fall.0120.png original/kerr_fall.0120.png || fail "the recorded look again did not give frame 120 back"
# A develop stopped part way and run again gives the frames one run whole
# gives (issue 43: the frames developed before the stop were shifted a
# second time).  Frame 60's PNG name is a directory, so a develop on one
# thread stops there after frames 0 and 30.
cp -r original stopped && cp -r original whole
rm stopped/kerr_fall.0060.png && mkdir stopped/kerr_fall.0060.png
SHIFT=(--exposure-shift 0.5 --threads 1)
expect_error stopped "kerr_fall.0060.png: it is a directory" -- "$LIGHTCONE" develop stopped "${SHIFT[@]}"
grep -q "develop: stopped after 2 of 7 frames" stopped.err || fail "the develop did not stop after two frames: $(cat stopped.err)"
rmdir stopped/kerr_fall.0060.png
"$LIGHTCONE" develop stopped "${SHIFT[@]}" 2>stopped_again.log || fail "develop again: $(cat stopped_again.log)"
"$LIGHTCONE" develop whole "${SHIFT[@]}" 2>whole.log || fail "develop whole: $(cat whole.log)"
same_frames whole stopped kerr_fall
# ... and run once more, the same again; the look's exposure as the decimals add.
"$LIGHTCONE" develop stopped "${SHIFT[@]}" 2>stopped_third.log || fail "develop a third time: $(cat stopped_third.log)"
same_frames whole stopped kerr_fall
$PY - stopped/kerr_fall.journal <<'PY' || fail "the shifted exposures are not the render's plus 0.5 as decimals add"
import re, sys
from decimal import Decimal
last = {}
for line in open(sys.argv[1]):
    m = re.match(r"frame=(\d+) .* look=exposure:(\S+?),.* render_look=exposure:(\S+?),", line)
    if m: last[m[1]] = (m[2], m[3])
assert len(last) == 7, last
for frame, (shown, rendered) in last.items():
    assert Decimal(shown) == Decimal(rendered) + Decimal("0.5"), (frame, shown, rendered)
PY
# A render resumed after develop keeps the developed frames (done, not damaged).
"$LIGHTCONE" render "$FALL" --out all --frames "$FRAMES" "${SMALL[@]}" 2>again.log || fail "again: $(cat again.log)"
grep -q "nothing to render" again.log || fail "developed frames were rendered again: $(cat again.log)"

# --- develop --out: the developed PNGs in a folder of their own, the
# render's frames and journal untouched (two looks side by side); the same
# PNGs a develop in place makes.  --reset starts from the render's own
# look (the last develop's is dropped); alone, it gives the render's PNGs back.
cp -r all all_before
"$LIGHTCONE" develop all --out side --reset --view filmic --exposure-shift 1 2>side.log || fail "develop --out: $(cat side.log)"
[ "$(ls side | grep -c '^kerr_fall\.[0-9]\{4\}\.png$')" = 7 ] || fail "develop --out made no 7 PNGs: $(ls side)"
[ -z "$(ls side | grep -v '^kerr_fall\.[0-9]\{4\}\.png$')" ] || fail "develop --out left more than PNGs: $(ls side)"
same_frames all_before all kerr_fall
cmp -s all_before/kerr_fall.journal all/kerr_fall.journal || fail "develop --out changed the render's journal"
"$LIGHTCONE" develop stopped --reset --view filmic --exposure-shift 1 2>in_place.log || fail "develop in place: $(cat in_place.log)"
for f in side/*.png; do cmp -s "$f" "stopped/$(basename "$f")" || fail "develop --out's $(basename "$f") differs from develop's in place"; done
"$LIGHTCONE" encode side -o side.mp4 2>side_encode.log || fail "encode of develop --out's folder: $(cat side_encode.log)"
check_probe side.mp4 nb_read_frames=7
"$LIGHTCONE" develop stopped --reset 2>reset.log || fail "develop --reset: $(cat reset.log)"
same_frames original stopped kerr_fall
cp -r original original_before
expect_error out_is_dir "--out all: the render's own folder" -- "$LIGHTCONE" develop all --out all --view filmic
expect_error out_is_render "--out original: it holds a render of 'kerr_fall'" -- "$LIGHTCONE" develop all --out original --view filmic
same_frames all_before all kerr_fall
same_frames original_before original kerr_fall

# --- Bad input: a clear error, nothing changed.
mkdir -p empty
expect_error no_render "no render here" -- "$LIGHTCONE" develop empty
expect_error no_dir "no such directory" -- "$LIGHTCONE" develop nowhere
expect_error bad_view "--view agx: must be standard, filmic or gamut_safe" -- "$LIGHTCONE" develop all --view agx
expect_error bad_wb "--white-balance" -- "$LIGHTCONE" develop all --white-balance 300
expect_error bad_saturation "--saturation 9: must be between 0 and 4" -- "$LIGHTCONE" develop all --saturation 9
expect_error bad_shot "--shot nope" -- "$LIGHTCONE" develop all --shot nope
expect_error unfinished "frame 5 of 'kerr_fall' is not finished" -- "$LIGHTCONE" develop all --frames 5
cp all/kerr_fall.0060.png before.png
head -c 2000 original/kerr_fall.0030.exr >all/kerr_fall.0030.exr
expect_error torn_exr "kerr_fall.0030.exr has 2000 bytes where the render wrote" -- "$LIGHTCONE" develop all --exposure 0
cmp -s before.png all/kerr_fall.0060.png || fail "a refused develop changed frame 60's PNG"

e2e_end
