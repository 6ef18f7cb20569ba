-- expect: 1 "bezier: weight w_1 is NaN; it must be finite"
-- a NaN weight
local c = bezier{ points = {{0,0},{1,1},{2,0}}, weights = {1, 0/0, 1} }
