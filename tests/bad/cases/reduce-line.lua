-- expect: 1 "reduce: a curve of degree 1 cannot be reduced (the least degree of a reduced curve is 1)"
-- a line has no lower degree that is still a curve
local c = bezier{{0,0},{2,4}}
local r = c:reduce()
