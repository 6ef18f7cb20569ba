-- expect: 1 "figure: width is "
-- a figure of width NaN
local f = figure{ name = 'z', width = 0/0 }
