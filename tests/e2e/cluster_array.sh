#!/usr/bin/env bash
# ctest-labels: slow
# docs/cluster.md's array job, its logic run here without Slurm: the job
# scripts tests/cluster/render-array.sbatch and join-array.sbatch run with
# bash and the variables Slurm would set (tests/cluster/slurm.sh runs
# Slurm itself).
#   1. Three array tasks at once, each its block of a 10-frame shot (4, 4, 2)
#      into its own folder; the join links the frames into one folder and
#      encodes them: every frame byte-identical to a one-process render, a
#      video of all 10.
#   2. A task told its time is running out (SIGUSR1 to the batch script, as
#      --signal=B:USR1@... does) stops its render cleanly (SIGTERM: frames
#      stored, exit 143), requeues itself with scontrol (a stand-in here that
#      records the call), and its next run resumes from the journal.
#   3. More tasks than frames: the spare task renders nothing and succeeds.
#   4. Two renders on one folder at once: the second is refused (why the
#      tasks get a folder each).
#   5. docs/cluster.md quotes the two scripts verbatim.
source "$(dirname "$0")/lib.sh"
e2e_begin "$@"
HERE="$SRC/tests/cluster"
SHOT="$SRC/tests/data/farm/farm_orbit.lua"  # 10 frames of 64x40
ARGS=(--supersample 2 --full-supersample --progress 0)  # 40 working sets a frame
export LIGHTCONE

"$LIGHTCONE" render "$SHOT" --out ref --threads 1 "${ARGS[@]}" >ref.log 2>&1 || fail "reference render: $(cat ref.log)"
same_frames() {
  local n=0 f
  for f in ref/farm_orbit.*.exr ref/farm_orbit.*.png; do
    n=$((n + 1))
    cmp -s "$f" "$1/$(basename "$f")" || fail "$1: $(basename "$f") differs from the one-process render"
  done
  [ "$n" -eq 20 ] || fail "ref holds $n frame files, expected 20"
}
# task ID PARTS OUT [render options]: one array task, as Slurm would start
# it.  It becomes the script (exec), so that `task ... &` leaves the
# script's own pid in $! for the signal; run it in the foreground as
# `(task ...)`.
task() {
  local id="$1" count="$2" out="$3"
  shift 3
  export SLURM_ARRAY_JOB_ID=77 SLURM_ARRAY_TASK_ID="$id"
  exec bash "$HERE/render-array.sbatch" "$count" "$SHOT" "$WORK/$out" "$@"
}
# Whatever this test started and left running (a check failed half way).
STARTED=()
cleanup() {
  local p
  for p in "${STARTED[@]}"; do
    pkill -TERM -P "$p" 2>/dev/null || true  # a render the script started
    kill -TERM "$p" 2>/dev/null || true
  done
}
trap cleanup EXIT
journalled() { grep -c '^frame=' "$1/farm_orbit.journal" 2>/dev/null || true; }

# 1. Three tasks at once, then the join.
CHECKS=$((CHECKS + 1))
pids=()
for t in 0 1 2; do
  task "$t" 3 film "${ARGS[@]}" >"task$t.log" 2>&1 &
  pids+=($!)
done
for t in 0 1 2; do wait "${pids[$t]}" || fail "task $t: exit $?: $(cat "task$t.log")"; done
for t in 0 1 2; do
  want=$([ "$t" -eq 2 ] && echo 2 || echo 4)
  [ "$(journalled "film/part-$t")" -eq "$want" ] || fail "task $t: $(journalled "film/part-$t") frames, expected $want"
done
grep -q "^render: 4 frames of 'farm_orbit'" task1.log || fail "task 1: not a 4-frame render: $(cat task1.log)"
bash "$HERE/join-array.sbatch" "$WORK/film" >join.log 2>&1 || fail "join: $(cat join.log)"
same_frames film/all
grep -q "^all: 10 frames" join.log || fail "join: the cost of the parts is not summed: $(cat join.log)"
check_probe film.mp4 codec_name=h264 nb_read_frames=10 width=64 height=40

