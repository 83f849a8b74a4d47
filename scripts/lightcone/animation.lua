-- lightcone.animation: easing, interpolation, keyframes, timelines and pans
-- for shot authors. Pure Lua (LuaJIT 2.1 / Lua 5.1), merged into the `lc`
-- table by scripts/lightcone.lua:
--
--   local lc = require "lightcone"
--   local tl = lc.timeline{fps = 30, {"rise", seconds = 10}, {"hold", frames = 45}}
--   local incl = lc.keyframes{{0, 0}, {tl:stop("rise"), 80, ease = "smoothstep"}}
--
-- Every function is pure: results depend on the arguments only (never on
-- earlier calls or call order), inputs are copied where they are kept, and
-- every table returned is fresh. Shots are evaluated frame by frame in any
-- order by several processes, and all of them must agree.
--
-- Errors are raised with error(msg, level), the level chosen so that the
-- `file:line:` prefix names the nearest line *outside* this file: the shot
-- author's line that made the bad call, not a line of the library.
-- Reference: docs/animation.md.

local type, tostring, pairs, ipairs, error, pcall = type, tostring, pairs, ipairs, error, pcall
local setmetatable, rawget = setmetatable, rawget
local floor, sqrt, sin, cos, atan2, pi = math.floor, math.sqrt, math.sin, math.cos, math.atan2, math.pi
local huge = math.huge
local concat, sort = table.concat, table.sort

local M = {}

---------------------------------------------------------------------------
-- Errors at the author's line
---------------------------------------------------------------------------

-- "file:line: " of the Lua function `level` frames above the caller of
-- position (1 = the caller itself), exactly the prefix error(msg, level)
-- would add there; "" for a C function or beyond the top of the stack.
-- (Scripts have no debug library; error's own level machinery does the work.)
local function position(level)
  local _, where = pcall(error, "", level + 2)
  return where
end

local function file_of(where)
  return where:match("^(.*):%d+: $")
end

-- This file, as error positions spell it (possibly shortened by Lua).
local LIBRARY_FILE = file_of(position(1))

-- Raises msg at the nearest stack frame that is not in this file. If there
-- is none, the author's call was a tail call (`return lc.lerp(...)` as the
-- last statement of a function the engine called), whose frame LuaJIT does
-- not keep: then the outermost library line is named, and the message says
-- why.
local function fail(msg)
  local fallback
  for level = 2, 100 do
    local where = position(level) -- same numbering as error(msg, level) here
    if where ~= "" then
      if file_of(where) ~= LIBRARY_FILE then
        error(msg, level) -- not a tail call: that would shift the levels
      end
      fallback = level
    end
  end
  error(msg .. " (the calling line is unknown: Lua keeps none for a tail call like " ..
        "`return lc.f(...)`)", fallback or 1)
end

---------------------------------------------------------------------------
-- Small helpers
---------------------------------------------------------------------------

local function num(x)
  -- Numbers as authors wrote them: 10 not 10.0.
  return tostring(x)
end

-- Levenshtein distance, case-insensitive.
local function distance(a, b)
  a, b = a:lower(), b:lower()
  local la, lb = #a, #b
  local prev = {}
  for j = 0, lb do prev[j] = j end
  for i = 1, la do
    local cur = {[0] = i}
    local ca = a:byte(i)
    for j = 1, lb do
      local cost = (ca == b:byte(j)) and 0 or 1
      local best = prev[j - 1] + cost
      if prev[j] + 1 < best then best = prev[j] + 1 end
      if cur[j - 1] + 1 < best then best = cur[j - 1] + 1 end
      cur[j] = best
    end
    prev = cur
  end
  return prev[lb]
end

