-- Three holes in a triangle (Majumdar–Papapetrou): three equal extreme
-- Reissner–Nordström holes of 0.3 at the corners of a triangle 1.5 from its
-- centre, in the plane z = 0, each held in place by the balance of its
-- charge and its mass.  A checkered sphere is released at rest on the axis,
-- 4 above the centre; it falls through the triangle, comes to rest 4 below
-- and swings back, two periods in the shot.  The observer watches from 30
-- away and 35 degrees above the plane while circling a third of the way
-- round: the holes' shadows, their lensed images of one another, and the
-- sphere's images pulled round each of them.
--
--   lightcone render shots/three_holes.lua --out out/three_holes
local lc = require "lightcone"

local fps, seconds = 30, 10
local m, R = 0.3, 1.5                 -- each hole's mass; their distance from the centre
local s = math.sqrt(3) / 2
local holes = lc.majumdar_papapetrou{holes = {
  {mass = m, position = {x = R, y = 0, z = 0}},
  {mass = m, position = {x = -R / 2, y = s * R, z = 0}},
  {mass = m, position = {x = -R / 2, y = -s * R, z = 0}},
}}
local swing = lc.worldline{spacetime = holes, start = {x = 0, y = 0, z = 4}, duration = 400}
-- The period from the engine: the second turning point away from the centre.
local T = lc.apocentres(swing)[2].t
local distance, elevation = 30, math.rad(35)

-- Light from the sphere takes the distance and the holes' delay (~2 M ln(4 r^2 / b^2)
-- with M the holes' total mass, ~10 here) to arrive: the observer's clock
-- runs that much behind the sphere's story, so the first frame shows it at
-- its start.
local delay = distance + 15

return {
  name = "three_holes",
  frames = fps * seconds,
  fps = fps,
  width = 1280,
  height = 720,
  supersample = 2,
  frame = function(i)
    local u = i / (fps * seconds)
    local phi = -math.pi / 2 + (2 * math.pi / 3) * lc.ease.smoothstep(u)
    local p = {x = distance * math.cos(elevation) * math.cos(phi), y = distance * math.cos(elevation) * math.sin(phi),
               z = distance * math.sin(elevation)}
    return {
      spacetime = holes,
      time = 2 * T * u + delay,
      observer = lc.static_observer{x = p.x, y = p.y, z = p.z},
      camera = lc.camera{fov = 34},
      sky = lc.starfield{},
      objects = {lc.sphere{radius = 0.4, worldline = swing}},
    }
  end,
}
