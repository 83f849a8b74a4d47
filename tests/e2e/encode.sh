#!/usr/bin/env bash
# ctest-labels: slow
# The encode stage through the real binary: a tiny rendered Kerr sequence to
# H.264 MP4 checked with ffprobe (codec, pixel format, frame count, duration
# exactly frames/fps, moov before mdat), preview sequences with a step, a
# sequence with holes refused with the holes named, odd sizes padded, bad
# outputs and inputs refused with nothing left behind, Ctrl-C, title cards,
# --concat, and the contact sheet.
source "$(dirname "$0")/lib.sh"
e2e_begin "$@"

# No temporaries or partial files anywhere in the work directory.
no_leftovers() {
  local left
  left=$(find . -name '*.tmp-*')
  [ -z "$left" ] || fail "$1: temporaries left: $left"
}

# A 12-frame shot at 32x18: a Kerr hole seen from an inclination that grows.
cat >tiny.lua <<'LUA'
local lc = require "lightcone"
return {name = "tiny", frames = 12, fps = 24, width = 32, height = 18,
  frame = function(i)
    return {spacetime = lc.kerr{mass = 1, spin = 0.9},
            observer = lc.static_observer{r = 30, theta = 10 + 6 * i, phi = 0},
            camera = lc.camera{fov = 40},
            disk = lc.disk{inner = 6, outer = 14}}
  end}
LUA
"$LIGHTCONE" render tiny.lua --out frames 2>render.log || fail "render: $(cat render.log)"

# --- the basic encode: 12 frames at 24 fps last exactly 0.5 s -------------
"$LIGHTCONE" encode frames -o tiny.mp4 --fps 24 2>encode.log || fail "encode: $(cat encode.log)"
check_probe tiny.mp4 codec_name=h264 pix_fmt=yuv420p width=32 height=18 nb_read_frames=12 avg_frame_rate=24/1 \
  duration=0.500000
[ "$(atoms tiny.mp4)" = "ftyp moov free mdat" ] || fail "not faststart (moov after mdat?): $(atoms tiny.mp4)"
grep -q "encode: done: 12 frames 32x18, 0.500 s at 24 fps" encode.log || fail "summary: $(cat encode.log)"
# Without --fps: the shot's 24 fps, which the renderer records in each EXR.
"$LIGHTCONE" encode frames -o tiny24.mp4 2>tiny24.log || fail "encode at the shot's fps: $(cat tiny24.log)"
check_probe tiny24.mp4 nb_read_frames=12 avg_frame_rate=24/1 duration=0.500000
grep -q "24 fps (the shot, from tiny.0000.exr)" tiny24.log || fail "fps source not named: $(cat tiny24.log)"
# --fps overrides it: 12 frames at 30 fps last 0.4 s.
"$LIGHTCONE" encode frames -o tiny30.mp4 --fps 30 2>/dev/null || fail "encode at 30 fps"
check_probe tiny30.mp4 nb_read_frames=12 avg_frame_rate=30/1 duration=0.400000
# Fractions are kept exactly: NTSC's 30000/1001 is the stream's rate (12
# frames last 0.4004 s), and 29.97 is 2997/100.
"$LIGHTCONE" encode frames -o ntsc.mp4 --fps 30000/1001 2>ntsc.log || fail "encode --fps 30000/1001: $(cat ntsc.log)"
check_probe ntsc.mp4 nb_read_frames=12 avg_frame_rate=30000/1001 duration=0.400400
"$LIGHTCONE" encode frames -o decimal.mp4 --fps 29.97 2>/dev/null || fail "encode --fps 29.97"
check_probe decimal.mp4 nb_read_frames=12 avg_frame_rate=2997/100
# Rates no container can hold are refused up front, naming the range (1e-9
# used to pass the check and fail in the muxer).
fps_range="must be from 1/1000 (one frame every 1000 s) to 1000 frames per second"
expect_error fps_tiny "--fps 1e-9: $fps_range" -- "$LIGHTCONE" encode frames -o fps1.mp4 --fps 1e-9
expect_error fps_huge "--fps 1001: $fps_range" -- "$LIGHTCONE" encode frames -o fps2.mp4 --fps 1001
expect_error fps_junk "--fps '30fps': expected frames per second" -- "$LIGHTCONE" encode frames -o fps3.mp4 --fps 30fps
expect_error fps_zero_den "--fps 30/0: the denominator is 0" -- "$LIGHTCONE" encode frames -o fps4.mp4 --fps 30/0
expect_error fps_title "--fps 1e-9: $fps_range" -- "$LIGHTCONE" encode --title X --size 32x18 --fps 1e-9 -o fps5.mp4
# A fraction is one however long its numbers: too large, not "expected a number".
expect_error fps_terms "--fps 4294967297/4294967296: too large: in lowest terms the fraction's numbers must be at most 1001000" -- \
  "$LIGHTCONE" encode frames -o fps6.mp4 --fps 4294967297/4294967296
