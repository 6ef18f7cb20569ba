-- expect: 1 "elevate: r is -1; it must be in [0, 1024]"
-- degree elevation by -1
local c = bezier{{0,0},{1,2},{2,0},{3,2},{4,0}}
local d = c:elevate(-1)
