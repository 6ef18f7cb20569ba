-- expect: 1 "figure: view is {azimuth, elevation} in degrees, got number"
-- a view that is one number
local f = figure{ name = 'z', view = 30 }
