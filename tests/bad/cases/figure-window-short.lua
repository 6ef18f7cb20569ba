-- expect: 1 "figure: window is {xmin, xmax, ymin, ymax}"
-- a window with three numbers
local f = figure{ name = 'z', window = {0, 1, 0} }
