#!/usr/bin/env bash
# A 360-degree video through the equirectangular camera (docs/cameras.md),
# as a producer for headsets and video sites would make one from the docs:
#   1. shots/equirect_example.lua renders at 2:1 with no warning; the EXR
#      records the projection; every pixel has a ray (no alpha channel);
#      the frame is seamless: its last and first columns differ no more
#      than neighbouring columns do.
#   2. The encoded MP4 carries the spherical video metadata: ffprobe reports
#      the equirectangular mapping, and the file holds Google's sv3d box.
#   3. A frame that is not 2:1 renders with a warning that says what size
#      it should be; a window of the sphere encodes as a flat video.
#   4. Omnidirectional stereo (stereo = "top-bottom"): a square frame of two
#      2:1 pictures whose MP4 carries the stereo layout beside the
#      spherical mapping; a stereo pinhole side by side says so too.
#   5. A span out of range, a separation of 0 and a side-by-side sphere are
#      errors at the shot's line, a --region of a stereo frame an error
#      naming the flag; nothing written.
source "$(dirname "$0")/lib.sh"
e2e_begin "$@"
SHOT="$SRC/shots/equirect_example.lua"

# 1. The render, read back.
CHECKS=$((CHECKS + 1))
"$LIGHTCONE" render "$SHOT" --out vr --size 128x64 --progress 0 >render.out 2>render.err || fail "render: $(cat render.err)"
if grep -q "warning" render.err; then fail "a 2:1 frame was warned about: $(cat render.err)"; fi
"$PY" - vr/equirect_example.0000.exr <<'PY' || fail "the 360-degree frame is not as the camera says"
import sys
import OpenImageIO as oiio
buf = oiio.ImageBuf(sys.argv[1])
spec = buf.spec()
if spec.getattribute("lightcone/projection") != "equirectangular":
    sys.exit(f"lightcone/projection is {spec.getattribute('lightcone/projection')!r}")
if "A" in list(spec.channelnames):
    sys.exit("an alpha channel: every pixel of a whole sphere has a ray")
W, H = spec.width, spec.height
px = [[buf.getpixel(i, j) for i in range(W)] for j in range(H)]
def column_step(a, b):  # mean |difference| of two columns' colours
    return sum(abs(px[j][a][c] - px[j][b][c]) for j in range(H) for c in range(3)) / (3 * H)
steps = sorted(column_step(i, i + 1) for i in range(W - 1))
seam = column_step(W - 1, 0)
if seam > steps[-1]:
    sys.exit(f"the seam differs by {seam:.4f}, more than any neighbouring columns ({steps[-1]:.4f})")
PY

# 2. Encoded, marked for players.
CHECKS=$((CHECKS + 1))
"$LIGHTCONE" encode vr -o vr.mp4 >encode.out 2>encode.err || fail "encode: $(cat encode.err)"
grep -q "equirectangular 360-degree video" encode.err || fail "encode did not say the video is a 360-degree one: $(cat encode.err)"
side=$(ffprobe -v error -show_entries stream_side_data=side_data_type,projection -of default=nw=1 vr.mp4 2>&1)
grep -qx "projection=equirectangular" <<<"$side" || fail "ffprobe finds no equirectangular mapping in vr.mp4: $side"
"$PY" -c 'import sys; d = open(sys.argv[1], "rb").read(); sys.exit(0 if b"sv3d" in d and b"equi" in d else "no sv3d/equi box")' vr.mp4 ||
  fail "vr.mp4 lacks the spherical video V2 boxes"
check_probe vr.mp4 width=128 height=64

# 3. Not 2:1: rendered, with a warning naming the size it should be; a
# window is a flat picture.
CHECKS=$((CHECKS + 1))
"$LIGHTCONE" render "$SHOT" --out wide --size 96x64 --progress 0 >wide.out 2>wide.err || fail "render 96x64: $(cat wide.err)"
grep -q "warning: frame 0: equirect: .* 2 times as wide as it is high" wide.err ||
  fail "a 3:2 whole sphere was not warned about: $(cat wide.err)"
[ -f wide/equirect_example.0000.png ] || fail "the 3:2 frame was not rendered"
sed 's/lc.equirect{}/lc.equirect{longitude = 180, latitude = 90}/' "$SHOT" >window.lua
"$LIGHTCONE" render window.lua --out window --size 64x32 --progress 0 >window.out 2>window.err || fail "window: $(cat window.err)"
"$LIGHTCONE" encode window -o window.mp4 >wenc.out 2>wenc.err || fail "encode window: $(cat wenc.err)"
side=$(ffprobe -v error -show_entries stream_side_data=side_data_type -of default=nw=1 window.mp4 2>&1)
[ -z "$side" ] || fail "a window of the sphere was marked for players: $side"

