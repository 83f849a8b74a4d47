#!/usr/bin/env bash
# ctest-labels: slow
# Where an output may point (docs/cli.md, "Output files"): every command that
# writes a file, given a device node, a FIFO or a symbolic link, writes
# through it and never replaces it (a rename over /dev/null once turned the
# system's /dev/null into a regular file: issue 25, defect 0); what cannot
# be a file is refused with nothing written; a temporary that a killed run
# left beside an output is removed by the next run that writes that output
# (defect 4).  Device nodes are made in the work folder (as root), so a
# regression replaces those and not the system's.
source "$(dirname "$0")/lib.sh"
e2e_begin "$@"

cat >tiny.lua <<'LUA'
local lc = require "lightcone"
return {name = "tiny", frames = 3, fps = 24, width = 32, height = 18,
  frame = function(i)
    return {spacetime = lc.kerr{mass = 1, spin = 0.9},
            observer = lc.static_observer{r = 30, theta = 60 + 5 * i, phi = 0},
            camera = lc.camera{fov = 40},
            disk = lc.disk{inner = 6, outer = 14}}
  end}
LUA
"$LIGHTCONE" render tiny.lua --out frames --progress 0 2>render.log || fail "render: $(cat render.log)"
GEO="$SRC/shots/geodesics/isco_precession.lua"
"$LIGHTCONE" geodesic "$GEO" -o isco.csv 2>geo.log || fail "geodesic: $(cat geo.log)"

# write_to TARGET NAME: runs the command NAME writing TARGET.
write_to() {
  local out="$1"
  case "$2" in
    geodesic) "$LIGHTCONE" geodesic "$GEO" -o "$out" ;;
    trace) "$LIGHTCONE" trace tiny.lua --frame 0 --pixel 5,9 -o "$out" ;;
    plot) "$LIGHTCONE" plot isco.csv -o "$out" ;;
    contact-sheet) "$LIGHTCONE" contact-sheet frames -o "$out" ;;
    starfield) "$LIGHTCONE" starfield -o "$out" --width 64 ;;
    encode) "$LIGHTCONE" encode frames -o "$out" --fps 24 ;;
    cost) "$LIGHTCONE" cost frames --csv "$out" ;;
  esac
}
ext_of() {
  case "$1" in
    geodesic | trace | cost) echo csv ;; plot) echo svg ;; contact-sheet | starfield) echo png ;; encode) echo mp4 ;;
  esac
}
COMMANDS=(geodesic trace plot contact-sheet starfield encode cost)

# --- A character device: written in place, still a device afterwards.
if mknod dev_probe c 1 3 2>/dev/null; then
  rm dev_probe
  for cmd in "${COMMANDS[@]}"; do
    node="null_$cmd.$(ext_of "$cmd")"
    mknod "$node" c 1 3
    write_to "$node" "$cmd" >/dev/null 2>"$cmd.null.log" || fail "$cmd -o a null device: $(cat "$cmd.null.log")"
    [ -c "$node" ] || fail "$cmd replaced the device $node with: $(stat -c %F "$node")"
    # A full device (as /dev/full): the short write is an error naming it.
    full="full_$cmd.$(ext_of "$cmd")"
    mknod "$full" c 1 7
    expect_error "$cmd.full" "cannot write $full: No space left on device" -- write_to "$full" "$cmd"
    [ -c "$full" ] || fail "$cmd replaced the device $full"
  done
else
  echo "outputs: not root, device nodes not tried (FIFOs and links still are)"
fi

# --- A FIFO: what a reader at its other end gets is what a file gets.
for cmd in geodesic trace cost contact-sheet; do
  ext=$(ext_of "$cmd")
  write_to "file_$cmd.$ext" "$cmd" >/dev/null 2>"$cmd.file.log" || fail "$cmd to a file: $(cat "$cmd.file.log")"
  mkfifo "fifo_$cmd.$ext"
  timeout 30 cat "fifo_$cmd.$ext" >"got_$cmd.$ext" &  # (a writer that replaced the FIFO would leave it waiting)
  reader=$!
  write_to "fifo_$cmd.$ext" "$cmd" >/dev/null 2>"$cmd.fifo.log" || fail "$cmd -o a FIFO: $(cat "$cmd.fifo.log")"
  wait "$reader" || fail "$cmd: the FIFO's reader got no end of file"
  [ -p "fifo_$cmd.$ext" ] || fail "$cmd replaced the FIFO"
  cmp -s "file_$cmd.$ext" "got_$cmd.$ext" || fail "$cmd through a FIFO differs from $cmd to a file"
done

# --- Standard output as a path (/dev/fd/1, never the system's /dev/stdout: a
# regression would replace it; /proc refuses a temporary): appended where the
# shell points it.
echo "before" >stdout.csv
"$LIGHTCONE" geodesic "$GEO" -o /dev/fd/1 >>stdout.csv 2>stdout.log || fail "-o /dev/fd/1: $(cat stdout.log)"
{ echo "before"; cat file_geodesic.csv; } | cmp -s - stdout.csv || fail "-o /dev/fd/1 with >> lost what the file held"

# --- A link: followed, the file it points at replaced, the link kept.
mkdir real
echo old >real/ray.csv
ln -s real/ray.csv link.csv
write_to link.csv geodesic 2>link.log || fail "geodesic -o a link: $(cat link.log)"
[ -L link.csv ] || fail "the link link.csv was replaced by a file"
cmp -s real/ray.csv file_geodesic.csv || fail "the file the link points at was not written"
ln -s real/made.csv dangling.csv
write_to dangling.csv geodesic 2>dangling.log || fail "geodesic -o a dangling link: $(cat dangling.log)"
[ -L dangling.csv ] && cmp -s real/made.csv file_geodesic.csv || fail "a dangling link's file was not made"

# --- What cannot be a file: refused before any work, nothing written.
mkdir adir.csv
expect_error dir "cannot write adir.csv: it is a directory" -- write_to adir.csv geodesic
python3 -c "import socket; s = socket.socket(socket.AF_UNIX); s.bind('sock.csv')"
expect_error socket "cannot write sock.csv: it is a socket, which lightcone does not write to" -- write_to sock.csv geodesic
ln -s loop_b.csv loop_a.csv
ln -s loop_a.csv loop_b.csv
expect_error loop "cannot follow the links of loop_a.csv: Too many levels of symbolic links" -- write_to loop_a.csv geodesic

# --- A temporary left by a killed run goes with the next run's write.
dead=$(sh -c 'echo $$')  # a pid whose process has ended
for cmd in "${COMMANDS[@]}"; do
  out="stale_$cmd.$(ext_of "$cmd")"
  echo half >"$out.tmp-$dead"
  write_to "$out" "$cmd" >/dev/null 2>"$cmd.stale.log" || fail "$cmd: $(cat "$cmd.stale.log")"
  [ ! -e "$out.tmp-$dead" ] || fail "$cmd left the killed run's temporary $out.tmp-$dead"
  [ -s "$out" ] || fail "$cmd wrote nothing to $out"
done
left=$(find . -name '*.tmp-*')
[ -z "$left" ] || fail "temporaries left: $left"

echo "outputs: $CHECKS error checks, $FAILURES failures"
[ "$FAILURES" -eq 0 ]
