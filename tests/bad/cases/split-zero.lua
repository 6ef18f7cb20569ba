-- expect: 1 "split: t = 0; it must lie in (0, 1)"
-- split at t = 0
local c = bezier{{0,0},{1,2},{2,0},{3,2},{4,0}}
local a, b = c:split(0)
