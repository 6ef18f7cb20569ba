-- expect: 1 "label 2 "P" (line 5) lies"
-- a label's offset of 1e17 bp: its width (a few bp) is lost in its place's rounding, so its ink box had no area; the page checks passed it over and the PDF and PNG were written without it, silently
local f = figure{ name = "far", width = "6cm", height = "4cm", window = {0, 1, 0, 1} }
f:polyline({ {0, 0}, {1, 1} })
f:label({ 0.5, 0.5 }, "P", { offset = 1e17 })
