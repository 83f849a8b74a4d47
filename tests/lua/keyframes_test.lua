-- lc.keyframes.
local lc = require "lightcone"
local T = require "test_helpers"

local NAN, INF = 0 / 0, math.huge

-- One key: a constant.
local one = lc.keyframes{{10, 3}}
T.eq(one(0), 3, "single key before")
T.eq(one(10), 3, "single key at")
T.eq(one(1e9), 3, "single key after")
T.eq(one.first, 10, "single key first")
T.eq(one.last, 10, "single key last")

-- Linear by default; holds outside; fractional frames.
local k = lc.keyframes{{0, 0}, {100, 80}, {150, 80}, {200, 0.3}}
T.eq(k.first, 0, "first")
T.eq(k.last, 200, "last")
T.eq(k(-5), 0, "hold before")
T.eq(k(-INF), 0, "hold at -inf")
T.eq(k(0), 0, "first key")
T.eq(k(50), 40, "linear inside")
T.eq(k(12.5), 10, "fractional frame")
T.eq(k(100), 80, "key frame")
T.eq(k(120), 80, "hold between equal keys")
T.eq(k(125.75), 80, "fractional hold is exact")
T.eq(k(200), 0.3, "last key exact")
T.eq(k(1000), 0.3, "hold after")
T.eq(k(INF), 0.3, "hold at +inf")
T.near(k(175), (80 + 0.3) / 2, 1e-13, "last segment midpoint")
T.eq(tostring(k), "keyframes(4 keys, frames 0 to 200)", "tostring")

-- Values at key frames are exactly the key values, whatever the arithmetic.
local awkward = {{0, 0.1}, {3, 0.7}, {7.25, 1e-17}, {10, 1 / 3}, {11, -2.2}}
local ka = lc.keyframes(awkward)
for _, key in ipairs(awkward) do T.eq(ka(key[1]), key[2], "value at key frame " .. key[1]) end
-- Fractional key frames.
local kf = lc.keyframes{{0.5, 0}, {1.5, 1}}
T.eq(kf(1), 0.5, "fractional key frames")
T.eq(kf(0), 0, "before a fractional first key")

-- The ease of a key shapes the segment arriving at it; the others stay linear.
local ke = lc.keyframes{{0, 0}, {10, 10, ease = "smoothstep"}, {20, 20}, {30, 30, ease = lc.ease.in_quad}}
T.eq(ke(2.5), 10 * lc.ease.smoothstep(0.25), "smoothstep segment")
T.eq(ke(15), 15, "linear segment after an eased key")
T.eq(ke(25), 20 + 10 * 0.25, "function ease")
T.eq(ke(10), 10, "eased key value")
-- An ease on the first key has nothing to shape.
local k1 = lc.keyframes{{0, 0, ease = "in_cubic"}, {10, 10}}
T.eq(k1(5), 5, "ease on the first key is ignored")
-- A user function may overshoot: values extrapolate (lerp does not clamp).
local kb = lc.keyframes{{0, 0}, {10, 10, ease = function(u) return u + math.sin(math.pi * u) / 2 end}}
T.near(kb(5), 10, 1e-14, "overshooting ease")
T.eq(kb(10), 10, "overshooting ease still ends on the key")
-- Even an ease that does not start at 0 cannot move a key's value.
local kj = lc.keyframes{{0, 0}, {10, 10}, {20, 20, ease = function(u) return u + 0.5 end}}
T.eq(kj(10), 10, "key value exact although the next segment's ease jumps")
T.eq(kj(15), 20, "that ease applies inside its segment")

-- Vectors, keyed and array-like.
local kv = lc.keyframes{{0, {x = 0, y = 80, z = 0}}, {60, {x = 80, y = 0, z = 0}, ease = "linear"}}
T.eq(kv(30), {x = 40, y = 40, z = 0}, "keyed vector")
T.eq(kv(0), {x = 0, y = 80, z = 0}, "keyed vector at key")
T.eq(kv(99), {x = 80, y = 0, z = 0}, "keyed vector hold")
local kr = lc.keyframes{{0, {1, 2}}, {4, {5, 10}}}
T.eq(kr(1), {2, 4}, "array vector")

