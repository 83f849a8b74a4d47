#!/usr/bin/env bash
# A frame's picture depends only on the shot's files and its number (issue
# 25, defect 2): a shot that keeps state between frame(i) calls (a global
# counter, an upvalue, "the first frame I saw") renders the same frames
# whole, as a sub-range, resumed from a later frame and under mpirun.
source "$(dirname "$0")/lib.sh"
e2e_begin "$@"
use_mpirun

cat >stateful.lua <<'LUA'
local lc = require "lightcone"
local calls = 0
return {name = "stateful", frames = 6, fps = 24, width = 32, height = 18,
  frame = function(i)
    counter = (counter or 0) + 1
    calls = calls + 1
    first = first or i
    return {spacetime = lc.kerr{mass = 1, spin = 0.9},
            observer = lc.static_observer{r = 30, theta = 70, phi = 0},
            camera = lc.camera{fov = 50, yaw = counter * 5 + calls + (i - first) * 7},
            disk = lc.disk{inner = 6, outer = 14}}
  end}
LUA
"$LIGHTCONE" render stateful.lua --out whole --threads 2 --progress 0 2>whole.log || fail "whole: $(cat whole.log)"
"$LIGHTCONE" render stateful.lua --out part --frames 3:5 --threads 1 --progress 0 2>part.log || fail "part: $(cat part.log)"
"$LIGHTCONE" render stateful.lua --out resumed --frames 4:5 --progress 0 2>r1.log || fail "resume 1: $(cat r1.log)"
"$LIGHTCONE" render stateful.lua --out resumed --progress 0 2>r2.log || fail "resume 2: $(cat r2.log)"
mpi 3 "$LIGHTCONE" render stateful.lua --out mpi --progress 0 2>mpi.log || fail "mpirun: $(cat mpi.log)"
for i in 0 1 2 3 4 5; do
  f=$(printf 'stateful.%04d.png' "$i")
  for dir in part resumed mpi; do
    [ "$dir" = part ] && [ "$i" -lt 3 ] && continue
    cmp -s "whole/$f" "$dir/$f" || fail "$dir/$f differs from the whole render's"
  done
done
# Every frame sees the same scene: the yaw is 5 + 1 + 0 in each.
cmp -s whole/stateful.0000.png whole/stateful.0005.png || fail "frames 0 and 5 differ: state was kept between frames"
echo "frame_independence: $FAILURES failures"
[ "$FAILURES" -eq 0 ]