for f in fps1 fps2 fps3 fps4 fps5 fps6; do [ -e $f.mp4 ] && fail "$f.mp4 written for a refused --fps"; done
# Colour survives: a flat orange frame decodes (as a player does, by the
# stream's BT.709 tags) to its PNG's bytes within 2 codes.  A BT.601 matrix
# under a BT.709 tag would be ~10 codes off.
mkdir flat
for i in 0 1 2; do
  oiiotool --pattern constant:color=0.8,0.4,0.1 64x64 3 -d uint8 -o flat/flat.000$i.png || fail "oiiotool"
done
"$LIGHTCONE" encode flat -o flat.mp4 2>/dev/null || fail "encode flat"
ffmpeg -v error -i flat.mp4 -frames:v 1 -pix_fmt rgb24 -f rawvideo flat.rgb || fail "decode flat.mp4"
python3 - flat.rgb <<'PY' || fail "flat colour decoded wrong"
import sys
d = open(sys.argv[1], 'rb').read()
want = (204, 102, 26)  # 0.8, 0.4, 0.1 of 255
worst = max(abs(d[i] - want[i % 3]) for i in range(len(d)))
assert len(d) == 64 * 64 * 3 and worst <= 2, (len(d), worst, d[:3].hex())
PY
no_leftovers "basic encode"

# --- a preview sequence: every 3rd frame (0, 3, 6, 9) at 8 fps: 0.5 s ------
"$LIGHTCONE" render tiny.lua --out step --frames 0:11:3 2>/dev/null || fail "render step"
"$LIGHTCONE" encode step -o step.mp4 --fps 8 2>step.log || fail "encode step: $(cat step.log)"
check_probe step.mp4 nb_read_frames=4 duration=0.500000
grep -q "frames (0-9 every 3)" step.log || fail "step not reported: $(cat step.log)"
# Without --fps a preview keeps the shot's pace: 24 fps / 3 = 8 fps (it
# used to play at 24, three times too fast).
"$LIGHTCONE" encode step -o step_pace.mp4 2>step_pace.log || fail "encode step at its pace: $(cat step_pace.log)"
check_probe step_pace.mp4 nb_read_frames=4 avg_frame_rate=8/1 duration=0.500000
grep -q "8 fps (the shot's 24, from tiny.0000.exr, divided by the step 3 to keep its pace)" step_pace.log \
  || fail "the divided rate is not explained: $(cat step_pace.log)"
# 11, the shot's last frame, is off the step: the render says so; rendered
# as well, it ends the preview instead of being called a hole.
"$LIGHTCONE" render tiny.lua --out step --frames 0:11:3 2>step_note.log || fail "render step again"
grep -q "render: note: --frames 0:11:3 takes 0, 3, ..., 9: 11 is not on the step" step_note.log \
  || fail "no note about the last frame: $(cat step_note.log)"
"$LIGHTCONE" render tiny.lua --out step --frames 11 2>/dev/null || fail "render the last frame"
"$LIGHTCONE" encode step -o step_last.mp4 2>step_last.log || fail "a stepped sequence and its last frame: $(cat step_last.log)"
check_probe step_last.mp4 nb_read_frames=5 avg_frame_rate=8/1
grep -q "5 frames (0-9 every 3, then 11)" step_last.log || fail "last frame not reported: $(cat step_last.log)"
# Frames the journal says were rendered and whose files are gone are holes,
# however regular the numbers left look (0, 9, 10 is not "every 9th, then 10").
mkdir lost && cp frames/tiny.* lost/ && rm lost/tiny.000[1-8].* lost/tiny.0011.*
expect_error lost "frames 0-10: missing frames 1-8" -- "$LIGHTCONE" encode lost -o lost.mp4

