-- expect: 1 "bezier: point P_1 coordinate 1 is string, not a number"
-- a coordinate that is a string
local c = bezier{ {0, 0}, {'x', 1}, {2, 0} }
