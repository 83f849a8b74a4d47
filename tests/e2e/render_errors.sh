#!/usr/bin/env bash
# ctest-labels: slow
# Every bad shot or flag: a clear message naming the shot file and line or the
# field or flag, a non-zero exit, and nothing under a frame's final name.
source "$(dirname "$0")/lib.sh"
e2e_begin "$@"

# shot NAME SCENE-FIELDS [SHOT-FIELDS]: a one-frame shot whose frame returns
# {SCENE-FIELDS}; the scene table starts on line 5.
shot() {
  cat >"$WORK/$1.lua" <<LUA
local lc = require "lightcone"
return {
  name = "$1", frames = 1, width = 8, height = 8, ${3:-}
  frame = function(i) return {
    $2
  } end,
}
LUA
}
good_kerr='spacetime = lc.kerr{mass = 1, spin = 0.9}, observer = lc.static_observer{r = 30, theta = 80, phi = 0},'

shot missing_texture "$good_kerr sky = lc.sky_image{file = 'nope.png'}"
expect_error missing_texture "sky image 'nope.png' not found" -- "$LIGHTCONE" render missing_texture.lua --out out
echo "not an image" >garbage.png
shot garbage_texture "$good_kerr sky = lc.sky_image{file = 'garbage.png'}"
expect_error garbage_texture "garbage.png" -- "$LIGHTCONE" render garbage_texture.lua --out out
shot negative_radius "$good_kerr disk = lc.disk{inner = -1, outer = 5}"
expect_error negative_radius "negative_radius.lua:5: disk: field 'inner' must be at least 0 M, got -1" -- "$LIGHTCONE" render negative_radius.lua --out out
shot inverted_disk "$good_kerr disk = lc.disk{inner = 10, outer = 5}"
expect_error inverted_disk "inverted_disk.lua:5: disk: inner radius 10 must be below the outer radius 5" -- "$LIGHTCONE" render inverted_disk.lua --out out
shot zero_width "$good_kerr" "width = 0,"
expect_error zero_width "field 'width' must be between 1 and 16384 pixels, got 0" -- "$LIGHTCONE" render zero_width.lua --out out
shot ok "$good_kerr"
expect_error zero_size "image size 0x10 is out of range" -- "$LIGHTCONE" render ok.lua --out out --size 0x10
expect_error absurd_size "image size 100000x10 is out of range" -- "$LIGHTCONE" render ok.lua --out out --size 100000x10
expect_error bad_size "--size 'big': expected WxH" -- "$LIGHTCONE" render ok.lua --out out --size big
expect_error bad_scale "--scale -1: must be a positive number" -- "$LIGHTCONE" render ok.lua --out out --scale -1
# Sizes are parsed strictly by every command that takes one: 2^32 + 64 once
# wrapped around to 64 and rendered 64x36; signs and trailing junk are refused.
expect_error size_overflow "--size '4294967360x36': 4294967360 is far too large" -- \
  "$LIGHTCONE" render ok.lua --out out --size 4294967360x36
expect_error size_sign "--size '-64x36': expected WxH" -- "$LIGHTCONE" render ok.lua --out out --size -64x36
expect_error size_plus "--size '64x+36': expected WxH" -- "$LIGHTCONE" render ok.lua --out out --size 64x+36
expect_error size_junk "--size '64x36px': expected WxH" -- "$LIGHTCONE" render ok.lua --out out --size 64x36px
expect_error trace_size "--size '4294967360x36': 4294967360 is far too large" -- \
  "$LIGHTCONE" trace ok.lua --frame 0 --pixel 0,0 --size 4294967360x36 -o trace.csv
expect_error trace_pixel "--pixel '4294967297,0': 4294967297 is far too large" -- \
  "$LIGHTCONE" trace ok.lua --frame 0 --pixel 4294967297,0 -o trace.csv
expect_error showcase_size "--size '4294967360x36': 4294967360 is far too large" -- \
  "$LIGHTCONE" showcase --size 4294967360x36 --out showcase_out
