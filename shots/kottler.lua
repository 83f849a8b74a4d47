-- A hole in a universe with a cosmological constant (Schwarzschild–de
-- Sitter, Kottler): a static observer 6 M from a hole of mass 1 watches Λ
-- rise from 1e-6 (the cosmological horizon 1,732 M away: Schwarzschild) to
-- 0.05, where the horizon has closed in to 6.43 M, just beyond the
-- observer.  Holding still against both the hole's pull and the cosmic
-- push, the observer is pulled less and less towards the hole: the shadow
-- shrinks from 45 to 17.5 degrees in radius (Perlick et al. 2018:
-- sin^2 α = 27 M^2 F(r_o) / (r_o^2 (1 - 9 Λ M^2)), F = 1 - 2M/r - Λr^2/3).
-- The sky is painted on the cosmological horizon, where the rays that
-- escape end.  Its light, measured against a source at rest at the static
-- radius (the data layers' hit.g), is blueshifted 1.22 at first (a static
-- observer at 6 M of a Schwarzschild hole), about 1 midway and 1.87 at the
-- end: through lc.light{model = "shifted"} the textures' bands would leave
-- the visible there (docs/light.md), so the shot keeps the paper's look.
-- Then a hold.
--
--   lightcone render shots/kottler.lua --out out/kottler
local lc = require "lightcone"

local fps = 30
local r_o = 6
local tl = lc.timeline{fps = fps,
  {"hold_flat", seconds = 1},
  {"expand", seconds = 6},   -- log Λ: 1e-6 -> 0.05, smoothstep
  {"hold", seconds = 1},
}

return {
  name = "kottler",
  frames = tl.frames,
  fps = fps,
  width = 1280,
  height = 720,
  supersample = 2,
  frame = function(i)
    local u = lc.ease.smoothstep(tl:progress("expand", i))
    local lambda = 1e-6 * (0.05 / 1e-6) ^ u
    return {
      spacetime = lc.kottler{mass = 1, lambda = lambda},
      observer = lc.static_observer{r = r_o, theta = 80, phi = 0},
      camera = lc.camera{fov = 110},
      sky = lc.starfield{},
    }
  end,
}