# --- holes: refused, holes named compactly, nothing written ----------------
mkdir holes
for f in 0 1 2 5 6 7 9 10 11; do cp frames/tiny.$(printf %04d $f).png holes/; done
expect_error holes "missing frames 3-4, 8" -- "$LIGHTCONE" encode holes -o holes.mp4
[ -e holes.mp4 ] && fail "holes.mp4 written for an incomplete sequence"
mkdir stephole
for f in 0 3 9; do cp frames/tiny.$(printf %04d $f).png stephole/; done
expect_error stephole "frames 0-9 every 3: missing frame 6" -- "$LIGHTCONE" encode stephole -o sh.mp4

# --- stale frames: a changed shot, a --force render stopped part way -------
# 30 frames rendered, the shot changed, then a --force render that stopped
# after frames 0-5 (deterministically: it was asked for 0-5 only).  Encode
# and contact-sheet refuse to mix the versions, naming the old frames,
# until the render is finished or --allow-stale is given.
sed -e 's/frames = 12/frames = 30/' -e 's/width = 32, height = 18/width = 16, height = 10/' \
  -e 's/name = "tiny"/name = "stale"/' tiny.lua >stale.lua
"$LIGHTCONE" render stale.lua --out stale --progress 0 2>/dev/null || fail "render stale"
sed -i 's/outer = 14/outer = 11/' stale.lua
"$LIGHTCONE" render stale.lua --out stale --force --frames 0:5 --progress 0 2>stale_force.log \
  || fail "render --force 0:5: $(cat stale_force.log)"
expect_error stale "stale: shot stale: frames 6-29 were rendered from an earlier version of the shot" -- \
  "$LIGHTCONE" encode stale -o stale.mp4
grep -q -- "--allow-stale" stale.err && grep -q -- "--force" stale.err || fail "no way out named: $(cat stale.err)"
expect_error stale_sheet "frames 6-29 were rendered from an earlier version of the shot" -- \
  "$LIGHTCONE" contact-sheet stale -o stale.png
[ -e stale.mp4 ] || [ -e stale.png ] && fail "stale frames were encoded or shown without --allow-stale"
"$LIGHTCONE" encode stale -o stale.mp4 --allow-stale 2>stale_allowed.log || fail "--allow-stale: $(cat stale_allowed.log)"
grep -q "warning: --allow-stale: using them as they are: .*frames 6-29" stale_allowed.log \
  || fail "--allow-stale does not say what it mixes: $(cat stale_allowed.log)"
check_probe stale.mp4 nb_read_frames=30
# Other settings and a frame put there by hand are named too.
mkdir stale2 && cp stale/stale.* stale2/
"$LIGHTCONE" render stale.lua --out stale2 --force --frames 7 --size 32x20 --progress 0 2>/dev/null || fail "render 7 bigger"
cp frames/tiny.0003.png stale2/stale.0003.png
expect_error stale_settings "frames 0-2, 4-6, 8-29 were rendered with other settings than the latest render (32x20" -- \
  "$LIGHTCONE" encode stale2 -o stale2.mp4
grep -q "frame 3 was not recorded in stale.journal as finished" stale_settings.err \
  || fail "a frame without its journal line is not named: $(cat stale_settings.err)"
# Finished, the sequence is one version again.
"$LIGHTCONE" render stale.lua --out stale --force --progress 0 2>/dev/null || fail "finish the --force render"
"$LIGHTCONE" encode stale -o stale_done.mp4 2>stale_done.log || fail "encode after finishing: $(cat stale_done.log)"
check_probe stale_done.mp4 nb_read_frames=30

# --- odd sizes are padded to even ----------------------------------------
"$LIGHTCONE" render tiny.lua --out odd --size 33x19 --frames 0:2 2>/dev/null || fail "render odd"
"$LIGHTCONE" encode odd -o odd.mp4 2>odd.log || fail "encode odd: $(cat odd.log)"
check_probe odd.mp4 width=34 height=20 pix_fmt=yuv420p nb_read_frames=3
grep -q "padded to 34x20" odd.log || fail "padding not reported: $(cat odd.log)"

