-- expect: 1 "isolines: u = 1.5 is outside the domain [0, 1]"
-- an iso-line parameter outside the domain
local f = figure{ name = 'z', view = { 30, 20 } }
f:surface(bezier_surface{ points = { { {0, 0, 0}, {0, 1, 0} },
                                     { {1, 0, 0}, {1, 1, 1} } } },
          { isolines = { u = { 0.5, 1.5 } } })
