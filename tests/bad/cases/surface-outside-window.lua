-- expect: 1 "lies wholly outside the window {10, 12, 10, 12}"
-- a surface drawn outside an explicit window
local f = figure{ name = 'z', view = { 30, 20 }, window = { 10, 12, 10, 12 } }
f:surface(bezier_surface{ points = { { {0, 0, 0}, {0, 1, 0} },
                                     { {1, 0, 0}, {1, 1, 1} } } })
