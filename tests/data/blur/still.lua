-- A Kerr disk seen by a static observer, nothing animated: a shutter open
-- on it changes nothing, to the bit (tests/e2e/motion_blur.sh).
local lc = require "lightcone"
return {
  name = "still",
  frames = 3,
  width = 48,
  height = 32,
  supersample = 2,
  frame = function(i)
    return {
      spacetime = lc.kerr{mass = 1, spin = 0.9},
      observer = lc.static_observer{r = 30, theta = 80, phi = 0},
      camera = lc.camera{fov = 40},
      disk = lc.disk{inner = 6, outer = 15},
      sky = lc.starfield{},
    }
  end,
}
