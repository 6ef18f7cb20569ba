-- expect: 1 "bspline: give either knots or kind"
-- knots and a kind of knots together
local s = bspline{ degree = 1, knots = { 0, 0, 1, 1 }, kind = 'uniform', points = { {0, 0}, {1, 1} } }
