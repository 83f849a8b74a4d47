-- What shot scripts may use: base, table, string, math, bit and our require.
return type(require) == "function" and type(pcall) == "function"
  and math.floor(math.sin(0) + 2.5) == 2 and bit.band(6, 3) == 2
  and table.concat({"a", "b"}, "-") == "a-b" and string.format("%03d", 7) == "007"
  and ("abc"):upper() == "ABC" and select("#", 1, 2) == 2
