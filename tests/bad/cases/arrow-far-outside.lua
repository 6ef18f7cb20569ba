-- expect: 1 "arrow 2 (line 5) lies 7.858e+05 mm outside the drawing's 60.0 x 40.0 mm page, on the top"
-- an arrow from far outside the drawing on a page cropped to its ink: a page of kilometres; refused, naming it and where it lies
local f = figure{ name = "far", width = "6cm", height = "4cm", window = {0, 1, 0, 1} }
f:polyline({ {0, 0}, {1, 1} })
f:arrow_to({ 1e5, 1e5 }, { 0.5, 0.5 })
