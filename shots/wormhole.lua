-- Through the wormhole of Interstellar (James, von Tunzelmann, Franklin &
-- Thorne 2015): a throat of radius 1 and length 0.01, flaring onto two flat
-- universes over a lensing width of 0.05, the film's proportions.  An
-- observer falls freely at 0.6 c from 12 throat radii out, through the
-- throat, to 12 radii beyond it, looking ahead.  This universe's sky is a
-- field of stars; the other's a coloured checker, so every ray's end shows:
-- at first the other universe is a small crystal ball ringed by the lensed
-- stars of this one (the ball's angular radius is arcsin(1/r(l)): 4.8
-- degrees at l = 12), it fills the view at the throat, and beyond it the
-- camera turns round to find this universe as the ball behind.  A sphere
-- stands at rest in the other universe, 5 radii from the throat, to one
-- side of the path.
--
--   lightcone render shots/wormhole.lua --out out/wormhole
local lc = require "lightcone"

local fps = 30
local frames = lc.seconds(fps, 8)  -- 240
local wormhole = lc.interstellar_wormhole{throat = 1, length = 0.01, lensing_width = 0.05}
local speed = 0.6
-- Proper time to cover 24 radii at 0.6 c: 24 / (0.6 γ) with γ = 1.25, 32.
local fall = lc.worldline{spacetime = wormhole, start = {r = 12, theta = 90, phi = 0},
                          velocity = {r = -speed, theta = 0, phi = 0}, duration = 33}

return {
  name = "wormhole",
  frames = frames,
  fps = fps,
  width = 1280,
  height = 720,
  supersample = 2,
  frame = function(i)
    -- The last two seconds turn the camera round (ahead is -e_l, towards
    -- smaller l, all the way: e_l points back at this universe).
    local turn = lc.ease.smoothstep(math.max(0, math.min(1, (i - (frames - 1 - 2 * fps)) / (2 * fps))))
    return {
      spacetime = wormhole,
      observer = lc.free_fall{worldline = fall, proper_time = 32 * i / (frames - 1)},
      camera = lc.camera{fov = 90, yaw = 180 * turn},
      sky = lc.starfield{},
      skies = {other_side = lc.sky_checker{rows = 18, columns = 36,
                                           colors = {{0.9, 0.45, 0.1}, {0.1, 0.2, 0.6}}}},
      objects = {lc.sphere{radius = 0.7, position = {r = -5, theta = 75, phi = 20}}},
    }
  end,
}
