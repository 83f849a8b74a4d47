#!/usr/bin/env bash
# Every file a frame reads is one of its inputs (issue 25, defect 8): a star
# catalogue named by LIGHTCONE_STAR_CATALOGUE that changes after frames were
# rendered makes a resume refuse (naming the catalogue) instead of keeping
# the old frames without a word; --force renders them again, with the new
# stars; encode then takes the frames as current.
source "$(dirname "$0")/lib.sh"
e2e_begin "$@"

# star LINE: a KStars stars.dat line (RA, Dec, V, B-V in their columns).
star() { printf '%s %s -000546.0-001223.100379.2 %s%sA0 1\n' "$1" "$2" "$3" "$4"; }
{ star 064508.92 -164258.0 -1.44 00.01; star 002000.00 +100000.0 00.03 -0.00; } >stars.dat
cat >catalogue.lua <<'LUA'
local lc = require "lightcone"
return {name = "catalogue", frames = 2, width = 32, height = 18,
  frame = function(i)
    return {spacetime = lc.kerr{mass = 1, spin = 0.9},
            observer = lc.static_observer{r = 30, theta = 90, phi = 0},
            camera = lc.camera{fov = 60, yaw = 180},
            sky = lc.starfield{catalogue = "kstars", background = "none"}}
  end}
LUA
export LIGHTCONE_STAR_CATALOGUE="$WORK/stars.dat"
"$LIGHTCONE" render catalogue.lua --out out --frames 0 --progress 0 2>r1.log || fail "render: $(cat r1.log)"
cp out/catalogue.0000.exr before.exr
# The second star made brighter by two magnitudes.
{ star 064508.92 -164258.0 -1.44 00.01; star 002000.00 +100000.0 -1.97 -0.00; } >stars.dat
expect_error changed "frame 0 was rendered from other versions of: $WORK/stars.dat" -- \
  "$LIGHTCONE" render catalogue.lua --out out --progress 0
cmp -s before.exr out/catalogue.0000.exr || fail "the refused resume changed frame 0"
[ ! -e out/catalogue.0001.png ] || fail "the refused resume rendered frame 1"
"$LIGHTCONE" render catalogue.lua --out out --force --progress 0 2>r2.log || fail "--force: $(cat r2.log)"
cmp -s before.exr out/catalogue.0000.exr && fail "frame 0 was not rendered again with the new catalogue"
"$LIGHTCONE" encode out -o film.mp4 2>enc.log || fail "encode after --force: $(cat enc.log)"
# The catalogue named at another path, with other stars: the refusal names
# it (issue 43; it said "other inputs (the script, its modules or sky
# images)").
"$LIGHTCONE" render catalogue.lua --out moved --frames 0 --progress 0 2>m1.log || fail "moved: $(cat m1.log)"
{ star 064508.92 -164258.0 -1.44 00.01; star 002000.00 +100000.0 00.03 -0.00; } >other.dat
LIGHTCONE_STAR_CATALOGUE="$WORK/other.dat" expect_error moved \
  "frame 0 was rendered from other files than this render reads: $WORK/other.dat was not among them" -- \
  "$LIGHTCONE" render catalogue.lua --out moved --progress 0
echo "render_inputs: $CHECKS error checks, $FAILURES failures"
[ "$FAILURES" -eq 0 ]
