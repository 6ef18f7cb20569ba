-- expect: 1 "bad argument #1 to 'eval' (curvefig.bezier expected, got number)"
-- a method called on the wrong receiver
local c = bezier{{0,0},{1,2},{2,0},{3,2},{4,0}}
local p = c.eval(5, 0.5)
