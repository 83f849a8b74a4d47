#!/usr/bin/env bash
# `lightcone plot`: a geodesic CSV drawn as SVG and PNG of the size asked
# for, whose curves are the CSV's points (one ray checked point by point),
# cut where they meet the disk and dashed from its bottom side; bad input is
# refused naming the flag or the line, leaving no file.
source "$(dirname "$0")/lib.sh"
e2e_begin "$@"

# The paper's Figure 2 setup with fewer, shorter rays.
sed -e 's/for k = -14, 14 do/for k = -8, 8, 4 do/' -e 's/samples = 441/samples = 121/' \
  "$SRC/shots/geodesics/disk_arches.lua" >arches.lua
"$LIGHTCONE" geodesic arches.lua -o arches.csv 2>geo.log || fail "geodesic: $(cat geo.log)"
"$LIGHTCONE" plot arches.csv -o arches.svg --disk 6:16 --horizon 2 --extent 24 --size 640x480 2>svg.log \
  || fail "plot svg: $(cat svg.log)"
grep -q "plot: 5 curves, [1-5] end on the disk" svg.log || fail "plot summary: $(cat svg.log)"
"$LIGHTCONE" plot arches.csv -o arches.png --size 320x240 2>png.log || fail "plot png: $(cat png.log)"

python3 - arches.csv arches.svg arches.png <<'PY' || fail "the figures do not show the CSV"
import csv, math, re, struct, sys, xml.etree.ElementTree as ET
lines = open(sys.argv[1]).read().splitlines()
assert lines[0] == "# chart: bl (t, r, theta, phi; kerr)", lines[0]
rows = list(csv.DictReader(lines[1:]))
# The PNG: a real PNG of the size asked for.
png = open(sys.argv[3], "rb").read()
assert png[:8] == b"\x89PNG\r\n\x1a\n", "not a PNG"
w, h = struct.unpack(">II", png[16:24])
assert (w, h) == (320, 240), (w, h)
# The SVG: well-formed, 640x480 pixels.
root = ET.parse(sys.argv[2]).getroot()
assert root.get("width") in ("640", "640px") and root.get("height") in ("480", "480px"), root.attrib
# A path's presentation properties, from its style (Cairo 1.16) or its
# attributes (Cairo 1.18 writes fill="none" stroke-width="1.5" ...).
def props(p):
    out = {k: v for k, v in p.attrib.items() if k != "d"}
    for decl in (p.get("style") or "").split(";"):
        if ":" in decl:
            k, v = decl.split(":", 1)
            out[k.strip()] = v.strip()
    return out
paths = [p for p in root.iter("{http://www.w3.org/2000/svg}path") if props(p).get("stroke-width") == "1.5"]
def points(d):
    nums = [float(x) for x in re.findall(r"-?\d+(?:\.\d+)?(?:e-?\d+)?", d)]
    return list(zip(nums[0::2], nums[1::2]))
# Each ray's side view (x, z), pseudo-Cartesian from Boyer-Lindquist.
rays = {}
for r in rows:
    rr, th, ph = float(r["x1"]), float(r["x2"]), float(r["x3"])
    rays.setdefault(r["ray"], []).append((rr * math.sin(th) * math.cos(ph), rr * math.cos(th)))
# Ray 1 (looking 8 degrees below the hole) is drawn up to where it meets
# the disk (z = 0, between the two samples either side): its vertices are
# its CSV rows under one scale and shift.  (Cairo merges runs of collinear
# segments, so a vertex may stand for several rows, which then lie on its
# segments.)
ray = rays["1"]
cut = next(i for i in range(1, len(ray)) if (ray[i - 1][1] > 0) != (ray[i][1] > 0) and 6 <= abs(ray[i][0]) <= 16)
(x0, z0), (x1, z1) = ray[cut - 1], ray[cut]
crossing = (x0 + z0 / (z0 - z1) * (x1 - x0), 0.0)
want = ray[:cut] + [crossing]
def seg_dist(p, a, b):
    ux, uy = b[0] - a[0], b[1] - a[1]
    t = max(0.0, min(1.0, ((p[0] - a[0]) * ux + (p[1] - a[1]) * uy) / max(ux * ux + uy * uy, 1e-300)))
    return math.hypot(a[0] + t * ux - p[0], a[1] + t * uy - p[1])
match = None
for p in paths:
    pts = points(p.get("d"))
    (ax, ay), (bx, by) = pts[0], pts[-1]
    if want[-1][0] == want[0][0]:
        continue
    sx = (bx - ax) / (want[-1][0] - want[0][0])
    sy = -sx  # equal scales, y pointing down
    mapped = [(ax + sx * (x - want[0][0]), ay + sy * (z - want[0][1])) for x, z in want]
    if math.hypot(mapped[-1][0] - bx, mapped[-1][1] - by) > 0.02:
        continue
    # Every vertex is a row, in order ...
    j, ok = 0, True
    for v in pts:
        while j < len(mapped) and math.hypot(mapped[j][0] - v[0], mapped[j][1] - v[1]) > 0.02:
            j += 1
        ok = ok and j < len(mapped)
    # ... and every row lies on the drawn line.
    ok = ok and all(min(seg_dist(m, pts[k], pts[k + 1]) for k in range(len(pts) - 1)) < 0.02 for m in mapped)
    if ok:
        match = (p, pts, sx)
assert match, "no SVG path is ray 1's points"
p, pts, sx = match
# It came from the disk's bottom side: dashed.
assert "stroke-dasharray" in props(p), props(p)
print("ray 1:", cut, "rows drawn,", len(pts), "vertices, scale", sx, "px/M")
PY