expect_error title_size "--size '4294967360x36': 4294967360 is far too large" -- \
  "$LIGHTCONE" encode --title X --size 4294967360x36 -o title.mp4
expect_error farm_bench_size "--size '4294967360x36': 4294967360 is far too large" -- \
  "$LIGHTCONE" farm-bench --size 4294967360x36 --frames 1
[ -e trace.csv ] || [ -e title.mp4 ] || [ -e showcase_out ] && fail "a refused size left an output behind"
expect_error bench_seconds "--seconds: -1 is out of range: give a number from 0 to 3600 (both included)" -- "$LIGHTCONE" bench --shot ok.lua --seconds -1
expect_error bench_seconds_nan "--seconds: 'nan' is not a finite number: give a number from 0 to 3600 (both included)" -- "$LIGHTCONE" bench --shot ok.lua --seconds nan
expect_error bench_seconds_long "--seconds: 4000 is out of range: give a number from 0 to 3600 (both included)" -- "$LIGHTCONE" bench --shot ok.lua --seconds 4000
# Every numeric flag takes the one check (CLI11's Range let NaN through and
# printed its ends as %f: "not in range 0.000000 to 0.010000", issue #25).
expect_error bench_tolerance_nan "--tolerance: 'nan' is not a finite number: give a number from 1e-15 to 0.01 (both included)" -- \
  "$LIGHTCONE" bench --shot ok.lua --tolerance nan
expect_error bench_tolerance_zero "--tolerance: 0 is out of range: give a number from 1e-15 to 0.01 (both included)" -- \
  "$LIGHTCONE" bench --shot ok.lua --tolerance 0
expect_error bench_reference_inf "--reference-tolerance: 'inf' is not a finite number: give a number from 1e-15 to 1e-06" -- \
  "$LIGHTCONE" bench --shot ok.lua --reference-tolerance inf
expect_error render_scale_nan "--scale: 'nan' is not a finite number" -- "$LIGHTCONE" render ok.lua --out out --scale nan
expect_error render_progress_inf "--progress: 'inf' is not a finite number" -- "$LIGHTCONE" render ok.lua --out out --progress=inf
expect_error render_threads_big "--threads: 2000 is out of range: give a number from 1 to 1024 (both included)" -- \
  "$LIGHTCONE" render ok.lua --out out --threads 2000
expect_error plot_extent_nan "--extent: 'nan' is not a finite number" -- "$LIGHTCONE" plot ok.lua -o x.svg --extent nan
expect_error encode_seconds_inf "--seconds: 'inf' is not a finite number" -- "$LIGHTCONE" encode --title X --size 32x18 -o x.mp4 --seconds inf
expect_error showcase_rate_nan "--rate: 'nan' is not a finite number" -- "$LIGHTCONE" showcase --rate nan
expect_error bad_frames "--frames '5:9': the shot has frames 0 to 0" -- "$LIGHTCONE" render ok.lua --out out --frames 5:9
expect_error bad_frames2 "--frames 'x'" -- "$LIGHTCONE" render ok.lua --out out --frames x
shot ergo "spacetime = lc.kerr{mass = 1, spin = 0.9}, observer = lc.static_observer{r = 1.8, theta = 90, phi = 0},"
expect_error ergo "ergo.lua: frame 0: ergo.lua:5: observer: static observer: no static observer exists here (inside the ergoregion" -- "$LIGHTCONE" render ergo.lua --out out
shot inside "spacetime = lc.kerr{mass = 1, spin = 0.9}, observer = lc.zamo{r = 1.2, theta = 90, phi = 0},"
expect_error inside "inside a horizon" -- "$LIGHTCONE" render inside.lua --out out
# inspect refuses what render refuses (it builds each scene, short of tracing).
expect_error inspect_ergo "ergo.lua: frame 0: ergo.lua:5: observer: static observer: no static observer exists here" -- "$LIGHTCONE" inspect ergo.lua
expect_error inspect_inside "inside.lua: frame 0: inside.lua:5: observer: ZAMO: the position is inside a horizon" -- "$LIGHTCONE" inspect inside.lua
# Where an observer cannot stand, said with the line and the reason (not
# "not timelike" or "the frame degenerates").
shot far "spacetime = lc.kerr{mass = 1, spin = 0.9}, observer = lc.static_observer{r = 1e300, theta = 90, phi = 0},"
expect_error far "far.lua:5: observer: 1e+300 M from the origin, farther than rays can be traced from (1e+10 M at most" -- "$LIGHTCONE" render far.lua --out out
shot far_flat "spacetime = lc.minkowski{}, observer = lc.zamo{x = 1e300, y = 1e300, z = 0},"
expect_error far_flat "far_flat.lua:5: observer: 1.41421e+300 M from the origin, farther" -- "$LIGHTCONE" inspect far_flat.lua
shot origin "spacetime = lc.minkowski{}, observer = lc.static_observer{x = 0, y = 0, z = 0},"
expect_error origin "origin.lua:5: observer: at the origin a static observer has no view 'at the hole'" -- "$LIGHTCONE" render origin.lua --out out
# A fall may start inside Kerr's ergoregion (its velocity is then relative to
# the ZAMO), where a static observer cannot stand, and be shown until just
# outside the horizon (issue 25, defect 9).
cat >"$WORK/fall.lua" <<'LUA'
local lc = require "lightcone"
local hole = lc.kerr{mass = 1, spin = 0.9}
local w = lc.worldline{spacetime = hole, start = {t = 0, r = 1.9, theta = 90, phi = 0},
                       velocity = {r = -0.1, theta = 0, phi = 0}, duration = 0.4}
