-- The paper's first sequence (Müller, Boblest & Weiskopf, sec. 4.1):
-- a static observer above the accretion disk of a spinning hole.  The
-- inclination rises from 0 to 80 degrees, so the back of the disk arches
-- above and below the shadow; then the spin goes to 0 (the shadow's
-- asymmetry shrinks); then the mass goes to 0 (flat spacetime: an
-- undistorted ring).  900 frames, 1280x720, 2x2 supersampling.
--
--   lightcone render shots/kerr_accrDisk.lua --out out/kerr_accrDisk
local lc = require "lightcone"

-- Choices (and why) -------------------------------------------------------
local fps = 30                 -- 900 frames = 30 s, as the paper's sequence
local spin = 0.99              -- near-extremal: the clearest shadow asymmetry (the paper gives no value)
local distance = 50            -- observer radius r (M): the whole disk (to r = 16) fits a 60 deg view face-on
local fov = 60                 -- horizontal field of view (deg); 16:9 leaves ~36 deg vertically
local phi = 0                  -- observer longitude; the sweep in theta starts on the axis (theta = 0)
local inner, outer = 6, 16     -- disk: inner rim at 6M as in the paper, 10M wide
local rings, sectors = 10, 36  -- checker: one ring per M, 10-degree sectors
local tl = lc.timeline{fps = fps,
  {"hold_top", seconds = 1},   -- looking straight down the axis
  {"incline", seconds = 12},   -- 0 -> 80 deg, smoothstep: starts and stops at rest
  {"hold_edge", seconds = 1},
  {"spin_down", seconds = 7},  -- a: 0.99 -> 0
  {"hold_schw", seconds = 1},
  {"mass_down", seconds = 7},  -- M: 1 -> 0 (a is already 0, so |a| <= M throughout)
  {"hold_flat", seconds = 1},
}
assert(tl.frames == 900, "the storyboard has 900 frames, the timeline " .. tl.frames)

return {
  name = "kerr_accrDisk",
  frames = tl.frames,
  fps = fps,
  width = 1280,
  height = 720,
  supersample = 2,
  frame = function(i)
    local theta = 80 * lc.ease.smoothstep(tl:progress("incline", i))
    local a = spin * (1 - lc.ease.smoothstep(tl:progress("spin_down", i)))
    local M = 1 - lc.ease.smoothstep(tl:progress("mass_down", i))
    local scene = {
      spacetime = lc.kerr{mass = M, spin = a},
      observer = lc.static_observer{r = distance, theta = theta, phi = phi},
      camera = lc.camera{fov = fov},
      disk = lc.disk{inner = inner, outer = outer, rings = rings, sectors = sectors},
      sky = lc.starfield{},
    }
    return scene
  end,
}
