-- expect: 1 "curve: style: line width -1 must be finite and positive"
-- a negative line width
local f = figure{ name = 'z' }
f:curve(bezier{ {0, 0}, {1, 1} }, { width = -1 })
