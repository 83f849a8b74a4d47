#!/usr/bin/env bash
# ctest-labels: slow
# Rendering through the real binary: the benchmark shots at a small size,
# EXR + PNG under their final names, data layers read back, inspect's JSON,
# trace's path, and identical frames with 1 and 2 threads.
source "$(dirname "$0")/lib.sh"
e2e_begin "$@"

"$LIGHTCONE" render "$SRC/shots/bench/kerr_disk.lua" --out frames --size 48x32 --layers 2>render.log \
  || fail "render kerr_disk: $(cat render.log)"
[ -s frames/kerr_disk.0000.exr ] || fail "no EXR"
[ -s frames/kerr_disk.0000.png ] || fail "no PNG"
ls frames | grep -q tmp && fail "temporary files left in frames/"
grep -q "render: done: 1 frames" render.log || fail "no summary line: $(cat render.log)"
# The EXR carries RGB as float and the six data layers.
channels=$(iinfo -v frames/kerr_disk.0000.exr | grep -i "channel list")
for c in R G B hit.kind hit.r hit.phi hit.t hit.g hit.order; do
  echo "$channels" | grep -q "$c" || fail "EXR lacks channel $c: $channels"
done
# hit.g (docs/light.md): 0 on the shadow, the approaching side of the disk
# blueshifted (a = 0.9 seen from r = 30 at 80 deg: up to ~1.38), every
# value finite.
gstats=$(oiiotool frames/kerr_disk.0000.exr --ch hit.g --printstats 2>&1)
echo "$gstats" | grep -q "Stats Min: 0.000000" || fail "hit.g: no zero (shadow): $gstats"
max=$(echo "$gstats" | sed -n 's/.*Stats Max: \([0-9.]*\).*/\1/p')
awk -v m="$max" 'BEGIN { exit !(m > 1.2 && m < 1.6) }' || fail "hit.g: max $max, expected ~1.38: $gstats"
echo "$gstats" | grep -q "NanCount: 0" || fail "hit.g has NaNs: $gstats"
iinfo -v frames/kerr_disk.0000.exr | grep -q "48 x   32\|48 x 32" || fail "EXR size: $(iinfo frames/kerr_disk.0000.exr)"
iinfo -v frames/kerr_disk.0000.exr | grep -q "compression: \"zip\"" || fail "EXR not zip-compressed"

