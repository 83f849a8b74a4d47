-- A test body released at rest on the axis of three extreme
-- Reissner–Nordström holes (Majumdar–Papapetrou: m = 0.3 each at the
-- corners of a triangle 1.5 from its centre, in the plane z = 0), 4 above
-- the centre: it falls through the triangle to z = -4 and back.  Along the
-- axis U = 1 + 3m / sqrt(1.5^2 + z^2), and the energy integral gives the
-- period T = 4 ∫_0^4 E U^3 / sqrt(E^2 U^2 - 1) dz = 91.91965 in coordinate
-- time (64.12910 proper), E = 1/U(4).  This traces two periods.  The balance
-- at the centre is unstable: started a little off the axis, the body falls
-- towards a hole.
--
--   lightcone geodesic shots/geodesics/triangle_swing.lua -o triangle.csv
local lc = require "lightcone"

local m, R = 0.3, 1.5
local s = math.sqrt(3) / 2
local period = 91.91965  -- coordinate time, from the energy integral

return {
  spacetime = lc.majumdar_papapetrou{holes = {
    {mass = m, position = {x = R, y = 0, z = 0}},
    {mass = m, position = {x = -R / 2, y = s * R, z = 0}},
    {mass = m, position = {x = -R / 2, y = -s * R, z = 0}},
  }},
  curve = "timelike",
  start = {t = 0, x = 0, y = 0, z = 4},
  velocity = {x = 0, y = 0, z = 0},     -- at rest relative to the static observer
  stop = {coordinate_time = 2 * period},
  samples = 2001,
}