-- " (did you mean 'x'?)" for the candidate closest to name, if close enough
-- (a few edits, or name is the start of it); candidates is an array (its
-- order breaks ties).
local function did_you_mean(name, candidates)
  if type(name) ~= "string" then return "" end
  local best, best_d
  for _, c in ipairs(candidates) do
    local d = distance(name, c)
    if #name >= 3 and c:lower():sub(1, #name) == name:lower() then d = 1 end
    if best_d == nil or d < best_d then best, best_d = c, d end
  end
  if best ~= nil and best_d <= math.max(2, floor(#best / 3)) then
    return " (did you mean '" .. best .. "'?)"
  end
  return ""
end

-- Key as it appears in messages: x, or [3] for array indices.
local function key_name(k)
  if type(k) == "string" then return k end
  if type(k) == "number" then return "[" .. num(k) .. "]" end
  return "[" .. tostring(k) .. "]"
end

-- A total, deterministic order on table keys: numbers, then strings, then
-- anything else by its type name.
local function key_less(a, b)
  local ta, tb = type(a), type(b)
  if ta ~= tb then
    if ta == "number" then return true end
    if tb == "number" then return false end
    if ta == "string" then return true end
    if tb == "string" then return false end
    return ta < tb
  end
  if ta == "number" or ta == "string" then return a < b end
  return false
end

local function sorted_keys(t)
  local keys = {}
  for k in pairs(t) do keys[#keys + 1] = k end
  sort(keys, key_less)
  return keys
end

local function check_number(x, what, ctx)
  if type(x) ~= "number" then
    fail(ctx .. ": " .. what .. " must be a number, got " .. type(x))
  end
  if x ~= x then fail(ctx .. ": " .. what .. " is NaN") end
  return x
end

local function check_finite(x, what, ctx)
  check_number(x, what, ctx)
  if x == huge or x == -huge then fail(ctx .. ": " .. what .. " must be finite, got " .. num(x)) end
  return x
end

local function check_fps(fps, ctx)
  if type(fps) ~= "number" or not (fps > 0) or fps == huge then
    fail(ctx .. ": fps must be a positive number, got " ..
         (type(fps) == "number" and num(fps) or type(fps)))
  end
  return fps
end

-- Rounds a length in frames to whole frames, halves up.
local function round(x)
  return floor(x + 0.5)
end

---------------------------------------------------------------------------
-- Easing
---------------------------------------------------------------------------

local EASE_ORDER = {"linear", "smoothstep", "smootherstep", "in_quad", "out_quad", "in_out_quad",
                    "in_cubic", "out_cubic", "in_out_cubic", "in_out_sine"}

-- The curves on (0, 1); the public wrappers below check u and clamp it.
local curves = {
  -- u: constant speed.
  linear = function(u) return u end,
  -- 3u^2 - 2u^3: starts and stops with zero speed.
  smoothstep = function(u) return u * u * (3 - 2 * u) end,
  -- Perlin's 6u^5 - 15u^4 + 10u^3: zero speed and acceleration at both ends.
  smootherstep = function(u) return u * u * u * (u * (6 * u - 15) + 10) end,
  -- u^2: starts at rest, arrives at full speed.
  in_quad = function(u) return u * u end,
  -- 1 - (1 - u)^2: starts at full speed, arrives at rest.
  out_quad = function(u) local v = 1 - u; return 1 - v * v end,
  -- in_quad for the first half, out_quad for the second.
  in_out_quad = function(u)
    if u < 0.5 then return 2 * u * u end
    local v = 2 - 2 * u
    return 1 - v * v / 2
  end,
  -- u^3.
  in_cubic = function(u) return u * u * u end,
  -- 1 - (1 - u)^3.
  out_cubic = function(u) local v = 1 - u; return 1 - v * v * v end,
  -- in_cubic for the first half, out_cubic for the second.
  in_out_cubic = function(u)
    if u < 0.5 then return 4 * u * u * u end
    local v = 2 - 2 * u
    return 1 - v * v * v / 2
  end,
  -- (1 - cos(pi u)) / 2: half a cosine wave.
  in_out_sine = function(u) return (1 - cos(pi * u)) / 2 end,
}

-- The easings: each maps u to [0, 1] with f(0) = 0 and f(1) = 1 exactly,
-- nondecreasing; u outside [0, 1] clamps (f(-2) = 0, f(3) = 1); u must be a
-- number (not NaN). Reading an unknown name is an error that suggests the
-- nearest one. Authors may add their own: lc.ease.mine = function(u) ... end.
local ease = {}
for _, name in ipairs(EASE_ORDER) do
  local curve = curves[name]
  local ctx = "ease." .. name
  ease[name] = function(u)
    check_number(u, "u", ctx)
    if u <= 0 then return 0 end
    if u >= 1 then return 1 end
    return curve(u)
  end
end

local function ease_names()
  local names = {}
  for _, name in ipairs(EASE_ORDER) do names[#names + 1] = name end
  local extra = {}
  for name in pairs(ease) do
    if curves[name] == nil and type(name) == "string" then extra[#extra + 1] = name end
  end
  sort(extra)
  for _, name in ipairs(extra) do names[#names + 1] = name end
  return names
end

setmetatable(ease, {
  __index = function(_, name)
    local hint = did_you_mean(name, ease_names())
    if hint == "" then hint = " (easings: " .. concat(ease_names(), ", ") .. ")" end
    fail("ease: no easing '" .. tostring(name) .. "'" .. hint)
  end,
})
M.ease = ease

-- The easing function named by e (a name of lc.ease or a function).
-- `what` starts the message, e.g. "keyframes: key 3 has ease".
local function resolve_ease(e, what)
  if type(e) == "function" then return e end
  if type(e) == "string" then
    local f = rawget(ease, e)
    if type(f) == "function" then return f end
    local hint = did_you_mean(e, ease_names())
    if hint == "" then hint = " (easings: " .. concat(ease_names(), ", ") .. ")" end
    fail(what .. " '" .. e .. "', which is not an easing" .. hint)
  end
  fail(what .. " of type " .. type(e) .. "; use an easing name like 'smoothstep' or a function")
end

---------------------------------------------------------------------------
-- Numbers and interpolation
---------------------------------------------------------------------------

-- clamp(x, lo, hi) -> x limited to [lo, hi]. All three are numbers (not
-- NaN); lo <= hi. Infinite x clamps like any other.
function M.clamp(x, lo, hi)
  check_number(x, "x", "clamp")
  check_number(lo, "lo", "clamp")
  check_number(hi, "hi", "clamp")
  if lo > hi then fail("clamp: lo (" .. num(lo) .. ") is greater than hi (" .. num(hi) .. ")") end
  if x < lo then return lo end
  if x > hi then return hi end
  return x
end

-- smooth(u [, e]) -> the easing e applied to u clamped to [0, 1]. e is the
-- name of an lc.ease function ("smoothstep" if omitted) or a function of u.
function M.smooth(u, e)
  check_number(u, "u", "smooth")
  local f = resolve_ease(e == nil and "smoothstep" or e, "smooth: ease")
  if u < 0 then u = 0 elseif u > 1 then u = 1 end
  return f(u)
end

-- Exact at both ends (u = 0 gives a, u = 1 gives b) and constant when a == b.
local function lerp_number(a, b, u)
  if u < 0.5 then return a + (b - a) * u end
  return b - (b - a) * (1 - u)
end

-- Why tables a and b (named name_a, name_b in the message) cannot be
-- interpolated component-wise, or nil if they can. Deterministic: keys are
-- visited in sorted order.
local function vector_mismatch(a, b, name_a, name_b)
  local only_a, only_b = {}, {}
  for _, k in ipairs(sorted_keys(a)) do
    if b[k] == nil then only_a[#only_a + 1] = key_name(k) end
  end
  for _, k in ipairs(sorted_keys(b)) do
    if a[k] == nil then only_b[#only_b + 1] = key_name(k) end
  end
  if #only_a > 0 or #only_b > 0 then
    local parts = {}
    if #only_a > 0 then parts[#parts + 1] = "only in " .. name_a .. ": " .. concat(only_a, ", ") end
    if #only_b > 0 then parts[#parts + 1] = "only in " .. name_b .. ": " .. concat(only_b, ", ") end
    return name_a .. " and " .. name_b .. " have different components (" .. concat(parts, "; ") .. ")"
  end
  for _, pair in ipairs({{a, name_a}, {b, name_b}}) do
    for _, k in ipairs(sorted_keys(pair[1])) do
      local v = pair[1][k]
      if type(v) ~= "number" then
        return "component " .. key_name(k) .. " of " .. pair[2] .. " is a " .. type(v) ..
               ", expected a number"
      end
    end
  end
  return nil
end

-- Component-wise lerp of two tables with the same keys (not checked here).
local function lerp_table(a, b, u)
  local out = {}
  for k, va in pairs(a) do out[k] = lerp_number(va, b[k], u) end
  return out
end

-- lerp(a, b, u) -> a + (b - a) u. a and b are both numbers, or both tables
-- of numbers with the same keys (array-like {1, 2, 3} or keyed {x=, y=, z=}),
-- interpolated component-wise into a new table. u is a number; it is not
-- clamped (u outside [0, 1] extrapolates). Exact at the ends: u = 0 gives a,
-- u = 1 gives b, and a == b gives a for every u.
function M.lerp(a, b, u)
  check_number(u, "u", "lerp")
  local ta, tb = type(a), type(b)
  if ta == "number" and tb == "number" then return lerp_number(a, b, u) end
  if ta == "table" and tb == "table" then
    local ok = true
    for k, va in pairs(a) do
      if type(va) ~= "number" or type(b[k]) ~= "number" then ok = false end
    end
    for k in pairs(b) do
      if a[k] == nil then ok = false end
    end
    if not ok then fail("lerp: " .. vector_mismatch(a, b, "a", "b")) end
    return lerp_table(a, b, u)
  end
  if (ta == "number" or ta == "table") and (tb == "number" or tb == "table") then
    fail("lerp: cannot interpolate a " .. ta .. " and a " .. tb)
  end
  local which, t = "a", ta
  if ta == "number" or ta == "table" then which, t = "b", tb end
  fail("lerp: " .. which .. " must be a number or a table of numbers, got " .. t)
end

---------------------------------------------------------------------------
-- Keyframes
---------------------------------------------------------------------------

local DATA = {} -- private key of the internal state of keyframes and timelines

local function copy(v)
  if type(v) ~= "table" then return v end
  local out = {}
  for k, x in pairs(v) do out[k] = x end
  return out
end

local Keyframes = {}

local function keyframes_at(self, i)
  check_number(i, "frame", "keyframes")
  local d = rawget(self, DATA)
  local frames, values, n = d.frames, d.values, d.n
  if i <= frames[1] then return copy(values[1]) end
  if i >= frames[n] then return copy(values[n]) end
  local lo, hi = 1, n -- frames[lo] <= i < frames[hi]
  while hi - lo > 1 do
    local mid = floor((lo + hi) / 2)
    if frames[mid] <= i then lo = mid else hi = mid end
  end
  if frames[lo] == i then return copy(values[lo]) end
  local u = (i - frames[lo]) / (frames[hi] - frames[lo])
  local e = d.eases[hi]
  if e ~= nil then
    u = e(u)
    if type(u) ~= "number" or u ~= u then
      fail("keyframes: the ease of key " .. hi .. " returned " ..
           (type(u) == "number" and "NaN" or "a " .. type(u)) .. ", expected a number")
    end
  end
  if d.vector then return lerp_table(values[lo], values[hi], u) end
  return lerp_number(values[lo], values[hi], u)
end

Keyframes.__call = keyframes_at
Keyframes.__index = function(_, k)
  fail("keyframes: no field '" .. tostring(k) .. "'" .. did_you_mean(k, {"first", "last"}) ..
       "; the fields are first and last, and k(i) gives the value at frame i")
end
Keyframes.__tostring = function(self)
  local d = rawget(self, DATA)
  return "keyframes(" .. d.n .. " keys, frames " .. num(d.frames[1]) .. " to " .. num(d.frames[d.n]) .. ")"
end

local KEY_FIELDS = {"ease"}

-- keyframes(list) -> k, a callable: k(i) is the value at frame i.
-- list = {{frame, value [, ease = name | function]}, ...}: at least one key,
-- frames finite and strictly increasing (fractional frames are fine), values
-- all numbers or all tables of numbers with the same keys (as for lerp). The
-- ease of a key shapes the segment that arrives at it (default linear; an
-- ease on the first key has nothing to shape). k(i) takes any number i
-- (fractional too): exactly the key's value at a key's frame, the first value
-- before k.first and the last from k.last on. Tables are copied both ways.
function M.keyframes(list)
  if type(list) ~= "table" then
    fail("keyframes: expected a list of keys {frame, value [, ease = ]}, got " .. type(list))
  end
  local n = #list
  for _, k in ipairs(sorted_keys(list)) do
    if type(k) ~= "number" or k < 1 or k > n or k ~= floor(k) then
      local hint = k == "ease" and " (ease goes inside a key: {frame, value, ease = ...})" or ""
      fail("keyframes: the list of keys has an unexpected field " .. key_name(k) .. hint)
    end
  end
  if n == 0 then fail("keyframes: needs at least one key {frame, value}") end
  local frames, values, eases = {}, {}, {}
  local vector, first_keys = nil, nil
  for j = 1, n do
    local key = list[j]
    local ctx = "keyframes: key " .. j
    if type(key) ~= "table" then
      fail(ctx .. " must be a table {frame, value [, ease = ]}, got " .. type(key))
    end
    for _, f in ipairs(sorted_keys(key)) do
      if f ~= 1 and f ~= 2 and f ~= "ease" then
        if type(f) == "number" then
          fail(ctx .. " has an extra element " .. key_name(f) .. "; a key is {frame, value [, ease = ]}")
        end
        if f == "frame" or f == "value" then
          fail(ctx .. " has a field '" .. f .. "'; keys are positional: {frame, value [, ease = ]}")
        end
        fail(ctx .. " has an unknown field '" .. tostring(f) .. "'" .. did_you_mean(f, KEY_FIELDS))
      end
    end
    local frame, value = key[1], key[2]
    if type(frame) ~= "number" then
      fail(ctx .. " needs a frame number as its first element, got " .. type(frame))
    end
    if frame ~= frame or frame == huge or frame == -huge then
      fail(ctx .. " has frame " .. num(frame) .. "; frames must be finite")
    end
    if j > 1 and not (frame > frames[j - 1]) then
      fail("keyframes: frames must increase (key " .. j .. " has frame " .. num(frame) ..
           " after " .. num(frames[j - 1]) .. ")")
    end
    if value == nil then fail(ctx .. " needs a value as its second element") end
    if type(value) == "number" then
      if value ~= value or value == huge or value == -huge then
        fail(ctx .. " has value " .. num(value) .. "; values must be finite")
      end
      if vector == true then fail(ctx .. " has a number value but key 1 has a table") end
      vector = false
    elseif type(value) == "table" then
      if vector == false then fail(ctx .. " has a table value but key 1 has a number") end
      for _, c in ipairs(sorted_keys(value)) do
        local x = value[c]
        if type(x) ~= "number" then
          fail(ctx .. " has a value whose component " .. key_name(c) .. " is a " .. type(x) ..
               ", expected a number")
        end
        if x ~= x or x == huge or x == -huge then
          fail(ctx .. " has a value whose component " .. key_name(c) .. " is " .. num(x) ..
               "; values must be finite")
        end
      end
      if first_keys == nil then
        vector, first_keys = true, value
      else
        local why = vector_mismatch(value, first_keys, "key " .. j, "key 1")
        if why ~= nil then fail("keyframes: " .. why) end
      end
      value = copy(value)
    else
      fail(ctx .. " has a value of type " .. type(value) .. "; values are numbers or tables of numbers")
    end
    if key.ease ~= nil then
      local e = resolve_ease(key.ease, ctx .. " has ease")
      if e ~= ease.linear then eases[j] = e end
    end
    frames[j], values[j] = frame, value
  end
  return setmetatable({
    first = frames[1],
    last = frames[n],
    [DATA] = {frames = frames, values = values, eases = eases, n = n, vector = vector},
  }, Keyframes)
end

---------------------------------------------------------------------------
-- Timelines
---------------------------------------------------------------------------

local Timeline = {}
local timeline_methods = {}
local TIMELINE_NAMES = {"frames", "fps", "start", "stop", "length", "progress", "at", "names"}

Timeline.__index = function(_, k)
  local m = timeline_methods[k]
  if m ~= nil then return m end
  if k == "fps" then return nil end -- a timeline without fps
  fail("timeline: no field or method '" .. tostring(k) .. "'" .. did_you_mean(k, TIMELINE_NAMES))
end
Timeline.__tostring = function(self)
  local d = rawget(self, DATA)
  local parts = {}
  for _, s in ipairs(d.segments) do
    parts[#parts + 1] = s.name .. " " .. s.start .. "-" .. s.stop
  end
  return "timeline(" .. concat(parts, ", ") .. "; " .. d.frames .. " frames)"
end

-- The internal state of the timeline `self` a method got; catches tl.start(...).
local function timeline_self(self, method)
  if type(self) ~= "table" or rawget(self, DATA) == nil or rawget(self, DATA).segments == nil then
    fail("timeline." .. method .. ": call it as a method, with a colon: tl:" .. method .. "(...)")
  end
  return rawget(self, DATA)
end

local function segment_of(d, name, method)
  if type(name) ~= "string" then
    fail("timeline:" .. method .. ": the segment name must be a string, got " .. type(name))
  end
  local s = d.by_name[name]
  if s == nil then
    local names = {}
    for j, seg in ipairs(d.segments) do names[j] = seg.name end
    local hint = did_you_mean(name, names)
    if hint == "" then hint = " (segments: " .. concat(names, ", ") .. ")" end
    fail("timeline:" .. method .. ": no segment '" .. name .. "'" .. hint)
  end
  return s
end

-- tl:start(name) -> the first frame of segment `name` (an integer).
function timeline_methods.start(self, name)
  local d = timeline_self(self, "start")
  return segment_of(d, name, "start").start
end

-- tl:stop(name) -> the first frame after segment `name`: start + length,
-- which is the start of the next segment (or tl.frames for the last).
function timeline_methods.stop(self, name)
  local d = timeline_self(self, "stop")
  return segment_of(d, name, "stop").stop
end

-- tl:length(name) -> the number of frames of segment `name` (>= 1).
function timeline_methods.length(self, name)
  local d = timeline_self(self, "length")
  return segment_of(d, name, "length").length
end

-- tl:progress(name, i) -> u in [0, 1] for frame i (a number, fractional
-- allowed): 0 up to the segment's start, (i - start) / length inside it,
-- 1 from its stop on (so the first frame of the next segment sees 1).
function timeline_methods.progress(self, name, i)
  local d = timeline_self(self, "progress")
  local s = segment_of(d, name, "progress")
  check_number(i, "frame", "timeline:progress")
  if i <= s.start then return 0 end
  if i >= s.stop then return 1 end
  return (i - s.start) / s.length
end

-- tl:at(i) -> name, local_frame, u of the segment containing frame i (a
-- number): start <= i < stop, local_frame = i - start, u = local_frame /
-- length. Outside the timeline the nearest segment answers (the first
-- before frame 0, the last from tl.frames on) with u clamped to 0 or 1.
function timeline_methods.at(self, i)
  local d = timeline_self(self, "at")
  check_number(i, "frame", "timeline:at")
  local segs = d.segments
  local lo, hi = 1, #segs -- the last segment with start <= i, or the first
  while lo < hi do
    local mid = floor((lo + hi + 1) / 2)
    if segs[mid].start <= i then lo = mid else hi = mid - 1 end
  end
  local s = segs[lo]
  local t = i - s.start
  local u = t / s.length
  if u < 0 then u = 0 elseif u > 1 then u = 1 end
  return s.name, t, u
end

-- tl:names() -> a new array of the segment names, in order.
function timeline_methods.names(self)
  local d = timeline_self(self, "names")
  local names = {}
  for j, s in ipairs(d.segments) do names[j] = s.name end
  return names
end

local SEGMENT_FIELDS = {"frames", "seconds"}

-- timeline(spec) -> tl, the segments of spec laid end to end from frame 0.
-- spec = {fps = f, {name, frames = n} or {name, seconds = s}, ...}: at
-- least one segment, names unique strings, each segment exactly one of
-- frames/seconds, fps (> 0) required if any segment uses seconds. Each
-- length rounds to whole frames, math.floor(x + 0.5) of n or s * fps, and
-- must come to >= 1. tl.frames is the total, tl.fps the fps (or nil); the
-- methods are start, stop, length, progress, at and names (see above).
function M.timeline(spec)
  if type(spec) ~= "table" then
    fail("timeline: expected a table {fps = , {name, seconds = } ...}, got " .. type(spec))
  end
  local n = #spec
  for _, k in ipairs(sorted_keys(spec)) do
    local segment_index = type(k) == "number" and k >= 1 and k <= n and k == floor(k)
    if not segment_index and k ~= "fps" then
      if type(k) == "string" then
        fail("timeline: unknown field '" .. k .. "'" .. did_you_mean(k, {"fps"}))
      end
      fail("timeline: unexpected field " .. key_name(k) .. "; segments are the array part, {name, frames = n}")
    end
  end
  local fps = spec.fps
  if fps ~= nil then check_fps(fps, "timeline") end
  if n == 0 then fail("timeline: needs at least one segment {name, frames = n} or {name, seconds = s}") end
  local segments, by_name, at = {}, {}, 0
  for j = 1, n do
    local seg = spec[j]
    if type(seg) ~= "table" then
      fail("timeline: segment " .. j .. " must be a table {name, frames = n} or {name, seconds = s}, got " ..
           type(seg))
    end
    local name = seg[1]
    if type(name) ~= "string" or name == "" then
      fail("timeline: segment " .. j .. " needs a name string as its first element, got " ..
           (name == "" and "an empty string" or type(name)))
    end
    local ctx = "timeline: segment '" .. name .. "'"
    for _, f in ipairs(sorted_keys(seg)) do
      if f ~= 1 and f ~= "frames" and f ~= "seconds" then
        if type(f) == "string" then
          fail(ctx .. " has an unknown field '" .. f .. "'" .. did_you_mean(f, SEGMENT_FIELDS))
        end
        fail(ctx .. " has an unexpected field " .. key_name(f) .. "; a segment is {name, frames = n} or {name, seconds = s}")
      end
    end
    if by_name[name] ~= nil then
      fail("timeline: segment " .. j .. " repeats the name '" .. name .. "' of segment " .. by_name[name].index)
    end
    local frames, seconds = seg.frames, seg.seconds
    if frames ~= nil and seconds ~= nil then fail(ctx .. " has both frames and seconds; give one") end
    if frames == nil and seconds == nil then fail(ctx .. " needs frames = n or seconds = s") end
    local length
    if frames ~= nil then
      check_finite(frames, "frames", ctx)
      length = round(frames)
      if length < 1 then
        fail(ctx .. " is " .. length .. " frames long (frames = " .. num(frames) ..
             "); a segment needs at least 1 frame")
      end
    else
      check_finite(seconds, "seconds", ctx)
      if fps == nil then fail(ctx .. " is given in seconds but the timeline has no fps") end
      length = round(seconds * fps)
      if length < 1 then
        fail(ctx .. " is " .. length .. " frames long (" .. num(seconds) .. " s at " .. num(fps) ..
             " fps); a segment needs at least 1 frame")
      end
    end
    local s = {name = name, index = j, start = at, length = length, stop = at + length}
    segments[j], by_name[name] = s, s
    at = s.stop
  end
  return setmetatable({
    frames = at,
    fps = fps,
    [DATA] = {segments = segments, by_name = by_name, frames = at},
  }, Timeline)
end

-- seconds(fps, s) -> the number of frames s seconds last at fps frames per
-- second, rounded to whole frames with math.floor(fps * s + 0.5). fps > 0,
-- s finite (negative gives a negative count, for offsets).
function M.seconds(fps, s)
  check_fps(fps, "seconds")
  check_finite(s, "s", "seconds")
  return round(fps * s)
end

-- frames_to_seconds(fps, n) -> n / fps, the duration of n frames in seconds
-- (n may be fractional or negative). fps > 0.
function M.frames_to_seconds(fps, n)
  check_fps(fps, "frames_to_seconds")
  check_finite(n, "n", "frames_to_seconds")
  return n / fps
end

---------------------------------------------------------------------------
-- Vectors {x=, y=, z=}
---------------------------------------------------------------------------

-- x, y, z of the vector v, or an error naming `what` (e.g. "from").
local function read_vec(v, what, ctx)
  if type(v) ~= "table" then
    fail(ctx .. ": " .. what .. " must be a vector {x=, y=, z=}, got " .. type(v))
  end
  local x, y, z = v.x, v.y, v.z
  for _, c in ipairs({{"x", x}, {"y", y}, {"z", z}}) do
    local value = c[2]
    if type(value) ~= "number" then
      fail(ctx .. ": " .. what .. "." .. c[1] .. " must be a number, got " .. type(value))
    end
    if value ~= value then fail(ctx .. ": " .. what .. "." .. c[1] .. " is NaN") end
  end
  return x, y, z
end

local vec = {}

-- vec.add(a, b) -> a + b, a new {x=, y=, z=}.
function vec.add(a, b)
  local ax, ay, az = read_vec(a, "argument 1", "vec.add")
  local bx, by, bz = read_vec(b, "argument 2", "vec.add")
  return {x = ax + bx, y = ay + by, z = az + bz}
end

-- vec.sub(a, b) -> a - b, a new {x=, y=, z=}.
function vec.sub(a, b)
  local ax, ay, az = read_vec(a, "argument 1", "vec.sub")
  local bx, by, bz = read_vec(b, "argument 2", "vec.sub")
  return {x = ax - bx, y = ay - by, z = az - bz}
end

-- vec.scale(v, s) -> s v, a new {x=, y=, z=}; s is a number.
function vec.scale(v, s)
  local x, y, z = read_vec(v, "argument 1", "vec.scale")
  check_number(s, "the factor (argument 2)", "vec.scale")
  return {x = x * s, y = y * s, z = z * s}
end

-- vec.dot(a, b) -> the number a . b.
function vec.dot(a, b)
  local ax, ay, az = read_vec(a, "argument 1", "vec.dot")
  local bx, by, bz = read_vec(b, "argument 2", "vec.dot")
  return ax * bx + ay * by + az * bz
end

-- vec.cross(a, b) -> a x b (right-handed: x cross y = z), a new {x=, y=, z=}.
function vec.cross(a, b)
  local ax, ay, az = read_vec(a, "argument 1", "vec.cross")
  local bx, by, bz = read_vec(b, "argument 2", "vec.cross")
  return {x = ay * bz - az * by, y = az * bx - ax * bz, z = ax * by - ay * bx}
end

-- vec.length(v) -> |v|, the Euclidean length.
function vec.length(v)
  local x, y, z = read_vec(v, "argument 1", "vec.length")
  return sqrt(x * x + y * y + z * z)
end

-- vec.normalize(v) -> v / |v|, a new unit {x=, y=, z=}; v must not be zero.
function vec.normalize(v)
  local x, y, z = read_vec(v, "argument 1", "vec.normalize")
  local r = sqrt(x * x + y * y + z * z)
  if r == 0 then fail("vec.normalize: cannot normalize the zero vector") end
  return {x = x / r, y = y / r, z = z / r}
end

M.vec = vec

---------------------------------------------------------------------------
-- Pans
---------------------------------------------------------------------------

-- Below this sin(angle) the directions of from and to count as parallel.
local PARALLEL_SIN = 1e-9
-- With an explicit axis, |cos(angle)| between a point and the axis allowed.
local PERPENDICULAR_COS = 1e-6

-- The axis argument of circle_pan: {x=, y=, z=}, {ax, ay, az} or {axis = v}.
local function read_axis(axis)
  if type(axis) == "table" and axis.axis ~= nil then
    for _, k in ipairs(sorted_keys(axis)) do
      if k ~= "axis" then
        fail("circle_pan: the options table has an unknown field " .. key_name(k) .. "; only axis = {x, y, z}")
      end
    end
    axis = axis.axis
  end
  if type(axis) == "table" and axis.x == nil and axis.y == nil and axis.z == nil and axis[1] ~= nil then
    axis = {x = axis[1], y = axis[2], z = axis[3]}
  end
  if type(axis) ~= "table" then
    fail("circle_pan: axis must be a vector {x, y, z} or {x=, y=, z=}, got " .. type(axis))
  end
  local x, y, z = read_vec(axis, "axis", "circle_pan")
  local r = sqrt(x * x + y * y + z * z)
  if r == 0 or r == huge then fail("circle_pan: axis must be a nonzero finite vector") end
  return x / r, y / r, z / r
end

-- circle_pan(from, to, u [, axis]) -> the point at progress u of a pan from
-- `from` to `to` ({x=, y=, z=} tables, neither at the origin) along a circle
-- about the origin: the direction turns in the plane of from and to, the
-- short way, by the fraction u of the angle between them, while the radius
-- goes linearly from |from| to |to|. u clamps to [0, 1]; u = 0 returns from
-- and u = 1 returns to exactly (as new tables). Without an axis, from and to
-- must not be parallel or antiparallel (the plane would be undetermined).
-- With axis ({x, y, z}, {x=, y=, z=} or {axis = ...}) the turn is about that
-- axis, right-handed (counter-clockwise seen from its tip) by the angle in
-- [0, 360) degrees that carries from to to, which may be the long way; both
-- points must then be perpendicular to the axis.
function M.circle_pan(from, to, u, axis)
  local fx, fy, fz = read_vec(from, "from", "circle_pan")
  local tx, ty, tz = read_vec(to, "to", "circle_pan")
  check_number(u, "u", "circle_pan")
  local r0 = sqrt(fx * fx + fy * fy + fz * fz)
  local r1 = sqrt(tx * tx + ty * ty + tz * tz)
  if r0 == 0 then fail("circle_pan: from is the origin; the pan circles the origin and needs a radius") end
  if r1 == 0 then fail("circle_pan: to is the origin; the pan circles the origin and needs a radius") end
  if r0 == huge or r1 == huge then fail("circle_pan: from and to must be finite") end
  local ax, ay, az = fx / r0, fy / r0, fz / r0
  local bx, by, bz = tx / r1, ty / r1, tz / r1
  local cx, cy, cz = ay * bz - az * by, az * bx - ax * bz, ax * by - ay * bx
  local c = ax * bx + ay * by + az * bz
  local nx, ny, nz, theta
  if axis == nil then
    local s = sqrt(cx * cx + cy * cy + cz * cz)
    if s <= PARALLEL_SIN then
      fail("circle_pan: from and to are " .. (c > 0 and "parallel" or "antiparallel") ..
           ", so the circle through them is not unique; pass an axis as the 4th argument")
    end
    nx, ny, nz = cx / s, cy / s, cz / s
    theta = atan2(s, c)
  else
    nx, ny, nz = read_axis(axis)
    local ca = ax * nx + ay * ny + az * nz
    local cb = bx * nx + by * ny + bz * nz
    for _, p in ipairs({{"from", ca}, {"to", cb}}) do
      if p[2] > PERPENDICULAR_COS or p[2] < -PERPENDICULAR_COS then
        local angle = math.deg(math.acos(p[2]))
        fail("circle_pan: " .. p[1] .. " is not perpendicular to the axis (" ..
             string.format("%.6g", angle) .. " degrees); with an axis both points " ..
             "must lie in the plane through the origin perpendicular to it")
      end
    end
    -- Drop what little lies along the axis, so the turn stays in the plane.
    ax, ay, az = ax - ca * nx, ay - ca * ny, az - ca * nz
    local ra = sqrt(ax * ax + ay * ay + az * az)
    ax, ay, az = ax / ra, ay / ra, az / ra
    bx, by, bz = bx - cb * nx, by - cb * ny, bz - cb * nz
    local rb = sqrt(bx * bx + by * by + bz * bz)
    bx, by, bz = bx / rb, by / rb, bz / rb
    cx, cy, cz = ay * bz - az * by, az * bx - ax * bz, ax * by - ay * bx
    theta = atan2(cx * nx + cy * ny + cz * nz, ax * bx + ay * by + az * bz)
    if theta < 0 then theta = theta + 2 * pi end
  end
  if u <= 0 then return {x = fx, y = fy, z = fz} end
  if u >= 1 then return {x = tx, y = ty, z = tz} end
  -- w = n x a completes the right-handed frame (a, w, n) of the plane.
  local wx, wy, wz = ny * az - nz * ay, nz * ax - nx * az, nx * ay - ny * ax
  local phi = u * theta
  local cp, sp = cos(phi), sin(phi)
  local r = lerp_number(r0, r1, u)
  return {
    x = r * (ax * cp + wx * sp),
    y = r * (ay * cp + wy * sp),
    z = r * (az * cp + wz * sp),
  }
end

return M
