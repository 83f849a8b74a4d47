-- Requires a module that exists nowhere, on line 3.
local ok = true
local m = require("nope")
return m
