#!/usr/bin/env bash
# The shipped geodesic examples run through the real binary, and their CSV
# read back agrees with the physics they illustrate.
source "$(dirname "$0")/lib.sh"
e2e_begin "$@"

"$LIGHTCONE" geodesic "$SRC/shots/geodesics/dihole_oscillation.lua" -o dihole.csv 2>dihole.log
grep -q "stop reason: reached" dihole.log || fail "dihole: $(cat dihole.log)"
[ "$(head -1 dihole.csv)" = "lambda,x0,x1,x2,x3,u0,u1,u2,u3" ] || fail "dihole: header $(head -1 dihole.csv)"
[ "$(wc -l <dihole.csv)" -eq 2002 ] || fail "dihole: $(wc -l <dihole.csv) lines, want 2002"
# After two periods (t = 2 T = 221.188) the body is back at x = 5, at rest;
# halfway through a period (row 501: t = T/2) it is at x = -5.
awk -F, 'NR == 2002 { if ($2 < 221.187 || $2 > 221.189 || $3 < 4.9999 || $3 > 5.0001) { print "end row " $0; exit 1 } }
         NR == 502  { if ($3 > -4.9999 || $3 < -5.0001) { print "half row " $0; exit 1 } }' dihole.csv \
  || fail "dihole: oscillation rows off"

"$LIGHTCONE" geodesic "$SRC/shots/geodesics/isco_precession.lua" -o isco.csv 2>isco.log
[ "$(head -1 isco.csv | tr ',' '\n' | wc -l)" -eq 25 ] || fail "isco: expected 25 columns with the tetrad"
# Stays on r = 6 at the equator, and phi (unwrapped) reaches 2 pi after one orbit.
awk -F, 'NR > 1 { if ($3 < 5.9999999 || $3 > 6.0000001) { print "r off: " $3; exit 1 } last = $5 }
         END { if (last < 6.2831 || last > 6.2833) { print "final phi " last; exit 1 } }' isco.csv || fail "isco: orbit off"

"$LIGHTCONE" geodesic "$SRC/shots/geodesics/kerr_ray_bundle.lua" -o bundle.csv 2>bundle.log
[ "$(head -1 bundle.csv | cut -d, -f1)" = "ray" ] || fail "bundle: no ray column"
[ "$(cut -d, -f1 bundle.csv | sort -u | grep -c '^[0-9]')" -eq 21 ] || fail "bundle: want 21 rays"
grep -q "stop reason: horizon" bundle.log || fail "bundle: no captured ray"
grep -q "stop reason: reached" bundle.log || fail "bundle: no passing ray"

# Standard output when no -o is given.
"$LIGHTCONE" geodesic "$SRC/shots/geodesics/isco_precession.lua" >stdout.csv 2>/dev/null
cmp -s stdout.csv isco.csv || fail "stdout output differs from -o output"

"$LIGHTCONE" --version | grep -q '^lightcone [0-9]' || fail "--version"
for sub in geodesic bench; do
  "$LIGHTCONE" "$sub" --help | grep -qi usage || fail "$sub --help"
done
e2e_end