local v = lc.worldline{spacetime = hole, start = {t = 0, r = 6, theta = 60, phi = 0},
                       velocity = {r = -0.5, theta = 0, phi = 0.3}, duration = 7.7}
return {name = "fall", frames = 4, width = 16, height = 9,
  frame = function(i)
    local o = i < 2 and lc.free_fall{worldline = w, proper_time = 0.2 * i}
                     or lc.free_fall{worldline = v, proper_time = 7.55 + 0.07 * (i - 2)}
    return {spacetime = hole, observer = o, camera = lc.camera{fov = 90}, disk = lc.disk{inner = 3, outer = 12}}
  end}
LUA
"$LIGHTCONE" render "$WORK/fall.lua" --out "$WORK/fall_out" --progress 0 2>"$WORK/fall.log" ||
  fail "a fall inside the ergoregion and close to the horizon: $(cat "$WORK/fall.log")"
expect_error inspect_texture "sky image 'nope.png' not found" -- "$LIGHTCONE" inspect missing_texture.lua
cat >"$WORK/spin_changed.lua" <<'LUA'
local lc = require "lightcone"
local fall = lc.worldline{spacetime = lc.kerr{mass = 1, spin = 0.9}, start = {r = 12, theta = 90, phi = 0}, duration = 20}
return {name = "spin_changed", frames = 2, width = 8, height = 8, frame = function(i) return {
  spacetime = lc.kerr{mass = 1, spin = 0.9 - 0.4 * i},
  observer = lc.static_observer{r = 30, theta = 80, phi = 0},
  objects = {lc.sphere{radius = 1, worldline = fall}},
} end}
LUA
expect_error inspect_spin "spin_changed.lua: frame 1: spin_changed.lua:2: a sphere's worldline (spin_changed.lua:2) was made in kerr(mass=1, spin=0.9)" -- "$LIGHTCONE" inspect spin_changed.lua
# A sphere whose worldline ends before the frame's rays may meet it would vanish.
cat >"$WORK/short_worldline.lua" <<'LUA'
local lc = require "lightcone"
local flat = lc.minkowski()
local drift = lc.worldline{spacetime = flat, start = {x = 5, y = 0, z = 0}, velocity = {x = 0, y = 0, z = 0.1}, duration = 10}
return {name = "short_worldline", frames = 1, width = 8, height = 8, frame = function(i) return {
  spacetime = flat, time = 100, observer = lc.static_observer{x = 0, y = 20, z = 0},
  objects = {lc.sphere{radius = 1, worldline = drift}},
} end}
LUA
expect_error short_worldline "short_worldline.lua: frame 0: a sphere's worldline (short_worldline.lua:3) ends" -- "$LIGHTCONE" render short_worldline.lua --out out
expect_error short_worldline_hint "lengthen its duration" -- "$LIGHTCONE" inspect short_worldline.lua
# What a shot may make the engine hold is bounded (docs/shots.md, Limits).
cat >"$WORK/long_worldline.lua" <<'LUA'
local lc = require "lightcone"
local w = lc.worldline{spacetime = lc.minkowski(), start = {x = 5, y = 0, z = 0}, duration = 49000}
return {name = "long_worldline", frames = 1, width = 8, height = 8, frame = function(i) return {
  spacetime = lc.minkowski(), observer = lc.static_observer{x = 0, y = 20, z = 0},
  objects = {lc.sphere{radius = 1, worldline = w}},
} end}
LUA
expect_error long_worldline "long_worldline.lua:2: worldline: field 'duration' must be at most 20000 M of proper time, got 49000" -- "$LIGHTCONE" render long_worldline.lua --out out
shot big_stars "$good_kerr sky = lc.sky_stars{resolution = 16384},"
expect_error big_stars "big_stars.lua:5: sky_stars: field 'resolution' must be between 64 and 8192 pixels, got 16384" -- "$LIGHTCONE" render big_stars.lua --out out
# The star catalogue: missing, a directory, a malformed line (named with its
# line and field, the shot and the frame), and a bad choice.
shot no_catalogue "$good_kerr sky = lc.starfield{catalogue = 'kstars'},"
expect_error no_catalogue "no_catalogue.lua:5: starfield: catalogue = \"kstars\" reads $WORK/none.dat, which is not there: install Debian's kstars-data" -- \
  env LIGHTCONE_STAR_CATALOGUE="$WORK/none.dat" "$LIGHTCONE" render no_catalogue.lua --out out
