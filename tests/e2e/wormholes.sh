#!/usr/bin/env bash
# Wormholes (lc.ellis_wormhole, lc.interstellar_wormhole) through the real
# binary: shots/wormhole.lua renders its first and last frames; from 6
# throat radii out the other universe's sky fills a disc of the closed-form
# angular radius arcsin(b/√(l² + b²)); a sphere beyond the throat is met
# there, its hit.r the signed l, and one flying through is seen beyond it;
# trace names the end a ray reached;
# the throat's photon orbit closes after 2πb; the other side's sky image is
# one of the render's inputs; bad input is refused at the shot's line.
source "$(dirname "$0")/lib.sh"
e2e_begin "$@"

SHOT="$SRC/shots/wormhole.lua"
CHECKS=$((CHECKS + 1))
"$LIGHTCONE" render "$SHOT" --out w --size 96x54 --frames 0:239:239 --supersample 1 --progress 0 >render.out 2>render.err ||
  fail "render: $(cat render.err)"
iinfo -v w/wormhole.0000.exr | grep -q 'lightcone/spacetime: "interstellar_wormhole(throat=1, length=0.01, lensing_width=0.05)"' ||
  fail "frame 0's spacetime: $(iinfo -v w/wormhole.0000.exr | grep spacetime)"

# An Ellis throat (b = 1) from a static observer at l = 6 through a 60
# degree pinhole, 121 pixels wide: this side's sky grey, the other side's
# orange and blue; on the centre row the other sky spans 2 tan α / tan 30°
# of the width, sin α = 1/√37 (α = 9.46°), within 2 pixels.  Then a sphere
# of radius 0.3 at rest at l = -5 on the axis: the centre pixel meets it
# (hit.kind 3) on its side facing the throat, hit.r = l = -4.7 (to 0.05:
# the sphere is round to first order in its radius over |l| beyond the
# throat, where the chart is compressed: docs/physics.md).
cat >edge.lua <<'LUA'
local lc = require "lightcone"
return {name = "edge", frames = 2, width = 121, height = 61, supersample = 1, frame = function(i)
  return {spacetime = lc.ellis_wormhole{throat = 1}, observer = lc.static_observer{r = 6, theta = 90, phi = 0},
          camera = lc.camera{fov = 60},
          sky = lc.sky_checker{colors = {{0.6, 0.6, 0.6}, {0.3, 0.3, 0.3}}},
          skies = {other_side = lc.sky_checker{colors = {{0.9, 0.45, 0.1}, {0.1, 0.2, 0.6}}}},
          objects = i == 1 and {lc.sphere{radius = 0.3, position = {r = -5, theta = 90, phi = 0}}} or {}}
end}
LUA
CHECKS=$((CHECKS + 1))
"$LIGHTCONE" render edge.lua --out e --layers --progress 0 >edge.out 2>edge.err || fail "edge: $(cat edge.err)"
"$PY" - e/edge.0000.exr e/edge.0001.exr <<'PY' || fail "the throat's edge or the sphere beyond it is off"
import math, sys
import OpenImageIO as oiio
buf = oiio.ImageBuf(sys.argv[1])
W, j = buf.spec().width, buf.spec().height // 2
other = sum(1 for i in range(W) if abs(buf.getpixel(i, j)[0] - buf.getpixel(i, j)[1]) > 0.05)
alpha = math.asin(1 / math.sqrt(37))
want = W * math.tan(alpha) / math.tan(math.radians(30))
print(f"other side's sky: {other} px wide, expected {want:.1f}")
if abs(other - want) > 2:
    sys.exit("edge off")
