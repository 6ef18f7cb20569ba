-- expect: 1 "label 2 "P" (line 5) lies 2.494e+299 mm outside the drawing's 60.0 x 40.0 mm page"
-- the same far label in a figure with a legend: the legend is placed beside the ink, as far out, and the error named the legend ("legend 4 "a line" lies ...") instead of the label to move
local f = figure{ name = "far", width = "6cm", height = "4cm", window = {0, 1, 0, 1} }
f:polyline({ {0, 0}, {1, 1} })
f:label({ 0.5, 0.5 }, "P", { offset = 1e300 })
f:polyline({ {0, 1}, {1, 0} }, { legend = "a line" })
