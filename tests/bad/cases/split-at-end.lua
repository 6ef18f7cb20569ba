-- expect: 1 "split: 1 must lie strictly inside the domain [0, 1]"
-- split at the end of the domain
local s = bspline{ degree = 2, points = {{0,0},{1,2},{2,0},{3,2},{4,0}} }
local a, b = s:split(1)
