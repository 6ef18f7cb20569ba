-- expect: 1 "polyline: closed is true or false, got string"
-- a yes/no option given a string is refused, not read as Lua's truth
local f = figure{ name = 'z' }
f:polyline({ {0, 0}, {1, 1}, {2, 0} }, { closed = 'no' })
