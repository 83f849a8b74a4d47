-- lc.look_at aims the camera along the straight line to a point.
local lc = require "lightcone"

local function near(a, b, tol, what)
  assert(math.abs(a - b) <= tol, what .. ": " .. tostring(a) .. " vs " .. tostring(b))
end

-- Looking at the origin is the default view.
local c = lc.look_at{from = {x = 0, y = 80, z = 0}, to = {x = 0, y = 0, z = 0}, fov = 30}
near(c.yaw, 0, 1e-12, "yaw at the origin")
near(c.pitch, 0, 1e-12, "pitch at the origin")
assert(c.fov == 30, "fov passes through")

-- From (0, 80, 0) the default right is e_phi = -x: a target at +x is to the left.
c = lc.look_at{from = {x = 0, y = 80, z = 0}, to = {x = 5, y = 0, z = 0}}
near(c.yaw, -math.deg(math.atan2(5, 80)), 1e-9, "yaw towards +x")
near(c.pitch, 0, 1e-12, "pitch towards +x")

-- Up is -e_theta = +z at the equator.
c = lc.look_at{from = {r = 30, theta = 90, phi = 0}, to = {x = 0, y = 0, z = 10}}
near(c.pitch, math.deg(math.atan2(10, 30)), 1e-9, "pitch up")
near(c.yaw, 0, 1e-9, "no yaw")

-- Mistakes are reported at the caller's line.
local ok, err = pcall(lc.look_at, {from = {x = 1, y = 0, z = 0}, to = {x = 1, y = 0, z = 0}})
assert(not ok and err:find("same point"), err)
ok, err = pcall(lc.look_at, {from = {x = 1}, to = {x = 2}, fvo = 3})
assert(not ok and err:find("unknown field 'fvo'"), err)
return true
