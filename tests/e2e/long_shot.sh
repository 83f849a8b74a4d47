#!/usr/bin/env bash
# ctest-labels: slow
# A long shot before its first frame (issue 43, items 7 and 17): the render
# evaluates every frame asked for and meters the exposure of those its
# smoothing reaches, each saying how far it is within 2 s and stopped by a
# SIGTERM within a second, with nothing rendered and the readings made kept;
# a render of a few frames meters only what their smoothing needs, and
# resumes the meter where a stopped one left it.
source "$(dirname "$0")/lib.sh"
e2e_begin "$@"

# long NAME FRAMES [SHOT-FIELDS]: a cheap shot of FRAMES frames.
long() {
  cat >"$WORK/$1.lua" <<LUA
local lc = require "lightcone"
return {
  name = "$1", frames = $2, width = 8, height = 8, ${3:-}
  frame = function(i) return {
    spacetime = lc.kerr{mass = 1, spin = 0.9},
    observer = lc.static_observer{r = 30, theta = 80, phi = i * 1e-4},
    camera = lc.camera{fov = 40}, disk = lc.disk{inner = 6, outer = 15},
  } end,
}
LUA
}

# wait_for LOG PATTERN: waits up to 10 s for PATTERN in LOG; false if it
# does not come.
wait_for() {
  local k
  for k in $(seq 100); do grep -q "$2" "$1" && return 0; sleep 0.1; done
  grep -q "$2" "$1"
}
# stop PID NAME LOG: sends SIGTERM to PID and checks it ends within 2 s with
# 143 (the log said in failures).
stop() {
  local pid="$1" name="$2" log="$3" k rc=0
  CHECKS=$((CHECKS + 1))
  kill -TERM "$pid"
  for k in $(seq 20); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
  if kill -0 "$pid" 2>/dev/null; then
    fail "$name: still running 2 s after SIGTERM: $(cat "$log")"
    kill -9 "$pid"
  fi
  wait "$pid" || rc=$?
  [ "$rc" = 143 ] || fail "$name: exit $rc, expected 143: $(cat "$log")"
}

# (A render that cannot stop is killed: the timeouts below.)
# --- 200,000 frames (minutes of evaluation): progress, then SIGTERM.
long long 200000
"$LIGHTCONE" render long.lua --out long_out --progress 1 2>long.log &
pid=$!
wait_for long.log "render: evaluating the frames: [0-9]*/200000 frames" || fail "survey: no progress in 10 s: $(cat long.log)"
stop $pid survey long.log
grep -q "render: interrupted by SIGTERM while evaluating the frames; nothing was rendered" long.log \
  || fail "survey: $(cat long.log)"
[ ! -e long_out ] || fail "a render stopped in its survey left $(ls long_out)"

# --- Auto exposure, smoothed over 100 frames (300 either side): frames 0-2
# meter 0-302 only, saying so; a SIGTERM stops the meter and keeps what it
# metered, and the next run meters only the rest.
long metered 200000 "auto_exposure = 1, auto_exposure_smoothing = 100,"
"$LIGHTCONE" render metered.lua --out metered_out --frames 0:2 --progress 1 2>stopped.log &
pid=$!
wait_for stopped.log "render: auto exposure: metering: [0-9]*/303 frames" || fail "meter: no progress in 10 s: $(cat stopped.log)"
# A monitor sees the run while it meters.
grep -q " event=run " metered_out/metered.events || fail "no run in the event log while metering"
stop $pid meter stopped.log
grep -q "auto exposure: the readings of frames 0-302 of the shot's 200000" stopped.log || fail "meter: $(cat stopped.log)"
grep -q "render: interrupted by SIGTERM while metering the exposure; nothing was rendered" stopped.log \
  || fail "meter: $(cat stopped.log)"
kept=$(grep -sc '^[0-9]* [0-9a-f]* ' metered_out/metered.meter || true)
kept=${kept:-0}
[ "$kept" -gt 0 ] && [ "$kept" -lt 303 ] || fail "the stopped meter kept $kept readings: $(head -3 metered_out/metered.meter)"
ls metered_out | grep -q png && fail "a render stopped in its meter left frames: $(ls metered_out)"
timeout -k 5 60 "$LIGHTCONE" render metered.lua --out metered_out --frames 0:2 --progress 0 2>resumed.log || fail "resume: $(cat resumed.log)"
grep -q "auto exposure: $kept readings kept from metered_out/metered.meter, $((303 - kept)) metered" resumed.log \
  || fail "the resumed meter: $(cat resumed.log)"
# ... and the frames are those of a meter made in one go.
timeout -k 5 60 "$LIGHTCONE" render metered.lua --out one_go --frames 0:2 --progress 0 2>one_go.log || fail "one go: $(cat one_go.log)"
same_frames metered_out one_go metered

# --- Smoothed over 10,000 frames (30,000 either side): frame 0's meter
# needs 30,001 readings, keyed (each frame evaluated) as they are taken, so
# it is said and stoppable at once, not after evaluating all of them.
long wide 200000 "auto_exposure = 1, auto_exposure_smoothing = 10000,"
"$LIGHTCONE" render wide.lua --out wide_out --frames 0 --progress 1 2>wide.log &
pid=$!
wait_for wide.log "render: auto exposure: metering: [0-9]*/30001 frames" || fail "wide meter: no progress in 10 s: $(cat wide.log)"
stop $pid wide_meter wide.log

e2e_end
