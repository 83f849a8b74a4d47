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
#   6. --region renders a window of the master: with every sample taken
#      (--full-supersample: adaptive sampling compares a pixel with row
#      neighbours the window may lack) its pixels are the whole render's
#      (the data layers exactly; the colour but for star light within a
#      pixel of the window's edge and glare of stars outside it),
#      the EXR and the journal say which window; a window outside the frame
#      is refused naming the frame's size, nothing written.  --png-depth 16
#      writes 16-bit PNGs; --png-depth 12 and --camera fisheye (render and
#      trace) are refused.
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

# 6. A window, and 16-bit PNGs.
CHECKS=$((CHECKS + 1))
"$LIGHTCONE" render "$SHOT" --out whole --size 64x64 --layers --full-supersample --progress 0 >whole.out 2>whole.err ||
  fail "render the whole master: $(cat whole.err)"
"$LIGHTCONE" render "$SHOT" --out window --size 64x64 --region 8,40,40,56 --layers --full-supersample --png-depth 16 \
  --progress 0 >window.out 2>window.err || fail "render --region: $(cat window.err)"
grep -q "at 32x16 (pixels 8,40 to 40,56 of the 64x64 frame)" window.err || fail "render did not say the window: $(cat window.err)"
grep -q " region=8,40,64x64 " window/dome_example.journal || fail "the journal lacks the window: $(tail -1 window/dome_example.journal)"
"$PY" - whole/dome_example.0000.exr window/dome_example.0000.exr window/dome_example.0000.png <<'PY' || fail "the window is not the whole frame's pixels"
import sys
import OpenImageIO as oiio
whole, part = oiio.ImageBuf(sys.argv[1]), oiio.ImageBuf(sys.argv[2])
if part.spec().getattribute("lightcone/region") != "8,40,40,56 of 64x64":
    sys.exit(f"lightcone/region is {part.spec().getattribute('lightcone/region')!r}")
wn, pn = list(whole.spec().channelnames), list(part.spec().channelnames)
for name in pn:
    for j in range(16):
        for i in range(32):
            a, b = whole.getpixel(8 + i, 40 + j)[wn.index(name)], part.getpixel(i, j)[pn.index(name)]
            inner = 0 < i < 31 and 0 < j < 15
            if name.startswith("hit.") or name == "A":
                if a != b: sys.exit(f"{name} at ({i},{j}): {b}, the whole frame has {a}")
            elif abs(a - b) > (1e-3 if inner else 5e-3):
                sys.exit(f"{name} at ({i},{j}): {b}, the whole frame has {a}")
png = oiio.ImageInput.open(sys.argv[3])
if png.spec().format != oiio.UINT16:
    sys.exit(f"the PNG is {png.spec().format}, not 16-bit")
PY
expect_error outside "--region 0,0,65,10: reaches outside the 64x64 frame" -- \
  "$LIGHTCONE" render "$SHOT" --out outside --size 64x64 --region 0,0,65,10
expect_error depth "--png-depth: '12' is not a PNG depth: give the bits per channel as the integer 8 or 16" -- "$LIGHTCONE" render "$SHOT" --out depth --size 32x32 --png-depth 12
expect_error camera "--camera: fisheye not in {shot,dome,360,ods}" -- "$LIGHTCONE" render "$SHOT" --out camera --camera fisheye
expect_error trace_camera "--camera: fisheye not in {shot,dome,360,ods}" -- \
  "$LIGHTCONE" trace "$SHOT" --frame 0 --pixel 1,1 --camera fisheye
CHECKS=$((CHECKS + 1))
if ls outside/*.png depth/*.png camera/*.png >/dev/null 2>&1; then fail "a refused render wrote frames"; fi

e2e_end
