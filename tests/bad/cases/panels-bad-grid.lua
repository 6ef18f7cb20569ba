-- expect: 1 "panels: rows is 9; it must be in [1, 8]"
-- a grid of too many rows
local f = figure{ name = 'z' }
f:panels{ rows = 9, cols = 1 }
