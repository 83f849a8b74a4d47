-- Example shot: a slow look around a spinning hole.  The observer stays
-- static at r = 25 while its inclination rises from 10 to 85 degrees with
-- smoothstep easing, over 4 seconds at 24 fps.
--
--   lightcone render shots/orbit_example.lua --out out/orbit --scale 0.5
local lc = require "lightcone"

local fps, seconds = 24, 4
local frames = fps * seconds

return {
  name = "orbit_example",
  frames = frames,
  fps = fps,
  width = 320,
  height = 180,
  supersample = 2,
  frame = function(i)
    local u = i / (frames - 1)
    local s = u * u * (3 - 2 * u)  -- smoothstep
    return {
      spacetime = lc.kerr{mass = 1, spin = 0.95},
      observer = lc.static_observer{r = 25, theta = 10 + 75 * s, phi = 0},
      camera = lc.camera{fov = 50},
      disk = lc.disk{inner = 3, outer = 12, rings = 9, sectors = 48},
      sky = lc.sky_checker{rows = 18, columns = 36},
    }
  end,
}
