-- expect: 1 "decasteljau: t = 1.5 is outside [0, 1]"
-- f:decasteljau at t = 1.5
local f = figure{ name = 'z' }
f:decasteljau(bezier{{0,0},{1,2},{2,0},{3,2},{4,0}}, 1.5)
