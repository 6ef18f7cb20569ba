-- expect: 1 "bezier: point 2 coordinate 2 is "
-- a NaN coordinate
local c = bezier{ {0, 0}, {1, 0/0}, {2, 0} }
