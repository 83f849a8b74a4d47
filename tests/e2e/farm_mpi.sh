#!/usr/bin/env bash
# ctest-labels: slow
# The farm gives the same bytes however it is run: one thread, several
# threads with another stripe count, real mpirun with 2 and 3 ranks (and a
# preview pass); progress lines, the live line on a terminal, the summary,
# an idle master, and farm-bench under mpirun.
source "$(dirname "$0")/lib.sh"
e2e_begin "$@"

use_mpirun  # lib.sh: Open MPI settings for a test, and `mpi N CMD...`
SHOT="$SRC/tests/data/farm/farm_orbit.lua"

# same_frames A B: every EXR and PNG of A is byte-identical in B (EXR
# headers carry no timestamp, so equal pixels give equal files).
same_frames() {
  local n=0
  for f in "$1"/farm_orbit.*.exr "$1"/farm_orbit.*.png; do
    n=$((n + 1))
    cmp -s "$f" "$2/$(basename "$f")" || fail "$(basename "$f") differs between $1 and $2"
  done
  [ "$n" -eq 20 ] || fail "$1 holds $n frame files, expected 20"
}

"$LIGHTCONE" render "$SHOT" --out ref --layers --threads 1 2>ref.log || fail "1-thread render: $(cat ref.log)"
grep -q "render: done: 10 frames" ref.log || fail "no summary: $(cat ref.log)"
grep -q "rays per core-second (1 core)" ref.log || fail "summary lacks rays per core-second: $(cat ref.log)"

"$LIGHTCONE" render "$SHOT" --out t2 --layers --threads 2 --stripes 7 --progress 0.05 2>t2.log || fail "2 threads: $(cat t2.log)"
same_frames ref t2
# Not a terminal: plain progress lines.
grep -Eq "^render: [0-9]+/10 frames, [0-9]+%, .* rays/s" t2.log || fail "no plain progress line: $(cat t2.log)"

mpi 2 "$LIGHTCONE" render "$SHOT" --out m2 --layers 2>m2.log || fail "mpirun -n 2: $(cat m2.log)"
grep -q "2 ranks (a master and 1 worker)" m2.log || fail "not a 2-rank farm: $(cat m2.log)"
same_frames ref m2

mpi 3 "$LIGHTCONE" render "$SHOT" --out m3 --layers --stripes 5 --preview 2 2>m3.log || fail "mpirun -n 3: $(cat m3.log)"
grep -q "3 ranks (a master and 2 workers)" m3.log || fail "not a 3-rank farm: $(cat m3.log)"
same_frames ref m3
[ "$(ls m3/preview/farm_orbit.*.png | wc -l)" -eq 10 ] || fail "previews: $(ls m3/preview)"
# What each frame cost comes back from the workers into the journal:
# `lightcone cost` reads it (the rays as the journal counts them, time spent).
"$LIGHTCONE" cost m3 ref --csv cost.csv >cost.log 2>&1 || fail "lightcone cost: $(cat cost.log)"
grep -q "farm_orbit (m3): 10 frames in the journal" cost.log || fail "cost summary: $(cat cost.log)"
grep -q "^all: 20 frames" cost.log || fail "cost total: $(cat cost.log)"
python3 - cost.csv m3/farm_orbit.journal <<'PY' || fail "cost CSV does not match the journal: $(cat cost.csv)"
import csv, re, sys
rows = [r for r in csv.DictReader(open(sys.argv[1])) if r["frame"] and r["shot"] == "farm_orbit"]
assert len(rows) == 20, len(rows)
journal = {int(m.group(1)): int(m.group(2)) for m in re.finditer(r"frame=(\d+) .* rays=(\d+)", open(sys.argv[2]).read())}
m3 = rows[:10]
assert {int(r["frame"]): int(r["rays"]) for r in m3} == journal, (m3, journal)
assert all(float(r["core_seconds"]) > 0 and int(r["finished"]) > 1.7e9 for r in rows), rows
PY
# What is not a render directory is named; a CSV must be called one.
"$LIGHTCONE" cost nowhere >bad.log 2>&1 && fail "cost of a missing directory: accepted"
grep -q "nowhere: not a directory" bad.log || fail "cost, missing directory: $(cat bad.log)"
mkdir -p plain
"$LIGHTCONE" cost plain >bad.log 2>&1 && fail "cost of a directory without a journal: accepted"
grep -q "plain: no journal" bad.log || fail "cost, no journal: $(cat bad.log)"
"$LIGHTCONE" cost m3 --csv cost.txt >bad.log 2>&1 && fail "cost --csv cost.txt: accepted"
grep -q "cost.txt" bad.log && [ ! -e cost.txt ] || fail "cost --csv cost.txt: $(cat bad.log)"
# The master sleeps while it waits: far less than a core (measured on a job
# of a few seconds; on the tiny one above its start-up would dominate).
mpi 3 "$LIGHTCONE" render "$SHOT" --out mcpu --size 192x120 --supersample 2 --full-supersample 2>mcpu.log \
  || fail "mpirun -n 3, longer job: $(cat mcpu.log)"
pct=$(sed -n 's/.*of CPU in .* (\([0-9]*\)% of one core).*/\1/p' mcpu.log)
[ -n "$pct" ] && [ "$pct" -lt 50 ] || fail "master CPU: $(grep master mcpu.log)"
# The same preview pass without MPI gives the same previews.
"$LIGHTCONE" render "$SHOT" --out p1 --layers --stripes 5 --preview 2 --threads 2 2>p1.log || fail "local preview: $(cat p1.log)"
for f in m3/preview/*.png; do cmp -s "$f" "p1/preview/$(basename "$f")" || fail "preview $(basename "$f") differs"; done

# On a terminal: one live line redrawn in place (carriage return, clear to
# end of line), then the summary on a fresh line.
if command -v script >/dev/null; then
  # Big enough to last a few seconds: the live line is redrawn on a timer.
  script -qec "'$LIGHTCONE' render '$SHOT' --out tty --threads 1 --size 192x120 --supersample 2 --full-supersample" \
    /dev/null >tty.log 2>&1 </dev/null \
    || fail "render on a pty: $(cat tty.log)"
  grep -q $'\r''render: [0-9]*/10 frames' tty.log || fail "no live line on a terminal: $(cat -v tty.log)"
  grep -q $'\x1b\[K' tty.log || fail "live line is not cleared to the end: $(cat -v tty.log)"
  grep -q "render: done: 10 frames" tty.log || fail "no summary on a terminal: $(cat -v tty.log)"
fi

# farm-bench under mpirun: the master's rate of handing out and assembling.
mpi 2 "$LIGHTCONE" farm-bench --size 128x72 --stripes 16 --frames 4 >bench.log 2>&1 || fail "farm-bench: $(cat bench.log)"
grep -Eq "handed out and assembled: [0-9]+ working sets/s" bench.log || fail "farm-bench output: $(cat bench.log)"
grep -q "master CPU" bench.log || fail "farm-bench lacks the master's CPU: $(cat bench.log)"

if ls ref m2 m3 | grep -q tmp; then fail "temporary files left behind"; fi
e2e_end
