-- expect: 1 "derivative: k is -1; it must be in [0, 64]"
-- derivative of order -1
local c = bezier{{0,0},{1,2},{2,0},{3,2},{4,0}}
local d = c:derivative(-1)
