-- lc.lerp and lc.vec.
local lc = require "lightcone"
local T = require "test_helpers"

local NAN = 0 / 0

-- Numbers: ends exact even for values that do not add up exactly in binary.
T.eq(lc.lerp(0, 10, 0.5), 5, "midpoint")
T.eq(lc.lerp(0, 10, 0.25), 2.5, "quarter")
T.eq(lc.lerp(10, 0, 0.25), 7.5, "decreasing")
for _, pair in ipairs({{0.1, 0.7}, {0.7, 0.1}, {1e-300, 3}, {-2.2, 1e16}, {0.3, 0.3}}) do
  local a, b = pair[1], pair[2]
  T.eq(lc.lerp(a, b, 0), a, "lerp(" .. a .. ", " .. b .. ", 0)")
  T.eq(lc.lerp(a, b, 1), b, "lerp(" .. a .. ", " .. b .. ", 1)")
end
-- Equal ends give exactly that value everywhere (a hold does not wobble).
for j = 0, 100 do T.eq(lc.lerp(0.9, 0.9, j / 100), 0.9, "constant lerp at " .. j / 100) end
-- No clamping: u outside [0, 1] extrapolates.
T.eq(lc.lerp(0, 10, 2), 20, "extrapolate above")
T.eq(lc.lerp(0, 10, -0.5), -5, "extrapolate below")
-- Monotone in u.
local prev = -math.huge
for j = 0, 1000 do
  local v = lc.lerp(0.1, 0.7, j / 1000)
  T.ok(v >= prev, "lerp nondecreasing at " .. j)
  prev = v
end

-- Tables: keyed and array-like, into new tables.
local a, b = {x = 0, y = 10, z = -4}, {x = 2, y = 20, z = 4}
T.eq(lc.lerp(a, b, 0.5), {x = 1, y = 15, z = 0}, "keyed vectors")
T.eq(lc.lerp({1, 2, 3}, {3, 4, 5}, 0.5), {2, 3, 4}, "arrays")
T.eq(lc.lerp({1, 2, 3}, {3, 4, 5}, 0), {1, 2, 3}, "arrays at 0")
T.eq(lc.lerp({r = 0.1}, {r = 0.7}, 1), {r = 0.7}, "exact end in a table")
T.eq(lc.lerp({}, {}, 0.5), {}, "empty tables")
local r0 = lc.lerp(a, b, 0)
T.eq(r0, a, "u = 0 gives a")
T.ok(r0 ~= a and lc.lerp(a, b, 1) ~= b, "results are new tables")
T.eq(a, {x = 0, y = 10, z = -4}, "inputs untouched")

-- Errors name the calling line and the problem.
T.fails(T.here(), "lerp: a and b have different components (only in a: z; only in b: w)", pcall(lc.lerp, {x = 1, z = 2}, {x = 1, w = 3}, 0.5))
T.fails(T.here(), "lerp: a and b have different components (only in a: [3])", pcall(lc.lerp, {1, 2, 3}, {1, 2}, 0.5))
T.fails(T.here(), "lerp: a and b have different components (only in a: [1], [2], [3]; only in b: x, y, z)", pcall(lc.lerp, {1, 2, 3}, {x = 1, y = 2, z = 3}, 0.5))
T.fails(T.here(), "lerp: component y of b is a string, expected a number", pcall(lc.lerp, {x = 1, y = 2}, {x = 1, y = "2"}, 0.5))
T.fails(T.here(), "lerp: component [2] of a is a table, expected a number", pcall(lc.lerp, {1, {}}, {1, 2}, 0.5))
T.fails(T.here(), "lerp: cannot interpolate a number and a table", pcall(lc.lerp, 1, {1}, 0.5))
T.fails(T.here(), "lerp: cannot interpolate a table and a number", pcall(lc.lerp, {1}, 1, 0.5))
T.fails(T.here(), "lerp: a must be a number or a table of numbers, got string", pcall(lc.lerp, "1", 2, 0.5))
T.fails(T.here(), "lerp: b must be a number or a table of numbers, got nil", pcall(lc.lerp, 1, nil, 0.5))
T.fails(T.here(), "lerp: u must be a number, got nil", pcall(lc.lerp, 1, 2))
T.fails(T.here(), "lerp: u is NaN", pcall(lc.lerp, 1, 2, NAN))

