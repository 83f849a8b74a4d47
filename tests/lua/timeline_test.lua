-- lc.timeline, lc.seconds and lc.frames_to_seconds.
local lc = require "lightcone"
local T = require "test_helpers"

local NAN, INF = 0 / 0, math.huge

-- The example of the brief: 10 s + 45 frames + 8 s at 30 fps.
local tl = lc.timeline{fps = 30, {"rise", seconds = 10}, {"hold", frames = 45}, {"spin_down", seconds = 8}}
T.eq(tl.frames, 300 + 45 + 240, "total frames")
T.eq(tl.fps, 30, "fps")
T.eq(tl:names(), {"rise", "hold", "spin_down"}, "names in order")
T.eq({tl:start("rise"), tl:stop("rise"), tl:length("rise")}, {0, 300, 300}, "rise")
T.eq({tl:start("hold"), tl:stop("hold"), tl:length("hold")}, {300, 345, 45}, "hold")
T.eq({tl:start("spin_down"), tl:stop("spin_down"), tl:length("spin_down")}, {345, 585, 240}, "spin_down")
T.eq(tostring(tl), "timeline(rise 0-300, hold 300-345, spin_down 345-585; 585 frames)", "tostring")
-- names() returns a fresh array.
local names = tl:names()
names[1] = "changed"
T.eq(tl:names()[1], "rise", "names is a copy")

-- progress: 0 before, (i - start) / length inside, 1 from stop on.
T.eq(tl:progress("hold", 0), 0, "progress before")
T.eq(tl:progress("hold", -INF), 0, "progress at -inf")
T.eq(tl:progress("hold", 299.5), 0, "progress just before")
T.eq(tl:progress("hold", 300), 0, "progress at start")
T.eq(tl:progress("hold", 309), 9 / 45, "progress inside")
T.eq(tl:progress("hold", 300.5), 0.5 / 45, "progress at a fractional frame")
T.eq(tl:progress("hold", 344), 44 / 45, "progress on the last frame")
T.eq(tl:progress("hold", 345), 1, "progress at stop")
T.eq(tl:progress("hold", 5000), 1, "progress after")
T.eq(tl:progress("rise", 150), 0.5, "progress of the first segment")
T.eq(tl:progress("spin_down", 585), 1, "progress at the end")

-- at: the segment holding frame i, its local frame and u.
local function at(i) return {tl:at(i)} end
T.eq(at(0), {"rise", 0, 0}, "at 0")
T.eq(at(150), {"rise", 150, 0.5}, "at 150")
T.eq(at(299), {"rise", 299, 299 / 300}, "at 299")
T.eq(at(299.5), {"rise", 299.5, 299.5 / 300}, "at 299.5")
T.eq(at(300), {"hold", 0, 0}, "at 300 (a boundary belongs to the next segment)")
T.eq(at(344), {"hold", 44, 44 / 45}, "at 344")
T.eq(at(345), {"spin_down", 0, 0}, "at 345")
T.eq(at(584), {"spin_down", 239, 239 / 240}, "at the last frame")
-- Outside: the nearest segment, u clamped.
T.eq(at(-3), {"rise", -3, 0}, "before the timeline")
T.eq(at(585), {"spin_down", 240, 1}, "at tl.frames")
T.eq(at(600), {"spin_down", 255, 1}, "after the timeline")
-- Every frame agrees with start/stop/progress.
for i = 0, tl.frames - 1 do
  local name, t, u = tl:at(i)
  T.ok(tl:start(name) <= i and i < tl:stop(name), "frame " .. i .. " inside " .. name)
  T.eq(t, i - tl:start(name), "local frame of " .. i)
  T.eq(u, tl:progress(name, i), "u of " .. i)
end

