-- expect: 1 "figure: the window list has an entry named 'xmax'; a list takes no names"
-- a window given by names is refused, not read as empty
local f = figure{ name = 'z', window = { xmin = 0, xmax = 1, ymin = 0, ymax = 1 } }
