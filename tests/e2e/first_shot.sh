#!/usr/bin/env bash
# ctest-labels: slow
# docs/first_shot.md, followed as a new user would, on the shot it builds
# (shots/circling.lua), at sizes small enough for a test: every command
# works, the misspelt-field example is reported as the guide says, the
# framing holds the disk, and the sphere the clock animates is in view.
source "$(dirname "$0")/lib.sh"
e2e_begin "$@"

mkdir myshots
cp "$SRC/shots/circling.lua" myshots/

# 1. inspect: two scenes, the clock, what the engine made of them.
"$LIGHTCONE" inspect myshots/circling.lua --frames 0:1 >inspect.json 2>inspect.log || fail "inspect: $(cat inspect.log)"
python3 - <<'PY' || fail "inspect JSON"
import json
d = json.load(open('inspect.json'))
s = d['scenes']
assert [x['frame'] for x in s] == [0, 1], s
assert abs(s[0]['observer']['position']['t'] - 40) < 1e-9, s[0]['observer']
assert s[1]['observer']['position']['t'] > 40
assert 'tetrad' in s[0]['evaluated']['observer'] and 'forward' in s[0]['evaluated']['camera']
PY
line=$(grep -n "disk = lc.disk" myshots/circling.lua | cut -d: -f1)
sed 's/inner = 6/iner = 6/' myshots/circling.lua >myshots/misspelt.lua
expect_error misspelt "misspelt.lua:$line: disk: unknown field 'iner' (did you mean 'inner'?)" -- \
  "$LIGHTCONE" inspect myshots/misspelt.lua --frames 0:1

# 4. a few small frames in their own folder, and a contact sheet.
"$LIGHTCONE" render myshots/circling.lua --out out/circling_preview --scale 0.1 --supersample 1 --frames 0:239:120 \
  --progress 0 2>preview.log || fail "preview render: $(cat preview.log)"
[ -s out/circling_preview/circling.0120.png ] || fail "no preview frame 120"
"$LIGHTCONE" contact-sheet out/circling_preview -o out/circling_sheet.png 2>sheet.log || fail "contact-sheet: $(cat sheet.log)"
iinfo out/circling_sheet.png >/dev/null || fail "the contact sheet is not an image"

# What frame 120 shows: the disk fits the view (no disk pixel on the left or
# right edge), the orbiting sphere is seen (hit.kind 3), nothing gave up (4).
"$LIGHTCONE" render myshots/circling.lua --out out/layers --size 96x54 --supersample 1 --frames 120 --layers \
  --progress 0 2>layers.log || fail "layers render: $(cat layers.log)"
oiiotool out/layers/circling.0120.exr --ch hit.kind --printstats >kind.stats 2>&1 || fail "oiiotool: $(cat kind.stats)"
grep -q "Stats Max: 3.000000" kind.stats || fail "frame 120 should show the sphere and no gave-up ray: $(cat kind.stats)"
for edge in 0 95; do
  oiiotool out/layers/circling.0120.exr --ch hit.kind --cut 1x54+$edge+0 --printstats >edge.stats 2>&1
  grep -q "Stats Max: 0.000000" edge.stats || fail "column $edge is not all sky: the disk is cut off ($(grep Max edge.stats))"
done

# 5. render (here three tiny frames) and encode.
"$LIGHTCONE" render myshots/circling.lua --out out/circling --preview 2 --progress 30 --scale 0.05 --frames 0:2 \
  2>render.log || fail "render: $(cat render.log)"
"$LIGHTCONE" encode out/circling -o circling.mp4 2>encode.log || fail "encode: $(cat encode.log)"
check_probe circling.mp4 codec_name=h264 nb_read_frames=3
e2e_end
