#!/usr/bin/env bash
# ctest-labels: slow
# Faults and bad input on the farm: a second render on a locked directory,
# a shot whose script, module or sky image changed (refused, then --force),
# other settings, a full disk, an output directory that cannot be made or
# written, a worker that fails under mpirun, a torn journal line and a
# damaged frame.  Each: a clear message, a non-zero exit, nothing corrupt,
# and a resume that works afterwards.
source "$(dirname "$0")/lib.sh"
umount "$3/disk" 2>/dev/null || true  # a tmpfs left by an interrupted earlier run
e2e_begin "$@"

export OMPI_MCA_plm_rsh_agent=
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_btl_vader_single_copy_mechanism=none
export OMPI_MCA_rmaps_base_oversubscribe=1
SHOT="$SRC/tests/data/farm/farm_orbit.lua"

"$LIGHTCONE" render "$SHOT" --out ref --threads 2 --progress 0 2>ref.log || fail "reference: $(cat ref.log)"
same_frames() {  # DIR: all ten frames equal the reference's
  for f in ref/farm_orbit.*.exr ref/farm_orbit.*.png; do
    cmp -s "$f" "$1/$(basename "$f")" || fail "$1: $(basename "$f") differs from the reference"
  done
}

# --- A second render on the same directory while one runs: refused, naming its pid.
# The holder must still be running when the second one starts: the test
# hook LIGHTCONE_TEST_PAUSE_AFTER=0 holds it at its first working set (it
# says so once it has the lock) until it is killed, however fast the machine.
LIGHTCONE_TEST_PAUSE_AFTER=0 "$LIGHTCONE" render "$SHOT" --out locked --threads 1 --progress 0 2>locked_first.log &
first=$!
wait_for_pause locked_first.log "$first" || true
expect_error second_render "another lightcone render is writing there (pid $first on" -- \
  "$LIGHTCONE" render "$SHOT" --out locked --progress 0
kill -9 "$first" || fail "the lock holder was gone before the kill"
wait "$first" 2>/dev/null || true
"$LIGHTCONE" render "$SHOT" --out locked --threads 2 --frames 0 --progress 0 2>locked_resume.log \
  || fail "render after the lock holder died: $(cat locked_resume.log)"

# --- A shot whose inputs change: script module and sky image.
mkdir -p shot
cp "$SHOT" shot/base.lua
cat >shot/params.lua <<'LUA'
return {spin = 0.9}
LUA
cat >shot/orbit.lua <<'LUA'
local lc = require "lightcone"
local params = require "params"
return {name = "orbit", frames = 4, width = 32, height = 20,
  frame = function(i)
    return {spacetime = lc.kerr{mass = 1, spin = params.spin},
            observer = lc.static_observer{r = 30, theta = 70 + 5 * i, phi = 0},
            camera = lc.camera{fov = 40}, disk = lc.disk{inner = 6, outer = 15},
            sky = lc.sky_image{file = "sky.png"}}
  end}
LUA
"$LIGHTCONE" starfield --width 64 --seed 3 -o shot/sky.png 2>/dev/null || fail "starfield"
"$LIGHTCONE" render shot/orbit.lua --out changed --frames 0:2 --progress 0 2>changed1.log || fail "first render: $(cat changed1.log)"
cp changed/orbit.0001.exr before.exr
sed -i 's/0.9/0.5/' shot/params.lua
expect_error changed_module "refusing to resume 'orbit'" -- "$LIGHTCONE" render shot/orbit.lua --out changed --progress 0
grep -q "other versions of: .*shot/params.lua" changed_module.err || fail "refusal does not name params.lua: $(cat changed_module.err)"
grep -q -- "--force" changed_module.err || fail "refusal does not mention --force: $(cat changed_module.err)"
cmp -s before.exr changed/orbit.0001.exr || fail "a refused render changed a frame"
"$LIGHTCONE" render shot/orbit.lua --out changed --force --progress 0 2>force.log || fail "--force: $(cat force.log)"
grep -q "frames 0-2 were made from other settings or inputs; rendering them again" force.log \
  || fail "--force does not say what it redoes: $(cat force.log)"
