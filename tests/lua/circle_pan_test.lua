-- lc.circle_pan.
local lc = require "lightcone"
local T = require "test_helpers"

local NAN = 0 / 0
local v = lc.vec

-- The angle between two vectors, in degrees.
local function angle(a, b)
  local c = v.dot(a, b) / (v.length(a) * v.length(b))
  return math.deg(math.acos(math.max(-1, math.min(1, c))))
end

-- The paper's first dihole pan: (0, 80, 0) to (80, 0, 0), the short way.
local A, B, C = {x = 0, y = 80, z = 0}, {x = 80, y = 0, z = 0}, {x = 0, y = 0, z = 80}
T.eq(lc.circle_pan(A, B, 0), A, "u = 0 gives from exactly")
T.eq(lc.circle_pan(A, B, 1), B, "u = 1 gives to exactly")
local h = math.sqrt(0.5) * 80
T.near(lc.circle_pan(A, B, 0.5), {x = h, y = h, z = 0}, 1e-12, "half way")
for j = 0, 100 do
  local u = j / 100
  local p = lc.circle_pan(A, B, u)
  T.near(v.length(p), 80, 1e-12, "radius stays 80 at u = " .. u)
  T.eq(p.z, 0, "stays in the plane z = 0 at u = " .. u)
  T.near(angle(A, p), 90 * u, 1e-9, "angle proportional to u at " .. u)
  T.ok(p.x >= 0 and p.y >= 0, "short way (first quadrant) at u = " .. u)
end
-- The second pan: (80, 0, 0) to (0, 0, 80).
T.near(lc.circle_pan(B, C, 0.5), {x = h, y = 0, z = h}, 1e-12, "second pan half way")
T.near(lc.circle_pan(B, C, 1 / 3), {x = 80 * math.cos(math.pi / 6), y = 0, z = 40}, 1e-12, "second pan at a third")
T.eq(lc.circle_pan(B, C, 1), C, "second pan ends exactly")

-- Clamping and fresh tables.
T.eq(lc.circle_pan(A, B, -1), A, "u < 0 clamps")
T.eq(lc.circle_pan(A, B, 2), B, "u > 1 clamps")
local from = {x = 0, y = 80, z = 0, label = "observer"}
local p0 = lc.circle_pan(from, B, 0)
T.ok(p0 ~= from, "a new table")
T.eq(p0, A, "only x, y, z are returned")
p0.x = 5
T.eq(from.x, 0, "from untouched")

-- The radius interpolates linearly when |from| ~= |to|.
for j = 0, 10 do
  local u = j / 10
  local p = lc.circle_pan({x = 10, y = 0, z = 0}, {x = 0, y = 20, z = 0}, u)
  T.near(v.length(p), 10 + 10 * u, 1e-12, "radius at u = " .. u)
  T.near(math.deg(math.atan2(p.y, p.x)), 90 * u, 1e-9, "angle at u = " .. u)
end

-- Short way both sides of 180 degrees.
local function dir(deg) return {x = math.cos(math.rad(deg)), y = math.sin(math.rad(deg)), z = 0} end
local p = lc.circle_pan(dir(0), dir(170), 0.5)
T.near(math.deg(math.atan2(p.y, p.x)), 85, 1e-9, "170 degrees counter-clockwise")
p = lc.circle_pan(dir(0), dir(190), 0.5)
T.near(math.deg(math.atan2(p.y, p.x)), -85, 1e-9, "190 degrees is 170 clockwise")
-- A general plane: stays on the great circle, perpendicular to from x to.
local F, G = {x = 3, y = -4, z = 12}, {x = -6, y = 2, z = 3}
local n = v.normalize(v.cross(F, G))
for j = 0, 10 do
  local q = lc.circle_pan(F, G, j / 10)
  T.near(v.dot(q, n), 0, 1e-12, "in the plane of from and to at " .. j / 10)
  T.near(angle(F, q), angle(F, G) * j / 10, 1e-9, "angle in a general plane at " .. j / 10)
end

