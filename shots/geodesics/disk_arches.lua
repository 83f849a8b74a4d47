-- The paper's Figure 2: the light rays behind the arches of the first
-- sequence.  A Schwarzschild hole (M = 1, a = 0) with the disk from 6 to 16
-- M, seen from r = 50 at 80 degrees inclination (the first sequence's last
-- view).  Rays leave the camera in its vertical plane (the plane of the
-- spin axis, phi = 0), from 14 degrees above the hole to 14 below, and are
-- traced into the past: some pass over the hole and reach the far side of
-- the disk from above (the upper arch), some pass under it and reach the far
-- side from below (the lower arch), some meet the near side or escape.
--
--   lightcone geodesic shots/geodesics/disk_arches.lua -o arches.csv
--   lightcone plot arches.csv -o arches.svg --disk 6:16 --horizon 2 --extent 24
local lc = require "lightcone"

local hole = lc.kerr{mass = 1, spin = 0}
local rays = {}
for k = -14, 14 do
  local a = math.rad(k)  -- up from the hole's direction, in the camera's vertical plane
  rays[#rays + 1] = {
    spacetime = hole,
    curve = "null",
    time = "past",
    start = {t = 0, r = 50, theta = 80, phi = 0},
    -- Where the camera looks: at the hole (-e_r), tilted towards the pole
    -- (-e_theta, up on the screen) by a.
    direction = {r = -math.cos(a), theta = -math.sin(a)},
    stop = {affine = 110},
    samples = 441,
  }
end
return rays
