-- expect: 1 "window"
-- a window of width 1e300 - (-1e300)
local f = figure{ name = 'big', window = {-1e308, 1e308, -1e308, 1e308} }
f:curve(bezier{ {0, 0}, {1, 1} })
