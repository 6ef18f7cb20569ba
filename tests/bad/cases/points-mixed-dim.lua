-- expect: 1 "bezier: point P_1 has 3 coordinates, point P_0 has 2"
-- points of different dimensions
local c = bezier{ {0, 0}, {1, 1, 1}, {2, 0} }