-- Results are fresh tables; the keys are copied when the keyframes are made.
local r = kv(0)
r.x = 1000
T.eq(kv(0), {x = 0, y = 80, z = 0}, "mutating a result changes nothing")
local h = kv(100)
h.y = 5
T.eq(kv(100), {x = 80, y = 0, z = 0}, "mutating a held result changes nothing")
local keys = {{0, {x = 1, y = 1, z = 1}}, {10, {x = 2, y = 2, z = 2}}}
local kc = lc.keyframes(keys)
keys[2][2].x = 99
keys[1][1] = 5
T.eq(kc(10), {x = 2, y = 2, z = 2}, "mutating the input list changes nothing")
T.eq(kc.first, 0, "first copied")

-- Many keys: the lookup agrees with a linear scan, in any evaluation order.
local many = {}
for j = 1, 200 do many[j] = {j * 3 + (j % 7) * 0.25, math.sin(j) * 10} end
local km = lc.keyframes(many)
local function reference(i)
  if i <= many[1][1] then return many[1][2] end
  for j = 1, #many - 1 do
    local f0, f1 = many[j][1], many[j + 1][1]
    if i >= f0 and i < f1 then return lc.lerp(many[j][2], many[j + 1][2], (i - f0) / (f1 - f0)) end
  end
  return many[#many][2]
end
local forward = {}
for i = -5, 620 do forward[i] = km(i * 0.9973) end
for i = -5, 620 do T.eq(forward[i], reference(i * 0.9973), "lookup at " .. i * 0.9973) end
for i = 620, -5, -1 do T.eq(km(i * 0.9973), forward[i], "reverse order " .. i) end
for step = 0, 36 do
  local i = (step * 173) % 626 - 5 -- a fixed permutation of -5..620
  T.eq(km(i * 0.9973), forward[i], "permuted order " .. i)
end
-- Continuity: no jumps at or next to key frames.
for j = 2, #many - 1 do
  local f = many[j][1]
  T.near(km(f - 1e-9), many[j][2], 1e-7, "continuous before key " .. j)
  T.near(km(f + 1e-9), many[j][2], 1e-7, "continuous after key " .. j)
end

-- Errors name the calling line.
T.fails(T.here(), "keyframes: frames must increase (key 3 has frame 10 after 20)", pcall(lc.keyframes, {{0, 1}, {20, 2}, {10, 3}}))
T.fails(T.here(), "keyframes: frames must increase (key 2 has frame 0 after 0)", pcall(lc.keyframes, {{0, 1}, {0, 2}}))
T.fails(T.here(), "keyframes: expected a list of keys {frame, value [, ease = ]}, got nil", pcall(lc.keyframes))
T.fails(T.here(), "keyframes: needs at least one key {frame, value}", pcall(lc.keyframes, {}))
T.fails(T.here(), "keyframes: key 2 must be a table {frame, value [, ease = ]}, got number", pcall(lc.keyframes, {{0, 1}, 5}))
T.fails(T.here(), "keyframes: key 1 needs a frame number as its first element, got string", pcall(lc.keyframes, {{"0", 1}}))
T.fails(T.here(), "keyframes: key 1 needs a frame number as its first element, got nil", pcall(lc.keyframes, {{nil, 1}}))
T.fails(T.here(), "keyframes: key 1 has a field 'frame'; keys are positional: {frame, value [, ease = ]}", pcall(lc.keyframes, {{frame = 0, value = 1}}))
T.fails(T.here(), "keyframes: key 2 has frame inf; frames must be finite", pcall(lc.keyframes, {{0, 1}, {INF, 2}}))
T.fails(T.here(), "keyframes: key 1 has frame nan; frames must be finite", pcall(lc.keyframes, {{NAN, 1}}))
T.fails(T.here(), "keyframes: key 2 needs a value as its second element", pcall(lc.keyframes, {{0, 1}, {5}}))
T.fails(T.here(), "keyframes: key 2 has a value of type string; values are numbers or tables of numbers", pcall(lc.keyframes, {{0, 1}, {5, "2"}}))
T.fails(T.here(), "keyframes: key 2 has value nan; values must be finite", pcall(lc.keyframes, {{0, 1}, {5, NAN}}))
T.fails(T.here(), "keyframes: key 2 has a table value but key 1 has a number", pcall(lc.keyframes, {{0, 1}, {5, {1}}}))
T.fails(T.here(), "keyframes: key 2 has a number value but key 1 has a table", pcall(lc.keyframes, {{0, {1}}, {5, 1}}))
T.fails(T.here(), "keyframes: key 3 and key 1 have different components (only in key 3: w; only in key 1: z)", pcall(lc.keyframes, {{0, {x = 0, z = 0}}, {5, {x = 1, z = 0}}, {9, {x = 1, w = 0}}}))
T.fails(T.here(), "keyframes: key 1 has a value whose component y is a string, expected a number", pcall(lc.keyframes, {{0, {x = 0, y = "0"}}}))
T.fails(T.here(), "keyframes: key 2 has a value whose component [1] is -inf; values must be finite", pcall(lc.keyframes, {{0, {0}}, {1, {-INF}}}))
T.fails(T.here(), "keyframes: key 2 has an unknown field 'eas' (did you mean 'ease'?)", pcall(lc.keyframes, {{0, 1}, {5, 2, eas = "smoothstep"}}))
T.fails(T.here(), "keyframes: key 1 has an extra element [3]; a key is {frame, value [, ease = ]}", pcall(lc.keyframes, {{0, 1, "smoothstep"}}))
T.fails(T.here(), "keyframes: the list of keys has an unexpected field ease (ease goes inside a key: {frame, value, ease = ...})", pcall(lc.keyframes, {{0, 1}, {5, 2}, ease = "smoothstep"}))
T.fails(T.here(), "keyframes: the list of keys has an unexpected field [4]", pcall(lc.keyframes, {{0, 1}, {5, 2}, [4] = {9, 3}}))
T.fails(T.here(), "keyframes: key 2 has ease 'smoothstepp', which is not an easing (did you mean 'smoothstep'?)", pcall(lc.keyframes, {{0, 1}, {5, 2, ease = "smoothstepp"}}))
T.fails(T.here(), "keyframes: key 2 has ease of type boolean; use an easing name like 'smoothstep' or a function", pcall(lc.keyframes, {{0, 1}, {5, 2, ease = true}}))
-- Evaluation errors.
local bad = lc.keyframes{{0, 0}, {10, 1, ease = function(u) return tostring(u) end}}
T.fails(T.here(), "keyframes: the ease of key 2 returned a string, expected a number", pcall(bad, 5))
T.eq(bad(10), 1, "a bad ease is not called at key frames")
local nan_ease = lc.keyframes{{0, 0}, {10, 1}, {20, 0, ease = function() return 0 / 0 end}}
T.fails(T.here(), "keyframes: the ease of key 3 returned NaN, expected a number", pcall(nan_ease, 15))
T.fails(T.here(), "keyframes: frame must be a number, got string", pcall(k, "5"))
T.fails(T.here(), "keyframes: frame must be a number, got nil", pcall(k))
T.fails(T.here(), "keyframes: frame is NaN", pcall(k, NAN))
T.fails(T.here(), "keyframes: no field 'frames'; the fields are first and last, and k(i) gives the value at frame i", pcall(function() return k.frames end))
T.fails(T.here(), "keyframes: no field 'lst' (did you mean 'last'?); the fields are first and last, and k(i) gives the value at frame i", pcall(function() return k.lst end))

return true
