-- A script that only knows whole frames (a table indexed by the frame
-- number): with the shutter open its instants between frames fail, and
-- the error must say so (tests/e2e/motion_blur.sh).
local lc = require "lightcone"
local heights = {20, 22, 24}
return {
  name = "whole_frames",
  frames = 3,
  width = 16,
  height = 16,
  frame = function(i)
    return {
      spacetime = lc.minkowski{},
      observer = lc.static_observer{x = 0, y = heights[i + 1], z = 0},
    }
  end,
}
