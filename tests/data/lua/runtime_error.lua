-- A runtime error on line 4, reached from line 6.
local function lookup(t)
  local unused = 1
  return t.x.y
end
local v = lookup({})
return v
