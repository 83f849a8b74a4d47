#!/usr/bin/env bash
# Delivery from the command line (issue 43, item 15): a paper's shot
# through a tilted dome, in omnidirectional stereo and under the real sky,
# without a Lua wrapper (docs/cameras.md, "A shot through a dome or a 360
# camera"):
#   1. --camera dome --dome-tilt 15 --dome-elevation 45: the shadow sits
#      where a dome tilted 15 degrees puts a subject 45 degrees above the
#      audience's horizon ((90 - 45 - 15)/90 of the radius below the
#      centre, not today's 55/90); the journal says so and a resume without
#      the flags is refused; trace takes the same flags and finds the hole
#      at that pixel;
#   2. --camera ods --separation 0.5: a square frame of two 2:1 pictures
#      that differ (the eyes are apart);
#   3. --sky kstars: the real catalogue (a two-star stand-in named by
#      LIGHTCONE_STAR_CATALOGUE, so the test runs without kstars-data) in
#      place of the generated stars, recorded as a setting and an input;
#      an image sky is refused, and a missing catalogue names the package;
#   4. the flags that do not fit are refused naming the flag, no frame
#      written.
source "$(dirname "$0")/lib.sh"
e2e_begin "$@"
SHOT="$SRC/shots/kerr_accrDisk.lua"
RENDER=(render "$SHOT" --frames 0 --progress 0)

# 1. The tilted dome.
CHECKS=$((CHECKS + 1))
"$LIGHTCONE" "${RENDER[@]}" --out tilted --camera dome --dome-tilt 15 --dome-elevation 45 --size 48x48 --layers \
  --supersample 1 2>tilted.log || fail "render --camera dome --dome-tilt 15 --dome-elevation 45: $(cat tilted.log)"
grep -q " camera=dome dome_tilt=15 dome_elevation=45 " tilted/kerr_accrDisk.journal ||
  fail "the journal does not say the dome's tilt and elevation: $(tail -1 tilted/kerr_accrDisk.journal)"
"$PY" - tilted/kerr_accrDisk.0000.exr <<'PY' || fail "the tilted dome's frame does not put the hole at 45 degrees"
import sys
import OpenImageIO as oiio
buf = oiio.ImageBuf(sys.argv[1])
names = list(buf.spec().channelnames)
W, H = buf.spec().width, buf.spec().height
if W != H: sys.exit(f"{W}x{H}, not square")
kind = names.index("hit.kind")
pts = [(i, j) for j in range(H) for i in range(W) if buf.getpixel(i, j)[kind] == 2]
if not pts: sys.exit("no shadow")
cy = sum(j + 0.5 for _, j in pts) / len(pts)
want = H / 2 + (90 - 45 - 15) / 90 * H / 2
if abs(cy - want) > 2: sys.exit(f"the shadow's centre is at row {cy:.1f}, want about {want:.1f}")
PY
expect_error resume "through the dome camera (tilted 0 degrees, the subject 35 degrees up)" -- \
  "$LIGHTCONE" "${RENDER[@]}" --out tilted --camera dome --size 48x48 --layers --supersample 1
# trace with the same flags: the hole at the tilted dome's pixel, the sky
# at the level dome's.
trace_hit() {
  local pixel="$1"
  shift
  "$LIGHTCONE" trace "$SHOT" --frame 0 --size 96x96 --pixel "$pixel" --json "$@" 2>trace.err |
    "$PY" -c 'import json, sys; print(json.load(sys.stdin)["hit"])'
}
CHECKS=$((CHECKS + 1))
[ "$(trace_hit 48,64 --camera dome --dome-tilt 15 --dome-elevation 45)" = horizon ] ||
  fail "trace --camera dome --dome-tilt 15 --dome-elevation 45 does not find the hole at 48,64: $(cat trace.err)"
[ "$(trace_hit 48,77 --camera dome --dome-tilt 15 --dome-elevation 45)" = sky ] ||
  fail "trace --dome-tilt 15 --dome-elevation 45 still finds the hole where a level dome has it"

# 2. Omnidirectional stereo.
CHECKS=$((CHECKS + 1))
"$LIGHTCONE" "${RENDER[@]}" --out ods --camera ods --separation 0.5 --scale 0.05 --supersample 1 2>ods.log ||
  fail "render --camera ods --separation 0.5: $(cat ods.log)"
grep -q " camera=ods separation=0.5 " ods/kerr_accrDisk.journal ||
  fail "the journal does not say ODS's separation: $(tail -1 ods/kerr_accrDisk.journal)"
