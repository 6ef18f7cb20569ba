-- expect: 1 "curve: unknown option 'colour'"
-- an unknown style option
local f = figure{ name = 'z' }
f:curve(bezier{ {0, 0}, {1, 1} }, { colour = 'red' })
