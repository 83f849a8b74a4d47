#!/usr/bin/env bash
# Stop a render with SIGKILL at random moments, several times, and resume
# it each time; under mpirun kill one worker rank (the job aborts) and
# resume.  The final frames must equal an uninterrupted render's byte for
# byte, no frame may be journalled twice, and no half-written file may ever
# sit under a frame's final name.
source "$(dirname "$0")/lib.sh"
e2e_begin "$@"

use_mpirun  # lib.sh: Open MPI settings for a test
SHOT="$SRC/tests/data/farm/farm_orbit.lua"
ARGS=(--supersample 2 --full-supersample --progress 0)  # the full grid: slow enough to be killed mid-job

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

# Local: four kills.  The first at a random moment of the first 1.5 s
# (maybe before any frame is done); the others at a random moment within
# 0.4 s after the next frame is journalled, so every round makes progress
# however slow the machine is.
frames_done() { grep -c '^frame=' "$1/farm_orbit.journal" 2>/dev/null || true; }
for round in 1 2 3 4; do
  before=$(frames_done local)
  "$LIGHTCONE" render "$SHOT" --out local --threads 2 "${ARGS[@]}" 2>>local.log &
  pid=$!
  if [ "$round" -gt 1 ]; then
    for _ in $(seq 1 600); do
      [ "$(frames_done local)" -gt "${before:-0}" ] && break
      kill -0 "$pid" 2>/dev/null || break
      sleep 0.05
    done
    sleep "$(awk -v r=$RANDOM 'BEGIN { printf "%.2f", 0.4 * r / 32768 }')"
  else
    sleep "$(awk -v r=$RANDOM 'BEGIN { printf "%.2f", 1.5 * r / 32768 }')"
  fi
  kill -9 "$pid" 2>/dev/null || true
  wait "$pid" 2>/dev/null || true
  check_store local
done
"$LIGHTCONE" render "$SHOT" --out local --threads 2 "${ARGS[@]}" 2>final.log || fail "final resume: $(cat final.log)"
check_store local
same_frames local
[ "$(grep -c '^frame=' local/farm_orbit.journal)" -eq 10 ] || fail "journal: $(cat local/farm_orbit.journal)"
grep -q "resuming" local.log final.log || fail "no run ever resumed: $(cat local.log final.log)"

# MPI: kill one worker rank once at least one frame is finished; the job
# aborts (Open MPI has no fault tolerance) and a new run resumes.
descendants() {
  for c in $(pgrep -P "$1"); do
    echo "$c"
    descendants "$c"
  done
}
worker_pid() {  # a process below `timeout mpirun` whose rank is not 0
  for c in $(descendants "$1"); do
    if tr '\0' '\n' <"/proc/$c/environ" 2>/dev/null | grep -q '^OMPI_COMM_WORLD_RANK=[12]$'; then
      echo "$c"
      return
    fi
  done
}
KILLS=0
for round in 1 2; do
  timeout 120 mpirun --oversubscribe --bind-to none -n 3 "$LIGHTCONE" render "$SHOT" --out mpi "${ARGS[@]}" \
    >>mpi.log 2>&1 &
  mpirun_pid=$!
  for _ in $(seq 1 300); do  # up to 30 s for the first frame
    [ -f mpi/farm_orbit.journal ] && grep -q '^frame=' mpi/farm_orbit.journal && break
    kill -0 "$mpirun_pid" 2>/dev/null || break
    sleep 0.1
  done
  sleep "$(awk -v r=$RANDOM 'BEGIN { printf "%.2f", 0.5 * r / 32768 }')"
  w=$(worker_pid "$mpirun_pid")
  killed=no
  if [ -n "$w" ] && kill -9 "$w" 2>/dev/null; then killed=yes; fi
  echo "round $round: killed worker: $killed ($w)" >>mpi.log
  rc=0
  wait "$mpirun_pid" || rc=$?
  if [ "$killed" = yes ] && [ "$rc" -eq 0 ] && [ "$(grep -c '^frame=' mpi/farm_orbit.journal)" -lt 10 ]; then
    fail "round $round: a worker was killed but mpirun exited 0 with frames missing"
  fi
  [ "$killed" = yes ] && KILLS=$((KILLS + 1))
  check_store mpi
done
timeout 120 mpirun --oversubscribe --bind-to none -n 2 "$LIGHTCONE" render "$SHOT" --out mpi "${ARGS[@]}" 2>mpi_final.log \
  || fail "MPI resume: $(cat mpi_final.log)"
check_store mpi
same_frames mpi
[ "$(grep -c '^frame=' mpi/farm_orbit.journal)" -eq 10 ] || fail "MPI journal: $(cat mpi/farm_orbit.journal)"
# A worker finishing all frames before the kill can happen is possible on a
# fast machine, but not twice in a row at this size.
[ "$KILLS" -ge 1 ] || fail "no worker rank was ever killed: $(cat mpi.log)"
CHECKS=$((CHECKS + 7))
e2e_end
