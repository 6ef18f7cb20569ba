-- expect: 1 "reduce: by is 0; it must be in [1, 1024]"
-- a reduction by no degree
local c = bezier{{0,0},{1,2},{2,0}}
local r = c:reduce(0)
