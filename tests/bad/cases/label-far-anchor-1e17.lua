-- expect: 1 "label 2 "P" (line 5) at (1e+17, 0.5) is outside the window [0, 1] x [0, 1], too far to fit the 60.0 x 40.0 mm page beside it"
-- a label at x = 1e17 outside an explicit window: at 1e15 an error, at 1e17 (its box without area in the rounding) left out of the PDF and PNG, silently
local f = figure{ name = "far", width = "6cm", height = "4cm", window = {0, 1, 0, 1} }
f:polyline({ {0, 0}, {1, 1} })
f:label({ 1e17, 0.5 }, "P", { place = "ne" })
