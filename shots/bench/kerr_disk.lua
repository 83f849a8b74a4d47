-- Benchmark scene 1 (fixed: `lightcone bench` measures against it).
-- Kerr M = 1, a = 0.9; a static observer at r = 30, theta = 80 deg, phi = 0
-- looking at the hole with a 40 deg horizontal field of view; a thin disk
-- from r = 6 to 15; the procedural checker sky; 256 x 256, one sample per pixel.
local lc = require "lightcone"

return {
  name = "kerr_disk",
  frames = 1,
  width = 256,
  height = 256,
  supersample = 1,
  frame = function(i)
    return {
      spacetime = lc.kerr{mass = 1, spin = 0.9},
      observer = lc.static_observer{r = 30, theta = 80, phi = 0},
      camera = lc.camera{fov = 40},
      disk = lc.disk{inner = 6, outer = 15, rings = 9, sectors = 36},
      sky = lc.sky_checker{rows = 18, columns = 36},
    }
  end,
}