# --- sizes the encoder cannot take: refused from the first frame's header --
# png_header W H FILE: a PNG whose header says W x H and whose pixel data is
# garbage, so only a check that reads no pixel gets past it (a 16384x16384
# frame used to be decoded, 6.4 GB, before the encoder said "(0x0): Invalid
# argument").  The header's CRC is gzip's (the same CRC-32), byte-reversed.
hex_bytes() { sed 's/../\\x&/g'; }
png_header() {
  local body crc
  body="49484452$(printf '%08x%08x' "$1" "$2")0802000000"  # IHDR: W, H, 8-bit RGB
  crc=$(printf "$(hex_bytes <<<"$body")" | gzip -c | tail -c8 | head -c4 | od -An -tx1 | tr -d ' \n')
  crc=${crc:6:2}${crc:4:2}${crc:2:2}${crc:0:2}
  printf "$(hex_bytes <<<"89504e470d0a1a0a0000000d${body}${crc}00000004494441540000000000000000")" >"$3"
}
mkdir big
png_header 16384 16384 big/big.0000.png
iinfo big/big.0000.png | grep -q "16384 x 16384" || fail "the test's PNG header is not read as 16384x16384: $(iinfo big/big.0000.png)"
expect_error big "big/big.0000.png: 16384x16384 frames are too large for FFmpeg's encoders" -- \
  "$LIGHTCONE" encode big -o big.mp4
expect_error big_title "16384x16384 frames are too large for FFmpeg's encoders" -- \
  "$LIGHTCONE" encode --title BIG --size 16384x16384 -o bigcard.mp4
[ -e big.mp4 ] || [ -e bigcard.mp4 ] && fail "an output was written for frames too large to encode"

# --- bad inputs and outputs: clear errors, nothing left ------------------
mkdir empty
expect_error empty "no frames" -- "$LIGHTCONE" encode empty -o e.mp4
expect_error nodir "nodir: no such directory" -- "$LIGHTCONE" encode nodir -o e.mp4
touch notadir
expect_error unwritable "cannot write notadir/x.mp4" -- "$LIGHTCONE" encode frames -o notadir/x.mp4
expect_error missingdir "cannot write nowhere/x.mp4: No such file or directory" -- "$LIGHTCONE" encode frames -o nowhere/x.mp4
expect_error badext "unknown video extension '.avi'" -- "$LIGHTCONE" encode frames -o x.avi
expect_error badcodec "--codec h265" -- "$LIGHTCONE" encode frames -o x.mp4 --codec h265
expect_error badcrf "--crf 99" -- "$LIGHTCONE" encode frames -o x.mp4 --crf 99
expect_error prores_mp4 "prores does not go in a .mp4 file" -- "$LIGHTCONE" encode frames -o x.mp4 --codec prores
mkdir two && cp frames/tiny.000[01].png two/ && cp frames/tiny.0000.png two/other.0000.png
expect_error twoshots "choose one with --shot" -- "$LIGHTCONE" encode two -o x.mp4
"$LIGHTCONE" encode two --shot other -o other.mp4 2>/dev/null || fail "--shot other"
check_probe other.mp4 nb_read_frames=1
# A frame of another size in the sequence is named.
mkdir mixed && cp frames/tiny.000[01].png mixed/ && cp odd/tiny.0002.png mixed/
expect_error mixed "mixed/tiny.0002.png: 33x19" -- "$LIGHTCONE" encode mixed -o mixed.mp4
[ -e x.mp4 ] || [ -e e.mp4 ] || [ -e mixed.mp4 ] && fail "an output was written despite an error"
no_leftovers "errors"

# --- Ctrl-C: exit 130, nothing under the final name or a temporary --------
"$LIGHTCONE" encode --title "STOP ME" --size 320x180 --seconds 600 -o long.mp4 2>long.log &
pid=$!
# Interrupt once encoding is under way (its first progress line), not
# during start-up, when SIGINT would still kill the process outright.
for _ in $(seq 300); do grep -q "frames," long.log 2>/dev/null && break; sleep 0.1; done
kill -INT "$pid"
rc=0
wait "$pid" || rc=$?
[ "$rc" -eq 130 ] || fail "Ctrl-C: exit $rc, want 130: $(tail -2 long.log)"
grep -q "interrupted by Ctrl-C" long.log || fail "no interruption message: $(tail -2 long.log)"
[ -e long.mp4 ] && fail "long.mp4 exists after Ctrl-C"
no_leftovers "Ctrl-C"