-- An explicit axis: right-handed (counter-clockwise seen from its tip).
local down = {x = 0, y = -80, z = 0}
T.near(lc.circle_pan(A, down, 0.5, {0, 0, 1}), {x = -80, y = 0, z = 0}, 1e-12, "antiparallel about +z")
T.near(lc.circle_pan(A, down, 0.5, {x = 0, y = 0, z = -1}), {x = 80, y = 0, z = 0}, 1e-12, "antiparallel about -z")
T.near(lc.circle_pan(A, down, 0.5, {axis = {0, 0, 2}}), {x = -80, y = 0, z = 0}, 1e-12, "options table, any axis length")
T.eq(lc.circle_pan(A, down, 1, {0, 0, 1}), down, "ends exactly with an axis")
-- The axis sets the sense, even the long way: +y to +x about +z is 270 degrees.
T.near(lc.circle_pan(A, B, 1 / 3, {0, 0, 1}), {x = -80, y = 0, z = 0}, 1e-12, "long way at a third")
T.near(lc.circle_pan(A, B, 0.5, {0, 0, -1}), {x = h, y = h, z = 0}, 1e-12, "short way about -z")
-- Parallel with an axis: no turn, only the radius changes.
T.near(lc.circle_pan({x = 10, y = 0, z = 0}, {x = 20, y = 0, z = 0}, 0.5, {0, 0, 1}), {x = 15, y = 0, z = 0}, 1e-12, "parallel with an axis")
-- Nearly perpendicular to the axis is fine: the tiny axial part is dropped.
local tilted = {x = 0, y = 80, z = 1e-7}
local pt = lc.circle_pan(tilted, B, 0.5, {0, 0, -1})
T.near(pt, {x = h, y = h, z = 0}, 1e-9, "almost perpendicular")

-- Errors name the calling line.
T.fails(T.here(), "circle_pan: from and to are antiparallel, so the circle through them is not unique; pass an axis as the 4th argument", pcall(lc.circle_pan, A, down, 0.5))
T.fails(T.here(), "circle_pan: from and to are parallel, so the circle through them is not unique; pass an axis as the 4th argument", pcall(lc.circle_pan, A, {x = 0, y = 10, z = 0}, 0.5))
-- The check does not depend on u: a bad pan fails on every frame.
T.fails(T.here(), "circle_pan: from and to are parallel, so the circle through them is not unique; pass an axis as the 4th argument", pcall(lc.circle_pan, A, A, 0))
T.fails(T.here(), "circle_pan: from must be a vector {x=, y=, z=}, got nil", pcall(lc.circle_pan, nil, B, 0.5))
T.fails(T.here(), "circle_pan: to.z must be a number, got nil", pcall(lc.circle_pan, A, {x = 1, y = 2}, 0.5))
T.fails(T.here(), "circle_pan: from.x is NaN", pcall(lc.circle_pan, {x = NAN, y = 1, z = 0}, B, 0.5))
T.fails(T.here(), "circle_pan: from is the origin; the pan circles the origin and needs a radius", pcall(lc.circle_pan, {x = 0, y = 0, z = 0}, B, 0.5))
T.fails(T.here(), "circle_pan: to is the origin; the pan circles the origin and needs a radius", pcall(lc.circle_pan, A, {x = 0, y = 0, z = 0}, 0.5))
T.fails(T.here(), "circle_pan: u must be a number, got nil", pcall(lc.circle_pan, A, B))
T.fails(T.here(), "circle_pan: u is NaN", pcall(lc.circle_pan, A, B, NAN))
T.fails(T.here(), "circle_pan: axis must be a nonzero finite vector", pcall(lc.circle_pan, A, down, 0.5, {0, 0, 0}))
T.fails(T.here(), "circle_pan: axis must be a vector {x, y, z} or {x=, y=, z=}, got string", pcall(lc.circle_pan, A, down, 0.5, "z"))
T.fails(T.here(), "circle_pan: axis.z must be a number, got nil", pcall(lc.circle_pan, A, down, 0.5, {1, 0}))
T.fails(T.here(), "circle_pan: the options table has an unknown field ease; only axis = {x, y, z}", pcall(lc.circle_pan, A, down, 0.5, {axis = {0, 0, 1}, ease = "smoothstep"}))
T.fails(T.here(), "circle_pan: from is not perpendicular to the axis (45 degrees); with an axis both points must lie in the plane through the origin perpendicular to it", pcall(lc.circle_pan, {x = 0, y = 1, z = 1}, {x = 1, y = 0, z = 0}, 0.5, {0, 0, 1}))
T.fails(T.here(), "circle_pan: to is not perpendicular to the axis (0 degrees); with an axis both points must lie in the plane through the origin perpendicular to it", pcall(lc.circle_pan, A, C, 0.5, {0, 0, 1}))

return true