mkdir -p catalogue_dir
expect_error dir_catalogue "no_catalogue.lua:5: starfield: catalogue = \"kstars\" reads $WORK/catalogue_dir, which is not a regular file" -- \
  env LIGHTCONE_STAR_CATALOGUE="$WORK/catalogue_dir" "$LIGHTCONE" render no_catalogue.lua --out out
printf '# stars\n064508.92 -164258.0 -000546.0-001223.100379.2 -1.4400.01A0 1\n1836x6.34 +384701.3 000000.0 000000.0 00000.0 00.03-0.00A0 1\n' >bad_stars.dat
expect_error bad_catalogue "starfield: the catalogue does not read: $WORK/bad_stars.dat:3: the right ascension (columns 1-9) is not hhmmss.ss" -- \
  env LIGHTCONE_STAR_CATALOGUE="$WORK/bad_stars.dat" "$LIGHTCONE" render no_catalogue.lua --out out
grep -qF "no_catalogue.lua" "$WORK/bad_catalogue.err" || fail "bad catalogue: no shot named: $(cat "$WORK/bad_catalogue.err")"
[ ! -e out/no_catalogue.0000.exr ] || fail "a frame was written from a bad catalogue"
# Numbers std::from_chars reads but no catalogue holds: a NaN seconds field
# crashed the render (SIGSEGV, issue #25); a NaN magnitude or colour was
# "a star's flux is negative or not finite" without a file or line.
star='064508.92 -164258.0 -000546.0-001223.100379.2 -1.4400.01A0 1'
printf '%s\n%s\n' "$star" "${star:0:4}  nan${star:9}" >nan_ra.dat
expect_error nan_ra "$WORK/nan_ra.dat:2: the right ascension (columns 1-9) is not hhmmss.ss" -- \
  env LIGHTCONE_STAR_CATALOGUE="$WORK/nan_ra.dat" "$LIGHTCONE" render no_catalogue.lua --out out
printf '%s\n' "${star:0:15} nan${star:19}" >nan_dec.dat
expect_error nan_dec "$WORK/nan_dec.dat:1: the declination (columns 11-19) is not sddmmss.s" -- \
  env LIGHTCONE_STAR_CATALOGUE="$WORK/nan_dec.dat" "$LIGHTCONE" render no_catalogue.lua --out out
