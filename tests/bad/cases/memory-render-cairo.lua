-- expect: 1 "out of memory for cairo's work on a path of 99998 segments"
-- the same B-spline as PNG with room for the display list: cairo's own work is bounded through its input
-- args: --max-memory 96 -f png
-- max-rss: 112
local pts = {}
for i = 1, 100000 do pts[i] = { i / 1000, math.sin(i / 100) } end
local f = figure{ name = "big" }
f:curve(bspline{ degree = 3, points = pts })
