-- Benchmark scene 2 (fixed: `lightcone bench` measures against it).
-- The paper's dihole (m1 = m2 = 0.4 at z = +-1) seen from (0, 80, 0), looking
-- at the origin; the checkered sphere of radius 1 at rest at (5, 0, 0);
-- 256 x 256, one sample per pixel.  A 12 deg field of view holds both
-- shadows and the sphere's images (the sphere subtends ~3.6 deg off-centre).
local lc = require "lightcone"

return {
  name = "dihole_sphere",
  frames = 1,
  width = 256,
  height = 256,
  supersample = 1,
  frame = function(i)
    return {
      spacetime = lc.dihole{m1 = 0.4, m2 = 0.4, d = 1},
      observer = lc.static_observer{x = 0, y = 80, z = 0},
      camera = lc.camera{fov = 12},
      sky = lc.sky_checker{rows = 36, columns = 72},
      objects = {lc.sphere{radius = 1, position = {x = 5, y = 0, z = 0}}},
    }
  end,
}
