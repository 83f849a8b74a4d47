-- Where library errors point: always at the author's line that made the bad
-- call, however deep inside the library the problem is found.
local lc = require "lightcone"
local T = require "test_helpers"

-- A call from a function of this file (not in tail position).
local make_line
local function make(i) make_line = T.here(); local k = lc.keyframes{{0, 1}, {i, 2}}; return k end
local ok, err = pcall(make, 0)
T.fails(make_line, "keyframes: frames must increase (key 2 has frame 0 after 0)", ok, err)

-- A call nested two author functions deep.
local function outer(i) local k = make(i); return k end
ok, err = pcall(outer, -1)
T.fails(make_line, "keyframes: frames must increase (key 2 has frame -1 after 0)", ok, err)

-- A call in tail position: the calling function's frame is gone, so the
-- error names the line that called it.
local function tail(u) return lc.lerp(1, "x", u) end
T.fails(T.here(), "lerp: b must be a number or a table of numbers, got string", pcall(function() local r = tail(0.5); return r end))

-- From a shot's frame function, as the engine calls it.
local tl = lc.timeline{fps = 30, {"rise", seconds = 1}, {"spin_down", seconds = 1}}
local frame_line
local shot = {
  frames = tl.frames,
  frame = function(i)
    frame_line = T.here(); local u = tl:progress("rize", i)
    return {inclination = 80 * lc.smooth(u)}
  end,
}
ok, err = pcall(shot.frame, 3)
T.fails(frame_line, "timeline:progress: no segment 'rize' (did you mean 'rise'?)", ok, err)

-- From a keyframes object called inside a frame function.
local k = lc.keyframes{{0, 0}, {10, 1}}
local k_line
ok, err = pcall(function(i) k_line = T.here(); return {x = k(i)} end, "7")
T.fails(k_line, "keyframes: frame must be a number, got string", ok, err)

-- From an author's module: reported at the module's line.
local author = require "fixtures.author_module"
ok, err = pcall(author.bad_pan, 0.5)
T.ok(author.line:find("fixtures/author_module.lua:9: $") ~= nil, "the fixture's line: " .. author.line)
T.fails(author.line, "circle_pan: from and to are antiparallel, so the circle through them is not unique; pass an axis as the 4th argument", ok, err)
T.fails(T.here(), "lerp: b must be a number or a table of numbers, got string", pcall(function() local r = author.tail_lerp(0.5); return r end))

-- An author's own error inside an ease function passes through untouched.
local ease_line
local raising = lc.keyframes{{0, 0}, {10, 1, ease = function(u) ease_line = T.here(); error("my ease failed at " .. u) end}}
ok, err = pcall(raising, 5)
T.eq(err, ease_line .. "my ease failed at 0.5", "the author's own error")

-- Reading an unknown easing, inside a frame function.
local e_line
ok, err = pcall(function() e_line = T.here(); return lc.ease.smooth(0.5) end)
T.fails(e_line, "ease: no easing 'smooth' (did you mean 'smoothstep'?)", ok, err)

-- Errors are raised by the library, not by Lua on a nil value: no message
-- mentions the library file.
ok, err = pcall(lc.keyframes, {{0, 1}, {5, {1}}})
T.ok(not err:find("animation.lua", 1, true), "no library position in " .. err)

return true
