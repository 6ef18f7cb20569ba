-- expect: 1 "unknown command"
-- a label with an unknown command
local f = figure{ name = 'z' }
f:label({0, 0}, '\\foo')
