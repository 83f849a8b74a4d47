-- Light round the throat of an Ellis wormhole (throat radius b = 1): the
-- throat, l = 0, is the wormhole's one photon orbit (r(l) = √(l² + b²) is
-- least there), so a ray launched along it circles it, one turn in 2π b =
-- 6.2832 of coordinate time (g_tt = -1: no clock runs slow).  The orbit is
-- unstable: a longer run drifts off into one universe or the other.
--
--   lightcone geodesic shots/geodesics/ellis_throat_orbit.lua -o throat.csv
local lc = require "lightcone"

return {
  spacetime = lc.ellis_wormhole{throat = 1},
  curve = "null",
  start = {t = 0, r = 0, theta = 90, phi = 0},
  direction = {phi = 1},
  stop = {coordinate_time = 2 * math.pi},
  samples = 361,
}
