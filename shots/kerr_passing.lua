-- The paper's second sequence (sec. 4.1, "kerr_passing"): an observer falls
-- freely along a timelike geodesic that pierces the disk plane between the
-- horizon and the inner rim and flies on.  Its frame is parallel-transported
-- (geodesic precession), and the camera is fixed in that frame, so the hole
-- drifts and turns in view as the frame precesses.  1700 frames, 1280x720,
-- 2x2 supersampling.
--
--   lightcone render shots/kerr_passing.lua --out out/kerr_passing
local lc = require "lightcone"

-- Choices (and why) -------------------------------------------------------
local fps = 30
local hole = lc.kerr{mass = 1, spin = 0.9}  -- r+ = 1.44; prograde photon orbit 1.56
-- The orbit: found with `lightcone geodesic` (docs/geodesic.md).  It starts
-- at r = 40 behind the pole (theta = 75 deg, phi = 180 deg), moving inwards
-- at 0.4 c and over the pole at 0.11 c; it is unbound (it escapes), reaches
-- periapsis r = 5.29 at proper time 88 exactly where it crosses the
-- equatorial plane — 0.7 M inside the disk's inner rim — and crosses that
-- plane nowhere else, so it never passes through the disk itself.
local orbit = lc.worldline{
  spacetime = hole,
  start = {t = 0, r = 40, theta = 75, phi = 180},
  velocity = {r = -0.4, theta = -0.11, phi = 0},
  duration = 180,
}
local tau_start, tau_end = 0, 176  -- symmetric about the periapsis: in from r = 40, out to r ~ 40
local fov = 90                     -- wide: the hole fills much of the sky near periapsis
-- The camera looks along the fall until the passage: the hole ahead, then
-- sweeping below as the disk rushes past.  From frame 780 it pitches down
-- inside the transported frame (a pan relative to the gyroscope frame, so
-- the precession still shows) to keep the hole in view while the orbit
-- turns it round behind the observer: the keys put the edge of the shadow
-- ~10 deg inside the view at periapsis (its radius is ~50 deg at r = 5.3)
-- and the hole in the centre once it has shrunk (from frame ~1440), 245
-- deg round by the end.  They come from where the hole is seen in the
-- observer's frame (the outgoing principal null direction, aberration
-- included), frame by frame, from `lightcone inspect` with pitch 0
-- (docs/showcase.md, "How the flyby keeps the hole in view").
local frames = 1700
local pitch = lc.keyframes{
  {780, 0}, {810, -1.9}, {840, -10.2}, {870, -29.5}, {900, -60.9}, {930, -98.0}, {960, -127.2},
  {990, -145.4}, {1020, -160.5}, {1050, -172.9}, {1080, -183.3}, {1110, -191.9}, {1140, -199.2},
  {1170, -205.4}, {1200, -210.7}, {1230, -215.3}, {1260, -219.3}, {1290, -222.9}, {1320, -226.1},
  {1350, -228.9}, {1380, -231.5}, {1410, -233.7}, {1440, -235.8}, {1470, -237.4}, {1500, -238.7},
  {1530, -239.9}, {1560, -241.1}, {1590, -242.1}, {1620, -243.1}, {1650, -244.0}, {1680, -244.8},
  {1699, -245.4},
}
local inner, outer = 6, 16         -- the disk of the first sequence

return {
  name = "kerr_passing",
  frames = frames,
  fps = fps,
  width = 1280,
  height = 720,
  supersample = 2,
  frame = function(i)
    -- Frames sample the observer's proper time uniformly: its own clock.
    local tau = tau_start + (tau_end - tau_start) * i / (frames - 1)
    return {
      spacetime = hole,
      observer = lc.free_fall{worldline = orbit, proper_time = tau},
      -- forward = -(transported e_r leg): at the hole when the fall starts
      camera = lc.camera{fov = fov, pitch = pitch(i)},
      disk = lc.disk{inner = inner, outer = outer, rings = 10, sectors = 36},
      sky = lc.starfield{},
    }
  end,
}
