-- expect: 1 "knots: label_place "sw2" is unknown (did you mean "sw"?)"
-- a misspelt place in a table of places
local f = figure{ name = 'z' }
local s = bspline{ degree = 1, points = { {0, 0}, {1, 1}, {2, 0} } }
f:knots(s, { labels = 'u_%d', label_place = { 'n', 'sw2' } })
