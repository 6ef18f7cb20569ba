-- expect: 1 "bezier: point 2 has 3 coordinates, point 1 has 2"
-- points of different dimensions
local c = bezier{ {0, 0}, {1, 1, 1}, {2, 0} }
