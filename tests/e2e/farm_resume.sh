#!/usr/bin/env bash
# ctest-labels: slow
# Stop a render with SIGKILL at several points and resume it each time;
# under mpirun kill one worker rank (the job aborts) and resume; stop it
# with Ctrl-C (SIGINT) and SIGTERM, alone and under mpirun.  The final
# frames must equal an uninterrupted render's byte for byte, no frame may be
# journalled twice, and no half-written file may ever sit under a frame's
# final name.
#
# Every stop happens at a known point, whatever the machine's speed: the
# test hook LIGHTCONE_TEST_PAUSE_AFTER=N makes each render process (each
# worker rank) hold its working sets after N of them and say so with its
# pid, so the test kills or interrupts a render that is certainly mid-job
# (a sleep-based kill once found the worker already gone).
source "$(dirname "$0")/lib.sh"
e2e_begin "$@"

use_mpirun  # lib.sh: Open MPI settings for a test
SHOT="$SRC/tests/data/farm/farm_orbit.lua"
ARGS=(--supersample 2 --full-supersample --progress 0)  # 10 frames of 40 stripes: 400 working sets

"$LIGHTCONE" render "$SHOT" --out ref --threads 2 "${ARGS[@]}" 2>ref.log || fail "reference render: $(cat ref.log)"

# check_store DIR: every EXR under a final name is a complete image, and
# the journal lists each frame at most once.
check_store() {
  for f in "$1"/farm_orbit.*.exr; do
    [ -e "$f" ] || continue
    iinfo "$f" >/dev/null 2>&1 || fail "$f is not a complete EXR"
  done
  if [ -f "$1/farm_orbit.journal" ]; then
    dup=$(grep -o '^frame=[0-9]*' "$1/farm_orbit.journal" | sort | uniq -d)
    [ -z "$dup" ] || fail "frames journalled twice (rendered again after they were finished): $dup"
  fi
}

same_frames() {
  for f in ref/farm_orbit.*.exr ref/farm_orbit.*.png; do
    cmp -s "$f" "$1/$(basename "$f")" || fail "$1: $(basename "$f") differs from the uninterrupted render"
  done
  if ls "$1" | grep -q tmp; then fail "$1: temporary files left: $(ls "$1")"; fi
}

# The journal's frame lines (0 without a journal).
frames_done() { cat "$1/farm_orbit.journal" 2>/dev/null | grep -c '^frame=' || true; }

# wait_paused LOG COUNT PID [DIR FRAMES]: until LOG shows COUNT processes
# paused by the test hook (and, with DIR, its journal FRAMES frames: the
# frames finished before the pause are stored by a writer thread, a little
# later).  Fails if the render ends first: it cannot, while its sets are held.
wait_paused() {
  local log="$1" count="$2" pid="$3" dir="${4:-}" frames="${5:-1}"
  for _ in $(seq 1 1200); do
    if [ "$(grep -c 'test pause: pid' "$log" 2>/dev/null)" -ge "$count" ] &&
       { [ -z "$dir" ] || [ "$(frames_done "$dir")" -ge "$frames" ]; }; then
      return 0
    fi
    kill -0 "$pid" 2>/dev/null || { fail "$log: the render ended before it paused: $(cat "$log")"; return 1; }
    sleep 0.05
  done
  fail "$log: no pause in 60 s: $(cat "$log")"
  return 1
}

# --- SIGKILL, four times: before the first set, then after 90 more sets
# each time (two frames and a bit), so every round makes progress and
# every kill lands while the render holds unfinished work.
for round in 1 2 3 4; do
  sets=$([ "$round" -eq 1 ] && echo 0 || echo 90)
  before=$(frames_done local)
  LIGHTCONE_TEST_PAUSE_AFTER=$sets "$LIGHTCONE" render "$SHOT" --out local --threads 2 "${ARGS[@]}" \
    2>"local.$round.log" &
  pid=$!
  wait_paused "local.$round.log" 1 "$pid" local $((before + (round > 1 ? 2 : 0)))
  kill -9 "$pid" 2>/dev/null || fail "round $round: the render was gone before the kill"
  wait "$pid" 2>/dev/null || true
  check_store local
done
[ "$(frames_done local)" -ge 6 ] || fail "rounds 2-4 should have finished two frames each: $(cat local/farm_orbit.journal)"
"$LIGHTCONE" render "$SHOT" --out local --threads 2 "${ARGS[@]}" 2>final.log || fail "final resume: $(cat final.log)"
check_store local
same_frames local
[ "$(frames_done local)" -eq 10 ] || fail "journal: $(cat local/farm_orbit.journal)"
grep -q "resuming" local.*.log final.log || fail "no run ever resumed: $(cat local.*.log final.log)"

