-- The shot that docs/first_shot.md builds step by step: a Schwarzschild hole
-- with a disk, seen by an observer who swings a quarter of the way round it
-- while a sphere orbits the hole and passes behind it (lensed into arcs
-- above and below the shadow).  240 frames, 1280x720, 2x2 supersampling.
--
--   lightcone render shots/circling.lua --out out/circling
local lc = require "lightcone"

-- Choices (and why) -------------------------------------------------------
local fps = 30
local seconds = 8
local distance = 40            -- observer radius r (M)
local fov = 55                 -- wide enough for the whole disk (to r = 14) from r = 40, with a margin
local frames = lc.seconds(fps, seconds)   -- 240

local hole = lc.kerr{mass = 1, spin = 0}
-- A sphere on a circular orbit at r = 20 (a static observer there sees it
-- pass at v = sqrt(M / (r - 2M)) = 0.2357 c), starting behind the hole.
local orbit = lc.worldline{spacetime = hole, start = {r = 20, theta = 90, phi = 150},
                           velocity = {r = 0, theta = 0, phi = 0.2357}, duration = 300}
-- Light from the sphere takes about `distance` of coordinate time to arrive,
-- so the clock starts there (frame 0 shows the sphere at its start) and runs
-- 280 M over the shot.
local function clock(i) return distance + 280 * i / (frames - 1) end

return {
  name = "circling",           -- frames are circling.NNNN.exr / .png
  frames = frames,
  fps = fps,
  width = 1280, height = 720,
  supersample = 2,
  frame = function(i)
    local s = lc.ease.smoothstep(i / (frames - 1))
    return {
      spacetime = hole,
      time = clock(i),
      observer = lc.static_observer{r = distance, theta = 80, phi = 90 * s},
      camera = lc.camera{fov = fov},
      disk = lc.disk{inner = 6, outer = 14},
      sky = lc.starfield{},
      objects = {lc.sphere{radius = 1, worldline = orbit}},
    }
  end,
}