-- lc.vec
local v = lc.vec
local p, q = {x = 1, y = 2, z = 3}, {x = -4, y = 0.5, z = 2}
T.eq(v.add(p, q), {x = -3, y = 2.5, z = 5}, "add")
T.eq(v.sub(p, q), {x = 5, y = 1.5, z = 1}, "sub")
T.eq(v.scale(p, -2), {x = -2, y = -4, z = -6}, "scale")
T.eq(v.dot(p, q), -4 + 1 + 6, "dot")
T.eq(v.cross({x = 1, y = 0, z = 0}, {x = 0, y = 1, z = 0}), {x = 0, y = 0, z = 1}, "x cross y = z")
T.eq(v.cross({x = 0, y = 1, z = 0}, {x = 0, y = 0, z = 1}), {x = 1, y = 0, z = 0}, "y cross z = x")
T.eq(v.cross({x = 0, y = 0, z = 1}, {x = 1, y = 0, z = 0}), {x = 0, y = 1, z = 0}, "z cross x = y")
T.eq(v.cross(p, q), {x = 2 * 2 - 3 * 0.5, y = 3 * -4 - 1 * 2, z = 1 * 0.5 - 2 * -4}, "cross")
T.eq(v.dot(v.cross(p, q), p), 0, "cross is perpendicular")
T.eq(v.length({x = 3, y = 4, z = 0}), 5, "length")
T.eq(v.length({x = 0, y = 0, z = 0}), 0, "length of zero")
T.eq(v.normalize({x = 0, y = -80, z = 0}), {x = 0, y = -1, z = 0}, "normalize")
T.near(v.length(v.normalize(q)), 1, 1e-15, "normalize gives unit length")
-- Extra keys are ignored; results are new plain vectors.
T.eq(v.add({x = 1, y = 1, z = 1, label = "a"}, p), {x = 2, y = 3, z = 4}, "extra keys ignored")
local s = v.scale(p, 1)
T.ok(s ~= p, "scale returns a new table")
T.eq(p, {x = 1, y = 2, z = 3}, "inputs untouched")
-- lerp works on these vectors too.
T.eq(lc.lerp(p, v.add(p, p), 1), {x = 2, y = 4, z = 6}, "lerp of vec results")

T.fails(T.here(), "vec.add: argument 1 must be a vector {x=, y=, z=}, got number", pcall(v.add, 1, p))
T.fails(T.here(), "vec.sub: argument 2.z must be a number, got nil", pcall(v.sub, p, {x = 1, y = 2}))
T.fails(T.here(), "vec.dot: argument 2.x must be a number, got string", pcall(v.dot, p, {x = "1", y = 2, z = 3}))
T.fails(T.here(), "vec.cross: argument 1.y is NaN", pcall(v.cross, {x = 1, y = NAN, z = 3}, p))
T.fails(T.here(), "vec.scale: the factor (argument 2) must be a number, got table", pcall(v.scale, p, p))
T.fails(T.here(), "vec.scale: argument 1 must be a vector {x=, y=, z=}, got number", pcall(v.scale, 2, p))
T.fails(T.here(), "vec.length: argument 1 must be a vector {x=, y=, z=}, got nil", pcall(v.length))
T.fails(T.here(), "vec.normalize: cannot normalize the zero vector", pcall(v.normalize, {x = 0, y = 0, z = 0}))
T.fails(T.here(), "vec.length: argument 1.x must be a number, got nil", pcall(v.length, {1, 2, 3}))

return true
