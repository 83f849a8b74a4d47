-- Benchmark scene of Schwarzschild–de Sitter (not in `lightcone bench`'s
-- default pair: `--shot shots/bench/kottler.lua`).  A hole of mass 1 with
-- Λ = 0.01 (horizons at 2.03 and 16.2), seen by a static observer at r = 8,
-- 80 degrees from the z axis, looking at the hole with a 90 degree field;
-- the checkered sphere of radius 1 at rest at r = 5, 25 degrees round from
-- the observer; 256 x 256, one sample per pixel.  Every ray that escapes is
-- integrated to the cosmological horizon (the outer stop rule).
local lc = require "lightcone"

return {
  name = "kottler",
  frames = 1,
  width = 256,
  height = 256,
  supersample = 1,
  frame = function(i)
    return {
      spacetime = lc.kottler{mass = 1, lambda = 0.01},
      observer = lc.static_observer{r = 8, theta = 80, phi = 0},
      camera = lc.camera{fov = 90},
      sky = lc.sky_checker{rows = 36, columns = 72},
      objects = {lc.sphere{radius = 1, position = {r = 5, theta = 90, phi = 25}}},
    }
  end,
}
