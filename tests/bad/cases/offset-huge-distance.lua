-- expect: 1 "offset: tolerance 0.001 cannot be reached at distance 1e+14"
-- an offset distance so large that the absolute tolerance is below what
-- doubles resolve there: the fit splits towards its minimum width (1e-9
-- of the interval) and runs for hours; 1e12 takes a second, 1e14 and
-- beyond (1e20, 1e300) do not end
local c = bezier{ {0, 0}, {1, 2}, {2, 0} }
local o = c:offset(1e14)
