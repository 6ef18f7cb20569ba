-- expect: 1 "figure: figure size 0 x 170.079 must be finite and positive"
-- a figure of width 0
local f = figure{ name = 'z', width = 0 }
