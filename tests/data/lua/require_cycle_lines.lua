-- Enters the cycle of cyc_c and cyc_d on line 2.
local m = require("cyc_c")
return m
