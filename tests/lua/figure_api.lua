-- every figure method once, with its options (rendered by the tests)
local P = { {3,1}, {3.75,2}, {5,3}, {4,4}, {3,3}, {2,4}, {1,3}, {2.25,2} }
local s = bspline{ degree = 2, points = P }
local c = bezier{ {0, 0}, {1, 2}, {3, 2}, {4, 0} }
local f = figure{ name = "api-all", caption = "all methods", width = "60mm",
                  height = "50mm", margin = "5mm", theme = "default",
                  tolerance = 0.02, title = "API" }
f:hull(c, { fill = "#ddeeff", opacity = 0.8 })
 :polygon(c, { labels = { "A", false, "C", "D" }, label_place = "s",
               marker = "square", dash = "dashed" })
 :curve(c, { color = { 0.1, 0.2, 0.6 }, width = 1.5 })
 :curve(c, { range = { 0.2, 0.4 }, color = "red", width = 3 })
 :curve({ c:split(0.5) }, { color = 2, dash = { 2, 1 } })
 :points(c:eval(0.5), { marker = "star", marker_size = 8 })
 :label(c:eval(0.5), "c(1/2)", { place = "ne", font_size = 9, offset = 3 })
 :arrow(c:eval(0.5), { 1, 0 }, { label = "v", arrow_size = 5 })
 :arrow_to({ 0, 0 }, { 1, 1 })
 :tangent(c, 0.25, { label = "c'" })
 :line({ 0, -1 }, { 4, -1 }, { dash = "dotted" })
 :polyline({ {0, -2}, {1, -1.5}, {2, -2} }, { closed = true })
 :fill({ {3, -2}, {4, -2}, {3.5, -1.5} }, { fill = "orange" })
 :decasteljau(c, 0.3, { labels = function(i, j) return j == 3 and "X" or nil end,
                        levels = 4, point = true })
f:window()
local g = figure{ name = "api-bspline", aspect = true }
g:polygon(s, { labels = "P_%d", label_start = 0, label_place = { "s", "se", "e" } })
 :curve(s)
 :knots(s, { labels = "u_%d", color = "red", marker = "tick" })
 :deboor(s, 0.5, { colors = { "grey", "blue", "green" }, labels = "P_{%d,%d}" })
local h = figure{ name = "api-plot", width = "200bp", height = "120bp" }
h:plot{ x = { 0, 1 }, y = { 0, 1.2 }, xticks = { 0, 0.5, 1 },
        xtick_labels = { "0", "1/2", "1" }, yticks = 0.5, xlabel = "u",
        ylabel = "N", knots = s:knots(), knot_labels = true, grid = true }
 :basis(s, 3)
 :basis({ 0, 1, 3, 6, 10 }, 0, 3, { color = 3 })
 :bernstein(3, 1, { color = "purple" })
 :func(function(x) return x * x end, 0, 1, { dash = "dashdot" })
 :graph(bezier{ {0}, {1}, {0.5} })
 :graph(bspline{ degree = 1, points = { {0}, {1}, {0} } })
local k = figure{ name = "api-3d", view = { 30, 20 } }
k:curve(bezier{ {0, 0, 0}, {1, 2, 3}, {2, 0, 1} })
local q = k:project({ {1, 2, 3} })
assert(#q == 1 and #q[1] == 2)
local m = figure{ name = "api-proj", projection = { {1, 0, 0.5}, {0, 1, 0.5} },
                  window = { -1, 5, -1, 5 } }
m:points({ {1, 1, 1} })
assert(f:name() == "api-all" and tostring(f) == "figure api-all")
print("figure api: ok")
