-- expect: 1 "figure: figure size 226.772 x -141.732 must be finite and positive"
-- a figure of height -5cm
local f = figure{ name = 'z', height = '-5cm' }
