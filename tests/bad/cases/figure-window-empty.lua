-- expect: 1 "figure: window [1, 1] x [0, 1] is empty"
-- a window of zero width
local f = figure{ name = 'z', window = {1, 1, 0, 1} }
