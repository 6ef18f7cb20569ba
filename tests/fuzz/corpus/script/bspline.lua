local s = bspline{ degree = 3, points = { {0,0}, {1,2}, {2,-1}, {3,2}, {4,0}, {5,1} } }
local t = s:insert_knot(0.5, 2)
local n = bspline{ degree = 2, knots = {0,0,0,0.4,1,1,1}, points = { {0,0}, {1,1}, {2,0}, {3,1} }, weights = {1, 2, 0.5, 1} }
local f = figure{ name = "seed-bspline" }
f:curve(t):polygon(t):deboor(s, 0.3):knots(s, { labels = "u_%d" })
f:curve(n:derivative(), { color = 2 })
for _, b in ipairs(s:to_beziers()) do f:curve(b, { width = 0.5 }) end
