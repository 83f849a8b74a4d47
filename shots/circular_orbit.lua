-- Riding a circular orbit: an observer on the Keplerian orbit at r = 15 M
-- of a Kerr hole (a = 0.9), co-rotating with it and with the disk's
-- matter, for one whole turn.  It moves at 0.27 c relative to the static
-- observer there, so the hole it faces (forward = -e_r) shows up 15.8
-- degrees ahead of "forward", towards its motion (aberration: sin = v); the
-- camera is turned by that much to centre it.  With the light model
-- "shifted" the sky ahead is brighter and bluer, behind dimmer and redder.
-- From the disk's own plane the thin disk (r = 3 to 12) is seen edge-on,
-- where it vanishes, and its far side lensed into a ring round the shadow.  One turn, 2 pi / Omega =
-- 370.7 M of scene time, in 10 s.
--
--   lightcone render shots/circular_orbit.lua --out out/circular_orbit
local lc = require "lightcone"

local fps, seconds = 30, 10
local frames = fps * seconds
local M, a, r = 1, 0.9, 15
local omega = math.sqrt(M) / (r ^ 1.5 + a * math.sqrt(M))  -- Kepler in Boyer–Lindquist time
local period = 2 * math.pi / omega

return {
  name = "circular_orbit",
  frames = frames,
  fps = fps,
  width = 1280,
  height = 720,
  supersample = 2,
  frame = function(i)
    return {
      spacetime = lc.kerr{mass = M, spin = a},
      time = period * i / frames,
      observer = lc.circular_orbit{r = r},
      camera = lc.camera{fov = 60, yaw = 15.8},
      disk = lc.disk{inner = 3, outer = 12, rings = 9, sectors = 36},
      sky = lc.starfield{},
      light = lc.light{model = "shifted"},
    }
  end,
}
