-- A sphere falling freely across the view of a static observer in flat
-- space, the observer's clock advancing 4 M a frame: with the shutter open
-- each frame blurs the sphere along its path (tests/e2e/motion_blur.sh).
-- Frame 3 closes its own shutter.  Tiny frames for the farm tests.
local lc = require "lightcone"
local flat = lc.minkowski{}
local path = lc.worldline{spacetime = flat, start = {t = -60, x = -30, y = 0, z = 0},
                          velocity = {x = 0.5, y = 0, z = 0}, duration = 200}
return {
  name = "moving_sphere",
  frames = 6,
  width = 64,
  height = 24,
  supersample = 2,
  shutter = 0.5,
  time_samples = 4,
  frame = function(i)
    return {
      spacetime = flat,
      observer = lc.static_observer{x = 0, y = 20, z = 0},
      time = 4 * i,
      camera = lc.camera{fov = 60},
      sky = lc.sky_checker{rows = 6, columns = 12},
      objects = {lc.sphere{radius = 2, worldline = path}},
      shutter = i == 3 and 0 or nil,
    }
  end,
}
