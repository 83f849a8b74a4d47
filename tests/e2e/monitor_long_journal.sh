#!/usr/bin/env bash
# `lightcone monitor` on a 100,000-frame journal (docs/monitor.md, "Long
# renders"): the first request parses it whole, later polls only what was
# appended since, so a poll costs little CPU and memory however long the
# film; frames appended between polls are counted at once, and a journal
# rewritten under the monitor is read afresh.
source "$(dirname "$0")/lib.sh"
e2e_begin "$@"

tiny_fall_render out
# Frames FROM to TO-1 as the render's journal lines (with FROM 0, a whole journal).
lines() { "$PY" "$SRC/tests/tools/journal_frames.py" out/kerr_fall.journal "$1" "$2"; }
lines 0 100000 >long.journal
mv long.journal out/kerr_fall.journal

start_monitor out
status() { curl -s --max-time 30 "$URL/api/status?folder=0&shot=kerr_fall"; }
field() { $PY -c "import json,sys; d=json.load(sys.stdin); print(eval(sys.argv[1]))" "$1"; }
# The monitor's CPU time so far, in ms (utime + stime of /proc/PID/stat).
cpu_ms() { awk -v hz="$(getconf CLK_TCK)" '{print int(($14 + $15) * 1000 / hz)}' "/proc/$MONITOR/stat"; }

# The first request parses it all; 10 polls after it must not.
[ "$(status | field 'd["frames"]["stale"] + len(d["latest"])')" -ge 1 ] || fail "the first status: $(status | head -c 300)"
base=$(awk '/^VmRSS:/ {print $2}' "/proc/$MONITOR/status")
before=$(cpu_ms)
for _ in $(seq 1 10); do status >status.json; done
polls=$(($(cpu_ms) - before))
echo "10 polls of a 100,000-frame journal: $polls ms CPU"
[ "$polls" -lt 2000 ] || fail "10 polls of an unchanged 100,000-frame journal took $polls ms of CPU"
grep -q '"latest": \[99999,' status.json || fail "the latest frames: $(grep -o '"latest": [^]]*]' status.json)"

# Frames appended between polls are counted by the next one, parsing only them.
lines 100000 100050 >>out/kerr_fall.journal
before=$(cpu_ms)
status >status.json
appended=$(($(cpu_ms) - before))
echo "a poll after 50 frames were appended: $appended ms CPU"
grep -q '"latest": \[100049,' status.json || fail "the appended frames: $(grep -o '"latest": [^]]*]' status.json)"
curl -s --max-time 30 "$URL/api/frames?folder=0&shot=kerr_fall&from=100040&count=5" >frames.json
grep -q '"total": 100050' frames.json || fail "the frames' total: $(head -c 200 frames.json)"
hwm=$(awk '/^VmHWM:/ {print $2}' "/proc/$MONITOR/status")
echo "monitor: VmRSS $base kB after the first request, VmHWM $hwm kB after the polls"
[ $((${hwm:-999999} - ${base:-0})) -lt 65536 ] || fail "the polls grew the monitor's memory from $base to $hwm kB"

# Rewritten under the monitor (a shorter journal in its place): read afresh.
lines 0 10 >short.journal
mv short.journal out/kerr_fall.journal
curl -s --max-time 30 "$URL/api/frames?folder=0&shot=kerr_fall&count=1" | grep -q '"total": 10' \
  || fail "a journal replaced by a shorter one: $(curl -s "$URL/api/frames?folder=0&shot=kerr_fall&count=1" | head -c 200)"
e2e_end
