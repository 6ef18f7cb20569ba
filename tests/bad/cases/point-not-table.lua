-- expect: 1 "bezier: point P_1 must be a table {x, y, ...}, got number"
-- a point given as a number
local c = bezier{ {0, 0}, 5, {2, 0} }
