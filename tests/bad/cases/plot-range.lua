-- expect: 1 "plot: axes ranges [1, 1] x [0, 1] are empty"
-- plot with an empty x range
local f = figure{ name = 'z' }
f:plot{ x = {1, 1}, y = {0, 1} }
