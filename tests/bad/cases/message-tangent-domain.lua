-- expect: 1 "tangent: t = 1.5 is outside the domain [0, 1]"
-- the tangent's parameter outside the curve's domain, named
local f = figure{ name = 'z' }
f:tangent(bezier{ {0, 0}, {1, 2}, {2, 0} }, 1.5)
