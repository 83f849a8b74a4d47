-- Benchmark scene of Majumdar–Papapetrou holes (not in `lightcone bench`'s
-- default pair: `--shot shots/bench/four_holes.lua`).  Four extreme
-- Reissner–Nordström holes of 0.25 at (+-1.2, +-1.2, 0), seen from 40 M at
-- 45 degrees above their plane, looking at the centre; the checkered sphere
-- of radius 0.35 at rest at (0, 0, 2) above it; 256 x 256, one sample per
-- pixel.  Each step of each ray sums four holes' terms (the dihole's two).
local lc = require "lightcone"

local m, a, d = 0.25, 1.2, 40 / math.sqrt(2)

return {
  name = "four_holes",
  frames = 1,
  width = 256,
  height = 256,
  supersample = 1,
  frame = function(i)
    return {
      spacetime = lc.majumdar_papapetrou{holes = {
        {mass = m, position = {x = a, y = a, z = 0}},
        {mass = m, position = {x = -a, y = a, z = 0}},
        {mass = m, position = {x = -a, y = -a, z = 0}},
        {mass = m, position = {x = a, y = -a, z = 0}},
      }},
      observer = lc.static_observer{x = 0, y = -d, z = d},
      camera = lc.camera{fov = 14},
      sky = lc.sky_checker{rows = 36, columns = 72},
      objects = {lc.sphere{radius = 0.35, position = {x = 0, y = 0, z = 2}}},
    }
  end,
}
