-- Loops inside a coroutine, then keeps resuming the dead coroutine.
local co = coroutine.wrap(function() while true do end end)
while true do pcall(co) end
