-- expect: 1 "polygon: unknown option 'closed'; the options are color, fill, width"
-- closed belongs to polyline only (a polygon is always closed)
local f = figure{ name = 'z' }
f:polygon({ {0, 0}, {1, 2}, {2, 0}, {3, 1} }, { closed = true })
