-- A test body released at rest at (5, 0, 0) between two extreme
-- Reissner–Nordström holes (m = 0.4 each at z = +-1, the paper's dihole).
-- It falls through the origin to x = -5 and back with the coordinate-time
-- period T = 110.594 (proper time 78.753); this traces two periods.
--
--   lightcone geodesic shots/geodesics/dihole_oscillation.lua -o dihole.csv
local lc = require "lightcone"

local period = 110.594  -- coordinate time (Wünsch et al. 2013; the paper quotes 110.59)

return {
  spacetime = lc.dihole{m1 = 0.4, m2 = 0.4, d = 1},
  curve = "timelike",
  start = {t = 0, x = 5, y = 0, z = 0},
  velocity = {x = 0, y = 0, z = 0},     -- at rest relative to the static observer
  stop = {coordinate_time = 2 * period},
  samples = 2001,
}
