-- Closes the cycle cyc_c -> cyc_d -> cyc_c on line 3.
local unused = 0
local c = require("cyc_c")
return c
