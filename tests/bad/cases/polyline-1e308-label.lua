-- expect: 1 "polyline 1 (line 4) lies too far outside the drawing's 60.0 x 40.0 mm page to be drawn (its place on the page overflows to inf)"
-- a point at 1.7e308 in an explicit window, with a label to place: the placement's rasteriser crashed (a round join between NaN directions wrote past its array) before the page's check named the element
local f = figure{ name = "far", width = "6cm", height = "4cm", window = {0, 1, 0, 1} }
f:polyline({ {0, 0}, {1.7e308, 1}, {1, 2} })
f:label({ 0.5, 0.5 }, "P")
