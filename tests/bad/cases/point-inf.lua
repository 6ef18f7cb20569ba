-- expect: 1 "bezier: point P_1 coordinate 1 is inf; coordinates must be finite"
-- an infinite coordinate
local c = bezier{ {0, 0}, {1/0, 1}, {2, 0} }
