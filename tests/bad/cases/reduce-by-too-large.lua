-- expect: 1 "reduce: cannot reduce a curve of degree 4 by 5 degrees (by must be 1 .. 3)"
-- a reduction by more degrees than the curve has
local c = bezier{{0,0},{1,2},{2,0},{3,2},{4,0}}
local r = c:reduce{ by = 5 }
