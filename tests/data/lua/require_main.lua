-- Exercises require: second directory, nested names, caching, shadowing.
local second = require("second")
local util = require("lib.util")
local c1 = require("counted")
local c2 = require("counted")
return {
  second = second.name,
  twice = util.twice(21),
  same = c1 == c2,
  loads = load_count,
  shadow = require("shadow"),
  nothing = require("returns_nothing"),
}