printf '%s\n' "${star:0:46}  nan${star:51}" >nan_v.dat
expect_error nan_v "$WORK/nan_v.dat:1: the magnitude V (columns 47-51) is not a number from -2 to 30" -- \
  env LIGHTCONE_STAR_CATALOGUE="$WORK/nan_v.dat" "$LIGHTCONE" render no_catalogue.lua --out out
printf '%s\n' "${star:0:51}  inf${star:56}" >inf_bv.dat
expect_error inf_bv "$WORK/inf_bv.dat:1: the colour index B-V (columns 52-56) is not a number from -1 to 6" -- \
  env LIGHTCONE_STAR_CATALOGUE="$WORK/inf_bv.dat" "$LIGHTCONE" render no_catalogue.lua --out out
# A catalogue that gives no star is an error, not a starless sky.
printf '# nothing but a comment\n' >empty_stars.dat
expect_error empty_catalogue "$WORK/empty_stars.dat: 0 stars read from it: it holds no star line" -- \
  env LIGHTCONE_STAR_CATALOGUE="$WORK/empty_stars.dat" "$LIGHTCONE" render no_catalogue.lua --out out
[ ! -e out/no_catalogue.0000.exr ] || fail "a frame was written from a bad catalogue"
shot no_background "$good_kerr sky = lc.starfield{background = 'nope.png'},"
expect_error no_background "sky image 'nope.png' not found" -- "$LIGHTCONE" render no_background.lua --out out
shot bad_choice "$good_kerr sky = lc.starfield{catalogue = 'hipparcos'},"
expect_error bad_choice "bad_choice.lua:5: starfield: field 'catalogue'" -- "$LIGHTCONE" render bad_choice.lua --out out
shot nan "$good_kerr camera = lc.camera{fov = 0/0},"
expect_error nan "nan.lua:5: camera: field 'fov' is nan" -- "$LIGHTCONE" render nan.lua --out out
shot wide "$good_kerr camera = lc.camera{fov = 200},"
expect_error wide "wide.lua:5: camera: field 'fov' must be greater than 0 and less than 180 degrees, got 200" -- "$LIGHTCONE" render wide.lua --out out
shot fov180 "$good_kerr camera = lc.camera{fov = 180},"
expect_error fov180 "fov180.lua:5: camera: field 'fov' must be greater than 0 and less than 180 degrees, got 180" -- "$LIGHTCONE" render fov180.lua --out out
shot typo "$good_kerr disk = lc.disk{iner = 6, outer = 10},"
expect_error typo "typo.lua:5: disk: unknown field 'iner' (did you mean 'inner'?)" -- "$LIGHTCONE" render typo.lua --out out
shot scene_typo "spacetime = lc.kerr{mass = 1}, obsrver = lc.static_observer{r = 30, theta = 80, phi = 0},"
expect_error scene_typo "scene_typo.lua: frame 0: missing field 'observer' (there is a field 'obsrver': misspelt?)" -- "$LIGHTCONE" render scene_typo.lua --out out
shot scene_typo2 "$good_kerr camra = lc.camera{fov = 30},"
expect_error scene_typo2 "scene_typo2.lua: frame 0: unknown field 'camra' (did you mean 'camera'?)" -- "$LIGHTCONE" render scene_typo2.lua --out out
shot wrong_coords "spacetime = lc.kerr{mass = 1}, observer = lc.static_observer{x = 30, y = 0, z = 0},"
expect_error wrong_coords "positions in kerr are Boyer–Lindquist" -- "$LIGHTCONE" render wrong_coords.lua --out out
shot raw_table "$good_kerr disk = {inner = 6, outer = 10},"
expect_error raw_table "expected a value made by an object constructor: lc.disk{...}" -- "$LIGHTCONE" render raw_table.lua --out out
shot runtime "$good_kerr camera = lc.camera{fov = nil + 1},"
expect_error runtime "runtime.lua:5: attempt to perform arithmetic" -- "$LIGHTCONE" render runtime.lua --out out
cat >"$WORK/not_a_scene.lua" <<'LUA'
return {name = "not_a_scene", frames = 1, width = 8, height = 8, frame = function(i) return 42 end}
LUA
expect_error not_a_scene "not_a_scene.lua: frame 0: frame(i) must return a scene table, got number" -- "$LIGHTCONE" render not_a_scene.lua --out out
cat >"$WORK/no_frame.lua" <<'LUA'
return {name = "no_frame", frames = 1, width = 8, height = 8}
LUA
expect_error no_frame "field 'frame' must be a function(i)" -- "$LIGHTCONE" render no_frame.lua --out out
cat >"$WORK/bad_name.lua" <<'LUA'
return {name = "../evil", frames = 1, width = 8, height = 8, frame = function(i) return {} end}
LUA
expect_error bad_name "name '../evil' may only use letters, digits" -- "$LIGHTCONE" render bad_name.lua --out out
touch not_a_dir
expect_error out_is_file "--out not_a_dir: cannot create the output directory" -- "$LIGHTCONE" render ok.lua --out not_a_dir
# A size lightcone encode cannot take is said at the start of a render (here
# one that then fails at once, so nothing 16384x16384 is rendered: its
# memory, ~29 GB, or its output directory); a showcase, which always
# encodes, refuses it.
expect_error big_render "lightcone: error: " -- \
  "$LIGHTCONE" render ok.lua --out not_a_dir/sub --size 16384x16384
