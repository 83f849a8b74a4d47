-- What each part of light_model does, frame by frame (docs/light.md): the
-- checkered disk of a Kerr hole (a = 0.9) from r = 60 at 82 degrees,
--   frame 0  the paper's look (model = "geometric"),
--   frame 1  the colour shift alone (beaming = 0),
--   frame 2  the beaming alone (color_shift = 0),
--   frame 3  both ("shifted"),
--   frame 4  the gravitational part alone (kinematic = 0),
--   frame 5  a Novikov–Thorne disk glowing at 8000 K, shifted.
--
--   lightcone render shots/light_models.lua --out out/light_models
local lc = require "lightcone"

local variants = {
  [0] = lc.light{},
  lc.light{model = "shifted", beaming = 0},
  lc.light{model = "shifted", color_shift = 0},
  lc.light{model = "shifted"},
  lc.light{model = "shifted", kinematic = 0},
  lc.light{model = "shifted"},
}

return {
  name = "light_models",
  frames = 6,
  width = 480,
  height = 270,
  supersample = 2,
  view = "gamut_safe",
  frame = function(i)
    return {
      spacetime = lc.kerr{mass = 1, spin = 0.9},
      observer = lc.static_observer{r = 60, theta = 82, phi = 0},
      camera = lc.camera{fov = 40},
      disk = lc.disk{inner = 2.4, outer = 20, temperature = i == 5 and 8000 or 0},
      sky = lc.sky_stars{},
      light = variants[i],
    }
  end,
}
