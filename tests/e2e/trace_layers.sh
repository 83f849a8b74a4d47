#!/usr/bin/env bash
# What a new user copies from the docs works as they say:
#   1. README.md's `lightcone trace` example looks at a pixel on the disk
#      (it once looked into the shadow).
#   2. `trace --json` is one JSON object on standard output holding what
#      the text report holds (the same values), docs/cli.md's example is
#      what the binary prints, and the path goes to -o only.
#   3. docs/layers.md's Python reader (Debian's python3-openimageio), run
#      as written on a frame rendered with --layers, prints what the docs
#      say and what `trace` reports for that pixel: channels looked up by
#      name, data[row, column] against --pixel column,row.
#   4. `lightcone --version` names the Open MPI it was built with, the one
#      mpirun here is.
#   5. docs/layers.md's second reader, for a pip or conda Python (numpy
#      alone, docs/python/lightcone_exr.py), run as written with OpenImageIO
#      unimportable, prints the same and reads every channel as OIIO does.
source "$(dirname "$0")/lib.sh"
e2e_begin "$@"
SHOT="$SRC/shots/bench/kerr_disk.lua"

# 1. The README's example, as written there (with this build's binary and the
# source tree's shot).
CHECKS=$((CHECKS + 1))
example=$(grep -o 'lightcone trace shots/[^#]*' "$SRC/README.md" | head -1)
[ -n "$example" ] || fail "README.md has no lightcone trace example"
read -r -a words <<<"${example#lightcone }"
words[1]="$SRC/${words[1]}"
"$LIGHTCONE" "${words[@]}" --json >readme.json 2>readme.err || fail "README example: $(cat readme.err)"
hit=$("$PY" -c 'import json, sys; print(json.load(open(sys.argv[1]))["hit"])' readme.json 2>&1)
[ "$hit" = disk ] || fail "README's trace example ($example) hits '$hit', not the disk"

# 2. --json against the text report, and the path only with -o.
CHECKS=$((CHECKS + 1))
"$LIGHTCONE" trace "$SHOT" --frame 0 --pixel 180,150 >path.csv 2>text.err || fail "trace: $(cat text.err)"
"$LIGHTCONE" trace "$SHOT" --frame 0 --pixel 180,150 --json >report.json 2>json.err || fail "trace --json: $(cat json.err)"
[ ! -s json.err ] || fail "trace --json wrote to standard error: $(cat json.err)"
"$LIGHTCONE" trace "$SHOT" --frame 0 --pixel 180,150 --json -o with_o.csv >with_o.json 2>/dev/null || fail "trace --json -o failed"
cmp -s path.csv with_o.csv || fail "trace --json -o FILE: the CSV differs from trace's standard output"
cmp -s report.json with_o.json || fail "trace --json -o FILE: the report differs from --json alone"
"$PY" - report.json text.err "$SRC/docs/cli.md" <<'PY' || fail "trace --json does not hold what the text report holds"
import json, re, struct, sys
text = open(sys.argv[2]).read()
try:
    report = json.loads(open(sys.argv[1]).read())  # the whole output: one object
except ValueError as e:
    sys.exit(f"not one JSON object: {e}")
m = re.match(r"trace: frame (\d+) pixel (\d+),(\d+): hit (\S+)(?: at (.+?))?, stop reason (\S+), (\d+) steps; (.*); colour (\S+) (\S+) (\S+)$", text.strip())
if not m:
    sys.exit(f"text report not as expected: {text}")
f32 = lambda v: struct.unpack("f", struct.pack("f", float(v)))[0]
want = {"frame": int(m[1]), "pixel": [int(m[2]), int(m[3])], "hit": m[4], "end": m[5], "stop_reason": m[6], "steps": int(m[7])}
for k, v in want.items():
    if report.get(k) != v:
        sys.exit(f"{k}: JSON {report.get(k)!r}, text {v!r}")
layers = dict(p.split(" ") for p in m[8].split(", "))
if list(report["layers"]) != list(layers):
    sys.exit(f"layers: JSON {list(report['layers'])}, text {list(layers)}")
for k, v in layers.items():  # the text's 9 digits give the float back
    if f32(v) != f32(report["layers"][k]):
        sys.exit(f"{k}: JSON {report['layers'][k]}, text {v}")
for a, b in zip(report["colour"], m.groups()[8:]):
    if abs(a - float(b)) > 5e-4 * max(1, abs(a)):
        sys.exit(f"colour: JSON {report['colour']}, text {m.groups()[8:]}")
# docs/cli.md shows this very output.
if json.dumps(report) not in open(sys.argv[3]).read():
    sys.exit(f"docs/cli.md's trace --json example is not what the binary prints: {json.dumps(report)}")
