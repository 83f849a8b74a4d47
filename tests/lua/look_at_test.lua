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

-- Any camera kind: the aim is the same, the other fields are the kind's;
-- a pitch given raises the view axis above the target (a dome's framing).
local dome = lc.look_at{from = {r = 30, theta = 90, phi = 0}, to = {x = 0, y = 0, z = 10}, camera = "fisheye",
                        field = 180, tilt = 15, pitch = 55}
near(dome.pitch, math.deg(math.atan2(10, 30)) + 55, 1e-9, "fisheye pitch: the aim's plus 55")
near(dome.yaw, 0, 1e-9, "fisheye yaw")
assert(dome.tilt == 15 and dome.field == 180, "the fisheye's own fields pass through")
local vr = lc.look_at{from = {x = 0, y = 80, z = 0}, to = {x = 5, y = 0, z = 0}, camera = "equirect"}
near(vr.yaw, -math.deg(math.atan2(5, 80)), 1e-9, "equirect yaw towards +x")
assert(vr.longitude == nil and vr.pitch ~= nil, "an equirect with the aim alone")
ok, err = pcall(lc.look_at, {from = {x = 1}, to = {x = 2}, camera = "kerr"})
assert(not ok and err:find("camera 'kerr' is not a camera kind (camera, fisheye, equirect)", 1, true), err)
-- Every camera constructor lc has is a kind look_at builds (the engine's
-- registry, not a list kept here).
for _, kind in ipairs(__lightcone.__camera_kinds) do
  assert(type(lc[kind]) == "function", kind)
  local made = lc.look_at{from = {x = 0, y = 30, z = 0}, to = {x = 0, y = 0, z = 0}, camera = kind}
  assert(type(made) == "table", kind)
end
assert(#__lightcone.__camera_kinds == 3, "camera, fisheye, equirect")
ok, err = pcall(lc.look_at, {from = {x = 1}, to = {x = 2}, camera = "fisheye", field = 20})
assert(not ok and err:find("look_at: fisheye: field 'field' must be between 90 and 360", 1, true), err)
ok, err = pcall(lc.look_at, {from = {x = 1}, to = {x = 2}, yaw = 3})
assert(not ok and err:find("yaw is the aim's"), err)
return true
