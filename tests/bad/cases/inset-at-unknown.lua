-- expect: 1 "inset: at "rigth" is unknown (did you mean "right"?)"
-- an inset at a misspelt place
local f = figure{ name = 'z' }
f:curve(bezier{ {0, 0}, {1, 1} })
f:inset{ region = { 0.2, 0.2, 0.4, 0.4 }, at = "rigth" }