# 2. Near the time limit: SIGUSR1 to the script, then the requeued run.
CHECKS=$((CHECKS + 1))
mkdir -p stub
printf '#!/bin/sh\necho "$@" >>"%s/scontrol.calls"\n' "$WORK" >stub/scontrol
chmod +x stub/scontrol
PATH="$WORK/stub:$PATH" LIGHTCONE_TEST_PAUSE_AFTER=40 task 1 2 late "${ARGS[@]}" >late.log 2>&1 &
script=$!
STARTED+=("$script")
ok=""
for _ in $(seq 1 240); do
  grep -q 'test pause: pid' late.log 2>/dev/null && [ "$(journalled late/part-1)" -ge 1 ] && { ok=1; break; }
  kill -0 "$script" 2>/dev/null || break
  sleep 0.25
done
if [ -z "$ok" ]; then
  fail "the task did not pause: $(cat late.log)"
  kill -TERM "$script" 2>/dev/null || true
fi
kill -USR1 "$script"
rc=0
timeout 60 tail --pid="$script" -f /dev/null || fail "the task did not end within 60 s of SIGUSR1"
wait "$script" || rc=$?
[ "$rc" -eq 0 ] || fail "the task exited $rc after requeueing: $(cat late.log)"
grep -q "render: interrupted by SIGTERM: [0-9]* of 5 frames done" late.log ||
  fail "the render was not stopped cleanly by SIGTERM: $(cat late.log)"
[ "$(cat scontrol.calls 2>/dev/null)" = "requeue 77_1" ] || fail "scontrol calls: '$(cat scontrol.calls 2>/dev/null)', expected 'requeue 77_1'"
before=$(journalled late/part-1)
[ "$before" -ge 1 ] && [ "$before" -lt 5 ] || fail "$before frames journalled when the task was stopped"
(task 1 2 late "${ARGS[@]}") >late.again.log 2>&1 || fail "the requeued run: $(cat late.again.log)"
grep -q "resuming: $before of 5 frames already finished" late.again.log || fail "the requeued run did not resume: $(cat late.again.log)"
[ "$(journalled late/part-1)" -eq 5 ] || fail "after the requeued run: $(journalled late/part-1) frames journalled"
for f in 5 6 7 8 9; do
  cmp -s "ref/farm_orbit.000$f.exr" "late/part-1/farm_orbit.000$f.exr" || fail "requeued task: frame $f differs"
done

# 3. More tasks than frames (10 frames, 12 tasks: blocks of 1): task 11 has none.
CHECKS=$((CHECKS + 1))
(task 11 12 spare "${ARGS[@]}") >spare.log 2>&1 || fail "a task without frames failed: $(cat spare.log)"
grep -q "no frames left for it" spare.log || fail "the spare task did not say it had nothing to do: $(cat spare.log)"
[ ! -e spare/part-11 ] || fail "the spare task made a folder"

# A task outside 0..PARTS-1 (an --array that does not match PARTS) is refused.
expect_error beyond "give the number of parts first" -- bash -c 'SLURM_ARRAY_JOB_ID=77 SLURM_ARRAY_TASK_ID=4 exec bash "$1" 4 "$2" "$3"' _ "$HERE/render-array.sbatch" "$SHOT" "$WORK/beyond"

# 4. One folder, two renders at once: the second stops (the lock).
LIGHTCONE_TEST_PAUSE_AFTER=1 "$LIGHTCONE" render "$SHOT" --out shared --progress 0 >first.log 2>&1 &
first=$!
STARTED+=("$first")
for _ in $(seq 1 240); do grep -q 'test pause' first.log 2>/dev/null && break; sleep 0.25; done
expect_error second "another lightcone render is writing there" -- "$LIGHTCONE" render "$SHOT" --out shared --frames 5:9 --progress 0
kill -TERM "$first"
wait "$first" || true

# 5. The docs quote the scripts as tested.
CHECKS=$((CHECKS + 1))
python3 - "$SRC/docs/cluster.md" "$HERE/render-array.sbatch" "$HERE/join-array.sbatch" <<'PY' || fail "docs/cluster.md does not quote the array scripts as tested"
import sys
doc = open(sys.argv[1]).read()
for f in sys.argv[2:]:
    if open(f).read() not in doc:
        sys.exit(f"{f} is not quoted verbatim in {sys.argv[1]}")
PY
e2e_end
