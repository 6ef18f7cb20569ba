-- expect: 1 "bezier: weight w_1 is inf; it must be finite"
-- an infinite weight
local c = bezier{ points = {{0,0},{1,1},{2,0}}, weights = {1, 1/0, 1} }
