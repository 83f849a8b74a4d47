-- The required module fails at its line 3; this line 2 requires it.
local m = require("bad_module")
return m
