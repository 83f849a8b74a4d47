#!/usr/bin/env bash
# Image outputs onto a full disk and into a missing directory: each is an
# error naming the file with the system's reason, a non-zero exit, and no
# file under the final name (issue #25: `contact-sheet -o` and `starfield
# -o` exited 0 leaving a truncated PNG; `plot -o` gave a raw Cairo
# message).  The full disk is a small tmpfs, so the test needs root; it is
# skipped (exit 77, which ctest shows as skipped) without it.
source "$(dirname "$0")/lib.sh"
umount "$3/disk" 2>/dev/null || true  # a run killed before its clean-up left it mounted
e2e_begin "$@"

if [ "$(id -u)" -ne 0 ]; then
  echo "SKIPPED: mounting a small tmpfs for a full disk needs root"
  exit 77
fi
disk="$WORK/disk"
mkdir -p "$disk"
mount -t tmpfs -o size=256k tmpfs "$disk" || { echo "FAIL: cannot mount a tmpfs at $disk (root, but without CAP_SYS_ADMIN?)" >&2; exit 1; }
trap 'umount "$disk" 2>/dev/null || true' EXIT

# A few frames to make a sheet of, rendered off the small disk.
cat >tiny.lua <<'LUA'
local lc = require "lightcone"
return {
  name = "tiny", frames = 2, width = 32, height = 18,
  frame = function(i) return {
    spacetime = lc.kerr{mass = 1, spin = 0.9}, observer = lc.static_observer{r = 30, theta = 80, phi = i},
  } end,
}
LUA
"$LIGHTCONE" render tiny.lua --out frames 2>render.log || fail "render: $(cat render.log)"

# check_refused NAME FILE WANT: the command's exit was non-zero, its message
# names FILE's name and says WANT, and nothing is left under FILE nor
# beside it.
check_refused() {
  local name=$1 file=$2 want=$3
  grep -qF -- "$(basename "$file")" "$WORK/$name.err" || fail "$name: the file is not named: $(cat "$WORK/$name.err")"
  [ ! -e "$file" ] || fail "$name: $file was left under its final name ($(stat -c %s "$file") bytes)"
  ! ls "$(dirname "$file")" 2>/dev/null | grep -q "$(basename "$file").tmp" || fail "$name: a temporary was left: $(ls "$(dirname "$file")")"
  grep -qF -- "$want" "$WORK/$name.err" || fail "$name: stderr lacks '$want': $(cat "$WORK/$name.err")"
}

# Filled but for 16 KiB: each output starts, then a write comes up short.
head -c $((240 * 1024)) /dev/zero >"$disk/filler" 2>/dev/null || true
full="No space left on device"
expect_error sheet_full "cannot write PNG '$disk/sheet.png': $full" -- "$LIGHTCONE" contact-sheet frames -o "$disk/sheet.png" --width 2048 --columns 1
check_refused sheet_full "$disk/sheet.png" "$full"
expect_error starfield_full "cannot write PNG '$disk/stars.png': $full" -- "$LIGHTCONE" starfield -o "$disk/stars.png" --width 2048
check_refused starfield_full "$disk/stars.png" "$full"
# 400 rays: the figure's PNG and SVG are far more than 16 KiB.
python3 - >rays.csv <<'PY'
import math
print("ray,lambda,x0,x1,x2,x3,u0,u1,u2,u3")
for ray in range(1, 400):
    for k in range(60):
        print(f"{ray},{k},0,{5 + k * 0.3},{0.1 + 0.007 * ray},{0.05 * k * math.sin(ray)},1,0,0,0")
PY
expect_error plot_full "$full" -- "$LIGHTCONE" plot rays.csv -o "$disk/rays.png" --size 1600x1200
check_refused plot_full "$disk/rays.png" "$full"
expect_error plot_svg_full "$full" -- "$LIGHTCONE" plot rays.csv -o "$disk/rays.svg" --size 1600x1200
check_refused plot_svg_full "$disk/rays.svg" "$full"
# Only the filler is there: every refused output took its temporary with it.
[ "$(ls -A "$disk")" = filler ] || fail "the full disk holds files: $(ls -A "$disk")"

# A render or develop onto a disk with no room left: the lock file it made
# and could not write is removed (a full disk left an empty lightcone.lock,
# issue 43); one that was there before (an empty one, as the bug left) is
# left as it was.
rm "$disk/filler"
"$LIGHTCONE" render tiny.lua --out "$disk/dev" 2>dev.log || fail "render onto the disk: $(cat dev.log)"
mkdir -p "$disk/out" "$disk/old"
: >"$disk/old/lightcone.lock"
head -c $((256 * 1024)) /dev/zero >"$disk/filler" 2>/dev/null || true
expect_error lock_full "$full" -- "$LIGHTCONE" render tiny.lua --out "$disk/out"
[ -z "$(ls -A "$disk/out")" ] || fail "a render onto a full disk left files: $(ls -A "$disk/out")"
expect_error develop_full "$full" -- "$LIGHTCONE" develop "$disk/dev" --exposure-shift 1
[ ! -e "$disk/dev/lightcone.lock" ] || fail "a develop onto a full disk left its lock file"
expect_error old_lock_full "$full" -- "$LIGHTCONE" render tiny.lua --out "$disk/old"
[ -f "$disk/old/lightcone.lock" ] || fail "a lock file that was there was removed"
expect_error new_dir_full "$full" -- "$LIGHTCONE" render tiny.lua --out "$disk/new"
[ ! -e "$disk/new" ] || fail "a refused render left the folder it made: $(ls -A "$disk/new")"

# Into a directory that does not exist: the system's reason, with the file.
missing="No such file or directory"
expect_error plot_missing "cannot write nowhere/rays.svg: $missing" -- "$LIGHTCONE" plot rays.csv -o nowhere/rays.svg
expect_error plot_png_missing "cannot write nowhere/rays.png: $missing" -- "$LIGHTCONE" plot rays.csv -o nowhere/rays.png
expect_error sheet_missing "cannot write nowhere/sheet.png: $missing" -- "$LIGHTCONE" contact-sheet frames -o nowhere/sheet.png
check_refused sheet_missing "$WORK/nowhere/sheet.png" "$missing"
[ ! -e nowhere ] || fail "a refused output made its directory"
e2e_end
