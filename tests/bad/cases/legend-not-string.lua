-- expect: 1 "curve: legend must be a string, got number"
-- a legend entry that is not a text
local f = figure{ name = 'z' }
f:curve(bezier{ {0, 0}, {1, 1} }, { legend = 3 })