# --- title card + clip + title card, joined without re-encoding -----------
"$LIGHTCONE" encode --title "KERR" --size 32x18 --fps 24 --seconds 0.25 -o card.mp4 2>card.log \
  || fail "title card: $(cat card.log)"
check_probe card.mp4 nb_read_frames=6 duration=0.250000 width=32 height=18
"$LIGHTCONE" encode --concat card.mp4 tiny.mp4 card.mp4 -o joined.mp4 2>concat.log || fail "concat: $(cat concat.log)"
check_probe joined.mp4 codec_name=h264 pix_fmt=yuv420p nb_read_frames=24 avg_frame_rate=24/1 duration=1.000000
[ "$(atoms joined.mp4)" = "ftyp moov free mdat" ] || fail "joined not faststart: $(atoms joined.mp4)"
# The joined stream decodes to exactly the inputs' frames, in order.
md5s() { ffmpeg -v error -i "$1" -f framemd5 - | grep -v '^#' | awk -F, '{print $NF}'; }
[ "$(md5s joined.mp4)" = "$(md5s card.mp4; md5s tiny.mp4; md5s card.mp4)" ] || fail "joined frames differ from the inputs'"
expect_error concat_size "join only videos of one size" -- "$LIGHTCONE" encode --concat tiny.mp4 odd.mp4 -o j2.mp4
expect_error concat_rate "join only videos of one frame rate" -- "$LIGHTCONE" encode --concat tiny.mp4 tiny30.mp4 -o j3.mp4
expect_error concat_flags "--concat copies the videos" -- "$LIGHTCONE" encode --concat tiny.mp4 tiny.mp4 --crf 20 -o j4.mp4
expect_error concat_missing "cannot read nope.mp4" -- "$LIGHTCONE" encode --concat tiny.mp4 nope.mp4 -o j5.mp4
[ -e j2.mp4 ] || [ -e j3.mp4 ] || [ -e j5.mp4 ] && fail "a failed concat left an output"

# --- contact sheet: 12 frames in 4 columns, 400 wide ----------------------
# Thumbnails (400 - 5*8)/4 = 90 wide, 90*18/32 -> 51 high, 9-pixel labels:
# 3 rows of 60 + gaps = 212 high.
"$LIGHTCONE" contact-sheet frames -o sheet.png --columns 4 --width 400 2>sheet.log || fail "contact-sheet: $(cat sheet.log)"
iinfo sheet.png >sheet.info 2>&1 || fail "sheet.png is not a readable image: $(cat sheet.info)"
grep -q "400 x  212, 3 channel, uint8 png" sheet.info || fail "sheet size: $(cat sheet.info)"
python3 - sheet.png <<'PY' || fail "sheet.png is not a valid PNG"
import struct, sys, zlib
d = open(sys.argv[1], 'rb').read()
assert d[:8] == b'\x89PNG\r\n\x1a\n'
i = 8
while i < len(d):
    n, t = struct.unpack('>I4s', d[i:i + 8])
    assert zlib.crc32(d[i + 4:i + 8 + n]) == struct.unpack('>I', d[i + 8 + n:i + 12 + n])[0], t
    i += 12 + n
assert t == b'IEND'
PY
# Many frames: 4 picks of the 12, one row.
"$LIGHTCONE" contact-sheet frames -o sheet4.png --count 4 --width 400 2>sheet4.log || fail "contact-sheet --count"
grep -q "4 of 12 frames" sheet4.log || fail "picks: $(cat sheet4.log)"
iinfo sheet4.png | grep -q "400 x   76" || fail "sheet4 size: $(iinfo sheet4.png)"
expect_error sheet_ext "a contact sheet is a PNG" -- "$LIGHTCONE" contact-sheet frames -o sheet.jpg
expect_error sheet_cols "--width 40: too narrow for 4 columns" -- "$LIGHTCONE" contact-sheet frames -o s.png --width 40
expect_error sheet_empty "no frames" -- "$LIGHTCONE" contact-sheet empty -o s.png
no_leftovers "contact sheet"
e2e_end
