-- expect: 1 "bezier: weight w_1 is string, not a number"
-- a weight that is a string
local c = bezier{ points = {{0,0},{1,1},{2,0}}, weights = {1, 'w', 1} }
