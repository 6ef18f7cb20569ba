-- expect: 1 "fill: its 3 points lie on one line: no region to fill (a fill needs three points off one line)"
-- a filled polygon in space whose points lie on one line
local f = figure{ name = 'z', view = { 30, 20 } }
f:fill({ {0, 0, 0}, {1, 1, 1}, {2, 2, 2} })
