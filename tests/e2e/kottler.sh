#!/usr/bin/env bash
# A hole in a universe with a cosmological constant (lc.kottler) through
# the real binary: shots/kottler.lua's first and last frames render, their
# shadows shrink as Perlick et al.'s formula says, their sky's light is the
# ratio of the static lapses; escaping rays end at the cosmological horizon
# in render, trace and geodesic alike; the photon sphere is at 3M; bad
# input is refused at the shot's line.
source "$(dirname "$0")/lib.sh"
e2e_begin "$@"

SHOT="$SRC/shots/kottler.lua"
CHECKS=$((CHECKS + 1))
"$LIGHTCONE" render "$SHOT" --out k --size 96x54 --frames 0:239:239 --layers --progress 0 >render.out 2>render.err ||
  fail "render: $(cat render.err)"
iinfo -v k/kottler.0239.exr | grep -q 'lightcone/spacetime: "kottler(mass=1, lambda=0.05)"' ||
  fail "frame 239's spacetime: $(iinfo -v k/kottler.0239.exr | grep spacetime)"

# The shadow's width on the centre row (hit.kind 2) against 2 tan(α) of a
# 110 degree pinhole, sin^2 α = 27 F(r_o) / (r_o^2 (1 - 9Λ)) at r_o = 6
# (M = 1): α = 44.9° at Λ = 1e-6, 17.5° at Λ = 0.05, within 2 pixels; the
# sky's g is sqrt(F(r_s) / F(r_o)), r_s = (3/Λ)^(1/3), to 1e-5.
CHECKS=$((CHECKS + 1))
"$PY" - k/kottler.0000.exr k/kottler.0239.exr <<'PY' || fail "the shadow or the sky's light is off"
import math, sys
import OpenImageIO as oiio
def F(lam, r): return 1 - 2 / r - lam * r * r / 3
for path, lam in zip(sys.argv[1:], (1e-6, 0.05)):
    buf = oiio.ImageBuf(path)
    names = list(buf.spec().channelnames)
    k, g = names.index("hit.kind"), names.index("hit.g")
    W, j = buf.spec().width, buf.spec().height // 2
    width = sum(1 for i in range(W) if buf.getpixel(i, j)[k] == 2)
    alpha = math.asin(math.sqrt(27 * F(lam, 6) / (36 * (1 - 9 * lam))))
    want = W * math.tan(alpha) / math.tan(math.radians(55))
    sky_g = buf.getpixel(0, 0)[g]
    want_g = math.sqrt(F(lam, (3 / lam) ** (1 / 3)) / F(lam, 6))
    print(f"Λ {lam}: shadow {width} px, expected {want:.1f}; sky g {sky_g:.6f}, expected {want_g:.6f}")
    if abs(width - want) > 2 or abs(sky_g - want_g) > 1e-5 * want_g:
        sys.exit("off")
PY

# The outer stop rule, in trace and geodesic: a sky pixel and a ray sent
# straight out end at the cosmological horizon.
CHECKS=$((CHECKS + 1))
"$LIGHTCONE" trace "$SHOT" --frame 239 --pixel 5,5 --size 96x54 >trace.out 2>&1 || fail "trace: $(cat trace.out)"
grep -q "hit sky at cosmological horizon, stop reason escaped" trace.out || fail "trace: $(grep trace: trace.out)"
cat >out.lua <<'LUA'
local lc = require "lightcone"
return {spacetime = lc.kottler{mass = 1, lambda = 0.01}, curve = "null", start = {t = 0, r = 6, theta = 90, phi = 0},
        direction = {r = 1}, stop = {affine = 1000}}
LUA
"$LIGHTCONE" geodesic out.lua -o out.csv 2>out.log || fail "geodesic: $(cat out.log)"
grep -q "stop reason: escaped (to cosmological horizon)" out.log || fail "geodesic out: $(cat out.log)"

# The photon sphere at 3M (Λ = 0.05): one turn, r = 3 throughout.
CHECKS=$((CHECKS + 1))
"$LIGHTCONE" geodesic "$SRC/shots/geodesics/kottler_photon_sphere.lua" -o sphere.csv 2>sphere.log ||
  fail "photon sphere: $(cat sphere.log)"
grep -q "stop reason: reached (coordinate time 44.023" sphere.log || fail "photon sphere: $(cat sphere.log)"
awk -F, 'NR > 2 { if ($3 < 2.999999 || $3 > 3.000001) { print "r off: " $3; exit 1 } last = $5 }
         END { if (last < 6.2831 || last > 6.2833) { print "final phi " last; exit 1 } }' sphere.csv ||
  fail "photon sphere: off"

# Bad input at the shot's line, nothing written.
refused_scene beyond 'spacetime = lc.kottler{mass = 1, lambda = 0.01}, observer = lc.static_observer{r = 20, theta = 90, phi = 0}' \
  "the position is on or beyond the cosmological horizon, where nothing can stay at rest"
refused_scene inside 'spacetime = lc.kottler{mass = 1, lambda = 0.01}, observer = lc.static_observer{r = 1.5, theta = 90, phi = 0}' \
  "inside the hole's horizon"
refused_scene crowded 'spacetime = lc.kottler{mass = 1, lambda = 0.2}' "no static region between the horizons"
refused_scene flat 'spacetime = lc.kottler{mass = 1, lambda = 0}' "lambda = 0 is Schwarzschild: lc.kerr{mass = 1}"
refused_scene named 'spacetime = lc.schwarzschild_de_sitter{mass = 1, lambda = 0.01}' \
  "lc.schwarzschild_de_sitter is no constructor of its own: it is written lc.kottler{mass = M, lambda = L}"
e2e_end