grep -q "render: done: 4 frames" force.log || fail "--force did not render the 4 frames: $(cat force.log)"
cmp -s before.exr changed/orbit.0001.exr && fail "--force kept a frame made with the old module"
"$LIGHTCONE" render shot/orbit.lua --out changed --progress 0 2>again.log || fail "resume after --force: $(cat again.log)"
grep -q "nothing to render" again.log || fail "after --force everything should be finished: $(cat again.log)"
"$LIGHTCONE" starfield --width 64 --seed 4 -o shot/sky.png 2>/dev/null
expect_error changed_sky "other versions of: " -- "$LIGHTCONE" render shot/orbit.lua --out changed --progress 0
grep -q "sky.png" changed_sky.err || fail "refusal does not name sky.png: $(cat changed_sky.err)"
expect_error other_size "were rendered at 32x20, 1x1 samples per pixel, no data layers, this render asks for 16x10" -- \
  "$LIGHTCONE" render shot/orbit.lua --out changed --size 16x10 --progress 0
expect_error other_layers "this render asks for 32x20, 1x1 samples per pixel, with data layers" -- \
  "$LIGHTCONE" render shot/orbit.lua --out changed --layers --progress 0

# --- Bad flags.
expect_error preview_one "--preview 1: must be between 2 and the number of stripes" -- \
  "$LIGHTCONE" render "$SHOT" --out flags --preview 1
expect_error stripes_zero "--stripes 0: must be between 1 and 16384" -- "$LIGHTCONE" render "$SHOT" --out flags --stripes 0
[ ! -e flags ] || fail "bad flags created the output directory"

# --- Output directories that cannot be made or written.
touch plain_file
expect_error out_under_file "--out plain_file/sub: cannot create the output directory" -- \
  "$LIGHTCONE" render "$SHOT" --out plain_file/sub
expect_error out_in_proc "--out /proc/self: cannot write to the output directory" -- \
  "$LIGHTCONE" render "$SHOT" --out /proc/self

# --- A full disk: a small tmpfs if this machine lets us mount one, else a
# file-size limit (ulimit -f).  The render stops with a message naming the
# cause; what is under final names is complete; the resume finishes.
mkdir -p disk
if mount -t tmpfs -o size=64k lightcone-test "$WORK/disk" 2>/dev/null; then
  trap 'umount "$WORK/disk" 2>/dev/null || true' EXIT
  expect_error disk_full "is the disk full?" -- "$LIGHTCONE" render "$SHOT" --out disk/out --threads 2 --progress 0
  for f in disk/out/farm_orbit.*.exr; do [ -e "$f" ] && { iinfo "$f" >/dev/null 2>&1 || fail "$f is incomplete"; }; done
  if ls disk/out | grep -q tmp; then fail "temporaries left on the full disk: $(ls disk/out)"; fi
  [ "$(grep -c '^frame=' disk/out/farm_orbit.journal 2>/dev/null || echo 0)" -lt 10 ] || fail "the disk was never full"
  mount -o remount,size=4m "$WORK/disk" || fail "cannot grow the tmpfs"
  "$LIGHTCONE" render "$SHOT" --out disk/out --threads 2 --progress 0 2>disk_resume.log || fail "resume: $(cat disk_resume.log)"
  same_frames disk/out
  umount "$WORK/disk"
  trap - EXIT
else
  expect_error file_limit "ulimit -f" -- bash -c "ulimit -f 4; exec '$LIGHTCONE' render '$SHOT' --out disk/out --threads 2 --progress 0"
  if ls disk/out | grep -q tmp; then fail "temporaries left after the size limit: $(ls disk/out)"; fi
  "$LIGHTCONE" render "$SHOT" --out disk/out --threads 2 --progress 0 2>disk_resume.log || fail "resume: $(cat disk_resume.log)"
  same_frames disk/out
fi