"$PY" - ods/kerr_accrDisk.0000.exr <<'PY' || fail "the ODS frame is not two different eyes in a square"
import sys
import OpenImageIO as oiio
buf = oiio.ImageBuf(sys.argv[1])
W, H = buf.spec().width, buf.spec().height
if (W, H) != (72, 72): sys.exit(f"{W}x{H}, want 72x72 (two 2:1 pictures of 720 * 0.05 rows)")
rgb = lambda j: [buf.getpixel(i, j)[:3] for i in range(W)]
if all(rgb(j) == rgb(j + H // 2) for j in range(H // 2)): sys.exit("the two eyes' pictures are the same")
PY

# 3. The real sky.
star() { printf '%s %s -000546.0-001223.100379.2 %s%sA0 1\n' "$1" "$2" "$3" "$4"; }
{ star 064508.92 -164258.0 -1.44 00.01; star 002000.00 +100000.0 00.03 -0.00; } >stars.dat
CHECKS=$((CHECKS + 1))
LIGHTCONE_STAR_CATALOGUE="$WORK/stars.dat" "$LIGHTCONE" "${RENDER[@]}" --out real --sky kstars --size 32x18 \
  --supersample 1 2>real.log || fail "render --sky kstars: $(cat real.log)"
"$LIGHTCONE" "${RENDER[@]}" --out generated --size 32x18 --supersample 1 2>generated.log ||
  fail "render: $(cat generated.log)"
grep -q " sky_catalogue=kstars " real/kerr_accrDisk.journal ||
  fail "the journal does not say the real sky: $(tail -1 real/kerr_accrDisk.journal)"
grep -q "path=$WORK/stars.dat " real/kerr_accrDisk.journal || fail "the catalogue is not among the frame's inputs"
cmp -s real/kerr_accrDisk.0000.exr generated/kerr_accrDisk.0000.exr && fail "--sky kstars drew the generated stars"
expect_error real_resume "under the shot's own sky" -- "$LIGHTCONE" "${RENDER[@]}" --out real --size 32x18 --supersample 1
cat >image_sky.lua <<'LUA'
local lc = require "lightcone"
return {name = "image_sky", frames = 1, width = 16, height = 8,
  frame = function(i)
    return {spacetime = lc.kerr{mass = 1, spin = 0}, observer = lc.static_observer{r = 30, theta = 90, phi = 0},
            camera = lc.camera{fov = 60}, sky = lc.sky_image{file = "textures/starfield.png"}}
  end}
LUA
LIGHTCONE_STAR_CATALOGUE="$WORK/stars.dat" expect_error image_sky \
  'frame 0: --sky kstars: the sky is lc.sky_image{file = "textures/starfield.png"}' -- \
  "$LIGHTCONE" render image_sky.lua --out image_sky --sky kstars --progress 0
LIGHTCONE_STAR_CATALOGUE="$WORK/none.dat" expect_error no_catalogue \
  "--sky kstars reads KStars' star catalogue $WORK/none.dat, which is not there: install Debian's kstars-data" -- \
  "$LIGHTCONE" "${RENDER[@]}" --out no_catalogue --sky kstars

# 4. Flags that do not fit.
expect_error tilt_alone "--dome-tilt 15: only with --camera dome" -- "$LIGHTCONE" "${RENDER[@]}" --out bad --dome-tilt 15
expect_error elevation_360 "--dome-elevation 45: only with --camera dome" -- \
  "$LIGHTCONE" "${RENDER[@]}" --out bad --camera 360 --dome-elevation 45
expect_error steep "--dome-tilt 95: must be between 0 and 90 degrees" -- \
  "$LIGHTCONE" "${RENDER[@]}" --out bad --camera dome --dome-tilt 95
expect_error low "--dome-elevation -10: must be between 0 and 90 degrees" -- \
  "$LIGHTCONE" "${RENDER[@]}" --out bad --camera dome --dome-elevation -10
expect_error separation_dome "--separation 0.5: only with --camera ods" -- \
  "$LIGHTCONE" "${RENDER[@]}" --out bad --camera dome --separation 0.5
expect_error no_eyes "--separation 0: must be greater than 0" -- "$LIGHTCONE" "${RENDER[@]}" --out bad --camera ods --separation 0
expect_error sky_name "--sky: tycho not in {shot,kstars}" -- "$LIGHTCONE" "${RENDER[@]}" --out bad --sky tycho
expect_error tilt_number "--dome-tilt: 'steep' is not a number" -- "$LIGHTCONE" "${RENDER[@]}" --out bad --camera dome --dome-tilt steep
expect_error trace_tilt "--dome-tilt 15: only with --camera dome" -- \
  "$LIGHTCONE" trace "$SHOT" --frame 0 --pixel 1,1 --dome-tilt 15
CHECKS=$((CHECKS + 1))
if [ -e bad ] || [ -e no_catalogue ] || [ -e image_sky ]; then fail "a refused render wrote into its --out"; fi

e2e_end
