-- expect: 1 "lies at or behind the eye of the view (distance = 1)"
-- a perspective eye inside the surface's box
local f = figure{ name = 'z', view = { 0, 0 }, projection = "perspective",
                  distance = 1 }
f:surface(bezier_surface{ points = { { {0, 0, 0}, {0, 1, 0} },
                                     { {3, 0, 0}, {3, 1, 1} } } })
