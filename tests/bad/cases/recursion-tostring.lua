-- expect: 1 "C stack overflow"
-- __tostring that recurses
local t
t = setmetatable({}, { __tostring = function(s) return tostring(s) end })
print(t)
