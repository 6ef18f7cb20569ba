-- expect: 1 "curve: curve range [0.5, 3] must satisfy 0 <= a < b <= 1"
-- a curve range outside the domain
local f = figure{ name = 'z' }
f:curve(bezier{ {0, 0}, {1, 1} }, { range = {0.5, 3} })
