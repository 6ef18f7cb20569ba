-- expect: 1 "curve: unknown option 'visibel' (did you mean 'visible'?)"
-- the overlay key misspelt
local f = figure{ name = 'z' }
f:curve(bezier{ {0, 0}, {1, 1} }, { visibel = '2-' })
