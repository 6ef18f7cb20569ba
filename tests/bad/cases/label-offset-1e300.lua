-- expect: 1 "label 2 "P" (line 5) lies 2.494e+299 mm outside the drawing's 60.0 x 40.0 mm page"
-- a label's offset of 1e300 bp: the label placement's ink sums turned its box into pixel indices no int holds and read far outside the raster (SIGSEGV)
local f = figure{ name = "far", width = "6cm", height = "4cm", window = {0, 1, 0, 1} }
f:polyline({ {0, 0}, {1, 1} })
f:label({ 0.5, 0.5 }, "P", { offset = 1e300 })
