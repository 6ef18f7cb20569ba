-- expect: 1 "bezier: weight w_1 is -1; weights must be finite and positive"
-- weights by their mathematical index (w_0 first)
local c = bezier{ {0, 0}, {1, 1}, {2, 0}, weights = { 1, -1, 1 } }