grep -q "render: warning: these frames cannot be encoded to video by lightcone encode (16384x16384 frames are too large" \
  big_render.err || fail "no warning that 16384x16384 frames cannot be encoded: $(cat big_render.err)"
expect_error big_showcase "--size 16384x16384: 16384x16384 frames are too large for FFmpeg's encoders" -- \
  "$LIGHTCONE" showcase --size 16384x16384 --out big_showcase
[ -e big_showcase ] && fail "a refused showcase created its output directory"

# The star field is a PNG: another extension is refused (PNG bytes were
# written under sky.jpg), nothing is left under it.
expect_error starfield_jpg "-o sky.jpg: the star field is written as an 8-bit sRGB PNG (name it .png)" -- \
  "$LIGHTCONE" starfield -o sky.jpg --width 64
[ -e sky.jpg ] && fail "starfield wrote sky.jpg"
"$LIGHTCONE" starfield -o sky.PNG --width 64 2>/dev/null || fail "starfield -o sky.PNG"
iinfo sky.PNG 2>&1 | grep -q "64 x   32, 3 channel, uint8 png" || fail "sky.PNG: $(iinfo sky.PNG 2>&1)"

# Usage errors look like every other error and suggest what was meant.
expect_error typo_command "lightcone: error: unknown command 'rendr' (did you mean 'render'?)" -- "$LIGHTCONE" rendr ok.lua
expect_error typo_flag "lightcone: error: render: unknown option --fram (did you mean --frames?)" -- \
  "$LIGHTCONE" render ok.lua --fram 0 --out out
expect_error typo_flag2 "lightcone: error: contact-sheet: unknown option --colums (did you mean --columns?)" -- \
  "$LIGHTCONE" contact-sheet out -o sheet.png --colums 3
expect_error no_command "lightcone: error: no command given; the commands are geodesic, plot, render" -- "$LIGHTCONE"
expect_error required "lightcone: error: --output is required" -- "$LIGHTCONE" encode out
expect_error not_a_number "lightcone: error: --crf: 'abc' is not a number" -- "$LIGHTCONE" encode out -o x.mp4 --crf abc
grep -q "Run 'lightcone encode --help' for the options." not_a_number.err || fail "no help hint: $(cat not_a_number.err)"

