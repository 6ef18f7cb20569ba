-- expect: 1 "script exceeded the memory limit of 32 MiB"
-- refining a B-spline with a million knots
-- args: --max-memory 32
local s = bspline{ degree = 3, points = {{0,0},{1,1},{2,0},{3,1}} }
local x = {}
for i = 1, 1e6 do x[i] = i / 1e6 * 0.999 end
local t = s:refine(x)
