#!/usr/bin/env bash
# The render farm under a real Slurm: a one-node cluster of its own
# (munged, slurmctld, slurmd from Debian 12's packages, started directly:
# there is no systemd) with a private slurm.conf, state, spool, logs and
# munge socket under this test's scratch directory, on unusual ports.
#   1. sbatch of tests/cluster/render-pmix.sbatch (srun --mpi=pmix) and of
#      render-mpirun.sbatch (mpirun inside the allocation), 3 tasks (the
#      master and 2 workers): frames byte-identical to a 1-thread render.
#   1b. sbatch --array=0-1 of render-array.sbatch, then join-array.sbatch
#      after both (afterok): the joined frames byte-identical, one video.
#   2. scancel mid-render (the workers held at a known point by the test
#      hook LIGHTCONE_TEST_PAUSE_AFTER), then sbatch again: it resumes, no
#      frame is rendered twice, the frames are byte-identical: under srun,
#      under mpirun, and with the master first killed by SIGKILL (it leaves
#      its lock file, which must not block the resubmission).
#   2b. `lightcone monitor` on a job: its ranks on the page (API and
#      chromium) while it runs; rank 2 killed by SIGKILL shows lost, the
#      resubmission resumes.
#   3. sbatch of tests/cluster/showcase-pmix.sbatch: the showcase at preview
#      quality as one job; its videos, and its frames byte-identical to a
#      1-thread run.
# docs/cluster.md quotes the job scripts; this test checks it still does.
#
# Needs root (to start the daemons) and the packages slurmctld slurmd
# slurm-client munge (installed here with apt-get if missing); without
# them it exits 77, which ctest shows as skipped.  Teardown (on any exit)
# cancels the jobs and kills only the daemons it started, by PID.
source "$(dirname "$0")/../e2e/lib.sh"
e2e_begin "$@"
HERE="$SRC/tests/cluster"
skip() {
  echo "SKIP: $*"
  exit 77
}

[ "$(id -u)" -eq 0 ] || skip "starting Slurm's daemons needs root"
need=(munged slurmctld slurmd sbatch srun scancel squeue scontrol mpirun)
have_all() { for c in "${need[@]}"; do command -v "$c" >/dev/null || return 1; done; }
if ! have_all; then
  command -v apt-get >/dev/null || skip "Slurm is not installed and there is no apt-get (packages: slurmctld slurmd slurm-client munge)"
  echo "slurm: installing slurmctld slurmd slurm-client munge"
  { apt-get update -q && DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends \
      slurmctld slurmd slurm-client munge; } >apt.log 2>&1 ||
    skip "could not install Slurm: $(tail -3 apt.log)"
  have_all || skip "still missing after apt-get: one of ${need[*]}"
fi

# --- Bring the cluster up --------------------------------------------------
S="$WORK/slurm"  # config, state, spool, logs, pid files
# munged's socket, pid, seed and log (owned by munge).  Not under $WORK:
# munged runs as the munge user, who cannot reach a checkout under /root.
M=$(mktemp -d /tmp/lightcone-munge.XXXXXX)
mkdir -p "$S/state" "$S/spool"
chown munge:munge "$M"
chmod 755 "$M"  # munged wants the socket's directory open to all (execute)
DAEMONS=()  # "name pid" of each daemon this test started
MOUNTED=()  # what this test mounted, innermost last
JOBS_SUBMITTED=0

