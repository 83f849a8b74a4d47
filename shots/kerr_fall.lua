-- A fall into a spinning hole, in the disk's own light (docs/light.md): an
-- observer let go at rest 30 M out, 10 degrees above a glowing
-- Novikov–Thorne disk, falls freely towards the hole, looking at it all the
-- way.  The light it sees climbs by more than three stops as the disk fills
-- the view and its light is blueshifted by the fall, so the exposure
-- follows it (auto_exposure): each frame metered from its own light and
-- smoothed over its neighbours, the same whichever frames are rendered.
-- The fall ends 4 M of proper time before the worldline would meet the
-- horizon.
--
--   lightcone render shots/kerr_fall.lua --out out/kerr_fall
local lc = require "lightcone"

local fps = 30
local frames = lc.seconds(fps, 6)            -- 180
local hole = lc.kerr{mass = 1, spin = 0.9}
local start = 30                             -- M, at rest
-- Proper time from rest at r0 to the horizon is about (pi/2) sqrt(r0^3 / 2)
-- = 182 M for r0 = 30 (181.2 for this one); the fall is shown to 176 M.
local fall = lc.worldline{spacetime = hole, start = {r = start, theta = 80, phi = 0},
                          velocity = {r = 0, theta = 0, phi = 0}, duration = 180}
local last = 176
local isco = 2.321                           -- M: the prograde ISCO of spin 0.9

return {
  name = "kerr_fall",
  frames = frames,
  fps = fps,
  width = 640, height = 360,
  supersample = 2,
  -- The look: a gamut-safe view, the ~10,000 K gas white balanced to read
  -- hot and bluish, a little bloom; the exposure metered.
  view = "gamut_safe",
  white_balance = 5000,
  saturation = 1.2,
  bloom = 0.2,
  auto_exposure = 1,
  frame = function(i)
    -- Proper time eased in: the fall starts slowly anyway, the end is the story.
    local tau = last * (i / (frames - 1)) ^ 0.8
    return {
      spacetime = hole,
      observer = lc.free_fall{worldline = fall, proper_time = tau},
      camera = lc.camera{fov = 70},
      disk = lc.disk{inner = isco, outer = 20, solar_masses = 4.3e6, accretion_rate = 1e-8},
      sky = lc.starfield{brightness = 34},
      light = lc.light{model = "shifted"},
    }
  end,
}
