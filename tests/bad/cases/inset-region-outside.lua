-- expect: 1 "inset 1: region {0.5, 0.5, 3, 0.8} is not inside the window [0, 1] x [0, 1]"
-- an inset of a region that is not in the window
local f = figure{ name = 'z', window = { 0, 1, 0, 1 } }
f:curve(bezier{ {0, 0}, {1, 1} })
f:inset{ region = { 0.5, 0.5, 3, 0.8 } }
