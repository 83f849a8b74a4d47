-- A minimal shot: frame(i) is called once per frame by the engine.
local shot = {}
function shot.frame(i)
  return {t = i / 24, mass = 1 + i * 1e-3}
end
function shot.spin()
  while true do end
end
function shot.bomb()
  local t = {}
  while true do t[#t + 1] = string.rep("y", 1e6) .. #t end
end
function shot.fail(i)
  error("frame " .. i .. " is broken")
end
function shot.work(n)
  local x = 0
  for i = 1, n do x = x + i end
  return x
end
return shot
