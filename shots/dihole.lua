-- The paper's third sequence (sec. 4.2, "dihole"): two equal extreme
-- Reissner–Nordström holes on the z axis at z = +-1.  A checkered sphere rests
-- at (5, 0, 0) while the masses grow from 0 to 0.4; released, it oscillates
-- along x with period T.  The observer watches from (0, 80, 0) for one
-- period, pans along a circle to (80, 0, 0) during the next, to (0, 0, 80)
-- during the third, and waits there until the fifth oscillation is over.
-- Then the sphere is fixed at its start again and the masses shrink to 0.
-- 2100 frames, 1280x720, 2x2 supersampling.
--
--   lightcone render shots/dihole.lua --out out/dihole
local lc = require "lightcone"

-- Choices (and why) -------------------------------------------------------
local fps = 30
local m, d = 0.4, 1                   -- the paper's holes
local start = {x = 5, y = 0, z = 0}   -- the sphere's rest position (and release point)
local radius = 1                      -- the sphere's proper radius
local distance = 80                   -- observer distance from the origin
local fov = 16                        -- horizontal (deg): the sphere's swing of +-5 at 80 (+-3.6 deg) and the shadows
local hole = lc.dihole{m1 = m, m2 = m, d = d}
local orbit = lc.worldline{spacetime = hole, start = start, duration = 420}  -- > 5 proper periods (5 x 78.75)
-- The period T comes from the engine: the second turning point of the motion.
local T = lc.apocentres(orbit)[2].t
-- Light from the sphere needs ~distance of coordinate time to reach the
-- observer, so the observer's clock runs `delay` behind the sphere's story:
-- it sees the release at the start of the oscillation segment and the end
-- of the fifth oscillation at its end.
local delay = distance

local tl = lc.timeline{fps = fps,
  {"hold_flat", frames = 75},      -- flat space: the sphere alone
  {"grow", frames = 150},          -- masses 0 -> 0.4 (smoothstep), sphere at rest
  {"oscillate", frames = 1650},    -- five periods of motion as seen by the observer
  {"shrink", frames = 150},        -- sphere fixed at its start, masses 0.4 -> 0
  {"hold_end", frames = 75},
}
assert(tl.frames == 2100, "the storyboard has 2100 frames, the timeline " .. tl.frames)

local y_axis, x_axis, z_axis = {x = 0, y = distance, z = 0}, {x = distance, y = 0, z = 0}, {x = 0, y = 0, z = distance}

-- Observer position at story time t (0 = release, T = one period).
local function observer_at(t)
  if t < T then return y_axis end
  if t < 2 * T then return lc.circle_pan(y_axis, x_axis, lc.ease.smoothstep((t - T) / T)) end
  if t < 3 * T then return lc.circle_pan(x_axis, z_axis, lc.ease.smoothstep((t - 2 * T) / T)) end
  return z_axis
end

-- Camera roll (degrees) at story time t.  Seen from the z axis the swing
-- would run up and down the frame's short side, and at its turning points
-- the sphere (pushed outwards by the holes' lensing) would leave the frame;
-- so the second pan also rolls the camera a quarter turn, and from the z axis
-- the swing runs along the long side, +x on the left as seen from the y axis.
local function roll_at(t)
  if t < 2 * T then return 0 end
  if t < 3 * T then return -90 * lc.ease.smoothstep((t - 2 * T) / T) end
  return -90
end

return {
  name = "dihole",
  frames = tl.frames,
  fps = fps,
  width = 1280,
  height = 720,
  supersample = 2,
  frame = function(i)
    local scene = {sky = lc.starfield{}}
    local _, _, u = tl:at(i)
    local segment = tl:at(i)
    if segment == "oscillate" then
      local t = 5 * T * u                      -- story time: five periods over the segment
      local p = observer_at(t)
      scene.camera = lc.camera{fov = fov, roll = roll_at(t)}
      scene.spacetime = hole
      scene.time = t + delay
      scene.observer = lc.static_observer{x = p.x, y = p.y, z = p.z}
      scene.objects = {lc.sphere{radius = radius, worldline = orbit}}
    else
      local grow = lc.ease.smoothstep(tl:progress("grow", i))
      local shrink = lc.ease.smoothstep(tl:progress("shrink", i))
      local mass = m * grow * (1 - shrink)
      local before = i < tl:start("oscillate")
      local p = before and y_axis or z_axis
      scene.camera = lc.camera{fov = fov, roll = before and 0 or roll_at(5 * T)}
      scene.spacetime = lc.dihole{m1 = mass, m2 = mass, d = d}
      scene.observer = lc.static_observer{x = p.x, y = p.y, z = p.z}
      scene.objects = {lc.sphere{radius = radius, position = start}}
    end
    return scene
  end,
}