# script NAME BEFORE [FRAME-BODY]: a one-frame shot with BEFORE on line 2
# and FRAME-BODY (then a good scene) in frame(i), from line 5.
script() {
  cat >"$WORK/$1.lua" <<LUA
local lc = require "lightcone"
$2
return {name = "$1", frames = 3, width = 8, height = 8,
  frame = function(i)
    ${3:-}
    return {spacetime = lc.kerr{mass = 1, spin = 0.9}, observer = lc.static_observer{r = 30, theta = 80, phi = 0}}
  end}
LUA
}
# Recursion through C functions overflowed the C stack (SIGSEGV, no message),
# also under MPI and in the render threads.
script gsub_nest "local function f(s) return (s:gsub('.', f)) end f('a')"
expect_error gsub_nest "gsub_nest.lua:2: too deeply nested: more than 200 calls back into Lua" -- "$LIGHTCONE" render gsub_nest.lua --out out
script wrap_nest "local function f() coroutine.wrap(f)() end" "if i == 2 then f() end"
expect_error wrap_nest "wrap_nest.lua: frame 2: wrap_nest.lua:2: too deeply nested" -- "$LIGHTCONE" render wrap_nest.lua --out out
expect_error wrap_nest_inspect "wrap_nest.lua: frame 2: wrap_nest.lua:2: too deeply nested" -- "$LIGHTCONE" inspect wrap_nest.lua
if command -v mpirun >/dev/null; then
  use_mpirun
  expect_error wrap_nest_mpi "wrap_nest.lua: frame 2: wrap_nest.lua:2: too deeply nested" -- mpi 2 "$LIGHTCONE" render wrap_nest.lua --out out
fi
# An error object whose __tostring loops gave "error in error handling" after 30 s.
script tostring_loop "error(setmetatable({}, {__tostring = function() while true do end end}))"
expect_error tostring_loop "tostring_loop.lua:2: error object (a table value): its __tostring did not return within 0.1 s" -- \
  timeout 20 "$LIGHTCONE" render tostring_loop.lua --out out
# A Lua error in frame(i) named the line, not the frame.
script frame_err "" "if i == 2 then local x = nil return x.y end"
for cmd in "render frame_err.lua --out out" "inspect frame_err.lua" "trace frame_err.lua --frame 2 --pixel 0,0"; do
  expect_error "frame_err_${cmd%% *}" "frame_err.lua: frame 2: frame_err.lua:5: attempt to index local 'x' (a nil value)" -- \
    "$LIGHTCONE" $cmd
done
# frame_count suggested 'frame', a field of every shot.
cat >"$WORK/frame_count.lua" <<'LUA'
return {name = "frame_count", frame_count = 1, width = 8, height = 8, frame = function(i) return {} end}
LUA
expect_error frame_count "frame_count.lua: unknown field 'frame_count' (did you mean 'frames'?)" -- \
  "$LIGHTCONE" render frame_count.lua --out out
# require followed a link out of the shot's folder, parsed the file and quoted it.
ln -s /etc/passwd "$WORK/passwd.lua"
script require_link "local m = require 'passwd'"
expect_error require_link "require_link.lua:2: module 'passwd' (./passwd.lua) leads through a link to /etc/passwd, outside the folders" -- \
  "$LIGHTCONE" render require_link.lua --out out
# (A line of it has user:x:uid:gid: fields; the checkout's path may hold "root".)
! grep -qE ':x:[0-9]+:[0-9]+:|nologin' require_link.err || fail "require_link: a line of /etc/passwd is in the message"
# Sky images: only regular files inside the shot's (or the project's shots/)
# folder; a FIFO or /dev/zero hung the input hash before any check.
mkfifo "$WORK/fifo.png"
ln -s /dev/zero "$WORK/zero.png"
ln -s /etc/passwd "$WORK/passwd.png"
shot sky_fifo "$good_kerr sky = lc.sky_image{file = 'fifo.png'}"
expect_error sky_fifo "sky_fifo.lua: frame 0: sky image 'fifo.png' (./fifo.png) is a FIFO, not a regular file" -- \
  timeout 60 "$LIGHTCONE" render sky_fifo.lua --out out
shot sky_zero "$good_kerr sky = lc.sky_image{file = 'zero.png'}"
expect_error sky_zero "sky image 'zero.png' (./zero.png) leads through a link to /dev/zero, outside the folders" -- \
  timeout 60 "$LIGHTCONE" render sky_zero.lua --out out
