-- One circular orbit at r = 6M around a charged hole (Reissner–Nordström,
-- Q = 0.8 M), of neutral matter.  The charge weakens the pull at small r:
-- the angular velocity is Omega = sqrt(M r - Q^2) / r^2 (Kerr's sqrt(M/r^3)
-- at Q = 0), so one orbit takes the coordinate time
--   T = 2 pi r^2 / sqrt(M r - Q^2) = 97.70 M    (Schwarzschild: 92.34 M),
-- and the ISCO moves in from 6M to 4.89M, so r = 6M is stable here.
--
--   lightcone geodesic shots/geodesics/reissner_nordstrom_orbit.lua -o rn_orbit.csv
local lc = require "lightcone"

local M, Q, r = 1, 0.8, 6
local f = 1 - 2 * M / r + Q * Q / (r * r)                  -- -g_tt
local speed = math.sqrt(M * r - Q * Q) / (r * math.sqrt(f))  -- r Omega / sqrt(f): relative to the static observer
local period = 2 * math.pi * r * r / math.sqrt(M * r - Q * Q)

return {
  spacetime = lc.kerr{mass = M, spin = 0, charge = Q},
  curve = "timelike",
  start = {t = 0, r = r, theta = 90, phi = 0},
  velocity = {phi = speed},
  stop = {coordinate_time = period},
  samples = 361,
}
