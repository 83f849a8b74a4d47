-- A 360-degree video frame (docs/cameras.md): the bench's Kerr hole and
-- disk seen from above the disk, 11 M out (within it), through the
-- equirectangular camera.  The hole is in the middle of the frame (ahead
-- of a viewer in a headset or a video site's player), the disk's far side
-- lensed over the shadow, its near side spread out under the viewer to
-- the horizon all the way round, the stars of the sky above.  The frame is 2:1, the
-- whole sphere; `lightcone encode` marks the video as a 360-degree one.
local lc = require "lightcone"

return {
  name = "equirect_example",
  frames = 1,
  width = 2048,
  height = 1024,
  supersample = 2,
  frame = function(i)
    return {
      spacetime = lc.kerr{mass = 1, spin = 0.9},
      observer = lc.static_observer{r = 11, theta = 78, phi = 0},
      camera = lc.equirect{},
      disk = lc.disk{inner = 6, outer = 15, rings = 9, sectors = 36},
      sky = lc.starfield{},
    }
  end,
}
