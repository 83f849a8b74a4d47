#!/usr/bin/env bash
# ctest-labels: slow
# Every bad geodesic spec: a clear message naming the file and line or the
# field, a non-zero exit, and no output file (an existing one left intact).
source "$(dirname "$0")/lib.sh"
e2e_begin "$@"

spec() {  # spec NAME BODY: writes NAME.lua
  printf '%s\n' "$2" >"$WORK/$1.lua"
}
good_tail='curve = "timelike", start = {r = 10, theta = 90, phi = 0}, stop = {proper_time = 1}'

spec typo "local lc = require 'lightcone'
return {spacetime = lc.kerr{mass = 1, spinn = 0.5}, $good_tail}"
expect_error typo "typo.lua:2: kerr: unknown field 'spinn' (did you mean 'spin'?)" -- "$LIGHTCONE" geodesic typo.lua -o out.csv

spec overspin "local lc = require 'lightcone'
return {
  spacetime = lc.kerr{mass = 1, spin = 1.5}, $good_tail}"
expect_error overspin "overspin.lua:3: kerr: |spin| must not exceed the mass" -- "$LIGHTCONE" geodesic overspin.lua -o out.csv

spec negmass "local lc = require 'lightcone'
return {spacetime = lc.dihole{m1 = -1, m2 = 0.4}, curve = 'null', start = {x = 5, y = 0, z = 0}, direction = {x = -1}, stop = {affine = 1}}"
expect_error negmass "negmass.lua:2: dihole: field 'm1' must be at least 0, got -1" -- "$LIGHTCONE" geodesic negmass.lua -o out.csv

spec unknown_kind "return {spacetime = {kind = 'kerr', mass = 1}, $good_tail}"
expect_error unknown_kind "spacetime: not a spacetime" -- "$LIGHTCONE" geodesic unknown_kind.lua -o out.csv

spec inside "local lc = require 'lightcone'
return {spacetime = lc.kerr{mass = 1, spin = 0.5}, curve = 'timelike', start = {r = 1.5, theta = 90, phi = 0}, stop = {proper_time = 1}}"
expect_error inside "inside.lua.start: the start r = 1.5 lies inside a horizon" -- "$LIGHTCONE" geodesic inside.lua -o out.csv

spec dihole_point "local lc = require 'lightcone'
return {spacetime = lc.dihole{m1 = 0.4, m2 = 0.4}, curve = 'timelike', start = {x = 0, y = 0, z = 1}, stop = {proper_time = 1}}"
expect_error dihole_point "the start lies inside a horizon" -- "$LIGHTCONE" geodesic dihole_point.lua -o out.csv

spec ergo "local lc = require 'lightcone'
return {spacetime = lc.kerr{mass = 1, spin = 0.9}, curve = 'timelike', start = {r = 1.8, theta = 90, phi = 0}, stop = {proper_time = 1}}"
# Inside the ergoregion no static observer exists; a start there takes its
# velocity relative to the ZAMO, so the geodesic is traced (docs/geodesic.md).
"$LIGHTCONE" geodesic ergo.lua -o ergo.csv 2>ergo.log || fail "a start inside the ergoregion: $(cat ergo.log)"

spec fast "local lc = require 'lightcone'
return {spacetime = lc.minkowski(), curve = 'timelike', start = {x = 0, y = 0, z = 0}, velocity = {x = 0.8, y = 0.6}, stop = {proper_time = 1}}"
expect_error fast "velocity: |v| = 1 must be below the speed of light" -- "$LIGHTCONE" geodesic fast.lua -o out.csv

spec missing "local lc = require 'lightcone'
return {spacetime = lc.kerr{mass = 1}, curve = 'timelike', start = {r = 10, theta = 90}, stop = {proper_time = 1}}"
expect_error missing "missing.lua.start: missing field 'phi'" -- "$LIGHTCONE" geodesic missing.lua -o out.csv

spec wrongtype "local lc = require 'lightcone'
return {spacetime = lc.kerr{mass = '1'}, $good_tail}"
expect_error wrongtype "wrongtype.lua:2: kerr: field 'mass' must be a number" -- "$LIGHTCONE" geodesic wrongtype.lua -o out.csv

