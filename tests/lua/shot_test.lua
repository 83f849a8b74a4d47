-- The worked example of docs/animation.md (the paper's kerr_accrDisk
-- sequence, tests/lua/fixtures/accr_disk_shot.lua): its values at the
-- segment boundaries, monotone ramps, and frames that do not depend on the
-- order in which they are evaluated.
local lc = require "lightcone"
local T = require "test_helpers"

local shot = require "fixtures.accr_disk_shot"
local tl = shot.timeline
T.eq(shot.frames, 900, "the paper's 900 frames")
T.eq(shot.fps, 30, "fps")
T.eq({tl:start("spin_down"), tl:start("mass_down"), tl:start("flat")}, {300, 570, 840}, "segment starts")

local function values(i)
  local s = shot.frame(i)
  return {incl = s.observer.theta, spin = s.spacetime.spin, mass = s.spacetime.mass}
end
T.eq(values(0), {incl = 0, spin = 0.9, mass = 1}, "frame 0")
T.eq(values(150), {incl = 40, spin = 0.9, mass = 1}, "half way up (smoothstep is symmetric)")
T.eq(values(300), {incl = 80, spin = 0.9, mass = 1}, "end of the rise")
T.eq(values(435), {incl = 80, spin = 0.45, mass = 1}, "half way through the spin-down")
T.eq(values(570), {incl = 80, spin = 0, mass = 1}, "end of the spin-down")
T.eq(values(705), {incl = 80, spin = 0, mass = 0.5}, "half way through the mass-down")
T.eq(values(840), {incl = 80, spin = 0, mass = 0}, "flat spacetime")
T.eq(values(899), {incl = 80, spin = 0, mass = 0}, "last frame")

-- Monotone ramps, |a| <= M on every frame (lc.kerr checks it), and the
-- same scene whatever the evaluation order.
local forward, prev = {}, values(0)
for i = 0, shot.frames - 1 do
  forward[i] = shot.frame(i)
  local v = values(i)
  T.ok(v.incl >= prev.incl and v.spin <= prev.spin and v.mass <= prev.mass, "monotone at frame " .. i)
  T.ok(math.abs(v.spin) <= v.mass, "|a| <= M at frame " .. i)
  prev = v
end
for i = shot.frames - 1, 0, -1 do T.eq(shot.frame(i), forward[i], "reverse order, frame " .. i) end
for step = 0, shot.frames - 1 do
  local i = (step * 389) % shot.frames -- 389 is prime to 900: a permutation
  T.eq(shot.frame(i), forward[i], "permuted order, frame " .. i)
end

return true
