-- expect: 1 "bezier: weight w_1 is 0; weights must be finite and positive"
-- a zero weight
local c = bezier{ points = {{0,0},{1,1},{2,0}}, weights = {1, 0, 1} }
