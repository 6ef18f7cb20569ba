-- expect: 1 "figure 'big': rendering exceeded the memory limit of 64 MiB"
-- the same in curvefig live: a run renders inside the limits of its process (--once runs it as the server does)
-- command: live
-- args: --once --max-memory 64
-- max-rss: 80
local pts = {}
for i = 1, 100000 do pts[i] = { i / 1000, math.sin(i / 100) } end
local f = figure{ name = "big" }
f:curve(bspline{ degree = 3, points = pts })
