-- A nested module: require("lib.util").
return { twice = function(x) return 2 * x end }
