-- expect: 1 "eval: (u, v) = (1e+300, 0.30000000000000004) is outside the domain [0, 1] x [0, 1]"
-- the numbers of the message in their shortest text that reads back as
-- them: 1e+300 (not 1.0000000000000001e+300), and 0.1 + 0.2 in full, as
-- it is not 0.3
local s = bezier_surface{ points = { { {0, 0, 0}, {1, 0, 0} },
                                     { {0, 1, 0}, {1, 1, 1} } } }
local p = s:eval(1e300, 0.1 + 0.2)
