-- A module that exhausts memory.
return require("bomb")
