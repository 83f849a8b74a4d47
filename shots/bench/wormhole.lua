-- Benchmark scene of a wormhole (not in `lightcone bench`'s default pair:
-- `--shot shots/bench/wormhole.lua`).  The Ellis wormhole of throat radius
-- 1, seen by a static observer 6 radii out, 80 degrees from the z axis,
-- with a 90 degree field; the checkered sphere of radius 1 at rest 5 radii
-- beyond the throat, 25 degrees round; a sky on each side; 256 x 256, one
-- sample per pixel.  Rays are integrated to |l| = 1000 on either side.
local lc = require "lightcone"

return {
  name = "wormhole",
  frames = 1,
  width = 256,
  height = 256,
  supersample = 1,
  frame = function(i)
    return {
      spacetime = lc.ellis_wormhole{throat = 1},
      observer = lc.static_observer{r = 6, theta = 80, phi = 0},
      camera = lc.camera{fov = 90},
      sky = lc.sky_checker{rows = 36, columns = 72},
      skies = {other_side = lc.sky_checker{rows = 18, columns = 36, colors = {{0.9, 0.45, 0.1}, {0.1, 0.2, 0.6}}}},
      objects = {lc.sphere{radius = 1, position = {r = -5, theta = 90, phi = 25}}},
    }
  end,
}
