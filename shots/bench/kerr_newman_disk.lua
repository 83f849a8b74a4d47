-- Benchmark scene for a charged hole: kerr_disk.lua's scene (a = 0.9, a
-- static observer at r = 30, theta = 80 deg, a 40 deg field, a disk from
-- r = 6 to 15, the checker sky, 256 x 256, one sample a pixel) with a
-- charge Q = 0.4 (a^2 + Q^2 = 0.97 M^2).  Not in `lightcone bench`'s
-- default pair: `lightcone bench --shot shots/bench/kerr_newman_disk.lua`.
local lc = require "lightcone"

return {
  name = "kerr_newman_disk",
  frames = 1,
  width = 256,
  height = 256,
  supersample = 1,
  frame = function(i)
    return {
      spacetime = lc.kerr{mass = 1, spin = 0.9, charge = 0.4},
      observer = lc.static_observer{r = 30, theta = 80, phi = 0},
      camera = lc.camera{fov = 40},
      disk = lc.disk{inner = 6, outer = 15, rings = 9, sectors = 36},
      sky = lc.sky_checker{rows = 18, columns = 36},
    }
  end,
}
