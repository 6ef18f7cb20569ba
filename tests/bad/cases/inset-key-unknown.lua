-- expect: 1 "inset: unknown option 'regoin' (did you mean 'region'?)"
-- an inset option misspelt
local f = figure{ name = 'z' }
f:curve(bezier{ {0, 0}, {1, 1} })
f:inset{ regoin = { 0.2, 0.2, 0.4, 0.4 } }
