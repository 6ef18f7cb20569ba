-- every figure method once, small and fast: a seed from which a mutated
-- argument reaches each method's edge cases within a few mutations
local c = bezier{ {0, 0}, {1, 2}, {2, 0}, weights = {1, 2, 1} }
local s = bspline{ degree = 2, points = { {0, 0}, {1, 2}, {2, 0}, {3, 1} } }
local P = { {0, 0}, {1, 1}, {2, 0} }
local f = figure{ name = "m", width = "4cm", height = "3cm" }
f:curve(c, { range = { 0.2, 0.8 } }):curve(s, { dash = "dashed" })
f:polygon(P, { labels = "P_%d", label_place = "s" }):points(P)
f:hull(P):fill(P):polyline(P, { closed = true }):line({0, 0}, {1, 1})
f:label({1, 1}, "x", { place = "ne" }):arrow({0, 0}, {1, 0}, { label = "v" })
f:arrow_to({0, 0}, {1, 1}):tangent(c, 0.5, { scale = 1 })
f:knots(s, { labels = "u_%d" }):decasteljau(c, 0.5, { point = true })
f:deboor(s, 0.5, { labels = "P_{%d,%d}" }):project(P)
local g = figure{ name = "p", width = "4cm", height = "3cm" }
g:plot{ x = {0, 1}, y = {0, 1}, knots = {0, 0.5, 1}, knot_labels = true }
g:func(math.sin, 0, 1):graph(bezier{ {0}, {1}, {0} }):basis(s, 1, 2)
g:bernstein(3, 1):window(0, 1, 0, 1)
