-- Fails while loading, on line 3.
local t = nil
local v = t.field
return v
