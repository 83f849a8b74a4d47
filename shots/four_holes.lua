-- Four holes in a square (Majumdar–Papapetrou): four extreme
-- Reissner–Nordström holes of 0.25 at the corners (+-1.2, +-1.2, 0), at rest
-- wherever they are put (each one's charge balances its mass).  The
-- observer, 40 away, rises from the square's plane to straight above it,
-- while a sphere swings along the axis through the middle of the square:
-- edge-on the four shadows line up and merge into one lensed band; from
-- above they stand apart, with a ring of images of the sky between them.
--
--   lightcone render shots/four_holes.lua --out out/four_holes
local lc = require "lightcone"

local fps, seconds = 30, 10
local m, a = 0.25, 1.2
local holes = lc.majumdar_papapetrou{holes = {
  {mass = m, position = {x = a, y = a, z = 0}},
  {mass = m, position = {x = -a, y = a, z = 0}},
  {mass = m, position = {x = -a, y = -a, z = 0}},
  {mass = m, position = {x = a, y = -a, z = 0}},
}}
local swing = lc.worldline{spacetime = holes, start = {x = 0, y = 0, z = 3}, duration = 400}
local T = lc.apocentres(swing)[2].t
local distance = 40

-- Light from the sphere takes the distance and the holes' delay (~2 M ln(4 r^2 / b^2)
-- with M the holes' total mass, ~10 here) to arrive: the observer's clock
-- runs that much behind the sphere's story, so the first frame shows it at
-- its start.
local delay = distance + 15

return {
  name = "four_holes",
  frames = fps * seconds,
  fps = fps,
  width = 1280,
  height = 720,
  supersample = 2,
  frame = function(i)
    local u = i / (fps * seconds)
    -- From 5 degrees above the plane (the axis would be the camera's
    -- pole) to 85, along the meridian through a corner's diagonal.
    local lift = math.rad(5 + 80 * lc.ease.smoothstep(u))
    local p = {x = distance * math.cos(lift) / math.sqrt(2), y = -distance * math.cos(lift) / math.sqrt(2),
               z = distance * math.sin(lift)}
    return {
      spacetime = holes,
      time = 2 * T * u + delay,
      observer = lc.static_observer{x = p.x, y = p.y, z = p.z},
      camera = lc.camera{fov = 20},
      sky = lc.starfield{},
      objects = {lc.sphere{radius = 0.35, worldline = swing}},
    }
  end,
}
