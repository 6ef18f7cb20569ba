-- expect: 1 "bezier: 2 weights given for 3 points"
-- two weights for three points
local c = bezier{ points = {{0,0},{1,1},{2,0}}, weights = {1, 2} }
