-- A glowing accretion disk (docs/light.md): Kerr a = 0.9 seen from r = 60,
-- 82 degrees from the spin axis.  The disk is a Novikov–Thorne thin disk
-- from near the ISCO (2.32 M) to 20 M whose hottest ring is at 8000 K; with
-- light = lc.light{model = "shifted"} each ring's light reaches the camera
-- shifted by g (hit.g), so the side that comes towards us is brighter and
-- bluer.  filmic = 1 rolls the beamed highlights off instead of clipping
-- them.  Set temperature = 0 for the paper's checkered disk in the same
-- view, model = "geometric" for the disk as its own matter sees it.
local lc = require "lightcone"

return {
  name = "glowing_disk",
  frames = 1,
  width = 640,
  height = 360,
  supersample = 2,
  filmic = 1,
  frame = function(i)
    return {
      spacetime = lc.kerr{mass = 1, spin = 0.9},
      observer = lc.static_observer{r = 60, theta = 82, phi = 0},
      camera = lc.camera{fov = 40},
      disk = lc.disk{inner = 2.4, outer = 20, temperature = 8000},
      sky = lc.sky_stars{},
      light = lc.light{model = "shifted"},
    }
  end,
}
