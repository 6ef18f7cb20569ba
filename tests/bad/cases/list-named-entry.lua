-- expect: 1 "polygon: the point list has an entry named 'closed'; a list takes no names (options go in the table after it)"
-- an option written into the list of points is refused, not ignored
local f = figure{ name = 'z' }
f:polygon({ {0, 0}, {1, 1}, {2, 0}, closed = true })