# 4. ODS and a stereo pinhole, marked for players.  What players read is
# the track's st3d box (Spherical Video V2: mode 1 top-bottom, 2 side by
# side); ffprobe's reading is checked too, except that FFmpeg 7.1 also
# writes visionOS's vexu box (eyes, no packing) and reads it after st3d,
# so it shows "unspecified" there (docs/encoding.md).
CHECKS=$((CHECKS + 1))
# The stereo mode byte of the st3d box inside the file's moov, or "none".
st3d_mode() {
  "$PY" - "$1" <<'PY'
import struct, sys
data = open(sys.argv[1], "rb").read()
at = 0
while at + 8 <= len(data):
    size, kind = struct.unpack(">I4s", data[at:at + 8])
    if size < 8:
        break
    if kind == b"moov":
        i = data.find(b"st3d", at, at + size)
        print(data[i + 8] if i >= 0 else "none")
        sys.exit(0)
    at += size
print("none")
PY
}
# Stereo side data as ffprobe reads it: the layout asked for, or FFmpeg
# 7.1's "unspecified" where the file also has a vexu box.
stereo_read() { # FILE TYPE
  local side
  side=$(ffprobe -v error -show_entries stream_side_data=side_data_type,type -of default=nw=1 "$1" 2>&1)
  grep -qx "type=$2" <<<"$side" && return 0
  grep -qx "type=unspecified" <<<"$side" && "$PY" -c "import sys; sys.exit(b'vexu' not in open(sys.argv[1], 'rb').read())" "$1"
}
sed 's/lc.equirect{}/lc.equirect{stereo = "top-bottom", separation = 1}/' "$SHOT" >ods.lua
"$LIGHTCONE" render ods.lua --out ods --size 128x128 --progress 0 >ods.out 2>ods.err || fail "render ODS: $(cat ods.err)"
if grep -q "warning" ods.err; then fail "a square ODS frame was warned about: $(cat ods.err)"; fi
"$LIGHTCONE" encode ods -o ods.mp4 >odsenc.out 2>odsenc.err || fail "encode ODS: $(cat odsenc.err)"
side=$(ffprobe -v error -show_entries stream_side_data=side_data_type,projection,type -of default=nw=1 ods.mp4 2>&1)
grep -qx "projection=equirectangular" <<<"$side" || fail "ods.mp4: no equirectangular mapping: $side"
[ "$(st3d_mode ods.mp4)" = 1 ] || fail "ods.mp4: its st3d box does not say top-bottom: $(st3d_mode ods.mp4)"
stereo_read ods.mp4 "top and bottom" || fail "ods.mp4: ffprobe reads no top-bottom stereo layout: $side"
sed 's/lc.equirect{}/lc.camera{fov = 60, stereo = "side-by-side", separation = 0.5}/' "$SHOT" >pair.lua
"$LIGHTCONE" render pair.lua --out pair --size 128x48 --progress 0 >pair.out 2>pair.err || fail "render a stereo pair: $(cat pair.err)"
"$LIGHTCONE" encode pair -o pair.mp4 >pairenc.out 2>pairenc.err || fail "encode a stereo pair: $(cat pairenc.err)"
side=$(ffprobe -v error -show_entries stream_side_data=side_data_type,projection,type -of default=nw=1 pair.mp4 2>&1)
[ "$(st3d_mode pair.mp4)" = 2 ] || fail "pair.mp4: its st3d box does not say side by side: $(st3d_mode pair.mp4)"
stereo_read pair.mp4 "side by side" || fail "pair.mp4: ffprobe reads no side-by-side stereo layout: $side"
if grep -q "projection=" <<<"$side"; then fail "a stereo pinhole was marked as a sphere: $side"; fi

# 5. Bad spans and stereo, at the shot's line, nothing written.
sed 's/lc.equirect{}/lc.equirect{longitude = 400}/' "$SHOT" >far.lua
expect_error far "far.lua:20: equirect: field 'longitude' must be greater than 0 and at most 360" -- \
  "$LIGHTCONE" render far.lua --out far --size 32x16
sed 's/lc.equirect{}/lc.equirect{latitude = 0}/' "$SHOT" >flat.lua
expect_error flat "flat.lua:20: equirect: field 'latitude' must be greater than 0 and at most 180" -- \
  "$LIGHTCONE" render flat.lua --out flat --size 32x16
sed 's/lc.equirect{}/lc.equirect{stereo = "top-bottom", separation = 0}/' "$SHOT" >blind.lua
expect_error blind "blind.lua:20: equirect: field 'separation' must be greater than 0" -- \
  "$LIGHTCONE" render blind.lua --out blind --size 32x32
sed 's/lc.equirect{}/lc.equirect{stereo = "side-by-side"}/' "$SHOT" >wide4.lua
expect_error wide4 "wide4.lua:20: equirect: stereo 'side-by-side' is not offered for the equirect" -- \
  "$LIGHTCONE" render wide4.lua --out wide4 --size 64x16
expect_error ods_region "--region: frame 0's camera is stereo; a region of a stereo frame is not offered" -- \
  "$LIGHTCONE" render ods.lua --out ods_region --size 128x128 --region 0,0,64,64
CHECKS=$((CHECKS + 1))
if ls far/*.png flat/*.png blind/*.png wide4/*.png ods_region/*.png >/dev/null 2>&1; then fail "a refused shot wrote frames"; fi

e2e_end
