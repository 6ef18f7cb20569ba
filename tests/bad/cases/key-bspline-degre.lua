-- expect: 1 "bspline: unknown field 'degre' (did you mean 'degree'?)"
-- a misspelt degree is named, not reported as a missing one
local s = bspline{ degre = 3, points = { {0, 0}, {1, 2}, {2, 0}, {3, 1} } }
