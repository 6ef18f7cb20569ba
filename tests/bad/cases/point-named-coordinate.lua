-- expect: 1 "bezier: point has an entry named 'z'; a point is {x, y, ...}"
-- a named coordinate is refused, not ignored
local c = bezier{ {0, 0}, {1, 1, z = 2} }