buf = oiio.ImageBuf(sys.argv[2])
names = list(buf.spec().channelnames)
px = buf.getpixel(W // 2, j)
kind, r = px[names.index("hit.kind")], px[names.index("hit.r")]
print(f"centre pixel: hit.kind {kind}, hit.r {r}")
if kind != 3 or abs(r + 4.7) > 0.05:
    sys.exit("sphere off")
PY

# A sphere flies through: from l = 4 at 0.5 c along the axis, seen by a
# static observer at l = 8.  At t = 24 the light that arrives left it at
# t = 13.3, when it was at l = -2.67, beyond the throat: the pixels that
# meet it have hit.r < -2 (its near side at -2.17 and the rim round it).
cat >fly.lua <<'LUA'
local lc = require "lightcone"
local st = lc.ellis_wormhole{throat = 1}
local w = lc.worldline{spacetime = st, start = {r = 4, theta = 90, phi = 0}, velocity = {r = -0.5, theta = 0, phi = 0},
                       duration = 30}
return {name = "fly", frames = 3, width = 192, height = 108, frame = function(i)
  return {spacetime = st, observer = lc.static_observer{r = 8, theta = 90, phi = 0, t = 12 * i},
          skies = {other_side = lc.sky_checker{colors = {{0.9, 0.45, 0.1}, {0.1, 0.2, 0.6}}}},
          objects = {lc.sphere{radius = 0.5, worldline = w}}}
end}
LUA
CHECKS=$((CHECKS + 1))
"$LIGHTCONE" render fly.lua --out fly --frames 2 --layers --progress 0 >fly.out 2>fly.err || fail "fly: $(cat fly.err)"
"$PY" - fly/fly.0002.exr <<'PY' || fail "the sphere beyond the throat is not seen"
import sys
import OpenImageIO as oiio
buf = oiio.ImageBuf(sys.argv[1])
names = list(buf.spec().channelnames)
k, r = names.index("hit.kind"), names.index("hit.r")
rs = [buf.getpixel(i, j)[r] for j in range(buf.spec().height) for i in range(buf.spec().width) if buf.getpixel(i, j)[k] == 3]
print(f"sphere pixels {len(rs)}, deepest hit.r {min(rs) if rs else None}")
if len(rs) < 5 or min(rs) > -2:
    sys.exit("not beyond")
PY

# inspect writes the other side's sky by its end's name.
CHECKS=$((CHECKS + 1))
"$LIGHTCONE" inspect edge.lua --frames 0 >inspect.json 2>inspect.err || fail "inspect: $(cat inspect.err)"
grep -q '"skies": {"other_side": {"kind": "sky_checker"' inspect.json || fail "inspect: $(cat inspect.json)"

# trace names the end: the centre pixel through the throat, a corner here.
CHECKS=$((CHECKS + 1))
"$LIGHTCONE" trace edge.lua --frame 0 --pixel 60,30 >centre.out 2>&1 || fail "trace: $(cat centre.out)"
grep -q "hit sky at other_side, stop reason escaped" centre.out || fail "trace centre: $(grep hit centre.out)"
"$LIGHTCONE" trace edge.lua --frame 0 --pixel 0,0 >corner.out 2>&1 || fail "trace: $(cat corner.out)"
grep -q "hit sky at infinity, stop reason escaped" corner.out || fail "trace corner: $(grep hit corner.out)"

# The throat's photon orbit: one turn in 2π, l = 0 throughout.
CHECKS=$((CHECKS + 1))
"$LIGHTCONE" geodesic "$SRC/shots/geodesics/ellis_throat_orbit.lua" -o throat.csv 2>throat.log ||
  fail "throat orbit: $(cat throat.log)"
grep -q "stop reason: reached (coordinate time 6.28318" throat.log || fail "throat orbit: $(cat throat.log)"
awk -F, 'NR > 2 { if ($3 < -1e-6 || $3 > 1e-6) { print "l off: " $3; exit 1 } last = $5 }
         END { if (last < 6.2831 || last > 6.2833) { print "final phi " last; exit 1 } }' throat.csv ||
  fail "throat orbit: off"

# The other side's sky image is an input: a new image is refused on resume.
CHECKS=$((CHECKS + 1))
mkdir -p img
"$LIGHTCONE" starfield --width 64 --seed 3 -o img/there.png 2>/dev/null || fail "starfield"
cat >img/two_skies.lua <<'LUA'
local lc = require "lightcone"
return {name = "two_skies", frames = 1, width = 16, height = 9, frame = function()
  return {spacetime = lc.ellis_wormhole{throat = 1}, observer = lc.static_observer{r = 3, theta = 90, phi = 0},
          skies = {other_side = lc.sky_image{file = "there.png"}}} end}
LUA
"$LIGHTCONE" render img/two_skies.lua --out two --progress 0 2>two.log || fail "two skies: $(cat two.log)"
"$LIGHTCONE" starfield --width 64 --seed 4 -o img/there.png 2>/dev/null || fail "starfield"
expect_error changed_sky "other versions of: " -- "$LIGHTCONE" render img/two_skies.lua --out two --progress 0
grep -q "there.png" changed_sky.err || fail "refusal does not name there.png: $(cat changed_sky.err)"

# Bad input at the shot's line, nothing written.
W='spacetime = lc.ellis_wormhole{throat = 1}, observer = lc.static_observer{r = 5, theta = 90, phi = 0}'
refused_scene no_throat 'spacetime = lc.ellis_wormhole{throat = 0}' "throat"
refused_scene flat_mouth 'spacetime = lc.interstellar_wormhole{throat = 1, lensing_width = 0}' "lensing_width"
refused_scene named 'spacetime = lc.wormhole{throat = 1}' "lc.wormhole is no constructor of its own: it is written lc.ellis_wormhole"
refused_scene unknown_end "$W, skies = {other_sid = lc.sky_checker{}}" "ellis_wormhole has these ends with a sky: infinity, other_side"
refused_scene twice "$W, sky = lc.sky_checker{}, skies = {infinity = lc.sky_checker{}}" "given twice"
refused_scene points "$W, skies = {other_side = lc.starfield{}}" "drawn as points on the scene's first sky only"
refused_scene horizon 'spacetime = lc.kerr{mass = 1}, observer = lc.static_observer{r = 10, theta = 90, phi = 0}, skies = {horizon = lc.sky_checker{}}' \
  "'horizon' is a horizon of kerr: no ray that reaches it sees a sky"
refused_scene negative_r 'spacetime = lc.kerr{mass = 1}, observer = lc.static_observer{r = -10, theta = 90, phi = 0}' "r must be > 0, got -10"
e2e_end
