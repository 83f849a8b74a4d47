#!/usr/bin/env bash
# A dome master through the fisheye camera (docs/cameras.md), as a
# planetarium producer would make one from the docs:
#   1. shots/dome_example.lua renders; outside the disc the EXR's hit.kind
#      is "no ray" (5), the colour black and alpha 0, inside it is a ray's
#      with alpha 1.  The same frame rendered by an MPI farm (2 ranks,
#      alpha travelling in the stripes) is the same EXR, byte for byte.
#   2. `trace --pixel` at a corner says "no ray" with no steps and an empty
#      path; at the centre it traces a ray.
#   3. Fewer rays are traced than an image of that size has samples (the
#      corners cost nothing).
#   4. The square frames encode to a square MP4.
#   5. A field or tilt out of range is an error at the shot's line, and
#      nothing is written.
source "$(dirname "$0")/lib.sh"
e2e_begin "$@"
use_mpirun  # lib.sh: Open MPI settings, and `mpi N CMD...`
SHOT="$SRC/shots/dome_example.lua"

# 1. The render, read back.
CHECKS=$((CHECKS + 1))
"$LIGHTCONE" render "$SHOT" --out dome --size 64x64 --layers --progress 0 >render.out 2>render.err ||
  fail "render: $(cat render.err)"
"$PY" - dome/dome_example.0000.exr <<'PY' || fail "the dome master's pixels are not as the fisheye says"
import sys
import OpenImageIO as oiio
buf = oiio.ImageBuf(sys.argv[1])
names = list(buf.spec().channelnames)
if "A" not in names or buf.spec().alpha_channel != names.index("A"):
    sys.exit(f"no alpha channel: {names}")
kind, r, g, b, a = (names.index(n) for n in ("hit.kind", "R", "G", "B", "A"))
W, H = buf.spec().width, buf.spec().height
bad = []
for j in range(H):
    for i in range(W):
        p = buf.getpixel(i, j)
        # The pixel's corners against the disc (radius W/2 about the centre):
        # wholly outside, wholly inside, or on its edge (not checked).
        inside = [(i + a - W / 2) ** 2 + (j + c - H / 2) ** 2 <= (W / 2) ** 2 for a in (0, 1) for c in (0, 1)]
        if not any(inside) and (p[kind] != 5 or p[r] or p[g] or p[b] or p[a]):
            bad.append(f"({i},{j}) outside the disc: kind {p[kind]}, colour {p[r]} {p[g]} {p[b]}, alpha {p[a]}")
        if all(inside) and (p[kind] == 5 or p[a] != 1):
            bad.append(f"({i},{j}) inside the disc: kind {p[kind]}, alpha {p[a]}")
if bad:
    sys.exit("; ".join(bad[:5]))
PY
CHECKS=$((CHECKS + 1))
mpi 2 "$LIGHTCONE" render "$SHOT" --out dome_mpi --size 64x64 --layers --progress 0 >mpi.out 2>mpi.err ||
  fail "render under mpirun -n 2: $(cat mpi.err)"
cmp -s dome/dome_example.0000.exr dome_mpi/dome_example.0000.exr ||
  fail "the MPI farm's dome master differs from the local render's"

# 2. trace at a corner and at the centre.
CHECKS=$((CHECKS + 1))
"$LIGHTCONE" trace "$SHOT" --frame 0 --size 64x64 --pixel 0,0 --json -o corner.csv >corner.json 2>corner.err ||
  fail "trace at a corner: $(cat corner.err)"
"$PY" -c 'import json, sys; d = json.load(open(sys.argv[1])); sys.exit(0 if d["hit"] == "no ray" and d["steps"] == 0 else f"corner: {d}")' corner.json ||
  fail "trace --pixel 0,0 does not say 'no ray'"
[ "$(grep -vc '^#\|^lambda' corner.csv || true)" = 0 ] || fail "trace at a corner wrote a path: $(cat corner.csv)"
"$LIGHTCONE" trace "$SHOT" --frame 0 --size 64x64 --pixel 32,32 --json >centre.json 2>centre.err ||
  fail "trace at the centre: $(cat centre.err)"
"$PY" -c 'import json, sys; d = json.load(open(sys.argv[1])); sys.exit(0 if d["hit"] != "no ray" and d["steps"] > 0 else f"centre: {d}")' centre.json ||
  fail "trace --pixel 32,32 traced no ray"

# 3. The corners cost nothing: the render's count of rays stays below the
# disc's share of the samples plus the adaptive refinement at most.
CHECKS=$((CHECKS + 1))
rays=$(grep -o '[0-9]* rays,' render.err | head -1 | grep -o '[0-9]*')
[ -n "$rays" ] || fail "render printed no ray count: $(cat render.err)"
# 64x64 pixels, 2x2 samples: the whole square would be 16384 samples; the
# disc is pi/4 of it.
[ "${rays:-99999}" -lt 13000 ] || fail "$rays rays for a 64x64 dome master at 2x2: the corners were traced"

# 4. A square MP4.
CHECKS=$((CHECKS + 1))
"$LIGHTCONE" encode dome -o dome.mp4 --fps 30 >encode.out 2>encode.err || fail "encode: $(cat encode.err)"
check_probe dome.mp4 width=64 height=64

# 5. Bad fields, at the shot's line, nothing written.
sed 's/field = 180/field = 400/' "$SHOT" >wide.lua
expect_error wide "wide.lua:20: fisheye: field 'field' must be between 90 and 360" -- "$LIGHTCONE" render wide.lua --out wide --size 32x32
sed 's/tilt = 0/tilt = -5/' "$SHOT" >tilt.lua
expect_error tilt "tilt.lua:20: fisheye: field 'tilt' must be between 0 and 90" -- "$LIGHTCONE" render tilt.lua --out tilt --size 32x32
CHECKS=$((CHECKS + 1))
if ls wide/*.png tilt/*.png >/dev/null 2>&1; then fail "a refused shot wrote frames"; fi

e2e_end
