-- lc.ease, lc.smooth and lc.clamp.
local lc = require "lightcone"
local T = require "test_helpers"

local NAMES = {"linear", "smoothstep", "smootherstep", "in_quad", "out_quad", "in_out_quad",
               "in_cubic", "out_cubic", "in_out_cubic", "in_out_sine"}
local NAN, INF = 0 / 0, math.huge

-- Exactly the documented set of easings, each a function.
T.eq(T.count(lc.ease), #NAMES, "number of easings")
for _, name in ipairs(NAMES) do T.eq(type(lc.ease[name]), "function", "lc.ease." .. name) end

-- Endpoints exact, clamping outside [0, 1], values in [0, 1], nondecreasing.
for _, name in ipairs(NAMES) do
  local f = lc.ease[name]
  T.eq(f(0), 0, name .. "(0)")
  T.eq(f(1), 1, name .. "(1)")
  T.eq(f(-0.5), 0, name .. "(-0.5)")
  T.eq(f(-INF), 0, name .. "(-inf)")
  T.eq(f(1.5), 1, name .. "(1.5)")
  T.eq(f(INF), 1, name .. "(inf)")
  local prev = 0
  for j = 0, 1000 do
    local u = j / 1000
    local v = f(u)
    T.ok(v >= 0 and v <= 1, name .. "(" .. u .. ") = " .. v .. " in [0, 1]")
    T.ok(v >= prev, name .. " nondecreasing at u = " .. u)
    prev = v
  end
end

-- The formulas.
for j = 0, 100 do
  local u = j / 100
  T.near(lc.ease.linear(u), u, 0, "linear")
  T.near(lc.ease.smoothstep(u), 3 * u ^ 2 - 2 * u ^ 3, 1e-14, "smoothstep(" .. u .. ")")
  T.near(lc.ease.smootherstep(u), 6 * u ^ 5 - 15 * u ^ 4 + 10 * u ^ 3, 1e-14, "smootherstep(" .. u .. ")")
  T.near(lc.ease.in_quad(u), u ^ 2, 1e-15, "in_quad")
  T.near(lc.ease.out_quad(u), 1 - (1 - u) ^ 2, 1e-15, "out_quad")
  T.near(lc.ease.in_cubic(u), u ^ 3, 1e-15, "in_cubic")
  T.near(lc.ease.out_cubic(u), 1 - (1 - u) ^ 3, 1e-15, "out_cubic")
  T.near(lc.ease.in_out_sine(u), (1 - math.cos(math.pi * u)) / 2, 1e-15, "in_out_sine")
end
T.eq(lc.ease.smoothstep(0.25), 0.15625, "smoothstep(0.25)")
T.eq(lc.ease.smootherstep(0.5), 0.5, "smootherstep(0.5)")
T.eq(lc.ease.in_out_quad(0.25), 0.125, "in_out_quad(0.25)")
T.eq(lc.ease.in_out_quad(0.75), 0.875, "in_out_quad(0.75)")
T.eq(lc.ease.in_out_cubic(0.25), 0.0625, "in_out_cubic(0.25)")
T.eq(lc.ease.in_out_cubic(0.75), 0.9375, "in_out_cubic(0.75)")
T.near(lc.ease.in_out_sine(0.5), 0.5, 1e-15, "in_out_sine(0.5)")

-- The symmetric ones: f(1 - u) = 1 - f(u); in/out pairs mirror each other.
for _, name in ipairs({"linear", "smoothstep", "smootherstep", "in_out_quad", "in_out_cubic", "in_out_sine"}) do
  for j = 0, 100 do
    local u = j / 100
    T.near(lc.ease[name](1 - u), 1 - lc.ease[name](u), 1e-14, name .. " symmetric at " .. u)
  end
end
for j = 0, 100 do
  local u = j / 100
  T.near(lc.ease.out_quad(u), 1 - lc.ease.in_quad(1 - u), 1e-15, "out_quad mirrors in_quad")
  T.near(lc.ease.out_cubic(u), 1 - lc.ease.in_cubic(1 - u), 1e-15, "out_cubic mirrors in_cubic")
end
-- Smoothstep and smootherstep start and end flat.
T.ok(lc.ease.smoothstep(1e-4) < 1e-7, "smoothstep flat at 0")
T.ok(1 - lc.ease.smootherstep(1 - 1e-3) < 1e-8, "smootherstep flat at 1")

-- Errors name the calling line.
T.fails(T.here(), "ease.smoothstep: u must be a number, got string", pcall(lc.ease.smoothstep, "0.5"))
T.fails(T.here(), "ease.in_out_sine: u must be a number, got nil", pcall(lc.ease.in_out_sine))
T.fails(T.here(), "ease.linear: u is NaN", pcall(lc.ease.linear, NAN))
T.fails(T.here(), "ease: no easing 'smoothstepp' (did you mean 'smoothstep'?)", pcall(function() return lc.ease.smoothstepp end))
T.fails(T.here(), "ease: no easing 'InOutSine' (did you mean 'in_out_sine'?)", pcall(function() return lc.ease.InOutSine end))
T.fails(T.here(), "ease: no easing 'bounce' (easings: linear, smoothstep, smootherstep, in_quad, out_quad, in_out_quad, in_cubic, out_cubic, in_out_cubic, in_out_sine)", pcall(function() return lc.ease.bounce end))

-- lc.smooth: smoothstep by default, a name, or a function; u clamps first.
T.eq(lc.smooth(0.25), 0.15625, "smooth default is smoothstep")
T.eq(lc.smooth(0.25, "linear"), 0.25, "smooth linear")
T.eq(lc.smooth(0.5, "in_quad"), 0.25, "smooth in_quad")
T.eq(lc.smooth(-3), 0, "smooth clamps below")
T.eq(lc.smooth(7, "in_cubic"), 1, "smooth clamps above")
T.eq(lc.smooth(0.5, function(u) return u / 2 end), 0.25, "smooth with a function")
T.eq(lc.smooth(2, function(u) return u end), 1, "smooth clamps before calling a function")
T.eq(lc.smooth(-1, function(u) return u end), 0, "smooth clamps before calling a function")
T.fails(T.here(), "smooth: u must be a number, got nil", pcall(lc.smooth))
T.fails(T.here(), "smooth: u is NaN", pcall(lc.smooth, NAN, "linear"))
T.fails(T.here(), "smooth: ease 'smootstep', which is not an easing (did you mean 'smoothstep'?)", pcall(lc.smooth, 0.5, "smootstep"))
T.fails(T.here(), "smooth: ease of type number; use an easing name like 'smoothstep' or a function", pcall(lc.smooth, 0.5, 3))

-- Authors may add easings; names then resolve like the built-in ones.
lc.ease.quartic = function(u) return u ^ 4 end
T.eq(lc.smooth(0.5, "quartic"), 0.0625, "a user easing by name")
T.fails(T.here(), "ease: no easing 'quartc' (did you mean 'quartic'?)", pcall(function() return lc.ease.quartc end))

-- lc.clamp.
T.eq(lc.clamp(5, 0, 10), 5, "clamp inside")
T.eq(lc.clamp(-5, 0, 10), 0, "clamp below")
T.eq(lc.clamp(15, 0, 10), 10, "clamp above")
T.eq(lc.clamp(0.25, 0.25, 0.25), 0.25, "clamp to a point")
T.eq(lc.clamp(INF, 0, 1), 1, "clamp +inf")
T.eq(lc.clamp(-INF, 0, 1), 0, "clamp -inf")
T.eq(lc.clamp(3, -INF, INF), 3, "clamp to the whole line")
T.fails(T.here(), "clamp: x must be a number, got string", pcall(lc.clamp, "1", 0, 1))
T.fails(T.here(), "clamp: lo must be a number, got nil", pcall(lc.clamp, 1, nil, 1))
T.fails(T.here(), "clamp: hi is NaN", pcall(lc.clamp, 1, 0, NAN))
T.fails(T.here(), "clamp: x is NaN", pcall(lc.clamp, NAN, 0, 1))
T.fails(T.here(), "clamp: lo (5) is greater than hi (1)", pcall(lc.clamp, 3, 5, 1))

return true
