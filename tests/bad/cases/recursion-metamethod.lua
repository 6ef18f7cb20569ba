-- expect: 1 "C stack overflow"
-- an __index chain that loops
local t = setmetatable({}, {})
getmetatable(t).__index = function(s, k) return s[k] end
local x = t.boom
