#!/usr/bin/env bash
# The shipped geodesic examples run through the real binary, and their CSV
# read back agrees with the physics they illustrate.
source "$(dirname "$0")/lib.sh"
e2e_begin "$@"

"$LIGHTCONE" geodesic "$SRC/shots/geodesics/dihole_oscillation.lua" -o dihole.csv 2>dihole.log
grep -q "stop reason: reached" dihole.log || fail "dihole: $(cat dihole.log)"
# The first line records the chart (issue 26): Cartesian for the dihole.
[ "$(head -1 dihole.csv)" = "# chart: cartesian (t, x, y, z; dihole)" ] || fail "dihole: chart line $(head -1 dihole.csv)"
[ "$(sed -n 2p dihole.csv)" = "lambda,x0,x1,x2,x3,u0,u1,u2,u3" ] || fail "dihole: header $(sed -n 2p dihole.csv)"
[ "$(wc -l <dihole.csv)" -eq 2003 ] || fail "dihole: $(wc -l <dihole.csv) lines, want 2003"
# After two periods (t = 2 T = 221.188) the body is back at x = 5, at rest;
# halfway through a period (row 501: t = T/2) it is at x = -5.
awk -F, 'NR == 2003 { if ($2 < 221.187 || $2 > 221.189 || $3 < 4.9999 || $3 > 5.0001) { print "end row " $0; exit 1 } }
         NR == 503  { if ($3 > -4.9999 || $3 < -5.0001) { print "half row " $0; exit 1 } }' dihole.csv \
  || fail "dihole: oscillation rows off"

"$LIGHTCONE" geodesic "$SRC/shots/geodesics/isco_precession.lua" -o isco.csv 2>isco.log
[ "$(head -1 isco.csv)" = "# chart: bl (t, r, theta, phi; kerr)" ] || fail "isco: chart line $(head -1 isco.csv)"
[ "$(sed -n 2p isco.csv | tr ',' '\n' | wc -l)" -eq 25 ] || fail "isco: expected 25 columns with the tetrad"
# Stays on r = 6 at the equator, and phi (unwrapped) reaches 2 pi after one orbit.
awk -F, 'NR > 2 { if ($3 < 5.9999999 || $3 > 6.0000001) { print "r off: " $3; exit 1 } last = $5 }
         END { if (last < 6.2831 || last > 6.2833) { print "final phi " last; exit 1 } }' isco.csv || fail "isco: orbit off"

# A charged hole (Reissner–Nordström, Q = 0.8): a circular orbit at r = 6
# closes after the coordinate time 2 pi r^2 / sqrt(M r - Q^2) = 97.701 M.
"$LIGHTCONE" geodesic "$SRC/shots/geodesics/reissner_nordstrom_orbit.lua" -o rn.csv 2>rn.log
grep -q "stop reason: reached (coordinate time 97.70" rn.log || fail "rn orbit: $(cat rn.log)"
awk -F, 'NR > 2 { if ($3 < 5.9999999 || $3 > 6.0000001) { print "r off: " $3; exit 1 } last = $5 }
         END { if (last < 6.2831 || last > 6.2833) { print "final phi " last; exit 1 } }' rn.csv || fail "rn orbit: off"

# Three holes in a triangle (Majumdar–Papapetrou): the body on the axis is
# back at z = 4 after two periods of the energy integral (2 T = 183.8393,
# proper 128.2582) and at z = -4 half a period in (row 503: t = T/2).
"$LIGHTCONE" geodesic "$SRC/shots/geodesics/triangle_swing.lua" -o triangle.csv 2>triangle.log
grep -q "stop reason: reached (coordinate time 183.839" triangle.log || fail "triangle: $(cat triangle.log)"
[ "$(head -1 triangle.csv)" = "# chart: cartesian (t, x, y, z; majumdar_papapetrou)" ] || fail "triangle: chart line $(head -1 triangle.csv)"
awk -F, 'NR == 2003 { if ($1 < 128.2581 || $1 > 128.2583 || $5 < 3.9999 || $5 > 4.0001) { print "end row " $0; exit 1 } }
         NR == 503  { if ($5 > -3.9999 || $5 < -4.0001) { print "half row " $0; exit 1 } }
         NR > 2 { if ($3 > 1e-9 || $3 < -1e-9 || $4 > 1e-9 || $4 < -1e-9) { print "off the axis " $0; exit 1 } }' triangle.csv \
  || fail "triangle: swing rows off"

"$LIGHTCONE" geodesic "$SRC/shots/geodesics/kerr_ray_bundle.lua" -o bundle.csv 2>bundle.log
[ "$(sed -n 2p bundle.csv | cut -d, -f1)" = "ray" ] || fail "bundle: no ray column"
[ "$(cut -d, -f1 bundle.csv | sort -u | grep -c '^[0-9]')" -eq 21 ] || fail "bundle: want 21 rays"
grep -q "stop reason: horizon" bundle.log || fail "bundle: no captured ray"
grep -q "stop reason: reached" bundle.log || fail "bundle: no passing ray"

# A bundle's rays are in one chart: a Kerr ray and a dihole ray are refused,
# naming both, with no file.
cat >mixed.lua <<'LUA'
local lc = require "lightcone"
local kerr = {spacetime = lc.kerr{mass = 1}, curve = "null", start = {r = 10, theta = 90, phi = 0},
              direction = {r = -1}, stop = {affine = 5}}
local dihole = {spacetime = lc.dihole{m1 = 1, m2 = 1}, curve = "null", start = {x = 5, y = 0, z = 0},
                direction = {x = -1}, stop = {affine = 5}}
return {kerr, dihole}
LUA
"$LIGHTCONE" geodesic mixed.lua -o mixed.csv 2>mixed.log && fail "a bundle of two charts was accepted"
grep -q "mixed.lua: all rays of a bundle must be in one scene chart (the CSV records one): ray 1 is in kerr (bl), ray 2 in dihole (cartesian)" mixed.log \
  || fail "mixed bundle: $(cat mixed.log)"
[ ! -e mixed.csv ] || fail "a refused bundle left a file"

# Standard output when no -o is given.
"$LIGHTCONE" geodesic "$SRC/shots/geodesics/isco_precession.lua" >stdout.csv 2>/dev/null
cmp -s stdout.csv isco.csv || fail "stdout output differs from -o output"

"$LIGHTCONE" --version | grep -q '^lightcone [0-9]' || fail "--version"
for sub in geodesic bench; do
  "$LIGHTCONE" "$sub" --help | grep -qi usage || fail "$sub --help"
done
e2e_end
