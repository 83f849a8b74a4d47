-- Each name must be refused (or not found) without touching the file system
-- outside the require directories.
local out = {}
for _, name in ipairs({"../x", "/etc/passwd", "a/b", "", "a..b", ".a", "a.", "x y", "..", "./second"}) do
  local ok, err = pcall(require, name)
  out[#out + 1] = tostring(ok) .. " " .. tostring(err)
end
local ok, err = pcall(require, 42)
out[#out + 1] = tostring(ok) .. " " .. tostring(err)
return table.concat(out, "\n")