PY

# 3. docs/layers.md's reader, as written, on the frame it names.
CHECKS=$((CHECKS + 1))
"$LIGHTCONE" render "$SHOT" --out out/kerr --layers --progress 0 >render.log 2>&1 || fail "render --layers: $(cat render.log)"
"$PY" - "$SRC/docs/layers.md" <<'PY' >reader.py || fail "docs/layers.md has no Python reader"
import re, sys
blocks = re.findall(r"```python\n(.*?)```", open(sys.argv[1]).read(), re.S)
if not blocks:
    sys.exit(1)
print(blocks[0], end="")
PY
grep -q '"out/kerr/kerr_disk.0000.exr"' reader.py || fail "docs/layers.md's reader no longer reads out/kerr/kerr_disk.0000.exr"
got=$("$PY" reader.py 2>&1) || fail "docs/layers.md's reader failed: $got"
said=$(grep -o 'prints `[^`]*`' "$SRC/docs/layers.md" | head -1 | sed 's/prints `\(.*\)`/\1/')
[ "$got" = "$said" ] || fail "docs/layers.md's reader printed '$got'; the docs say '$said'"
"$PY" - "$got" report.json <<'PY' || fail "docs/layers.md's reader and trace disagree on hit.r of pixel 180,150"
import json, sys
r = json.load(open(sys.argv[2]))["layers"]["hit.r"]
if float(sys.argv[1]) != r:
    sys.exit(f"reader {sys.argv[1]}, trace {r}")
PY

# 4. --version says which MPI.
CHECKS=$((CHECKS + 1))
"$LIGHTCONE" --version >version.out 2>&1 || fail "--version failed: $(cat version.out)"
mpi=$(mpirun --version 2>/dev/null | sed -n 's/^mpirun (Open MPI) \([0-9.]*\).*/\1/p')
[ -n "$mpi" ] || fail "mpirun --version names no Open MPI version"
grep -q "^MPI: Open MPI $mpi (built against; loaded: Open MPI v$mpi)" version.out ||
  fail "--version does not name Open MPI $mpi: $(cat version.out)"

# 5. docs/layers.md's reader for a pip or conda Python (numpy alone:
# docs/python/lightcone_exr.py), as written, with OpenImageIO unimportable:
# it prints what the docs say, and reads every channel of the frame exactly
# as OpenImageIO does.
CHECKS=$((CHECKS + 1))
"$PY" - "$SRC/docs/layers.md" <<'PY' >reader_numpy.py || fail "docs/layers.md has no second Python reader"
import re, sys
blocks = re.findall(r"```python\n(.*?)```", open(sys.argv[1]).read(), re.S)
if len(blocks) < 2:
    sys.exit(1)
print(blocks[1], end="")
PY
grep -q 'import lightcone_exr' reader_numpy.py || fail "docs/layers.md's second reader does not use lightcone_exr"
mkdir -p docs && cp -r "$SRC/docs/python" docs/
got=$("$PY" -c 'import sys; sys.modules["OpenImageIO"] = None; exec(open("reader_numpy.py").read())' 2>&1) ||
  fail "docs/layers.md's numpy reader failed: $got"
[ "$got" = "$said" ] || fail "docs/layers.md's numpy reader printed '$got'; the docs say '$said'"
"$PY" - out/kerr/kerr_disk.0000.exr <<'PY' || fail "docs/python/lightcone_exr.py and OpenImageIO disagree"
import sys
import numpy as np
import OpenImageIO as oiio
sys.path.insert(0, "docs/python")
import lightcone_exr
frame = lightcone_exr.read(sys.argv[1])
exr = oiio.ImageInput.open(sys.argv[1])
names, data = exr.spec().channelnames, exr.read_image("float")
if sorted(frame.channels) != sorted(names):
    sys.exit(f"channels {sorted(frame.channels)}, OpenImageIO {sorted(names)}")
for c in names:
    if not np.array_equal(frame.channels[c], data[:, :, names.index(c)], equal_nan=True):
        sys.exit(f"channel {c} differs")
if frame.header.get("lightcone/shot") != "kerr_disk":
    sys.exit(f"header: {frame.header}")
PY
# A file it cannot read is refused with its name, not misread.
printf 'not an exr' >bad.exr
bad=$("$PY" -c 'import sys; sys.path.insert(0, "docs/python"); import lightcone_exr; lightcone_exr.read("bad.exr")' 2>&1) &&
  fail "lightcone_exr read a file that is no EXR"
grep -q 'bad.exr: not an OpenEXR file' <<<"$bad" || fail "lightcone_exr's refusal does not name the file: $bad"

e2e_end
