-- expect: 1 "too large"
-- a curve with coordinates +-1.7e308 in a fitted figure
local f = figure{ name = 'big' }
f:curve(bezier{ {-1.7e308, 0}, {1.7e308, 1} })