spec nan "local lc = require 'lightcone'
return {spacetime = lc.kerr{mass = 0/0}, $good_tail}"
expect_error nan "field 'mass' is nan" -- "$LIGHTCONE" geodesic nan.lua -o out.csv

spec badcurve "local lc = require 'lightcone'
return {spacetime = lc.kerr{mass = 1}, curve = 'nul', start = {r = 10, theta = 90, phi = 0}, stop = {affine = 1}}"
expect_error badcurve "field 'curve' must be one of \"null\", \"timelike\", got \"nul\" (did you mean \"null\"?)" -- "$LIGHTCONE" geodesic badcurve.lua -o out.csv

spec nostop "local lc = require 'lightcone'
return {spacetime = lc.kerr{mass = 1}, curve = 'timelike', start = {r = 10, theta = 90, phi = 0}, stop = {}}"
expect_error nostop "give exactly one of affine, proper_time, coordinate_time" -- "$LIGHTCONE" geodesic nostop.lua -o out.csv

spec nullproper "local lc = require 'lightcone'
return {spacetime = lc.kerr{mass = 1}, curve = 'null', start = {r = 10, theta = 90, phi = 0}, direction = {r = -1}, stop = {proper_time = 1}}"
expect_error nullproper "a null curve has no proper time" -- "$LIGHTCONE" geodesic nullproper.lua -o out.csv

spec zerodir "local lc = require 'lightcone'
return {spacetime = lc.kerr{mass = 1}, curve = 'null', start = {r = 10, theta = 90, phi = 0}, direction = {}, stop = {affine = 1}}"
expect_error zerodir "direction: the direction must not be zero" -- "$LIGHTCONE" geodesic zerodir.lua -o out.csv

spec cartesian_in_kerr "local lc = require 'lightcone'
return {spacetime = lc.kerr{mass = 1}, curve = 'timelike', start = {r = 10, theta = 90, phi = 0}, velocity = {x = 0.1}, stop = {proper_time = 1}}"
expect_error cartesian_in_kerr "velocity: unknown field 'x'" -- "$LIGHTCONE" geodesic cartesian_in_kerr.lua -o out.csv

spec syntax "local lc = require 'lightcone'
return {spacetime = lc.kerr{mass = 1},,}"
expect_error syntax "syntax.lua:2:" -- "$LIGHTCONE" geodesic syntax.lua -o out.csv

spec runtime "local lc = require 'lightcone'
local x = nil
return {spacetime = lc.kerr{mass = x.y}}"
expect_error runtime "runtime.lua:3: attempt to index" -- "$LIGHTCONE" geodesic runtime.lua -o out.csv

spec io "local f = io.open('/etc/passwd')"
expect_error io "io.lua:1: attempt to index global 'io' (a nil value)" -- "$LIGHTCONE" geodesic io.lua -o out.csv

spec os "os.execute('touch pwned')"
expect_error os "os.lua:1: attempt to index global 'os' (a nil value)" -- "$LIGHTCONE" geodesic os.lua -o out.csv
[ ! -e pwned ] || fail "os.execute ran"

spec escape "local m = require '../etc/passwd'"
expect_error escape "escape.lua:1:" -- "$LIGHTCONE" geodesic escape.lua -o out.csv

spec nothing "return 42"
expect_error nothing "the script must return a table" -- "$LIGHTCONE" geodesic nothing.lua -o out.csv

spec ok "local lc = require 'lightcone'
return {spacetime = lc.kerr{mass = 1}, $good_tail}"
expect_error nofile "nofile.lua" -- "$LIGHTCONE" geodesic nofile.lua -o out.csv
expect_error badflag "--frobnicate" -- "$LIGHTCONE" geodesic ok.lua --frobnicate
expect_error nosub "" -- "$LIGHTCONE"

[ ! -e out.csv ] || fail "a failed run left out.csv behind"
ls "$WORK" | grep -q 'tmp-' && fail "a temporary file was left behind"

# An existing output survives a failed run untouched.
echo "precious" >out.csv
expect_error keep "kerr: unknown field" -- "$LIGHTCONE" geodesic typo.lua -o out.csv
[ "$(cat out.csv)" = "precious" ] || fail "a failed run changed an existing output"

# An output directory that does not exist.
expect_error nodir "cannot write" -- "$LIGHTCONE" geodesic ok.lua -o no/such/dir/out.csv
e2e_end
