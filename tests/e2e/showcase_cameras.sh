#!/usr/bin/env bash
# The paper's film for a dome and a headset (docs/showcase.md), at a tiny
# preview (a frame every 4 s of story):
#   1. showcase --camera dome --png-depth 16: square clips and film; the
#      frames are dome masters (the corners transparent in the EXRs, the
#      journal says the camera and the PNGs' depth); the hole of the disk's first frame is in the lower half of
#      the disc (above the dome's front horizon), not at its centre; the
#      title cards are drawn inside the disc (black corners, the text in
#      its lower half, none at the zenith); trace --camera dome finds the
#      shadow at the hole's pixel.
#   2. showcase --camera 360: 2:1 clips and film, each sequence's video and
#      the film marked as 360-degree video, the frames' EXRs record the
#      projection.
#   3. A camera the showcase does not know is refused.
source "$(dirname "$0")/lib.sh"
e2e_begin "$@"
ARGS=(--rate 0.25 --progress 0)

# 1. The dome.
CHECKS=$((CHECKS + 1))
"$LIGHTCONE" showcase "${ARGS[@]}" --camera dome --size 192x192 --png-depth 16 --out dome 2>dome.log || fail "showcase --camera dome: $(cat dome.log)"
check_probe dome/showcase.mp4 width=192 height=192
grep -q " png_depth=16 camera=dome " dome/frames/kerr_accrDisk/kerr_accrDisk.journal || fail "the journal does not say the dome camera and the 16-bit PNGs: $(tail -1 dome/frames/kerr_accrDisk/kerr_accrDisk.journal)"
"$PY" - dome/frames/kerr_accrDisk/kerr_accrDisk.0000.exr <<'PY' || fail "the dome's first frame is not a dome master framed for a dome"
import sys
import OpenImageIO as oiio
buf = oiio.ImageBuf(sys.argv[1])
names = list(buf.spec().channelnames)
if "A" not in names: sys.exit(f"no alpha: {names}")
W, H = buf.spec().width, buf.spec().height
if buf.getpixel(0, 0)[names.index("A")] != 0: sys.exit("a corner is not transparent")
# The shadow (hit.kind 2): its centre below the disc's centre by about
# sin(55)/(90/55)... i.e. 55/90 of the radius (the hole 35 degrees above
# the front horizon), within a few pixels.
kind = names.index("hit.kind")
pts = [(i, j) for j in range(H) for i in range(W) if buf.getpixel(i, j)[kind] == 2]
if not pts: sys.exit("no shadow in the dome's first frame")
cy = sum(j + 0.5 for _, j in pts) / len(pts)
want = H / 2 + 55 / 90 * H / 2
if abs(cy - want) > 4: sys.exit(f"the shadow's centre is at row {cy:.1f}, want about {want:.1f} (35 degrees above the front horizon)")
PY
# trace --camera dome looks at the same frame: the pixel at the hole's
# place (55/90 of the radius below the centre) is the shadow.
"$LIGHTCONE" trace "$SRC/shots/kerr_accrDisk.lua" --frame 0 --camera dome --size 192x192 --pixel 96,154 --json \
  >hole.json 2>hole.err || fail "trace --camera dome: $(cat hole.err)"
"$PY" -c 'import json, sys; d = json.load(open(sys.argv[1])); sys.exit(0 if d["hit"] == "horizon" else f"{d}")' hole.json ||
  fail "trace --camera dome at the hole's pixel did not reach the horizon: $(cat hole.json)"
ffmpeg -v error -i dome/cards/opening.mp4 -frames:v 1 -y card.png || fail "cannot decode the dome's opening card"
"$PY" - card.png <<'PY' || fail "the dome's title card is not drawn inside the disc where a dome shows it"
import sys
import OpenImageIO as oiio
buf = oiio.ImageBuf(sys.argv[1])
W, H = buf.spec().width, buf.spec().height
corner = max(buf.getpixel(1, 1)[:3])
if corner > 0.03: sys.exit(f"a corner is {corner}, not black")
lit = [(i, j) for j in range(H) for i in range(W) if min(buf.getpixel(i, j)[:3]) > 0.5]
if not lit: sys.exit("no text")
if min(j for _, j in lit) < H / 2: sys.exit("text above the disc's centre (towards the zenith)")
PY

# 2. The 360-degree film.
CHECKS=$((CHECKS + 1))
"$LIGHTCONE" showcase "${ARGS[@]}" --camera 360 --size 128x64 --out vr 2>vr.log || fail "showcase --camera 360: $(cat vr.log)"
check_probe vr/showcase.mp4 width=128 height=64
for video in vr/showcase.mp4 vr/dihole.mp4; do
  side=$(ffprobe -v error -show_entries stream_side_data=projection -of default=nw=1 "$video" 2>&1)
  grep -qx "projection=equirectangular" <<<"$side" || fail "$video is not marked as a 360-degree video: $side"
done
"$PY" -c 'import sys, OpenImageIO as o; b = o.ImageBuf(sys.argv[1]); sys.exit(0 if b.spec().getattribute("lightcone/projection") == "equirectangular" else "no projection")' \
  vr/frames/dihole/dihole.0000.exr || fail "the 360 frames do not record their projection"

# 3. A camera it does not know.
expect_error camera "--camera: fisheye not in {shot,dome,360}" -- "$LIGHTCONE" showcase --camera fisheye --out bad
CHECKS=$((CHECKS + 1))
[ ! -e bad ] || fail "a refused showcase left bad/ behind"

e2e_end