# Bad input: named, non-zero, no file left.
expect_fail() {  # expect_fail WHAT PATTERN ARGS...
  local what=$1 pattern=$2
  shift 2
  if "$LIGHTCONE" plot "$@" >bad.log 2>&1; then fail "$what: accepted"; fi
  grep -q -- "$pattern" bad.log || fail "$what: $(cat bad.log)"
}
expect_fail "a PDF" "-o arches.pdf: a figure is written as SVG or PNG" arches.csv -o arches.pdf
expect_fail "a bad disk" "--disk 16:6: expected INNER:OUTER" arches.csv -o x.svg --disk 16:6
printf 'ray,lambda,x0,x1,x2,x3\n1,0,0,10,1.5,0\n1,1,0,nan?,1.5,0\n' >broken.csv
expect_fail "a broken row" "broken.csv:3: column x1 is 'nan?'" broken.csv -o x.svg
# Finite but huge coordinates gave a blank figure "inf M across" (issue #25).
printf 'ray,lambda,x0,x1,x2,x3\n1,0,0,10,1.5,0\n1,1,0,1e308,1.5,0\n' >huge.csv
expect_fail "a huge radius" "huge.csv:3: the point (9.97495e+307, 0, 7.07372e+306) M is too far out: plot draws points within 1e+12 M" huge.csv -o x.svg
printf 'ray,lambda,x0,x1,x2,x3\n1,0,0,10,1.5,0\n1,1,0,-1e308,1e308,0\n' >huge_xyz.csv
expect_fail "huge Cartesian coordinates" "huge_xyz.csv:3: the point" huge_xyz.csv -o x.png --coordinates cartesian
printf 'ray,lambda,x0,x1,x2,x3\n1e300,0,0,10,1.5,0\n' >huge_ray.csv
expect_fail "a huge ray number" "huge_ray.csv:2: column ray is '1e300', not a whole number from 1 to 1e9" huge_ray.csv -o x.svg
expect_fail "a huge extent" "--extent 1e+300: must be a positive number of M, at most 1e+12" arches.csv -o x.svg --extent 1e300
expect_fail "a huge disk" "--disk 6:1e300: expected INNER:OUTER" arches.csv -o x.svg --disk 6:1e300
python3 -c "import sys; sys.stdout.write('ray,lambda,x0,x1,x2,x3\\n1,0,0,10,1.5,0\\n' + '1' * 100000 + '\\n')" >long.csv
expect_fail "an overlong line" "long.csv:3: the line is longer than 16384 bytes" long.csv -o x.svg
printf 'a,b\n1,2\n' >other.csv
expect_fail "another CSV" "other.csv:1: no column x0" other.csv -o x.svg
head -2 arches.csv >empty.csv
expect_fail "a header alone" "empty.csv: a header but no rows" empty.csv -o x.svg
expect_fail "a tiny figure" "--size 10x10: a figure is 200x150" arches.csv -o x.svg --size 10x10
expect_fail "a negative extent" "--extent -1: must be a positive number" arches.csv -o x.svg --extent -1
expect_fail "a negative horizon" "--horizon -2: must be a radius" arches.csv -o x.svg --horizon -2
expect_fail "an unknown view" "--view" arches.csv -o x.svg --view side
# The CSV records its chart, so plot reads a dihole's x1..x3 as Cartesian
# without being told; a CSV from before the chart line is read as it was
# (bl, or as --coordinates says), and a flag that contradicts a recorded
# chart is refused.
cat >osc.lua <<'LUA'
local lc = require "lightcone"
return {spacetime = lc.dihole{m1 = 0.4, m2 = 0.4, d = 1}, curve = "timelike", start = {x = 5, y = 0, z = 0},
        velocity = {x = 0, y = 0.1, z = 0}, stop = {coordinate_time = 60}, samples = 61}
LUA
"$LIGHTCONE" geodesic osc.lua -o osc.csv 2>osc.log || fail "geodesic osc: $(cat osc.log)"
[ "$(head -1 osc.csv)" = "# chart: cartesian (t, x, y, z; dihole)" ] || fail "osc chart line: $(head -1 osc.csv)"
"$LIGHTCONE" plot osc.csv -o osc.svg --view xy 2>osc_plot.log || fail "plot osc: $(cat osc_plot.log)"
tail -n +2 osc.csv >old_osc.csv
"$LIGHTCONE" plot old_osc.csv -o old_cart.svg --view xy --coordinates cartesian 2>old.log || fail "plot old CSV: $(cat old.log)"
cmp -s osc.svg old_cart.svg || fail "the chart line and --coordinates cartesian draw different figures"
"$LIGHTCONE" plot old_osc.csv -o old_bl.svg --view xy 2>old_bl.log || fail "plot old CSV as bl: $(cat old_bl.log)"
cmp -s osc.svg old_bl.svg && fail "an old CSV without --coordinates was not read as bl"
expect_fail "a contradicting flag" "--coordinates bl: osc.csv records its chart as cartesian (its first line); drop --coordinates" \
  osc.csv -o x.svg --coordinates bl
{ echo "# chart: polar (t, r, theta, phi; kerr)"; tail -n +2 arches.csv; } >badchart.csv
expect_fail "an unknown chart" "badchart.csv:1: chart 'polar' is not one lightcone knows (bl or cartesian)" badchart.csv -o x.svg
"$LIGHTCONE" plot --help | grep -q "bl (r, theta, phi: kerr, kottler, ellis_wormhole, interstellar_wormhole; the default) or cartesian (x, y, z: minkowski, dihole, majumdar_papapetrou)" \
  || fail "plot --help does not list the spacetimes of each chart: $("$LIGHTCONE" plot --help | grep -A3 coordinates)"
[ ! -e x.svg ] && [ ! -e arches.pdf ] || fail "a refused plot left a file"
ls | grep -q tmp && fail "temporary files left behind"
e2e_end
