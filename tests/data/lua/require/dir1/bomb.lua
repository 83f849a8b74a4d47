-- Exhausts memory while being required.
local t = {}
while true do t[#t + 1] = string.rep("z", 1e6) .. #t end