shot sky_dev "$good_kerr sky = lc.sky_image{file = '/dev/zero'}"
expect_error sky_dev "sky image '/dev/zero': the field 'file' must be a path relative to the shot's folder" -- \
  timeout 60 "$LIGHTCONE" render sky_dev.lua --out out
expect_error sky_dev_trace "sky image '/dev/zero': the field 'file' must be a path relative" -- \
  timeout 60 "$LIGHTCONE" trace sky_dev.lua --frame 0 --pixel 0,0
shot sky_passwd "$good_kerr sky = lc.sky_image{file = 'passwd.png'}"
expect_error sky_passwd "sky image 'passwd.png' (./passwd.png) leads through a link to /etc/passwd" -- \
  "$LIGHTCONE" render sky_passwd.lua --out out
# The shot itself must be a regular file too.
mkfifo "$WORK/fifo_shot.lua"
expect_error fifo_shot "fifo_shot.lua: a FIFO, not a regular file" -- timeout 60 "$LIGHTCONE" inspect fifo_shot.lua

# Point stars need pictures of at least 2x2: a smaller frame, eye's picture
# or --region is refused before the render starts, naming the flag or field.
shot tiny_stars "$good_kerr camera = lc.camera{fov = 40}, sky = lc.starfield{},"
expect_error tiny_frame "the frame is 1x1 pixels (--size, --scale or the shot's width and height); frame 0's sky has point stars, which are drawn on pictures of at least 2x2" -- \
  "$LIGHTCONE" render tiny_stars.lua --out out --size 1x1
expect_error tiny_region "--region: 1x8 pixels; frame 0's sky has point stars, which are drawn on pictures of at least 2x2" -- \
  "$LIGHTCONE" render tiny_stars.lua --out out --region 0,0,1,8
shot tiny_eyes "$good_kerr camera = lc.camera{fov = 40, stereo = 'side-by-side'}, sky = lc.starfield{},"
expect_error tiny_eyes "frame 0: the camera's \`stereo\` puts each eye's picture in 1x8 pixels of the 3x8 frame" -- \
  "$LIGHTCONE" render tiny_eyes.lua --out out --size 3x8
# --png-depth says what it takes.
expect_error png_depth_float "--png-depth: '16.0' is not a PNG depth: give the bits per channel as the integer 8 or 16" -- \
  "$LIGHTCONE" render ok.lua --out out --png-depth 16.0
# A stereo eye pushed into the ergoregion (the camera looks along phi, its
# left eye 1 M towards the hole from a static observer at r = 2.5): named
# with the file and frame and what to change, by render and inspect alike.
shot ergo_eye "spacetime = lc.kerr{mass = 1, spin = 0.9}, observer = lc.static_observer{r = 2.5, theta = 90, phi = 0},
    camera = lc.camera{fov = 40, stereo = 'side-by-side', separation = 2, yaw = 90},"
expect_error ergo_eye "ergo_eye.lua: frame 0: the camera's left eye (stereo, \`separation\` 2 M) cannot stand there" -- \
  "$LIGHTCONE" render ergo_eye.lua --out out
grep -qF "give the camera a smaller \`separation\`, or place the observer further out" ergo_eye.err || fail "no advice: $(cat ergo_eye.err)"
expect_error inspect_ergo_eye "ergo_eye.lua: frame 0: the camera's left eye" -- "$LIGHTCONE" inspect ergo_eye.lua
# A frame larger than the memory is refused before the render starts, with
# the figures (~108 bytes a pixel at its peak: 29 GB at 16384x16384), where
# this machine has less than that.
if [ "$(awk '/MemAvailable/ {print $2}' /proc/meminfo)" -lt 28000000 ]; then
  expect_error frame_memory "frames of 16384x16384 need ~29.0 GB of memory at their peak" -- \
    timeout 60 "$LIGHTCONE" render ok.lua --out out --size 16384x16384 --supersample 8
fi

[ ! -e out ] || [ -z "$(ls -A out)" ] || fail "failed renders left files in out/: $(ls out)"
e2e_end
