-- A dome master (docs/cameras.md): the bench's Kerr hole and disk through
-- a 180-degree equidistant fisheye, framed for a level dome: the camera
-- looks at the hole and its axis (the dome's zenith) is pitched 55 degrees
-- above it, so the hole sits 35 degrees above the dome's front horizon
-- (the bottom of the frame), where an audience looks without craning.
-- For a dome tilted forward by 15 degrees, add tilt = 15: the hole stays at
-- 35 degrees above the audience's horizon.
local lc = require "lightcone"

return {
  name = "dome_example",
  frames = 1,
  width = 1024,
  height = 1024,
  supersample = 2,
  frame = function(i)
    return {
      spacetime = lc.kerr{mass = 1, spin = 0.9},
      observer = lc.static_observer{r = 30, theta = 80, phi = 0},
      camera = lc.fisheye{field = 180, tilt = 0, pitch = 55},
      disk = lc.disk{inner = 6, outer = 15, rings = 9, sectors = 36},
      sky = lc.starfield{},
    }
  end,
}
