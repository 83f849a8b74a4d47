-- Raises an error object that knows how to print itself.
error(setmetatable({}, {__tostring = function() return "custom failure object" end}))
