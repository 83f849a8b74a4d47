#!/usr/bin/env bash
# Majumdar–Papapetrou holes through the real binary: the shipped triangle
# and square render with their holes named in the frame files; seen from
# above, the square's four shadows stand apart; two holes on the z axis
# render as the paper's dihole; bad holes are refused at the shot's line
# with nothing written.
source "$(dirname "$0")/lib.sh"
e2e_begin "$@"

CHECKS=$((CHECKS + 1))
"$LIGHTCONE" render "$SRC/shots/three_holes.lua" --out tri --size 64x36 --frames 0 --progress 0 >tri.out 2>tri.err ||
  fail "three_holes: $(cat tri.err)"
iinfo -v tri/three_holes.0000.exr | grep -q 'lightcone/spacetime: "majumdar_papapetrou(holes={0.3 at (1.5, 0, 0), 0.3 at (-0.75, 1.29904, 0), 0.3 at (-0.75, -1.29904, 0)})"' ||
  fail "three_holes' spacetime: $(iinfo -v tri/three_holes.0000.exr | grep spacetime)"

# The square from 85 degrees above its plane: four separate shadows
# (connected regions of hit.kind 2 larger than 40 pixels: each hole's is
# ~1 M across, ~150 pixels here; the smaller ones are the shadows' lensed
# images near the other holes), and the sphere (3) between them.
CHECKS=$((CHECKS + 1))
"$LIGHTCONE" render "$SRC/shots/four_holes.lua" --out sq --size 96x54 --frames 299 --layers --progress 0 >sq.out 2>sq.err ||
  fail "four_holes: $(cat sq.err)"
"$PY" - sq/four_holes.0299.exr <<'PY' || fail "four_holes from above: not four shadows and a sphere"
import sys
import OpenImageIO as oiio
buf = oiio.ImageBuf(sys.argv[1])
spec = buf.spec()
k = list(spec.channelnames).index("hit.kind")
W, H = spec.width, spec.height
kind = [[buf.getpixel(i, j)[k] for i in range(W)] for j in range(H)]
seen, regions = set(), 0
for j in range(H):
    for i in range(W):
        if kind[j][i] != 2 or (i, j) in seen:
            continue
        size = 0
        stack = [(i, j)]
        seen.add((i, j))
        while stack:
            a, b = stack.pop()
            size += 1
            for c, d in ((a + 1, b), (a - 1, b), (a, b + 1), (a, b - 1)):
                if 0 <= c < W and 0 <= d < H and (c, d) not in seen and kind[d][c] == 2:
                    seen.add((c, d))
                    stack.append((c, d))
        regions += size > 40
sphere = sum(row.count(3) for row in kind)
print(f"{regions} shadows, {sphere} sphere pixels")
if regions != 4 or sphere == 0:
    sys.exit(f"{regions} shadows and {sphere} sphere pixels; want 4 and some")
PY

# Two holes of 0.4 on the z axis at +-1 are the dihole: the paper's bench
# view (the sphere at (5, 0, 0), seen from (0, 80, 0)) in both.  Not bit for
# bit (the general sum rounds otherwise): the same hit in all but a few
# pixels on an edge, and colours within 1e-3 on average.
CHECKS=$((CHECKS + 1))
for kind in dihole mp; do
  cat >$kind.lua <<LUA
local lc = require "lightcone"
local holes = "$kind" == "dihole" and lc.dihole{m1 = 0.4, m2 = 0.4, d = 1}
  or lc.majumdar_papapetrou{holes = {{mass = 0.4, position = {x = 0, y = 0, z = 1}},
                                     {mass = 0.4, position = {x = 0, y = 0, z = -1}}}}
return {name = "$kind", frames = 1, width = 64, height = 64, frame = function()
  return {spacetime = holes, observer = lc.static_observer{x = 0, y = 80, z = 0}, camera = lc.camera{fov = 12},
          sky = lc.sky_checker{rows = 36, columns = 72},
          objects = {lc.sphere{radius = 1, position = {x = 5, y = 0, z = 0}}}}
end}
LUA
  "$LIGHTCONE" render $kind.lua --out $kind --layers --progress 0 >$kind.out 2>$kind.err || fail "$kind: $(cat $kind.err)"
done
"$PY" - dihole/dihole.0000.exr mp/mp.0000.exr <<'PY' || fail "two holes on the axis did not render as the dihole"
import sys
import OpenImageIO as oiio
a, b = oiio.ImageBuf(sys.argv[1]), oiio.ImageBuf(sys.argv[2])
names = list(a.spec().channelnames)
k, rgb = names.index("hit.kind"), [names.index(c) for c in "RGB"]
W, H = a.spec().width, a.spec().height
differ, total = 0, 0.0
for j in range(H):
    for i in range(W):
        pa, pb = a.getpixel(i, j), b.getpixel(i, j)
        differ += pa[k] != pb[k]
        total += sum(abs(pa[c] - pb[c]) for c in rgb) / 3
mean = total / (W * H)
print(f"{differ} of {W * H} pixels hit another kind; mean colour difference {mean:.2e}")
if differ > 4 or mean > 1e-3:
    sys.exit("too different")
PY

# Bad holes: at the shot's line, the reason, no frame files.
bad() {  # name, holes table, expected message part
  cat >$1.lua <<LUA
local lc = require "lightcone"
local holes = lc.majumdar_papapetrou{holes = $2}
return {name = "$1", frames = 1, frame = function() return {spacetime = holes} end}
LUA
  expect_refused_at "$1" 2 "$3"
}
bad massless '{{mass = 0, position = {x = 0, y = 0, z = 0}}}' "hole 1's mass must be a number > 0, got 0"
bad together '{{mass = 1, position = {x = 0, y = 0, z = 0}}, {mass = 1, position = {x = 0, y = 0, z = 0}}}' \
  "holes 1 and 2 are 0 apart, inside each other's capture spheres"
bad none '{}' "must list at least one hole"
bad nowhere '{{mass = 1}}' "position"
bad many "{$(for i in $(seq 17); do printf '{mass = 0.1, position = {x = %d, y = 0, z = 0}}, ' $i; done)}" "at most 16 holes, got 17"
e2e_end