# The shot's exposure and tone curve change the PNG only: the EXR keeps the
# light as traced (docs/light.md).  One stop down halves the linear values
# (sRGB codes compared after decoding, to within their rounding).
sed 's/supersample = 1,/supersample = 1, exposure = -1, filmic = 1,/' "$SRC/shots/bench/kerr_disk.lua" >dim.lua
grep -q "exposure = -1" dim.lua || fail "could not make the dimmed shot"
"$LIGHTCONE" render dim.lua --out dim --size 48x32 --layers 2>dim.log || fail "render dimmed: $(cat dim.log)"
idiff -a frames/kerr_disk.0000.exr dim/kerr_disk.0000.exr >dim.idiff 2>&1 || fail "exposure changed the EXR: $(cat dim.idiff)"
python3 - frames/kerr_disk.0000.png dim/kerr_disk.0000.png <<'PY' || fail "exposure/filmic: the PNG is not the EXR's light through the curve"
import struct, sys, zlib
def pixels(path):
    data = open(path, "rb").read()
    pos, idat, w = 8, b"", 0
    while pos < len(data):
        n, kind = struct.unpack(">I4s", data[pos:pos + 8])
        if kind == b"IHDR": w, h, depth, ctype = struct.unpack(">IIBB", data[pos + 8:pos + 18])
        if kind == b"IDAT": idat += data[pos + 8:pos + 8 + n]
        pos += 12 + n
    raw, out, prev, stride = zlib.decompress(idat), [], bytearray(3 * w), 3 * w
    for y in range(len(raw) // (stride + 1)):
        f, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - 3] if i >= 3 else 0
            b, c = prev[i], prev[i - 3] if i >= 3 else 0
            if f == 1: line[i] = (line[i] + a) & 255
            elif f == 2: line[i] = (line[i] + b) & 255
            elif f == 3: line[i] = (line[i] + (a + b) // 2) & 255
            elif f == 4:
                p = a + b - c; pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        out += line; prev = line
    return out
lin = lambda s: s / 12.92 if s <= 0.04045 else ((s + 0.055) / 1.055) ** 2.4
aces = lambda x: min(1.0, x * (2.51 * x + 0.03) / (x * (2.43 * x + 0.59) + 0.14))
full, dim = pixels(sys.argv[1]), pixels(sys.argv[2])
worst = 0.0
for a, b in zip(full, dim):
    if a == 255: continue  # clipped in the plain PNG: its light is unknown
    want = aces(0.5 * lin(a / 255))
    worst = max(worst, abs(lin(b / 255) - want) / max(want, 0.02))
sys.exit(0 if worst < 0.05 else 1)
PY

# A frame's own exposure replaces the shot's: the same PNG, to the byte,
# as the shot at exposure -1; the EXR as traced.
sed 's/supersample = 1,/supersample = 1, filmic = 1,/; s/^    return {$/    return { exposure = -1,/' \
  "$SRC/shots/bench/kerr_disk.lua" >frame_dim.lua
grep -q "return { exposure = -1," frame_dim.lua || fail "could not make the frame-exposure shot"
"$LIGHTCONE" render frame_dim.lua --out frame_dim --size 48x32 --layers 2>frame_dim.log ||
  fail "render with a frame's exposure: $(cat frame_dim.log)"
cmp frame_dim/kerr_disk.0000.png dim/kerr_disk.0000.png || fail "a frame's exposure -1 is not the shot's exposure -1"
idiff -a frames/kerr_disk.0000.exr frame_dim/kerr_disk.0000.exr >frame_dim.idiff 2>&1 ||
  fail "a frame's exposure changed the EXR: $(cat frame_dim.idiff)"

# The shipped light-model shot renders: its glowing disk (frame 5) is
# blueshifted on one side (hit.g above 1.1); the checker seen shifted
# (frame 3) looks different from the paper's look (frame 0) though every
# hit's g is the same.
"$LIGHTCONE" render "$SRC/shots/light_models.lua" --frames 0:5 --out glow --size 64x36 --layers 2>glow.log ||
  fail "render light_models: $(cat glow.log)"
gl=$(oiiotool glow/light_models.0005.exr --ch hit.g --printstats 2>&1)
gmax=$(echo "$gl" | sed -n 's/.*Stats Max: \([0-9.]*\).*/\1/p')
awk -v m="$gmax" 'BEGIN { exit !(m > 1.1) }' || fail "glowing disk: no blueshifted pixel: $gl"
cmp -s glow/light_models.0000.png glow/light_models.0003.png && fail "the shifted checker looks like the paper's"
oiiotool glow/light_models.0000.exr --ch hit.g -o g0.exr && oiiotool glow/light_models.0003.exr --ch hit.g -o g3.exr
idiff -a g0.exr g3.exr >gdiff.log 2>&1 || fail "hit.g depends on the light model: $(cat gdiff.log)"

# One thread and two threads give the same pixels.
"$LIGHTCONE" render "$SRC/shots/bench/kerr_disk.lua" --out frames1 --size 48x32 --layers --threads 1 2>/dev/null
idiff -a frames/kerr_disk.0000.exr frames1/kerr_disk.0000.exr >idiff.log 2>&1 || fail "1 vs 2 threads differ: $(cat idiff.log)"
cmp -s frames/kerr_disk.0000.png frames1/kerr_disk.0000.png || fail "PNGs differ between thread counts"

"$LIGHTCONE" render "$SRC/shots/bench/dihole_sphere.lua" --out frames --scale 0.125 2>dihole.log \
  || fail "render dihole_sphere: $(cat dihole.log)"
[ -s frames/dihole_sphere.0000.png ] || fail "no dihole PNG"

# Frames of a still scene reuse samples (the dihole's oscillation, watched
# from the y axis): the same EXRs as traced afresh with --no-reuse.
"$LIGHTCONE" render "$SRC/shots/dihole.lua" --out still --frames 300:302 --size 64x36 --layers 2>still.log \
  || fail "render dihole 300-302: $(cat still.log)"
grep -q "samples reused from earlier frames" still.log || fail "no samples reused: $(cat still.log)"
"$LIGHTCONE" render "$SRC/shots/dihole.lua" --out fresh --frames 300:302 --size 64x36 --layers --no-reuse 2>fresh.log \
  || fail "render dihole 300-302 --no-reuse: $(cat fresh.log)"
grep -q "reused" fresh.log && fail "--no-reuse reused samples: $(cat fresh.log)"
for f in 0300 0301 0302; do
  cmp -s still/dihole.$f.png fresh/dihole.$f.png || fail "frame $f differs with reuse"
  idiff -a still/dihole.$f.exr fresh/dihole.$f.exr >idiff_$f.log 2>&1 || fail "frame $f EXR differs with reuse: $(cat idiff_$f.log)"
done

# inspect: JSON of frames 0..5 step 5 of the example shot (frames 0 and 5).
"$LIGHTCONE" inspect "$SRC/shots/orbit_example.lua" --frames 0:5:5 >inspect.json 2>inspect.log || fail "inspect: $(cat inspect.log)"
python3 -c "
import json, sys
d = json.load(open('inspect.json'))
assert d['shot']['name'] == 'orbit_example', d['shot']
assert [s['frame'] for s in d['scenes']] == [0, 5], [s['frame'] for s in d['scenes']]
th0 = d['scenes'][0]['observer']['position']['theta']
assert abs(th0 - 10) < 1e-9, th0
assert d['scenes'][1]['observer']['position']['theta'] > th0
# What the engine made of it: the event, the tetrad, the camera's axes
# (looking at the hole: forward = -e1, up = -e2, right = e3).
for s in d['scenes']:
  ev = s['evaluated']
  assert ev['observer']['event'] == s['observer']['position'], ev['observer']['event']
  t = ev['observer']['tetrad']
  for axis, leg, sign in (('forward', 'e1', -1), ('up', 'e2', -1), ('right', 'e3', 1)):
    assert all(abs(a - sign * b) < 1e-12 for a, b in zip(ev['camera'][axis], t[leg])), (axis, ev['camera'][axis], t[leg])
  assert t['e0'][0] > 1 and t['e1'][1] > 0, t
" || fail "inspect JSON"

# trace: the centre pixel of the Kerr bench at 48x32 looks into the shadow.
"$LIGHTCONE" trace "$SRC/shots/bench/kerr_disk.lua" --frame 0 --pixel 24,16 --size 48x32 -o ray.csv 2>trace.log \
  || fail "trace: $(cat trace.log)"
grep -q "hit horizon" trace.log || fail "centre pixel should see the horizon: $(cat trace.log)"
[ "$(head -1 ray.csv)" = "# chart: bl (t, r, theta, phi; kerr)" ] || fail "trace CSV chart line: $(head -1 ray.csv)"
[ "$(sed -n 2p ray.csv)" = "lambda,x0,x1,x2,x3,u0,u1,u2,u3" ] || fail "trace CSV header"
[ "$(wc -l <ray.csv)" -gt 10 ] || fail "trace CSV too short"
# The path starts at the observer (BL r = 30) and ends near the horizon.
awk -F, 'NR == 3 && ($3 < 29.999 || $3 > 30.001) { exit 1 }' ray.csv || fail "trace starts at r = $(sed -n 3p ray.csv)"
# The shipped star field is the project's own: regenerating it gives the same bytes.
"$LIGHTCONE" starfield -o stars.png 2>/dev/null || fail "starfield"
cmp -s stars.png "$SRC/shots/textures/starfield.png" || fail "starfield.png is not what 'lightcone starfield' makes"

# Both star skies render: the shipped image (looked up in shots/) and the procedural one.
cat >skies.lua <<'LUA'
local lc = require "lightcone"
return {name = "skies", frames = 2, width = 16, height = 8,
  frame = function(i)
    return {spacetime = lc.kerr{mass = 1}, observer = lc.static_observer{r = 20, theta = 90, phi = 0},
            sky = i == 0 and lc.starfield{rotate = 90} or lc.sky_stars{seed = 7, resolution = 256}}
  end}
LUA
"$LIGHTCONE" render skies.lua --out skies 2>skies.log || fail "star skies: $(cat skies.log)"
[ -s skies/skies.0000.png ] && [ -s skies/skies.0001.png ] || fail "star sky frames missing"
# bench on a small copy of the Kerr benchmark shot: speed and accuracy lines.
sed 's/width = 256/width = 24/; s/height = 256/height = 16/' "$SRC/shots/bench/kerr_disk.lua" >bench_small.lua
"$LIGHTCONE" bench --shot bench_small.lua --repeats 1 --seconds 0.05 --threads 2 >bench.log 2>&1 || fail "bench: $(cat bench.log)"
grep -q "rays per core-second on 1 thread" bench.log || fail "bench speed line: $(cat bench.log)"
grep -q "0 of 384 pixels differ in hit kind" bench.log || fail "bench accuracy line: $(cat bench.log)"
e2e_end
