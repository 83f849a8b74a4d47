-- Calls C functions registered by sandbox_test; no tail calls, so each
-- call keeps this file's line on the stack (except where noted).
return {
  throws = function() local r = throws() return r end,
  kerr_missing = function() local r = kerr({}) return r end,
  kerr_typo = function() local r = kerr({mass = 1, spinn = 0.5}) return r end,
  kerr_ok = function() local r = kerr({mass = 2, spin = 0.5, __kind = "kerr"}) return r end,
  raises = function() local r = raises() return r end,
  where = function() local r = where_here() return r end,
  probe = function() local r = dtor_probe() return r end,
  -- Tail calls: LuaJIT replaces the calling Lua frame, even for C functions.
  tail = function() return throws() end,
  tail_nested = function()
    local function inner()
      return throws()
    end
    local r = inner()
    return r
  end,
  via_pcall = function()
    local ok, err = pcall(throws)
    return err
  end,
}
