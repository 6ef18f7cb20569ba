-- expect: 1 "bad argument #1 to 'curve' (curvefig.bezier expected, got number)"
-- curve given a number
local f = figure{ name = 'z' }
f:curve(42)
