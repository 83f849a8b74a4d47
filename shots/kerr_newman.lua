-- A charged, spinning hole (Kerr–Newman): a static observer 30 M out, 80
-- degrees from the spin axis, watches the hole charge up at fixed spin
-- a = 0.6 from Q = 0 (Kerr) to Q = 0.8, where a^2 + Q^2 = M^2 (extremal:
-- the horizons meet at r = M).  The charge pulls the photon orbits in, so
-- the shadow narrows (by ~21% in width here: the prograde photon orbit
-- falls to the horizon at extremality); the disk's inner matter orbits faster.  Then a hold.
--
--   lightcone render shots/kerr_newman.lua --out out/kerr_newman
local lc = require "lightcone"

local fps = 30
local spin = 0.6                -- a; the charge rises to sqrt(1 - a^2) = 0.8
local q_max = math.sqrt(1 - spin * spin)
local tl = lc.timeline{fps = fps,
  {"hold_kerr", seconds = 1},
  {"charge_up", seconds = 6},   -- Q: 0 -> 0.8, smoothstep
  {"hold_extremal", seconds = 1},
}

return {
  name = "kerr_newman",
  frames = tl.frames,
  fps = fps,
  width = 1280,
  height = 720,
  supersample = 2,
  frame = function(i)
    local q = q_max * lc.ease.smoothstep(tl:progress("charge_up", i))
    return {
      spacetime = lc.kerr{mass = 1, spin = spin, charge = q},
      observer = lc.static_observer{r = 30, theta = 80, phi = 0},
      camera = lc.camera{fov = 40},
      disk = lc.disk{inner = 4, outer = 14, rings = 10, sectors = 36},
      sky = lc.starfield{},
    }
  end,
}
