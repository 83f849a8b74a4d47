-- Raises a non-string error value on line 3.
local function fail()
  error({code = 42})
end
fail()
