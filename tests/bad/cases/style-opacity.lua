-- expect: 1 "curve: style: opacity 2 must lie in [0, 1]"
-- opacity 2
local f = figure{ name = 'z' }
f:curve(bezier{ {0, 0}, {1, 1} }, { opacity = 2 })
