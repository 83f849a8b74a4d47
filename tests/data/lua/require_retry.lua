-- A failed require is not cached and is not mistaken for a cycle later.
local ok1, err1 = pcall(require, "bad_module")
local ok2, err2 = pcall(require, "bad_module")
return tostring(ok1) .. "|" .. tostring(ok2) .. "|" .. tostring(err2)
