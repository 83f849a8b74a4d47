-- A bundle of light rays passing a Kerr hole (M = 1, a = 0.9) in its
-- equatorial plane, all launched parallel (along +x) from x = -40 with impact parameters
-- from -10 to +10: prograde rays (b > 0) get closer before being captured
-- than retrograde ones, so the captured band is shifted.  A script may
-- return an array of specs; the CSV then starts with a `ray` column.
--
--   lightcone geodesic shots/geodesics/kerr_ray_bundle.lua -o bundle.csv
local lc = require "lightcone"

local hole = lc.kerr{mass = 1, spin = 0.9}
local distance = 40
local rays = {}
for b = -10, 10, 1 do
  -- Start on the equator at BL distance sqrt(d^2 + b^2), at phi such that the
  -- ray, sent along +x in the static frame, has impact parameter ~b.
  local r = math.sqrt(distance ^ 2 + b ^ 2)
  local phi = 180 - math.deg(math.atan2(b, distance))
  local ang = math.rad(phi)
  -- direction +x expressed on (e_r, e_phi) at this phi (flat-space directions;
  -- close enough at r = 40 for a picture)
  rays[#rays + 1] = {
    spacetime = hole,
    curve = "null",
    start = {t = 0, r = r, theta = 90, phi = phi},
    direction = {r = math.cos(ang) * 1, phi = -math.sin(ang) * 1},
    stop = {affine = 120},
    samples = 241,
  }
end
return rays
