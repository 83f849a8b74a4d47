-- Lists every forbidden name that is reachable; the sandbox must return "".
local found = {}
for _, name in ipairs({"io", "os", "ffi", "debug", "jit", "package", "load", "loadstring",
                       "loadfile", "dofile", "module", "getfenv", "setfenv",
                       "collectgarbage", "newproxy", "gcinfo"}) do
  if _G[name] ~= nil then found[#found + 1] = name end
end
if string.dump ~= nil then found[#found + 1] = "string.dump" end
if ("").dump ~= nil then found[#found + 1] = '("").dump' end
-- Scripts must be deterministic (every rank evaluates them in its own order).
if math.random ~= nil then found[#found + 1] = "math.random" end
if math.randomseed ~= nil then found[#found + 1] = "math.randomseed" end
return table.concat(found, ",")
