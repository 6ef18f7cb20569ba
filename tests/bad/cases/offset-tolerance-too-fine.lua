-- expect: 1 "offset: offset tolerance 1e-14 is below what doubles resolve"
-- a tolerance finer than doubles resolve at the size of the curve
local c = bezier{{0,0},{100,200},{200,0},{300,200},{400,0}}
local l = c:offset(10, { tolerance = 1e-14, trim = true })
