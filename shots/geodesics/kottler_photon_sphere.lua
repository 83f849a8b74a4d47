-- Light on the photon sphere of a hole in a universe with a cosmological
-- constant (Schwarzschild–de Sitter, Λ = 0.05): Λ drops out of the orbit
-- equation of light, (du/dφ)^2 = 1/b^2 + Λ/3 - u^2 + 2 M u^3, so the photon
-- sphere is at r = 3M whatever Λ.  A ray launched along it stays on it for
-- one turn, 2π r / sqrt(F(r)) = 44.023 M of static time with
-- F(3M) = 1/3 - 3Λ M^2.  (The orbit is unstable: a longer run drifts off.)
--
--   lightcone geodesic shots/geodesics/kottler_photon_sphere.lua -o kottler.csv
local lc = require "lightcone"

local M, lambda, r = 1, 0.05, 3
local F = 1 - 2 * M / r - lambda * r * r / 3

return {
  spacetime = lc.kottler{mass = M, lambda = lambda},
  curve = "null",
  start = {t = 0, r = r, theta = 90, phi = 0},
  direction = {phi = 1},
  stop = {coordinate_time = 2 * math.pi * r / math.sqrt(F)},
  samples = 361,
}
