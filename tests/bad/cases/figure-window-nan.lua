-- expect: 1 "figure: window 1 is "
-- a window with NaN
local f = figure{ name = 'z', window = {0, 0/0, 0, 1} }
