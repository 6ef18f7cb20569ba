-- expect: 1 "offset: d is "
-- offset by NaN
local c = bezier{{0,0},{1,2},{2,0},{3,2},{4,0}}
local l = c:offset(0/0)
