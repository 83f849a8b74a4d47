#!/usr/bin/env bash
# Memory stays bounded whatever the size of an input (issue #25): a star
# catalogue of one 512 MB line, a journal with a 512 MB junk line, and a
# contact sheet of an 8192x8192 frame are each handled in well under their
# size (before: the catalogue peaked at ~1.2 GB, the journal at ~2x its
# line, the sheet at ~12 bytes a pixel, 0.8 GB and more).  Peaks are each
# process's maximum resident set, as the kernel counts it.  The big files
# are sparse (holes of zero bytes), so they cost no disk.
source "$(dirname "$0")/lib.sh"
e2e_begin "$@"

# max_rss_mb CMD...: runs CMD (its output to $WORK/rss.out and rss.err) and
# prints its peak resident memory in MB; CMD's exit status is in rss.rc.
max_rss_mb() {
  python3 - "$@" <<'PY'
import resource, subprocess, sys
with open("rss.out", "wb") as out, open("rss.err", "wb") as err:
    rc = subprocess.run(sys.argv[1:], stdout=out, stderr=err).returncode
open("rss.rc", "w").write(str(rc))
print(resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss // 1024)
PY
}
# sparse FILE BEFORE BYTES AFTER: BEFORE, then BYTES zero bytes (a hole),
# then AFTER.
sparse() {
  python3 - "$@" <<'PY'
import sys
path, before, n, after = sys.argv[1], sys.argv[2].encode(), int(sys.argv[3]), sys.argv[4].encode()
with open(path, "wb") as f:
    f.write(before)
    f.seek(len(before) + n)
    f.write(after)
PY
}
limit=400  # MB: what lightcone needs for a tiny frame, with room to spare
big=$((512 * 1024 * 1024))

cat >tiny.lua <<'LUA'
local lc = require "lightcone"
return {
  name = "tiny", frames = 2, width = 16, height = 16,
  frame = function(i) return {
    spacetime = lc.kerr{mass = 1, spin = 0.9}, observer = lc.static_observer{r = 30, theta = 80, phi = i},
    sky = lc.starfield{catalogue = "kstars"},
  } end,
}
LUA

# --- a star catalogue of one 512 MB line: refused at its line, in bounded memory
sparse big.dat "" "$big" $'\n'
mb=$(LIGHTCONE_STAR_CATALOGUE="$WORK/big.dat" max_rss_mb "$LIGHTCONE" render tiny.lua --out cat_out)
[ "$(cat rss.rc)" != 0 ] || fail "catalogue: a 512 MB line was accepted"
grep -qF "big.dat:1: the line is longer than 1024 bytes" rss.err || fail "catalogue: $(cat rss.err)"
[ "$mb" -lt "$limit" ] || fail "catalogue: peak $mb MB for a catalogue of one long line"
echo "catalogue of one 512 MB line: peak $mb MB"

# --- a journal with a 512 MB junk line: skipped as a bad line, in bounded memory
star='064508.92 -164258.0 -000546.0-001223.100379.2 -1.4400.01A0 1'
printf '%s\n' "$star" >stars.dat
export LIGHTCONE_STAR_CATALOGUE="$WORK/stars.dat"
"$LIGHTCONE" render tiny.lua --out frames --frames 0 2>render.log || fail "render: $(cat render.log)"
head -1 frames/tiny.journal >header
tail -n +2 frames/tiny.journal >rest
sparse frames/tiny.journal "$(cat header)"$'\n' "$big" $'\n'"$(cat rest)"$'\n'
mb=$(max_rss_mb "$LIGHTCONE" cost frames)
[ "$(cat rss.rc)" = 0 ] || fail "cost: $(cat rss.err)"
grep -q "1 frame" rss.out || fail "cost lost the frame after the junk line: $(cat rss.out)"
[ "$mb" -lt "$limit" ] || fail "cost: peak $mb MB for a journal with a 512 MB junk line"
echo "cost, journal with a 512 MB junk line: peak $mb MB"
mb=$(max_rss_mb "$LIGHTCONE" render tiny.lua --out frames)
[ "$(cat rss.rc)" = 0 ] || fail "render after the junk line: $(cat rss.err)"
[ "$mb" -lt "$limit" ] || fail "render: peak $mb MB for a journal with a 512 MB junk line"
echo "render, journal with a 512 MB junk line: peak $mb MB"

# --- a contact sheet of one 8192x8192 frame: read in bands of rows
mkdir -p huge
python3 - huge/huge.0000.png <<'PY'
import struct, sys, zlib
w = h = 8192
def chunk(kind, data):
    return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))
z = zlib.compressobj(1)
row = b"\0" + bytes(range(256)) * (3 * w // 256)  # a grey ramp; filter byte 0
data = b"".join(z.compress(row) for _ in range(h)) + z.flush()
with open(sys.argv[1], "wb") as f:
    f.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 2, 0, 0, 0)) + chunk(b"IDAT", data) + chunk(b"IEND", b""))
PY
mb=$(max_rss_mb "$LIGHTCONE" contact-sheet huge -o huge_sheet.png)
[ "$(cat rss.rc)" = 0 ] || fail "contact-sheet: $(cat rss.err)"
[ -s huge_sheet.png ] || fail "contact-sheet wrote no sheet"
[ "$mb" -lt "$limit" ] || fail "contact-sheet: peak $mb MB for one 8192x8192 frame"
echo "contact sheet of one 8192x8192 frame: peak $mb MB"
rm -f big.dat huge/huge.0000.png frames/tiny.journal
e2e_end