# --- Ctrl-C and SIGTERM: the render stores the frames it holds complete,
# says how far it got, leaves a valid journal and nothing half-written, and
# exits 130 (SIGINT) or 143 (SIGTERM); the same command then finishes it.
# 90 sets with 2 threads complete exactly frames 0 and 1.
interrupt_round() {  # NAME SIGNAL STATUS MESSAGE
  local name="$1" sig="$2" want="$3" message="$4" rc=0
  LIGHTCONE_TEST_PAUSE_AFTER=90 "$LIGHTCONE" render "$SHOT" --out "$name" --threads 2 "${ARGS[@]}" 2>"$name.log" &
  local pid=$!
  wait_paused "$name.log" 1 "$pid" "$name" 2 || return
  kill "-$sig" "$pid"
  wait "$pid" || rc=$?
  [ "$rc" -eq "$want" ] || fail "$name: exit $rc after SIG$sig, want $want: $(cat "$name.log")"
  grep -q "$message" "$name.log" || fail "$name: no message '$message': $(cat "$name.log")"
  check_store "$name"
  if ls "$name" | grep -q tmp; then fail "$name: temporaries left: $(ls "$name")"; fi
  "$LIGHTCONE" render "$SHOT" --out "$name" --threads 2 "${ARGS[@]}" 2>"$name.resume.log" \
    || fail "$name: resume: $(cat "$name.resume.log")"
  grep -q "resuming: 2 of 10 frames already finished in $name (0-1)" "$name.resume.log" \
    || fail "$name: the journal left by the interruption was not read back as frames 0-1: $(cat "$name.resume.log")"
  same_frames "$name"
  [ "$(frames_done "$name")" -eq 10 ] || fail "$name journal: $(cat "$name/farm_orbit.journal")"
}
interrupt_round ctrl_c INT 130 \
  "render: interrupted by Ctrl-C (SIGINT): 2 of 10 frames done (2 in this run); run the same command again to resume"
interrupt_round sigterm TERM 143 "render: interrupted by SIGTERM: 2 of 10 frames done"

# --- MPI: kill one worker rank, twice.  Each worker holds its sets after
# 40 (together two frames' worth, so at least one frame is stored); the
# job cannot end before the kill, and aborts after it (Open MPI has no
# fault tolerance); a new run resumes.
for round in 1 2; do
  LIGHTCONE_TEST_PAUSE_AFTER=40 timeout 120 mpirun --oversubscribe --bind-to none -n 3 "$LIGHTCONE" render "$SHOT" \
    --out mpi "${ARGS[@]}" >"mpi.$round.log" 2>&1 &
  mpirun_pid=$!
  wait_paused "mpi.$round.log" 2 "$mpirun_pid" mpi
  w=$(sed -n 's/^render: test pause: pid \([0-9]*\) (rank 1).*/\1/p' "mpi.$round.log")
  [ -n "$w" ] && kill -9 "$w" || fail "round $round: no worker to kill: $(cat "mpi.$round.log")"
  rc=0
  wait "$mpirun_pid" || rc=$?
  [ "$rc" -ne 0 ] && [ "$rc" -ne 124 ] || fail "round $round: mpirun exited $rc after a worker was killed"
  check_store mpi
done
timeout 120 mpirun --oversubscribe --bind-to none -n 2 "$LIGHTCONE" render "$SHOT" --out mpi "${ARGS[@]}" 2>mpi_final.log \
  || fail "MPI resume: $(cat mpi_final.log)"
check_store mpi
same_frames mpi
[ "$(frames_done mpi)" -eq 10 ] || fail "MPI journal: $(cat mpi/farm_orbit.journal)"

# --- MPI and a Ctrl-C: mpirun turns it into SIGTERM for every rank (and
# SIGKILL a second later); sent here straight to the ranks, the master
# stores what it holds, stops the workers and exits 143, and no rank is
# left waiting.
LIGHTCONE_TEST_PAUSE_AFTER=40 timeout 120 mpirun --oversubscribe --bind-to none -n 3 "$LIGHTCONE" render "$SHOT" \
  --out mpi_int "${ARGS[@]}" >mpi_int.log 2>&1 &
timeout_pid=$!
if wait_paused mpi_int.log 2 "$timeout_pid" mpi_int; then
  mpirun_pid=$(pgrep -P "$timeout_pid")
  ranks=$(pgrep -P "$mpirun_pid" | tr '\n' ' ')
  [ "$(wc -w <<<"$ranks")" -eq 3 ] || fail "expected 3 ranks under mpirun $mpirun_pid, found: $ranks"
  kill -TERM $ranks
  rc=0
  wait "$timeout_pid" || rc=$?
  [ "$rc" -ne 0 ] && [ "$rc" -ne 124 ] || fail "mpirun exited $rc after SIGTERM (124: a rank hung)"
  grep -q "render: interrupted by SIGTERM: [0-9]* of 10 frames done" mpi_int.log || fail "no message: $(cat mpi_int.log)"
  grep -q "Exit code:    143" mpi_int.log || fail "no rank exited 143 (128 + SIGTERM): $(cat mpi_int.log)"
  check_store mpi_int
  timeout 120 mpirun --oversubscribe --bind-to none -n 3 "$LIGHTCONE" render "$SHOT" --out mpi_int "${ARGS[@]}" \
    2>mpi_int_resume.log || fail "resume after SIGTERM under mpirun: $(cat mpi_int_resume.log)"
  same_frames mpi_int
fi
CHECKS=$((CHECKS + 9))
e2e_end
