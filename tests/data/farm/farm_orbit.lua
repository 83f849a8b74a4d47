-- A small multi-frame shot for the farm tests: the Kerr disk benchmark with
-- the observer rising from 60 to 85 degrees over 10 frames.  Tiny frames
-- (tens of ms each) so tests can render, kill and resume it many times; its
-- point stars go through the stage after the pixels in every farm mode.
local lc = require "lightcone"

return {
  name = "farm_orbit",
  frames = 10,
  width = 64,
  height = 40,
  supersample = 1,
  frame = function(i)
    return {
      spacetime = lc.kerr{mass = 1, spin = 0.9},
      observer = lc.static_observer{r = 30, theta = 60 + 25 * i / 9, phi = 10 * i},
      camera = lc.camera{fov = 40},
      disk = lc.disk{inner = 6, outer = 15, rings = 9, sectors = 36},
      sky = lc.starfield{},
    }
  end,
}
