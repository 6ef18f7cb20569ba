-- expect: 1 "curve: color: unknown colour "octarine" (use #rrggbb, #rrggbbaa, none"
-- an unknown colour
local f = figure{ name = 'z' }
f:curve(bezier{ {0, 0}, {1, 1} }, { color = 'octarine' })
