-- Returns three values and defines a function for Sandbox::call.
double = function(x) return 2 * x end
return 1, "two", {three = 3}
