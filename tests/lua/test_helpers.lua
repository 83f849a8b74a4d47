-- Helpers for the Lua tests of the shot-author library (tests/lua/*_test.lua,
-- run in the engine's sandbox by tests/unit/engine_api_test.cpp). Every
-- check raises at the test's own line (error level 2), with what it expected
-- and what it got.
--
--   local T = require "test_helpers"
--   T.eq(lc.lerp(1, 3, 0.5), 2, "midpoint")
--   T.fails(T.here(), "lerp: u is NaN", pcall(lc.lerp, 1, 2, 0 / 0))
--
-- T.fails checks the whole message, including that its "file:line:" prefix
-- is the test's line: keep T.here() and the pcall on one line.

local T = {}

-- A readable, deterministic rendering of a value (tables with sorted keys,
-- numbers with all 17 significant digits).
local function show(v, depth)
  depth = depth or 0
  if type(v) == "number" then
    if v == math.floor(v) and v > -1e15 and v < 1e15 then return string.format("%d", v) end
    return string.format("%.17g", v)
  end
  if type(v) == "string" then return string.format("%q", v) end
  if type(v) ~= "table" or depth > 3 then return tostring(v) end
  local keys = {}
  for k in pairs(v) do keys[#keys + 1] = k end
  table.sort(keys, function(a, b)
    if type(a) ~= type(b) then return type(a) < type(b) end
    if type(a) == "number" or type(a) == "string" then return a < b end
    return tostring(a) < tostring(b)
  end)
  local parts = {}
  for _, k in ipairs(keys) do
    parts[#parts + 1] = (type(k) == "string" and k or "[" .. show(k) .. "]") .. " = " .. show(v[k], depth + 1)
  end
  return "{" .. table.concat(parts, ", ") .. "}"
end
T.show = show

-- "file:line: " of the line calling T.here(), as error positions spell it.
function T.here()
  local _, where = pcall(error, "", 3)
  return where
end

-- Deep equality: numbers exactly (NaN equals NaN), tables by keys and values.
local function same(a, b)
  if type(a) ~= type(b) then return false end
  if type(a) == "number" then return a == b or (a ~= a and b ~= b) end
  if type(a) ~= "table" then return a == b end
  for k, v in pairs(a) do
    if not same(v, b[k]) then return false end
  end
  for k in pairs(b) do
    if a[k] == nil then return false end
  end
  return true
end
T.same = same

-- Fails unless actual equals expected exactly (deeply for tables).
function T.eq(actual, expected, what)
  if not same(actual, expected) then
    error((what or "value") .. ": expected " .. show(expected) .. ", got " .. show(actual), 2)
  end
end

-- Fails unless |actual - expected| <= tol; for tables, component-wise.
function T.near(actual, expected, tol, what)
  local ok = true
  if type(expected) == "table" then
    if type(actual) ~= "table" then
      ok = false
    else
      for k, v in pairs(expected) do
        if type(actual[k]) ~= "number" or math.abs(actual[k] - v) > tol then ok = false end
      end
      for k in pairs(actual) do
        if expected[k] == nil then ok = false end
      end
    end
  else
    ok = type(actual) == "number" and math.abs(actual - expected) <= tol
  end
  if not ok then
    error((what or "value") .. ": expected " .. show(expected) .. " within " .. show(tol) ..
          ", got " .. show(actual), 2)
  end
end

-- Fails unless cond is true.
function T.ok(cond, what)
  if not cond then error((what or "condition") .. ": expected true", 2) end
end

-- Fails unless a pcall failed with exactly at .. message, i.e. the error
-- names the test's line `at` (from T.here()) and says `message`.
function T.fails(at, message, ok, err)
  if ok then error("expected the error " .. show(message) .. ", but the call succeeded", 2) end
  if err ~= at .. message then
    error("wrong error:\n  expected " .. show(at .. message) .. "\n       got " .. show(err), 2)
  end
end

-- The number of keys of a table (array and hash parts).
function T.count(t)
  local n = 0
  for _ in pairs(t) do n = n + 1 end
  return n
end

return T
