-- expect: 1 "reduce: cannot reduce a curve of degree 3 by 3 degrees (by must be 1 .. 2)"
-- a reduction by the whole degree would leave a point
local c = bezier{{0,0},{1,2},{2,0},{3,2}}
local r = c:reduce(3)