-- Frames only: no fps; lengths round with floor(x + 0.5).
local tf = lc.timeline{{"a", frames = 2.5}, {"b", frames = 2.49}, {"c", frames = 1}}
T.eq(tf.fps, nil, "no fps")
T.eq({tf:length("a"), tf:length("b"), tf:length("c")}, {3, 2, 1}, "frames round")
T.eq(tf.frames, 6, "total of rounded frames")
local ts = lc.timeline{fps = 24, {"x", seconds = 0.0625}, {"y", seconds = 1 / 48}, {"z", seconds = 110.59 / 24}}
T.eq({ts:length("x"), ts:length("y"), ts:length("z")}, {2, 1, 111}, "seconds round")
T.eq(ts:start("z"), 3, "start after rounded segments")

-- lc.seconds / lc.frames_to_seconds use the same rounding.
T.eq(lc.seconds(30, 10), 300, "seconds")
T.eq(lc.seconds(24, 1 / 48), 1, "half a frame rounds up")
T.eq(lc.seconds(30, 0.01), 0, "a third of a frame rounds down")
T.eq(lc.seconds(30, -1), -30, "negative seconds")
T.eq(lc.seconds(25, 1.3), 33, "seconds(25, 1.3)")
T.eq(lc.frames_to_seconds(30, 45), 1.5, "frames_to_seconds")
T.eq(lc.frames_to_seconds(24, 1), 1 / 24, "one frame")
T.eq(lc.frames_to_seconds(30, 0), 0, "zero frames")
for _, s in ipairs({1, 2.5, 10, 8, 110.59 / 30}) do
  T.eq(lc.timeline{fps = 30, {"s", seconds = s}}:length("s"), lc.seconds(30, s), "timeline rounds like seconds() for " .. s)
end
T.fails(T.here(), "seconds: fps must be a positive number, got 0", pcall(lc.seconds, 0, 1))
T.fails(T.here(), "seconds: fps must be a positive number, got nil", pcall(lc.seconds, nil, 1))
T.fails(T.here(), "seconds: s must be finite, got inf", pcall(lc.seconds, 30, INF))
T.fails(T.here(), "seconds: s must be a number, got string", pcall(lc.seconds, 30, "1"))
T.fails(T.here(), "frames_to_seconds: fps must be a positive number, got -30", pcall(lc.frames_to_seconds, -30, 1))
T.fails(T.here(), "frames_to_seconds: n is NaN", pcall(lc.frames_to_seconds, 30, NAN))

