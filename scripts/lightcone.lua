-- lightcone: the library for shot and geodesic-spec authors.
--
--   local lc = require "lightcone"
--   local bh = lc.kerr{mass = 1, spin = 0.9}
--
-- Units are geometric (G = c = 1, lengths and times in units of the mass
-- scale M). Angles are in degrees everywhere in Lua.
-- Reference: docs/shots.md (shots), docs/geodesic.md (geodesic specs).

local engine = __lightcone
local M = {}

-- Scene constructors live in the engine (validated where they are called, so
-- errors name your line); every function of the engine API is re-exported
-- (but its own "__" names).
for name, fn in pairs(engine) do
  if name:sub(1, 2) ~= "__" then M[name] = fn end
end

-- Cartesian components and polar angles (radians) of a position table
-- {x, y, z} or {r, theta, phi} (degrees).
local function cartesian(p, what)
  if type(p) ~= "table" then error("look_at: " .. what .. " must be a position table", 3) end
  if p.r ~= nil then
    local th, ph = math.rad(p.theta or 0), math.rad(p.phi or 0)
    return {p.r * math.sin(th) * math.cos(ph), p.r * math.sin(th) * math.sin(ph), p.r * math.cos(th)}, th, ph
  end
  local x, y, z = p.x or 0, p.y or 0, p.z or 0
  local r = math.sqrt(x * x + y * y + z * z)
  return {x, y, z}, r > 0 and math.acos(z / r) or 0, math.atan2(y, x)
end

-- lc.look_at{from = pos, to = pos, camera = "camera", ...} -> a camera for
-- an observer at `from` that aims at the point `to`.  Aims along the
-- straight coordinate line (the flat-space picture: exact for M = 0; near a
-- hole the light from `to` arrives bent, so the point may appear
-- off-centre): the yaw and pitch that turn the default view "at the hole"
-- (forward = -e_r, up = -e_theta, right = e_phi) towards `to`.  `camera`
-- names the kind (lc.camera, the pinhole, by default; "fisheye",
-- "equirect"); every other field goes to its constructor, but a `pitch`
-- given is added to the aim's (the view axis that many degrees above the
-- target: a dome master framed with the target low in the dome, as
-- docs/cameras.md says) and a yaw is the aim's alone.  The kinds are the
-- engine's camera registry's (a new camera kind is aimed without a line here).
local camera_kinds, camera_list = {}, {}
for _, name in ipairs(engine.__camera_kinds) do
  camera_kinds[name] = true
  camera_list[#camera_list + 1] = name
end
camera_list = table.concat(camera_list, ", ")

function M.look_at(t)
  if type(t) ~= "table" then error("look_at: expected look_at{from = ..., to = ...}", 2) end
  local kind = t.camera or "camera"
  if not camera_kinds[kind] then
    error("look_at: camera '" .. tostring(kind) .. "' is not a camera kind (" .. camera_list .. ")", 2)
  end
  if t.yaw ~= nil then error("look_at: yaw is the aim's; the camera turns towards `to` by itself", 2) end
  local p, th, ph = cartesian(t.from, "from")
  local q = cartesian(t.to, "to")
  local d = {q[1] - p[1], q[2] - p[2], q[3] - p[3]}
  local len = math.sqrt(d[1] ^ 2 + d[2] ^ 2 + d[3] ^ 2)
  if len == 0 then error("look_at: from and to are the same point", 2) end
  local er = {math.sin(th) * math.cos(ph), math.sin(th) * math.sin(ph), math.cos(th)}
  local et = {math.cos(th) * math.cos(ph), math.cos(th) * math.sin(ph), -math.sin(th)}
  local ep = {-math.sin(ph), math.cos(ph), 0}
  local function dot(a, b) return a[1] * b[1] + a[2] * b[2] + a[3] * b[3] end
  local f, r, u = -dot(d, er) / len, dot(d, ep) / len, -dot(d, et) / len
  local fields = {}
  for k, v in pairs(t) do
    if k ~= "from" and k ~= "to" and k ~= "camera" then fields[k] = v end
  end
  fields.yaw = math.deg(math.atan2(r, f))
  fields.pitch = math.deg(math.asin(math.max(-1, math.min(1, u)))) + (t.pitch or 0)
  -- The constructor's own message (an unknown field, a value out of
  -- range), at the line that called look_at.
  local ok, made = pcall(engine[kind], fields)
  if not ok then error("look_at: " .. tostring(made):gsub("^[^\n]-:%d+: ", ""), 2) end
  return made
end

-- Animation helpers: easing, keyframes, timelines, paths (pure Lua).
for name, value in pairs(require "lightcone.animation") do
  assert(M[name] == nil, "lightcone: duplicate name " .. name)
  M[name] = value
end

-- A name lc lacks (lc.fisheye{...}) is an error at the line that reads it,
-- listing the names lc has and the nearest one, not "attempt to call a nil
-- value" later.  rawget(lc, "name") tests for a name without the error.
setmetatable(M, {__index = engine.__unknown_name})

return M
