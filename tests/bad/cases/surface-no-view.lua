-- expect: 1 "surface: the figure has no view; give figure{view = {azimuth, elevation}, ...}"
-- a surface in a figure without a view
local f = figure{ name = 'z' }
f:surface(bezier_surface{ points = { { {0, 0, 0}, {0, 1, 0} },
                                     { {1, 0, 0}, {1, 1, 1} } } })