-- Construction errors name the calling line.
T.fails(T.here(), "timeline: expected a table {fps = , {name, seconds = } ...}, got string", pcall(lc.timeline, "rise"))
T.fails(T.here(), "timeline: unknown field 'fsp' (did you mean 'fps'?)", pcall(lc.timeline, {fsp = 30, {"a", frames = 1}}))
T.fails(T.here(), "timeline: unknown field 'length'", pcall(lc.timeline, {length = 30, {"a", frames = 1}}))
T.fails(T.here(), "timeline: unexpected field [3]; segments are the array part, {name, frames = n}", pcall(lc.timeline, {{"a", frames = 1}, [3] = {"c", frames = 1}}))
T.fails(T.here(), "timeline: fps must be a positive number, got 0", pcall(lc.timeline, {fps = 0, {"a", frames = 1}}))
T.fails(T.here(), "timeline: fps must be a positive number, got string", pcall(lc.timeline, {fps = "30", {"a", frames = 1}}))
T.fails(T.here(), "timeline: fps must be a positive number, got nan", pcall(lc.timeline, {fps = NAN, {"a", frames = 1}}))
T.fails(T.here(), "timeline: needs at least one segment {name, frames = n} or {name, seconds = s}", pcall(lc.timeline, {fps = 30}))
T.fails(T.here(), "timeline: segment 2 must be a table {name, frames = n} or {name, seconds = s}, got string", pcall(lc.timeline, {{"a", frames = 1}, "b"}))
T.fails(T.here(), "timeline: segment 1 needs a name string as its first element, got nil", pcall(lc.timeline, {{frames = 1}}))
T.fails(T.here(), "timeline: segment 1 needs a name string as its first element, got an empty string", pcall(lc.timeline, {{"", frames = 1}}))
T.fails(T.here(), "timeline: segment 3 repeats the name 'a' of segment 1", pcall(lc.timeline, {{"a", frames = 1}, {"b", frames = 1}, {"a", frames = 2}}))
T.fails(T.here(), "timeline: segment 'a' has both frames and seconds; give one", pcall(lc.timeline, {fps = 30, {"a", frames = 1, seconds = 1}}))
T.fails(T.here(), "timeline: segment 'a' needs frames = n or seconds = s", pcall(lc.timeline, {fps = 30, {"a"}}))
T.fails(T.here(), "timeline: segment 'b' is given in seconds but the timeline has no fps", pcall(lc.timeline, {{"a", frames = 3}, {"b", seconds = 1}}))
T.fails(T.here(), "timeline: segment 'a' is 0 frames long (frames = 0.4); a segment needs at least 1 frame", pcall(lc.timeline, {{"a", frames = 0.4}}))
T.fails(T.here(), "timeline: segment 'a' is -2 frames long (frames = -2); a segment needs at least 1 frame", pcall(lc.timeline, {{"a", frames = -2}}))
T.fails(T.here(), "timeline: segment 'blink' is 0 frames long (0.01 s at 30 fps); a segment needs at least 1 frame", pcall(lc.timeline, {fps = 30, {"blink", seconds = 0.01}}))
T.fails(T.here(), "timeline: segment 'a': frames must be a number, got string", pcall(lc.timeline, {{"a", frames = "3"}}))
T.fails(T.here(), "timeline: segment 'a': seconds must be finite, got inf", pcall(lc.timeline, {fps = 30, {"a", seconds = INF}}))
T.fails(T.here(), "timeline: segment 'a' has an unknown field 'second' (did you mean 'seconds'?)", pcall(lc.timeline, {fps = 30, {"a", second = 1}}))
T.fails(T.here(), "timeline: segment 'a' has an unexpected field [2]; a segment is {name, frames = n} or {name, seconds = s}", pcall(lc.timeline, {{"a", 30}}))

-- Method errors.
T.fails(T.here(), "timeline:start: no segment 'spin_dwn' (did you mean 'spin_down'?)", pcall(tl.start, tl, "spin_dwn"))
T.fails(T.here(), "timeline:stop: no segment 'Rise' (did you mean 'rise'?)", pcall(tl.stop, tl, "Rise"))
T.fails(T.here(), "timeline:length: no segment 'mass_down' (segments: rise, hold, spin_down)", pcall(tl.length, tl, "mass_down"))
T.fails(T.here(), "timeline:progress: no segment 'hodl' (did you mean 'hold'?)", pcall(tl.progress, tl, "hodl", 3))
T.fails(T.here(), "timeline:progress: the segment name must be a string, got number", pcall(tl.progress, tl, 3))
T.fails(T.here(), "timeline:progress: frame must be a number, got nil", pcall(tl.progress, tl, "rise"))
T.fails(T.here(), "timeline:at: frame must be a number, got string", pcall(tl.at, tl, "3"))
T.fails(T.here(), "timeline:at: frame is NaN", pcall(tl.at, tl, NAN))
T.fails(T.here(), "timeline.start: call it as a method, with a colon: tl:start(...)", pcall(tl.start, "rise"))
T.fails(T.here(), "timeline.names: call it as a method, with a colon: tl:names(...)", pcall(tl.names))
T.fails(T.here(), "timeline.at: call it as a method, with a colon: tl:at(...)", pcall(tl.at, lc.keyframes{{0, 1}}, 3))
T.fails(T.here(), "timeline: no field or method 'progres' (did you mean 'progress'?)", pcall(function() return tl:progres("rise", 3) end))
T.fails(T.here(), "timeline: no field or method 'frame' (did you mean 'frames'?)", pcall(function() return tl.frame end))
-- The methods as written in a shot (colon calls) report the shot's line.
T.fails(T.here(), "timeline:start: no segment 'x' (segments: rise, hold, spin_down)", pcall(function() return tl:start("x") end))

return true
