-- The first sequence again (shots/kerr_accrDisk.lua: the same storyboard,
-- camera and timing), with light as physics says (docs/light.md): the disk
-- is a Novikov–Thorne disk glowing at its own temperatures, and everything
-- is seen through the frequency shift g of its light, so the side whose
-- matter comes towards the camera is brighter and bluer.
--
-- The hole stands for 4.3 million Suns (the mass of the Milky Way's)
-- accreting 1e-8 Suns a year: the rings' temperatures are near 10,000 K,
-- light the eye sees.  Its length scale stays fixed while the storyboard
-- takes the mass to 0, so the disk dims as the hole that powers it
-- shrinks, and with no hole left (the last second) there is no disk.
--
--   lightcone render shots/kerr_accrDisk_thermal.lua --out out/kerr_accrDisk_thermal
local lc = require "lightcone"
local paper = require "kerr_accrDisk"

local solar_masses = 4.3e6   -- per unit of the spacetime's mass
local accretion_rate = 1e-8  -- Suns per year
-- The light is in cd/m^2 (~1e10 at 10,000 K): 2^-34 brings the disk's
-- bright side to the tone curve's shoulder, fixed for the whole film.
-- The star field's texture has no units; it is brightened by as much, so
-- the stars show as in the paper's sequence.
local exposure = -34

local shot = {}
for k, v in pairs(paper) do shot[k] = v end
shot.name = "kerr_accrDisk_thermal"
shot.exposure = exposure
-- The look (docs/light.md): the gamut-safe view lets the beamed side fade
-- to white without clipping; white balanced for 5000 K, the ~10,000 K gas
-- reads as hot, bluish white rather than grey-beige; a little more colour;
-- and the brightest light glows.
shot.view = "gamut_safe"
shot.white_balance = 5000
shot.saturation = 1.3
shot.bloom = 0.25
shot.bloom_radius = 0.015
shot.frame = function(i)
  local scene = paper.frame(i)
  local M = scene.spacetime.mass
  scene.disk = M > 0 and lc.disk{inner = scene.disk.inner, outer = scene.disk.outer,
                                 solar_masses = solar_masses * M, accretion_rate = accretion_rate} or nil
  scene.sky = lc.starfield{brightness = -exposure}
  scene.light = lc.light{model = "shifted"}
  return scene
end
return shot
