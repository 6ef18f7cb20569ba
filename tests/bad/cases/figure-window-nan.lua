-- expect: 1 "figure: window 2 is "
-- a window with NaN
local f = figure{ name = 'z', window = {0, 0/0, 0, 1} }
