-- One circular orbit at r = 6M around a Schwarzschild hole (the last stable
-- orbit), carrying a parallel-transported tetrad.  Seen from the comoving
-- frame the transported legs turn by 2 pi (1 - sqrt(1 - 3M/r)) = 105.44 deg per
-- orbit (geodesic precession; the paper's "105 deg rotation").
--
--   lightcone geodesic shots/geodesics/isco_precession.lua -o isco.csv
-- Columns e10..e13 are the transported leg that starts radial.
local lc = require "lightcone"

local M, r = 1, 6
local speed = math.sqrt(M / (r - 2 * M))                      -- 0.5 c relative to the static observer
local proper_period = 2 * math.pi * r ^ 1.5 / math.sqrt(M) * math.sqrt(1 - 3 * M / r)

return {
  spacetime = lc.kerr{mass = M, spin = 0},
  curve = "timelike",
  start = {t = 0, r = r, theta = 90, phi = 0},
  velocity = {phi = speed},
  transport = true,
  stop = {proper_time = proper_period},
  samples = 361,
}