# --- A worker that cannot render a frame, under mpirun: the master reports
# it (naming the rank, shot and frame), stops the job, keeps what is done.
cat >ergo.lua <<'LUA'
local lc = require "lightcone"
return {name = "ergo", frames = 3, width = 16, height = 8,
  frame = function(i)
    return {spacetime = lc.kerr{mass = 1, spin = 0.9},
            observer = lc.static_observer{r = i == 2 and 1.8 or 30, theta = 90, phi = 0}}
  end}
LUA
expect_error worker_error "ergo.lua: frame 2: ergo.lua:5: observer: static observer: no static observer exists here" -- \
  timeout 120 mpirun --oversubscribe --bind-to none -n 3 "$LIGHTCONE" render ergo.lua --out ergo --progress 0
grep -q "^lightcone: error: rank [12]: " worker_error.err || fail "the error does not name the rank: $(cat worker_error.err)"
[ "$(grep -c 'lightcone: error' worker_error.err)" -eq 1 ] || fail "the error is printed more than once: $(cat worker_error.err)"
# Frames finished before the error are kept (which ones depends on timing:
# sets of frame 1 may still have been out); frame 2 never is.
if grep -q '^frame=2 ' ergo/ergo.journal 2>/dev/null; then fail "the failing frame was journalled"; fi
for f in ergo/ergo.*.exr; do [ -e "$f" ] && { iinfo "$f" >/dev/null 2>&1 || fail "$f is incomplete"; }; done
sed -i 's/1.8 or 30/30 or 30/' ergo.lua
timeout 120 mpirun --oversubscribe --bind-to none -n 2 "$LIGHTCONE" render ergo.lua --out ergo --force --progress 0 \
  2>ergo_fixed.log || fail "resume after fixing the shot: $(cat ergo_fixed.log)"
[ "$(grep -c '^frame=' ergo/ergo.journal)" -ge 3 ] || fail "ergo: $(cat ergo/ergo.journal)"

# --- Ranks that loaded different jobs (here: other flags; on a cluster, a
# stale copy of the shot on one node) refuse to work together.
# One app context whose rank 1 adds a flag, not an MPMD line ("A : B"):
# Debian 13's Open MPI 5.0.7 mpirun dies of a segfault on any MPMD line
# (open-mpi/ompi#13303), before a rank starts.
cat >digest_rank.sh <<'SH'
#!/bin/sh
if [ "${OMPI_COMM_WORLD_RANK:-0}" = 1 ]; then exec "$@" --size 32x20; else exec "$@"; fi
SH
chmod +x digest_rank.sh
expect_error digest "rank 1 loaded a different job" -- timeout 120 mpirun --oversubscribe --bind-to none \
  -n 2 ./digest_rank.sh "$LIGHTCONE" render "$SHOT" --out digest --progress 0
if ls digest 2>/dev/null | grep -q '\.exr'; then fail "ranks that disagree rendered frames: $(ls digest)"; fi

# --- A torn last journal line and a damaged frame: resume cuts the one and
# re-renders the other.
"$LIGHTCONE" render "$SHOT" --out torn --frames 0:4 --progress 0 2>torn1.log || fail "torn: $(cat torn1.log)"
printf 'frame=9 size=64x40 supers' >>torn/farm_orbit.journal
rm torn/farm_orbit.0002.exr
"$LIGHTCONE" render "$SHOT" --out torn --progress 0 2>torn2.log || fail "resume over a torn journal: $(cat torn2.log)"
grep -q "resuming: 4 of 10 frames already finished in torn (0-1, 3-4)" torn2.log || fail "resume plan: $(cat torn2.log)"
grep -q "frames 2: in the journal but their files are missing or changed" torn2.log || fail "damaged frame: $(cat torn2.log)"
grep -q "supers$" torn/farm_orbit.journal && fail "the torn line was not cut off"
[ "$(tail -c1 torn/farm_orbit.journal | od -An -c | tr -d ' ')" = '\n' ] || fail "journal does not end with a full line"
same_frames torn

e2e_end