MONITOR=""  # the pid of section 2b's monitor while it runs
teardown() {
  local rc=$?
  set +e
  [ -n "$MONITOR" ] && kill "$MONITOR" 2>/dev/null
  if [ "$JOBS_SUBMITTED" -gt 0 ] && [ -n "${SLURM_CONF:-}" ]; then
    # Every job on this private cluster is ours.
    jobs=$(squeue -h -o %i 2>/dev/null)
    if [ -n "$jobs" ]; then
      scancel $jobs 2>/dev/null
      for _ in $(seq 1 60); do [ -z "$(squeue -h -o %i 2>/dev/null)" ] && break; sleep 0.5; done
    fi
  fi
  # The daemons, newest first, by the PIDs they wrote: TERM, then KILL.  A
  # daemon started but not yet recorded (the test stopped in between) is
  # found by its pid file, if that pid is really the daemon.
  local i name pid pidfile
  for pidfile in "$S/slurmd.pid" "$S/slurmctld.pid" "$M/munged.pid"; do
    pid=$(cat "$pidfile" 2>/dev/null) || continue
    name=$(basename "$pidfile" .pid)
    [ "$(cat "/proc/$pid/comm" 2>/dev/null)" = "$name" ] || continue
    [[ " ${DAEMONS[*]} " == *" $name $pid "* ]] || DAEMONS+=("$name $pid")
  done
  for ((i = ${#DAEMONS[@]} - 1; i >= 0; i--)); do
    read -r name pid <<<"${DAEMONS[$i]}"
    kill -TERM "$pid" 2>/dev/null || continue
    for _ in $(seq 1 50); do kill -0 "$pid" 2>/dev/null || break; sleep 0.2; done
    if kill -0 "$pid" 2>/dev/null; then
      echo "teardown: $name ($pid) ignored SIGTERM; SIGKILL" >&2
      kill -KILL "$pid" 2>/dev/null
    fi
  done
  rm -rf "$M"
  for ((i = ${#MOUNTED[@]} - 1; i >= 0; i--)); do umount "${MOUNTED[$i]}" || echo "teardown: could not unmount ${MOUNTED[$i]}" >&2; done
  exit "$rc"
}
trap teardown EXIT
trap 'exit 130' INT
trap 'exit 143' TERM

# slurmd (Slurm 22.05) initialises its cgroup plugin whatever the
# configuration and stops without a cgroup filesystem.  Every booted
# Debian 12 has one; a chroot whose /sys is bound without its submounts (a
# fresh-root check's, say) has none.  There the test mounts the least
# slurmd accepts (cgroup v1: a tmpfs holding the named hierarchy
# name=systemd, which takes no controllers) and unmounts it at teardown.
if ! mountpoint -q /sys/fs/cgroup; then
  [ -d /sys/fs/cgroup ] || skip "slurmd needs the cgroup filesystem, and this system has no /sys/fs/cgroup"
  mount -t tmpfs -o mode=755 lightcone-test-cgroup /sys/fs/cgroup ||
    skip "slurmd needs the cgroup filesystem at /sys/fs/cgroup, which is not mounted here and cannot be"
  MOUNTED+=(/sys/fs/cgroup)
  mkdir -p /sys/fs/cgroup/systemd
  mount -t cgroup -o none,name=systemd lightcone-test-cgroup /sys/fs/cgroup/systemd ||
    skip "slurmd needs the cgroup filesystem at /sys/fs/cgroup, which is not mounted here and cannot be"
  MOUNTED+=(/sys/fs/cgroup/systemd)
  echo "slurm: no cgroup filesystem here: mounted a tmpfs and the name=systemd hierarchy at /sys/fs/cgroup for this test"
fi


# start_daemon NAME PIDFILE CMD...: CMD daemonises and writes PIDFILE.
start_daemon() {
  local name="$1" pidfile="$2" pid=""
  shift 2
  "$@" >"$WORK/$name.start.log" 2>&1 || { fail "$name did not start: $(cat "$WORK/$name.start.log")"; exit 1; }
  for _ in $(seq 1 100); do
    pid=$(cat "$pidfile" 2>/dev/null || true)
    [ -n "$pid" ] && kill -0 "$pid" 2>/dev/null && break
    pid=""
    sleep 0.1
  done
  [ -n "$pid" ] || { fail "$name wrote no pid file $pidfile: $(cat "$WORK/$name.start.log")"; exit 1; }
  DAEMONS+=("$name $pid")
}

# munge: the package's key (created with mungekey if absent), our own socket.
KEY=/etc/munge/munge.key
if [ ! -s "$KEY" ]; then
  if command -v mungekey >/dev/null; then mungekey -c -k "$KEY"; else create-munge-key -f; fi
  chown munge:munge "$KEY"
  chmod 400 "$KEY"
fi
start_daemon munged "$M/munged.pid" runuser -u munge -- munged --socket="$M/munge.socket" \
  --pid-file="$M/munged.pid" --log-file="$M/munged.log" --seed-file="$M/munged.seed"

# Two free ports near 26817.
port_free() { ! ss -Hltn "sport = :$1" 2>/dev/null | grep -q .; }
PORT=26817
while ! { port_free "$PORT" && port_free $((PORT + 1)); }; do PORT=$((PORT + 2)); done

export SLURM_CONF="$S/slurm.conf"
NODE=$(slurmd -C | head -1)  # NodeName=host CPUs=... RealMemory=...
NODENAME=$(sed 's/^NodeName=\([^ ]*\).*/\1/' <<<"$NODE")
cat >"$SLURM_CONF" <<EOF
ClusterName=lightcone-test
SlurmctldHost=$NODENAME(127.0.0.1)
SlurmctldPort=$PORT
SlurmdPort=$((PORT + 1))
SlurmUser=root
AuthType=auth/munge
AuthInfo=socket=$M/munge.socket
CredType=cred/munge
StateSaveLocation=$S/state
SlurmdSpoolDir=$S/spool
SlurmctldPidFile=$S/slurmctld.pid
SlurmdPidFile=$S/slurmd.pid
SlurmctldLogFile=$S/slurmctld.log
SlurmdLogFile=$S/slurmd.log
PlugStackConfig=$S/plugstack.conf
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
SchedulerType=sched/builtin
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
MpiDefault=none
MailProg=/bin/true
ReturnToService=2
KillWait=5
$NODE NodeAddr=127.0.0.1 State=UNKNOWN
PartitionName=test Nodes=$NODENAME Default=YES MaxTime=INFINITE State=UP
EOF
: >"$S/plugstack.conf"
start_daemon slurmctld "$S/slurmctld.pid" slurmctld -f "$SLURM_CONF"
start_daemon slurmd "$S/slurmd.pid" slurmd -f "$SLURM_CONF"
state=""
for _ in $(seq 1 120); do
  state=$(sinfo -h -n "$NODENAME" -o %T 2>/dev/null || true)
  [ "$state" = idle ] && break
  sleep 0.5
done
[ "$state" = idle ] || { fail "the node is not idle after 60 s ($state): $(tail -5 "$S/slurmctld.log" "$S/slurmd.log")"; exit 1; }
echo "slurm: node $NODENAME idle, ports $PORT-$((PORT + 1))"
srun --mpi=list 2>&1 | grep -q pmix || skip "this Slurm has no PMIx plugin: $(srun --mpi=list 2>&1 | tr '\n' ' ')"

# --- Jobs --------------------------------------------------------------------
use_mpirun  # lib.sh: Open MPI as root, no core binding; sbatch passes the environment on
export LIGHTCONE
SHOT="$SRC/tests/data/farm/farm_orbit.lua"  # 10 frames of 64x40
ARGS=(--supersample 2 --full-supersample --progress 0)  # 40 stripes a frame: 400 working sets

# submit NAME SCRIPT OUT [options]: sbatch, the job's output in NAME.log; sets JOB.
submit() {
  local name="$1" script="$2" out="$3"
  shift 3
  JOBS_SUBMITTED=$((JOBS_SUBMITTED + 1))
  JOB=$(sbatch --parsable --job-name="lc-$name" --output="$WORK/$name.log" "$HERE/$script" "$SHOT" "$WORK/$out" "$@") ||
    { fail "$name: sbatch failed"; return 1; }
  JOB=${JOB%%;*}
}
job_field() { scontrol -o show job "$1" 2>/dev/null | tr ' ' '\n' | sed -n "s/^$2=//p"; }
# wait_job JOB SECONDS: until the job has ended; prints its state.
wait_job() {
  local s=""
  for _ in $(seq 1 $(($2 * 4))); do
    s=$(job_field "$1" JobState)
    case "$s" in COMPLETED | FAILED | CANCELLED | TIMEOUT | NODE_FAIL | OUT_OF_MEMORY | PREEMPTED | BOOT_FAIL | DEADLINE)
      echo "$s"
      return
      ;;
    esac
    sleep 0.25
  done
  echo "still ${s:-unknown} after $2 s"
}
# run_job NAME SCRIPT OUT [options]: submit, wait, expect COMPLETED.
run_job() {
  local name="$1"
  submit "$@" || return 1
  local s
  s=$(wait_job "$JOB" 120)
  [ "$s" = COMPLETED ] || fail "$name (job $JOB): $s, exit $(job_field "$JOB" ExitCode): $(cat "$WORK/$name.log" 2>/dev/null)"
}

same_frames() {
  local n=0 f
  for f in ref/farm_orbit.*.exr ref/farm_orbit.*.png; do
    n=$((n + 1))
    cmp -s "$f" "$1/$(basename "$f")" || fail "$1: $(basename "$f") differs from the 1-thread render"
  done
  [ "$n" -eq 20 ] || fail "ref holds $n frame files, expected 20"
  if ls "$1" | grep -q tmp; then fail "$1: temporary files left: $(ls "$1")"; fi
}
frames_done() { cat "$1/farm_orbit.journal" 2>/dev/null | grep -c '^frame=' || true; }
check_journal() {
  local dup
  dup=$(grep -o '^frame=[0-9]*' "$1/farm_orbit.journal" 2>/dev/null | sort | uniq -d)
  [ -z "$dup" ] || fail "$1: frames journalled twice (rendered again after they were finished): $dup"
}

"$LIGHTCONE" render "$SHOT" --out ref --threads 1 "${ARGS[@]}" 2>ref.log || fail "1-thread render: $(cat ref.log)"

# 1. Both job scripts, 3 tasks.
for launcher in pmix mpirun; do
  CHECKS=$((CHECKS + 1))
  run_job "$launcher" "render-$launcher.sbatch" "$launcher" "${ARGS[@]}"
  grep -q "3 ranks (a master and 2 workers)" "$launcher.log" || fail "$launcher: not a 3-rank farm: $(cat "$launcher.log")"
  same_frames "$launcher"
  [ "$(frames_done "$launcher")" -eq 10 ] || fail "$launcher: journal: $(cat "$launcher/farm_orbit.journal")"
done

# 1b. docs/cluster.md's array job: two tasks, each its block of frames in its
# own folder, then the join once both have succeeded (afterok).
CHECKS=$((CHECKS + 1))
JOBS_SUBMITTED=$((JOBS_SUBMITTED + 1))
if ARRAY=$(sbatch --parsable --array=0-1 --output="$WORK/array-%a.log" "$HERE/render-array.sbatch" 2 "$SHOT" "$WORK/array" "${ARGS[@]}") &&
  JOIN=$(sbatch --parsable --dependency="afterok:${ARRAY%%;*}" --kill-on-invalid-dep=yes --output="$WORK/join.log" \
    "$HERE/join-array.sbatch" "$WORK/array"); then
  s=$(wait_job "${JOIN%%;*}" 180)
  [ "$s" = COMPLETED ] || fail "array join (job ${JOIN%%;*}): $s: $(cat join.log array-*.log 2>/dev/null)"
  for t in 0 1; do
    [ "$(frames_done "array/part-$t")" -eq 5 ] || fail "array task $t: $(frames_done "array/part-$t") frames journalled, expected 5"
  done
  same_frames array/all
  check_probe array.mp4 codec_name=h264 nb_read_frames=10
else
  fail "array: sbatch failed"
fi

# 2. scancel mid-render, then sbatch again.  Each worker holds its sets after
# 40 (two frames' worth together: a frame is certainly stored), so the job
# is still running when it is cancelled.
# rank_pid JOB RANK LOG: the pid of the job's rank RANK (0: the master).  A
# worker that paused said its pid in LOG ("test pause: pid N (rank R)"),
# which is taken if that process is still there; else (the master, which
# does not pause) /proc is searched for a lightcone process with the job's
# id and the rank in its environment, for up to 5 s: under heavy load that
# search once found no rank 2 that the monitor still showed working.
rank_pid() {
  local p said
  said=$(sed -n "s/.*test pause: pid \([0-9]*\) (rank $2).*/\1/p" "$3" 2>/dev/null | head -1)
  if [ -n "$said" ] && [ "$(cat "/proc/$said/comm" 2>/dev/null)" = lightcone ]; then
    echo "$said"
    return
  fi
  for _ in $(seq 1 20); do
    for p in /proc/[0-9]*; do
      [ "$(cat "$p/comm" 2>/dev/null)" = lightcone ] || continue
      tr '\0' '\n' <"$p/environ" 2>/dev/null | grep -qx "SLURM_JOB_ID=$1" || continue
      tr '\0' '\n' <"$p/environ" 2>/dev/null | grep -Eqx "(OMPI_COMM_WORLD_RANK|PMIX_RANK)=$2" || continue
      echo "${p#/proc/}"
      return
    done
    sleep 0.25
  done
}
# What /proc shows of the lightcone processes, for a message when rank_pid
# finds none: each pid, its command and the Slurm and rank variables.
lightcone_processes() {
  local p
  for p in /proc/[0-9]*; do
    [ "$(cat "$p/comm" 2>/dev/null)" = lightcone ] || continue
    echo "pid ${p#/proc/}: $(tr '\0' ' ' <"$p/environ" 2>/dev/null | tr ' ' '\n' | grep -E '^(SLURM_JOB_ID|OMPI_COMM_WORLD_RANK|PMIX_RANK)=' | tr '\n' ' ')"
  done
}
# What a round checks of a monitor, if it watches one (section 2b).
on_paused() { :; }
on_stopped() { :; }
# cancel_round NAME SCRIPT HOW: HOW is scancel, or kill-master / kill-worker
# (SIGKILL to the master or to rank 2, as the OOM killer would; the job must
# end by itself).
cancel_round() {
  local name="$1" script="$2" how="$3" s
  LOCK_LEFT=unknown  # yes or no once the job is cancelled
  CHECKS=$((CHECKS + 1))
  LIGHTCONE_TEST_PAUSE_AFTER=40 submit "$name" "$script" "$name" "${ARGS[@]}" || return
  local ok=""
  for _ in $(seq 1 480); do
    if [ "$(cat "$name.log" 2>/dev/null | grep -c 'test pause: pid' || true)" -ge 2 ] && [ "$(frames_done "$name")" -ge 1 ]; then
      ok=1
      break
    fi
    s=$(job_field "$JOB" JobState)
    [ "$s" = PENDING ] || [ "$s" = RUNNING ] || break
    sleep 0.25
  done
  [ -n "$ok" ] || { fail "$name: the job did not pause ($(job_field "$JOB" JobState)): $(cat "$name.log" 2>/dev/null)"; return; }
  on_paused "$name"
  if [ "$how" = kill-master ] || [ "$how" = kill-worker ]; then
    local rank=0 victim
    [ "$how" = kill-worker ] && rank=2
    victim=$(rank_pid "$JOB" "$rank" "$name.log")
    [ -n "$victim" ] || {
      fail "$name: no process of rank $rank of job $JOB found; pause lines: $(grep 'test pause' "$name.log" | tr '\n' ' '); lightcone processes: $(lightcone_processes | tr '\n' ';')"
      return
    }
    kill -KILL "$victim"
    # Slurm's PMIx plugin aborts the step when a task dies: no scancel.
    s=$(wait_job "$JOB" 60)
    [ "$s" = FAILED ] || fail "$name: after rank $rank was killed: $s: $(cat "$name.log")"
  else
    scancel "$JOB"
    s=$(wait_job "$JOB" 60)
    [ "$s" = CANCELLED ] || fail "$name: after scancel: $s"
  fi
  local before
  before=$(frames_done "$name")
  [ "$before" -ge 1 ] && [ "$before" -lt 10 ] || fail "$name: $before frames in the journal after the cancel"
  check_journal "$name"
  if ls "$name" | grep -q tmp; then fail "$name: temporaries left after the cancel: $(ls "$name")"; fi
  cp "$name.log" "$name.cancelled.log"
  on_stopped "$name"
  LOCK_LEFT=no
  [ -e "$name/lightcone.lock" ] && LOCK_LEFT=yes
  run_job "$name.resume" "$script" "$name" "${ARGS[@]}"
  grep -q "resuming: $before of 10 frames already finished" "$name.resume.log" ||
    fail "$name: the resubmission did not resume from $before frames: $(cat "$name.resume.log")"
  check_journal "$name"
  [ "$(frames_done "$name")" -eq 10 ] || fail "$name: journal: $(cat "$name/farm_orbit.journal")"
  same_frames "$name"
}
# scancel: SIGTERM to every process of the job.  Under srun the master
# stores what it holds, says so and removes its lock file.
cancel_round cancel render-pmix.sbatch scancel
grep -q "render: interrupted by SIGTERM: [0-9]* of 10 frames done" cancel.cancelled.log ||
  fail "cancel: the master did not report the interruption: $(cat cancel.cancelled.log)"
[ "$LOCK_LEFT" != yes ] || fail "cancel: the master left its lock file after SIGTERM"
# The same under mpirun (which is signalled too and may lose the ranks' last words).
cancel_round cancel_mpirun render-mpirun.sbatch scancel
# The master killed outright leaves its lock file, which must not block the
# next job (the kernel dropped the flock with the process).
cancel_round kill render-pmix.sbatch kill-master
[ "$LOCK_LEFT" != no ] || fail "kill: no lock file was left by the killed master, so this round tested nothing"

# 2b. `lightcone monitor` on a job's folder (docs/monitor.md): the job's
# three ranks on its page while it runs, each worker with what it holds;
# then rank 2 killed outright, which the master names and the page shows
# lost; the resubmitted job resumes and the page shows it done.
mkdir -p "$WORK/lost"
"$LIGHTCONE" monitor "$WORK/lost" --port 0 2>monitor.log &
MONITOR=$!
for _ in $(seq 1 100); do grep -q "http://127.0.0.1:" monitor.log && break; sleep 0.05; done
URL=$(grep -o "http://127.0.0.1:[0-9]*" monitor.log || true)
status() { curl -s --max-time 10 "$URL/api/status?folder=0&shot=farm_orbit" || true; }  # a failed request fails a check, not the test
field() { $PY -c "import json,sys; d=json.load(sys.stdin); print(eval(sys.argv[1]))" "$1"; }
BROWSER=(chromium --headless=new --no-sandbox --disable-gpu --hide-scrollbars --window-size=1200,800 --virtual-time-budget=6000)
on_paused() {
  sleep 2.5  # a progress line (every 2 s) says what each worker holds
  local st
  st=$(status)
  [ "$(field 'd["run"]["ranks"], d["run"]["state"]' <<<"$st")" = "(3, 'running')" ] || fail "monitor: the job's run: $st"
  [ "$(field 'sorted((w["rank"], w["host"], w["state"], w["sets"] > 0) for w in d["run"]["workers"])' <<<"$st")" = \
    "[(1, '$(hostname)', 'working', True), (2, '$(hostname)', 'working', True)]" ] || fail "monitor: the job's workers: $st"
  if command -v chromium >/dev/null; then
    timeout 60 "${BROWSER[@]}" --dump-dom "$URL/" >page_slurm.html 2>browser.log || fail "chromium: $(tail -3 browser.log)"
    [ "$(grep -o '<tr class="rank working"' page_slurm.html | wc -l)" = 2 ] ||
      fail "monitor: the page does not show the job's two workers working: $(grep -o '<tr class="rank[^>]*>' page_slurm.html)"
    timeout 60 "${BROWSER[@]}" --screenshot="$WORK/monitor_slurm.png" "$URL/" >/dev/null 2>>browser.log || fail "chromium's screenshot"
  fi
}
on_stopped() {
  # (Its words on stderr may not reach the job's log: mpirun is ending
  # the job.  Its event log is written directly.)
  grep -q " event=lost rank=2 host=$(hostname) " "$1/farm_orbit.events" ||
    fail "$1: the master did not log the lost rank: $(cat "$1/farm_orbit.events")"
  local st
  st=$(status)
  [ "$(field 'sorted((w["rank"], w["state"]) for w in d["run"]["workers"])' <<<"$st")" = "[(1, 'interrupted'), (2, 'lost')]" ] ||
    fail "monitor: after rank 2 was killed: $st"
  if command -v chromium >/dev/null; then
    timeout 60 "${BROWSER[@]}" --dump-dom "$URL/" >page_lost.html 2>>browser.log || fail "chromium: $(tail -3 browser.log)"
    grep -q '<tr class="rank lost" data-rank="2"' page_lost.html ||
      fail "monitor: the page does not show rank 2 lost: $(grep -o '<tr class="rank[^>]*>' page_lost.html)"
    timeout 60 "${BROWSER[@]}" --screenshot="$WORK/monitor_slurm_lost.png" "$URL/" >/dev/null 2>>browser.log || fail "chromium's screenshot"
  fi
}
if [ -n "$URL" ]; then
  # Under mpirun: Slurm's PMIx plugin answers a task's death under srun
  # with SIGKILL to every task at once, so no rank can say which one died
  # (docs/monitor.md); mpirun first sends SIGTERM.
  cancel_round lost render-mpirun.sbatch kill-worker
  [ "$(status | field 'd["frames"]["done"], d["run"]["state"]')" = "(10, 'done')" ] || fail "monitor: the resumed job: $(status)"
else
  fail "the monitor did not start: $(cat monitor.log)"
fi
on_paused() { :; }
on_stopped() { :; }
kill "$MONITOR" 2>/dev/null || true
MONITOR=""

# 3. The showcase as one job, at preview quality (a tiny size and rate, to
# stay quick): its videos, and frames byte-identical to a 1-thread run.
SC=(--quality preview --size 128x72 --rate 0.25 --progress 0)
"$LIGHTCONE" showcase "${SC[@]}" --threads 1 --out showcase.ref >showcase.ref.log 2>&1 ||
  fail "showcase (1 thread): $(cat showcase.ref.log)"
JOBS_SUBMITTED=$((JOBS_SUBMITTED + 1))
if JOB=$(sbatch --parsable --output="$WORK/showcase.log" "$HERE/showcase-pmix.sbatch" "$WORK/showcase" "${SC[@]}"); then
  JOB=${JOB%%;*}
  s=$(wait_job "$JOB" 300)
  [ "$s" = COMPLETED ] || fail "showcase (job $JOB): $s: $(cat showcase.log 2>/dev/null)"
  grep -q "3 ranks (a master and 2 workers)" showcase.log || fail "showcase: not a 3-rank farm: $(cat showcase.log)"
  check_probe showcase/showcase.mp4 codec_name=h264 width=128 height=72
  for seq in kerr_accrDisk kerr_passing dihole; do
    [ -s "showcase/$seq.mp4" ] || fail "showcase: no $seq.mp4"
  done
  CHECKS=$((CHECKS + 1))
  n=0
  while IFS= read -r f; do
    n=$((n + 1))
    cmp -s "showcase.ref/frames/$f" "showcase/frames/$f" || fail "showcase: frames/$f differs from the 1-thread run"
  done < <(cd showcase.ref/frames && find . -name '*.png' -o -name '*.exr' | sort)
  [ "$n" -gt 50 ] || fail "showcase: only $n frame files to compare"
else
  fail "showcase: sbatch failed"
fi

# docs/cluster.md quotes the job scripts exactly as tested here.
CHECKS=$((CHECKS + 1))
python3 - "$SRC/docs/cluster.md" "$HERE/render-pmix.sbatch" "$HERE/render-mpirun.sbatch" "$HERE/showcase-pmix.sbatch" <<'PY' || fail "docs/cluster.md does not quote the job scripts as tested"
import sys
doc = open(sys.argv[1]).read()
for f in sys.argv[2:]:
    if open(f).read() not in doc:
        print(f"{f} is not quoted verbatim in {sys.argv[1]}", file=sys.stderr)
        sys.exit(1)
PY
e2e_end
