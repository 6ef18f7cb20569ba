-- expect: 1 "arrow 2 (line 5) lies too far outside the drawing's 60.0 x 40.0 mm page to be drawn"
-- an arrow from (1e308, 1e308): its page coordinates overflow to infinity; it was left out of the PDF and PNG, silently (and the page shrank)
local f = figure{ name = "far", width = "6cm", height = "4cm", window = {0, 1, 0, 1} }
f:polyline({ {0, 0}, {1, 1} })
f:arrow_to({ 1e308, 1e308 }, { 0.5, 0.5 })
