-- lightcone: the library for shot and geodesic-spec authors.
--
--   local lc = require "lightcone"
--   local bh = lc.kerr{mass = 1, spin = 0.9}
--
-- Units are geometric (G = c = 1, lengths and times in units of the mass
-- scale M). Angles are in degrees everywhere in Lua.
-- See docs/geodesic.md and docs/shots.md for the full reference.

local engine = __lightcone
local M = {}

-- Spacetimes (validated where they are made: errors name your line).
M.kerr = engine.kerr            -- kerr{mass = M, spin = a}, |a| <= M
M.dihole = engine.dihole        -- dihole{m1 = , m2 = , d = 1}: extreme RN holes at z = +d, -d
M.minkowski = engine.minkowski  -- minkowski(): flat spacetime

return M
