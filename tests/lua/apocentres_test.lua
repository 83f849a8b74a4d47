-- lc.apocentres times an animation by the motion: the dihole body released
-- at rest at x = 5 turns at x = -5 after T/2 and is back after T = 110.594.
local lc = require "lightcone"

local hole = lc.dihole{m1 = 0.4, m2 = 0.4, d = 1}
local w = lc.worldline{spacetime = hole, start = {x = 5, y = 0, z = 0}, duration = 100}
local turns = lc.apocentres(w)
local list = {} for k, e in ipairs(turns) do list[k] = string.format("t=%.6f r=%.6f", e.t, e.r) end
assert(#turns == 2, "two turning points in 100 of proper time, got " .. table.concat(list, "; "))
assert(math.abs(turns[1].t - 110.594 / 2) < 1e-3, "half period " .. turns[1].t)
assert(math.abs(turns[2].t - 110.594) < 1e-3, "period " .. turns[2].t)
assert(math.abs(turns[2].tau - 78.753) < 1e-3, "proper period " .. turns[2].tau)
assert(math.abs(turns[1].r - 5) < 1e-6 and math.abs(turns[2].r - 5) < 1e-6, "turning radius")
return true
