-- expect: 1 "eval: (u, v) = (0.5, 1.25) is outside the domain [0, 1] x [0, 1]"
-- a parameter pair outside the domain
local s = bezier_surface{ points = { { {0, 0, 0}, {1, 0, 0} },
                                     { {0, 1, 0}, {1, 1, 1} } } }
local p = s:eval(0.5, 1.25)
