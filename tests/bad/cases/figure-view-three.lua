-- expect: 1 "figure: view is two numbers {azimuth, elevation} in degrees, got 3"
-- a view of three numbers
local f = figure{ name = 'z', view = { 30, 20, 10 } }
