-- expect: 1 "C stack overflow"
-- __concat recursion
local t = setmetatable({}, {})
getmetatable(t).__concat = function(a, b) return a .. b end
local s = t .. t
