-- expect: 1 "bezier: point P_1 coordinate 2 is NaN; coordinates must be finite"
-- a NaN coordinate
local c = bezier{ {0, 0}, {1, 0/0}, {2, 0} }
